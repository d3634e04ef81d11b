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
}
