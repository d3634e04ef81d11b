package dev.crt.lang;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.scene.SourceSpan;
import java.util.List;
import org.junit.jupiter.api.Test;

class DiagnosticFormatterTest {
    @Test
    void compilerStyleWithSourceLineAndSpan() {
        String text = "s = Sphere {\n\tradus -> 2\n}\n";
        Diagnostic d = Scripts.error(text);
        assertThat(DiagnosticFormatter.format(d, text)).isEqualTo("""
                test.crt:2:2: error: unknown attribute 'radus' for Sphere (did you mean 'radius'?)
                \tradus -> 2
                \t^~~~~""");
    }

    @Test
    void singleCharacterGetsACaretAndWarningsSayWarning() {
        String text = "ab\ncd\n";
        Diagnostic d = new Diagnostic(Severity.WARNING, "look", new SourceSpan("f.crt", 2, 2, 4, 5), List.of("in macro 'm' called at 1:1"));
        assertThat(DiagnosticFormatter.format(d, text)).isEqualTo("f.crt:2:2: warning: look\ncd\n ^\n  in macro 'm' called at 1:1");
    }

    @Test
    void spansOverSeveralLinesStopAtTheEndOfTheFirst() {
        String text = "x = [1,\n2]\r\ny";
        Diagnostic d = new Diagnostic(Severity.ERROR, "m", new SourceSpan("f.crt", 1, 5, 4, 10), List.of());
        assertThat(DiagnosticFormatter.format(d, text)).isEqualTo("f.crt:1:5: error: m\nx = [1,\n    ^~~");
    }

    @Test
    void spansOutsideTheTextPrintOnlyTheHeader() {
        Diagnostic d = new Diagnostic(Severity.ERROR, "m", new SourceSpan("f.crt", 3, 1, 50, 60), List.of());
        assertThat(DiagnosticFormatter.format(d, "short")).isEqualTo("f.crt:3:1: error: m");
        assertThat(DiagnosticFormatter.format(d, null)).isEqualTo("f.crt:3:1: error: m");
    }

    @Test
    void theCaretCountsDisplayColumnsAsTerminalsDo() {
        // Two CJK characters take four columns; the column in the header still counts characters.
        String text = "s = \"漢字\" + radus\n";
        Diagnostic d = new Diagnostic(Severity.ERROR, "m", new SourceSpan("f.crt", 1, 12, 11, 16), List.of());
        assertThat(DiagnosticFormatter.format(d, text)).isEqualTo("f.crt:1:12: error: m\n" + text.strip() + "\n"
                + " ".repeat(13) + "^~~~~");
    }

    @Test
    void controlCharactersAreEscapedNotSentToTheTerminal() {
        String text = "a\u001b[2Jb = 1\n";
        Diagnostic d = new Diagnostic(Severity.ERROR, "m", new SourceSpan("f.crt", 1, 2, 1, 2), List.of());
        assertThat(DiagnosticFormatter.format(d, text)).isEqualTo("f.crt:1:2: error: m\na\\u001B[2Jb = 1\n ^~~~~~")
                .doesNotContain("\u001b");
    }

    @Test
    void aVeryLongLineIsShownAroundTheCaret() {
        String text = "x = " + "1 + ".repeat(10_000) + "zz\n";
        int at = text.indexOf("zz");
        Diagnostic d = new Diagnostic(Severity.ERROR, "m", new SourceSpan("f.crt", 1, at + 1, at, at + 2), List.of());
        List<String> lines = DiagnosticFormatter.format(d, text).lines().toList();
        assertThat(lines.get(1)).startsWith("…").endsWith("1 + zz").hasSizeLessThanOrEqualTo(DiagnosticFormatter.MAX_SHOWN + 2);
        assertThat(lines.get(2).indexOf('^')).isEqualTo(lines.get(1).indexOf("zz"));
    }
}
