package dev.crt.studio;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.fife.ui.rsyntaxtextarea.RSyntaxTextArea;
import org.fife.ui.rsyntaxtextarea.folding.CurlyFoldParser;
import org.fife.ui.rsyntaxtextarea.folding.Fold;
import org.junit.jupiter.api.Test;

/**
 * The editor's fold parser reads characters, not tokens: it must find the folds the library's
 * token-based parser finds with CRT's own lexer, on the example scenes and on braces hidden in
 * strings, escapes, unterminated strings and comments.
 */
class BraceFoldParserTest {
    @Test
    void findsTheFoldsTheLexerBasedParserFinds() throws Exception {
        List<String> texts = new ArrayList<>();
        try (Stream<Path> scenes = Files.list(Path.of("scenes"))) {
            for (Path p : (Iterable<Path>) scenes.filter(p -> p.toString().endsWith(".crt")).sorted()::iterator) {
                texts.add(Files.readString(p));
            }
        }
        texts.add("""
                Settings {
                  title -> "a { in a string"
                  author -> "an escaped \\" { quote"
                  -- a comment {
                  notes -> "unterminated {
                }
                m = Macro (x) {
                  Sphere { radius -> x
                    center -> vec3(0, 0, 0) }
                  "}" -- }
                }
                } } {
                Scene { Box {
                } }
                """);
        texts.add("Scene {\r\n  Sphere {\r\n  }\r\n}\r\n");
        texts.add("{\n{\n");
        for (String text : texts) {
            CrtTokenMaker.register();
            RSyntaxTextArea area = new RSyntaxTextArea();
            area.setSyntaxEditingStyle(CrtTokenMaker.STYLE);
            area.setText(text);
            List<String> expected = describe(new CurlyFoldParser().getFolds(area));
            assertThat(expected).as("the test text has folds").isNotEmpty();
            assertThat(describe(new BraceFoldParser().getFolds(area))).as(text).isEqualTo(expected);
        }
    }

    private static List<String> describe(List<Fold> folds) {
        List<String> out = new ArrayList<>();
        for (Fold f : folds) describe(f, "", out);
        return out;
    }

    private static void describe(Fold f, String indent, List<String> out) {
        out.add(indent + f.getStartOffset() + ".." + f.getEndOffset());
        for (int i = 0; i < f.getChildCount(); i++) describe(f.getChild(i), indent + "  ", out);
    }
}
