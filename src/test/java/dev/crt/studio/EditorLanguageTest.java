package dev.crt.studio;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.lang.eval.Vocabulary;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import javax.swing.text.Segment;
import org.fife.ui.autocomplete.Completion;
import org.fife.ui.rsyntaxtextarea.Token;
import org.fife.ui.rsyntaxtextarea.TokenTypes;
import org.junit.jupiter.api.Test;

/** What the editor reads from a script with the compiler's lexer: colours, context, definitions, completions. */
class EditorLanguageTest {
    private static List<String> tokens(String line) {
        Token t = new CrtTokenMaker().getTokenList(new Segment(line.toCharArray(), 0, line.length()), TokenTypes.NULL, 100);
        List<String> out = new ArrayList<>();
        for (; t != null && t.isPaintable(); t = t.getNextToken()) {
            assertThat(t.getOffset()).isEqualTo(100 + line.indexOf(t.getLexeme(), t.getOffset() - 100));
            out.add(t.getType() + ":" + t.getLexeme());
        }
        return out;
    }

    @Test
    void theTokenMakerCoversTheLineWithTheCompilersTokens() {
        String line = "ball = Sphere { radius -> 1.5 } -- a comment";
        assertThat(tokens(line)).containsExactly(
                TokenTypes.IDENTIFIER + ":ball", TokenTypes.WHITESPACE + ": ", TokenTypes.OPERATOR + ":=",
                TokenTypes.WHITESPACE + ": ", TokenTypes.DATA_TYPE + ":Sphere", TokenTypes.WHITESPACE + ": ",
                TokenTypes.SEPARATOR + ":{", TokenTypes.WHITESPACE + ": ", TokenTypes.IDENTIFIER + ":radius",
                TokenTypes.WHITESPACE + ": ", TokenTypes.OPERATOR + ":->", TokenTypes.WHITESPACE + ": ",
                TokenTypes.LITERAL_NUMBER_FLOAT + ":1.5", TokenTypes.WHITESPACE + ": ", TokenTypes.SEPARATOR + ":}",
                TokenTypes.WHITESPACE + ": ", TokenTypes.COMMENT_EOL + ":-- a comment");
        assertThat(tokens("s = \"a -- b\" while")).contains(TokenTypes.LITERAL_STRING_DOUBLE_QUOTE + ":\"a -- b\"",
                TokenTypes.RESERVED_WORD + ":while");
        assertThat(tokens("x = \"open")).contains(TokenTypes.ERROR_STRING_DOUBLE + ":\"open");
        assertThat(tokens("")).isEmpty();
        assertThat(new CrtTokenMaker().getLineCommentStartAndEnd(0)[0]).isEqualTo("-- ");
    }

    @Test
    void theContextSaysWhichObjectLiteralTheCaretIsIn() {
        String text = "Settings { width -> 10 }\nScene { Sphere { radius -> 1 cen";
        assertThat(ScriptWords.contextAt(text, text.length())).isEqualTo(new ScriptWords.Context("Sphere", true));
        String value = "Scene { Sphere { radius -> ra";
        assertThat(ScriptWords.contextAt(value, value.length())).isEqualTo(new ScriptWords.Context("Sphere", false));
        String settings = "Settings { wid";
        assertThat(ScriptWords.contextAt(settings, settings.length())).isEqualTo(new ScriptWords.Context("Settings", true));
        String outside = "Scene { Sphere { radius -> 1 } ";
        assertThat(ScriptWords.contextAt(outside, outside.length()).type()).isNull();
    }

    @Test
    void definitionsAreTheNearestEarlierAssignment() {
        String text = "r = 1\nr = 2\nball = Macro (p) { Sphere { center -> p radius -> r } }\nScene { ball(vec3(0, 0, 0)) }";
        assertThat(ScriptWords.definitionAt(text, text.indexOf("radius -> r") + 10)).hasValue(text.indexOf("r = 2"));
        assertThat(ScriptWords.definitionAt(text, text.indexOf("ball(v"))).hasValue(0 + text.indexOf("ball = "));
        assertThat(ScriptWords.definitionAt(text, text.indexOf("Sphere"))).isEmpty();
        assertThat(ScriptWords.assignedNames(ScriptWords.lex(text))).isEqualTo(Map.of("r", false, "ball", true));
    }

    @Test
    void completionOffersTheCompilersWords() {
        CompletionSource source = new CompletionSource();
        String attr = "Scene { Box { ";
        assertThat(source.candidates(attr, attr.length())).extracting(Completion::getInputText)
                .containsExactlyElementsOf(Vocabulary.objectTypes().get("Box"));
        String expr = "size = 2\nshape = Macro () { }\nScene { Sphere { radius -> ";
        List<String> words = source.candidates(expr, expr.length()).stream().map(Completion::getInputText).toList();
        assertThat(words).contains("size", "shape", "t", "sqrt", "vec3", "Sphere", "Material", "while");
        assertThat(words).containsAll(Vocabulary.builtins().keySet()).containsAll(Vocabulary.objectTypes().keySet());
    }

    @Test
    void settingsFollowTheXdgVariables() {
        Path home = Path.of("/home/ada");
        StudioPaths defaults = StudioPaths.from(Map.of(), home);
        assertThat(defaults.config()).isEqualTo(Path.of("/home/ada/.config/crt"));
        assertThat(defaults.recovery()).isEqualTo(Path.of("/home/ada/.local/state/crt/recovery"));
        StudioPaths set = StudioPaths.from(Map.of("XDG_CONFIG_HOME", "/cfg", "XDG_STATE_HOME", "/st"), home);
        assertThat(set.config()).isEqualTo(Path.of("/cfg/crt"));
        assertThat(set.recovery()).isEqualTo(Path.of("/st/crt/recovery"));
        // Relative values are invalid by the specification and ignored.
        assertThat(StudioPaths.from(Map.of("XDG_CONFIG_HOME", "rel"), home)).isEqualTo(defaults);
    }
}
