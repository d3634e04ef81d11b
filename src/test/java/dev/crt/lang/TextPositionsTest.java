package dev.crt.lang;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.scene.SourceSpan;
import org.junit.jupiter.api.Test;

class TextPositionsTest {
    @Test
    void crLfCrAndLfAreEachOneLineBreak() {
        TextPositions p = new TextPositions("f.crt", "a\r\nb\rc\nd");
        assertThat(p.span(3, 4)).isEqualTo(new SourceSpan("f.crt", 2, 1, 3, 4));
        assertThat(p.span(5, 6)).isEqualTo(new SourceSpan("f.crt", 3, 1, 5, 6));
        assertThat(p.span(7, 8)).isEqualTo(new SourceSpan("f.crt", 4, 1, 7, 8));
    }

    @Test
    void codePointIndicesBecomeCharacterOffsets() {
        String text = "x = \"\uD83D\uDE00\" + 1";
        TextPositions p = new TextPositions("f.crt", text);
        // ANTLR counts the emoji as one code point; Java strings as two chars.
        assertThat(p.charOffset(7)).isEqualTo(8);
        Diagnostic d = CrtCompiler.compile(Source.of("f.crt", text), CompileOptions.DEFAULT).diagnostics().get(0);
        assertThat(text.substring(d.span().start(), d.span().end())).isEqualTo("\"\uD83D\uDE00\" + 1");
    }

    @Test
    void spansAreClampedToTheText() {
        TextPositions p = new TextPositions("f.crt", "ab");
        assertThat(p.span(5, 9)).isEqualTo(new SourceSpan("f.crt", 1, 3, 2, 2));
    }

    @Test
    void crOnlyFilesReportTheRightLine() {
        Diagnostic d = Scripts.error("a = 1\rb = 2\rc = a + \"s\"\r");
        assertThat(d.span().line()).isEqualTo(3);
        assertThat(d.span().column()).isEqualTo(5);
    }

    @Test
    void everyOffsetGetsTheLineAndColumnACountOfLineBreaksGivesInAnyOrderOfQuestions() {
        java.util.Random random = new java.util.Random(7);
        for (String breaks : new String[] {"\n", "\r\n", "\r", "\n\r\n"}) {
            StringBuilder b = new StringBuilder();
            for (int i = 0; i < 400; i++) {
                b.append("ab c".repeat(random.nextInt(3)));
                if (random.nextInt(4) == 0) b.append("\uD83D\uDE00");
                b.append(breaks.charAt(random.nextInt(breaks.length())));
            }
            String text = b.toString();
            TextPositions p = new TextPositions("f.crt", text);
            // Reading order (the compiler's), then at random (the studio's, the diagnostics').
            java.util.List<Integer> offsets = new java.util.ArrayList<>();
            for (int i = 0; i <= text.length(); i++) offsets.add(i);
            for (int round = 0; round < 2; round++) {
                for (int offset : offsets) {
                    int line = 1, lineStart = 0;
                    for (int i = 0; i < offset; i++) {
                        char c = text.charAt(i);
                        if (c == '\n' || c == '\r' && (i + 1 >= text.length() || text.charAt(i + 1) != '\n')) {
                            line++;
                            lineStart = i + 1;
                        }
                    }
                    SourceSpan span = p.span(offset, offset);
                    assertThat(span.line()).as("line of offset %d", offset).isEqualTo(line);
                    assertThat(span.column()).as("column of offset %d", offset).isEqualTo(text.codePointCount(lineStart, offset) + 1);
                }
                java.util.Collections.shuffle(offsets, random);
            }
        }
    }
}
