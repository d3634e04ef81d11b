package dev.crt.lang.syntax;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.lang.parser.CRTLexer;
import dev.crt.lang.parser.CRTParser;
import java.io.IOException;
import java.lang.reflect.Field;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.CommonTokenStream;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.atn.PredictionMode;
import org.antlr.v4.runtime.misc.ParseCancellationException;
import org.antlr.v4.runtime.tree.ParseTree;
import org.antlr.v4.runtime.tree.TerminalNode;
import org.junit.jupiter.api.Test;

/**
 * The hand-written reader builds exactly the tree ANTLR's generated parser builds (same context
 * classes, children, labelled tokens, and every token's type, text and positions), accepts every
 * script the generated parser accepts without a lexical mistake, and refuses every other (and
 * ANTLR's LL prediction, which reads the refused ones, gives SLL's tree): on the
 * example scenes, on thousands of random expressions using every operator and construct, and on
 * thousands of mangled scripts.
 */
class QuickParserTest {
    private static final ParseClock UNLIMITED = new ParseClock(System.nanoTime(), Duration.ofDays(1));

    /**
     * ANTLR's statements for {@code script} with SLL prediction (or full LL, the prediction of
     * ScriptParser's reading of the scripts QuickParser refuses), or null when it has a lexical or
     * syntax mistake.
     */
    private static List<CRTParser.StatementContext> antlr(String script, PredictionMode mode) {
        CommonTokenStream tokens = new CommonTokenStream(new CRTLexer(CharStreams.fromString(script)));
        tokens.fill();
        for (Token t : tokens.getTokens()) {
            int type = t.getType();
            if (type == CRTLexer.UNTERMINATED_STRING || type == CRTLexer.BAD_CHARACTER) return null;
            if (type == CRTLexer.FLOAT && "eE+-".indexOf(t.getText().charAt(t.getText().length() - 1)) >= 0) return null;
        }
        CRTParser parser = ScriptParser.checkingParser(tokens, UNLIMITED);
        parser.setBuildParseTree(true);
        parser.getInterpreter().setPredictionMode(mode);
        try {
            return parser.script().statement();
        } catch (ParseCancellationException mistake) {
            return null;
        }
    }

    /** Checks that both readers agree on {@code script}; whether they accepted it. */
    private static boolean agree(String script) {
        List<CRTParser.StatementContext> expected = antlr(script, PredictionMode.SLL);
        if (expected != null) {
            // A valid script with characters beyond the Basic Multilingual Plane is read by ANTLR
            // with LL prediction: its tree must be the one SLL prediction gave until now.
            List<CRTParser.StatementContext> full = antlr(script, PredictionMode.LL);
            assertThat(full).hasSameSizeAs(expected);
            for (int i = 0; i < expected.size(); i++) same(full.get(i), expected.get(i), script);
        }
        QuickParser.Result quick = QuickParser.parse(script, UNLIMITED);
        boolean beyondBmp = script.codePoints().anyMatch(Character::isSupplementaryCodePoint);
        if (expected == null || beyondBmp) {
            assertThat(quick).as("refused, as by ANTLR: %s", script).isNull();
            return false;
        }
        assertThat(quick).as("accepted, as by ANTLR: %s", script).isNotNull();
        // The names it gathers while it lexes are those read off ANTLR's tokens.
        CommonTokenStream tokens = new CommonTokenStream(new CRTLexer(CharStreams.fromString(script)));
        tokens.fill();
        assertThat(quick.assignedNames()).as("assigned names of %s", script).isEqualTo(ScriptParser.assignedNames(tokens.getTokens()));
        List<CRTParser.StatementContext> statements = new ArrayList<>();
        quick.forEachRemaining(statements::add);
        assertThat(statements).hasSameSizeAs(expected);
        for (int i = 0; i < expected.size(); i++) same(statements.get(i), expected.get(i), script);
        // The trees of a huge script's later statements are built again when they are to run.
        List<CRTParser.StatementContext> rebuilt = new ArrayList<>();
        QuickParser.parse(script, UNLIMITED, 0).forEachRemaining(rebuilt::add);
        assertThat(rebuilt).hasSameSizeAs(expected);
        for (int i = 0; i < expected.size(); i++) same(rebuilt.get(i), expected.get(i), script);
        return true;
    }

    private static void same(ParseTree actual, ParseTree expected, String script) {
        if (expected instanceof TerminalNode t) {
            assertThat(actual).as(script).isInstanceOf(TerminalNode.class);
            sameToken(((TerminalNode) actual).getSymbol(), t.getSymbol(), script);
            assertThat(actual.getParent()).isNotNull();
            return;
        }
        assertThat(actual.getClass()).as(script).isEqualTo(expected.getClass());
        ParserRuleContext a = (ParserRuleContext) actual, e = (ParserRuleContext) expected;
        sameToken(a.getStart(), e.getStart(), script);
        sameToken(a.getStop(), e.getStop(), script);
        assertThat(a.getChildCount()).as(script).isEqualTo(e.getChildCount());
        for (Field f : a.getClass().getFields()) {
            if (f.getType() == Token.class) {
                try {
                    sameToken((Token) f.get(a), (Token) f.get(e), script);
                } catch (IllegalAccessException ex) {
                    throw new AssertionError(ex);
                }
            }
        }
        for (int i = 0; i < e.getChildCount(); i++) {
            assertThat(a.getChild(i).getParent()).as(script).isSameAs(a);
            same(a.getChild(i), e.getChild(i), script);
        }
    }

    private static void sameToken(Token a, Token e, String script) {
        if (e == null) {
            assertThat(a).isNull();
            return;
        }
        String what = e + " in " + script;
        assertThat(a.getType()).as(what).isEqualTo(e.getType());
        assertThat(a.getText()).as(what).isEqualTo(e.getText());
        assertThat(a.getStartIndex()).as(what).isEqualTo(e.getStartIndex());
        assertThat(a.getStopIndex()).as(what).isEqualTo(e.getStopIndex());
        assertThat(a.getLine()).as(what).isEqualTo(e.getLine());
        assertThat(a.getCharPositionInLine()).as(what).isEqualTo(e.getCharPositionInLine());
        assertThat(a.getTokenIndex()).as(what).isEqualTo(e.getTokenIndex());
        assertThat(a.getChannel()).as(what).isEqualTo(e.getChannel());
    }

    @Test
    void theExampleScenesReadTheSame() throws IOException {
        List<Path> files = new ArrayList<>();
        for (String folder : List.of("scenes", "bench/scenes", "src/test/resources")) {
            if (!Files.isDirectory(Path.of(folder))) continue;
            try (Stream<Path> walk = Files.walk(Path.of(folder))) {
                walk.filter(p -> p.toString().endsWith(".crt")).sorted().forEach(files::add);
            }
        }
        assertThat(files).hasSizeGreaterThan(10);
        for (Path f : files) {
            String script = Files.readString(f);
            // A few scenes of the test resources have mistakes on purpose; the rest must be compared.
            if (!agree(script)) assertThat(f.toString()).contains("resources");
        }
    }

    @Test
    void randomExpressionsReadTheSame() {
        Random random = new Random(42);
        int accepted = 0;
        for (int i = 0; i < 3000; i++) {
            StringBuilder s = new StringBuilder();
            int statements = 1 + random.nextInt(4);
            for (int k = 0; k < statements; k++) statement(s, random, 3);
            if (agree(s.toString())) accepted++;
        }
        // Most are valid (an assignment inside an operation is not): the trees were compared.
        assertThat(accepted).isGreaterThan(1500);
    }

    @Test
    void mangledScriptsAreReadTheSameOrRefusedAlike() {
        Random random = new Random(7);
        int accepted = 0;
        String[] pieces = {"+", "-", "*", "<", ">", "<=", "==", "&&", "||", "?", ":", ",", "(", ")", "[", "]", "{", "}",
            "=", "->", "!", "1", "1.5", ".5", "1.", "1e3", "1e", "2.5E-", "x", "scale", "translate", "Sphere", "Macro",
            "if", "else", "while", "\n", " ", "--", "\"", "\"a\\\"b\"", "\"\\", "&", "|", ".", "#", "\u00e9", "\uD83D\uDE00", "\r"};
        for (int i = 0; i < 3000; i++) {
            StringBuilder s = new StringBuilder();
            statement(s, random, 3);
            statement(s, random, 2);
            for (int m = 1 + random.nextInt(3); m > 0; m--) {
                int at = random.nextInt(s.length() + 1);
                if (random.nextBoolean()) s.insert(at, pieces[random.nextInt(pieces.length)]);
                else s.delete(at, Math.min(s.length(), at + 1 + random.nextInt(4)));
            }
            if (agree(s.toString())) accepted++;
        }
        assertThat(accepted).isBetween(300, 2700);
    }

    @Test
    void numbersStringsAndCommentsAreCutAsByTheGeneratedLexer() {
        for (String script : List.of("x = 1.", "x = 1..2", "x = .5e3", "x = 1.5e+3 + 2E-2", "x = 1.e5", "x = 1e", "x = 1.e",
                "x = 1.5.3", "x = \"a\\\"b\\\\\"", "x = \"a\\qb\"", "x = \"abc", "x = 1 -- c\ny = 2", "x = 1 --> c", "x = a--b",
                "x = 1\r\ny = 2\rz = 3", "\uFEFFx = 1", "x = \"\u00e9\"", "-- \u00e9\nx = 1", "x = \"\uD83D\uDE00\"", "x = 1 & 2",
                "x = scaled + rotate_", "Settingsx = 1", "x = 12abc", "x = 1\f+\t2", "", "   ", "-- only a comment",
                // Characters beyond Latin-1, which the lexer reads as '?' and checks in the text.
                "x = \"\u0142\u20ac?\"", "-- \u0142\u20ac ?\nx = 1", "x = 1 \u0142", "x = 1 \u00e9", "x = a ? 1 : 2",
                "x = a \u0142 1 : 2", "x = \uFEFF1", "x\uFEFF= 1", "x = \"\\\u0142\"", "x = 1 -- \uD83D\uDE00",
                "x = \"\uFFFD\u00ff\"")) {
            agree(script);
        }
        // A lone surrogate in a comment or a string: the generated lexer takes it, this reader
        // leaves the script to it (as it did when it read chars).
        for (String script : List.of("-- \uD800\nx = 1", "x = \"\uDC00\"", "x = \"\\\uD800\"")) {
            assertThat(QuickParser.parse(script, UNLIMITED)).as(script).isNull();
        }
    }

    @Test
    void theFixedTextsAreTheGeneratedLexersLiterals() {
        int max = CRTLexer.VOCABULARY.getMaxTokenType();
        for (int type = 0; type <= max + 1; type++) {
            String literal = CRTLexer.VOCABULARY.getLiteralName(type);
            assertThat(QuickParser.fixedText(type)).as("token type %d", type)
                    .isEqualTo(literal == null ? null : literal.substring(1, literal.length() - 1));
        }
    }

    @Test
    void manyDistinctNamesAndKeywordsAmongThem() {
        // The lexer's table of names (each with its token type) grows past its first size, with
        // keywords, names of types and names that merely start like keywords spread through it.
        StringBuilder s = new StringBuilder();
        for (int i = 0; i < 300; i++) {
            s.append("n").append(i).append(" = ").append(i % 7 == 0 ? "true" : "false")
                    .append(" if (n").append(i).append(") { whilex").append(i).append(" = n").append(i)
                    .append(" } else { scale").append(i).append(" = Sphere").append(i % 5).append(" { radius -> 1 } }\n");
        }
        assertThat(agree(s.toString())).isTrue();
    }

    private static void statement(StringBuilder s, Random r, int depth) {
        switch (r.nextInt(depth > 0 ? 9 : 3)) {
            case 0, 1 -> s.append("v").append(r.nextInt(3)).append(space(r)).append('=').append(space(r));
            case 3 -> {
                s.append("if").append(space(r)).append('(');
                expression(s, r, depth - 1);
                s.append(')').append(space(r)).append('{');
                statement(s, r, depth - 1);
                s.append('}');
                if (r.nextBoolean()) {
                    s.append(space(r)).append("else").append(space(r));
                    if (r.nextBoolean()) statement(s.append("{ "), r, depth - 1);
                    else s.append("if (true) {");
                    s.append('}');
                }
                s.append('\n');
                return;
            }
            case 4 -> {
                s.append("while (");
                expression(s, r, depth - 1);
                s.append(") {");
                statement(s, r, depth - 1);
                s.append("}\n");
                return;
            }
            case 5 -> {
                s.append(r.nextBoolean() ? "Scene {" : "Settings { width -> 3 scale -> ");
                if (s.charAt(s.length() - 1) == ' ') expression(s, r, depth - 1);
                else statement(s, r, depth - 1);
                s.append("}\n");
                return;
            }
            default -> { }
        }
        expression(s, r, depth);
        s.append(r.nextInt(3) == 0 ? "\n" : " ");
    }

    private static String space(Random r) {
        return switch (r.nextInt(6)) {
            case 0 -> "";
            case 1 -> "\n";
            case 2 -> " -- note\n";
            default -> " ";
        };
    }

    private static final String[] BINARY = {"+", "-", "*", "/", "%", "^", "<", ">", "<=", ">=", "==", "!=", "&&", "||"};

    private static void expression(StringBuilder s, Random r, int depth) {
        if (depth <= 0) {
            primary(s, r, 0);
            return;
        }
        switch (r.nextInt(12)) {
            case 0, 1, 2 -> {
                expression(s, r, depth - 1);
                s.append(space(r)).append(BINARY[r.nextInt(BINARY.length)]).append(space(r));
                expression(s, r, depth - 1);
            }
            case 3 -> {
                s.append(r.nextBoolean() ? "-" : r.nextBoolean() ? "+" : "!").append(space(r));
                expression(s, r, depth - 1);
            }
            case 4 -> {
                expression(s, r, depth - 1);
                s.append(" ? ");
                expression(s, r, depth - 1);
                s.append(" : ");
                expression(s, r, depth - 1);
            }
            case 5 -> {
                expression(s, r, depth - 1);
                s.append(space(r)).append('<');
                for (int i = 1 + r.nextInt(3); i > 0; i--) {
                    s.append(List.of("translate", "rotate", "scale").get(r.nextInt(3))).append(' ');
                    expression(s, r, depth - 1);
                    if (i > 1) s.append(", ");
                }
                s.append('>');
            }
            case 6 -> {
                expression(s, r, depth - 1);
                s.append(space(r)).append('(');
                for (int i = r.nextInt(3); i > 0; i--) {
                    expression(s, r, depth - 1);
                    if (i > 1) s.append(", ");
                }
                s.append(')');
            }
            case 7 -> {
                expression(s, r, depth - 1);
                s.append(space(r)).append('[');
                expression(s, r, depth - 1);
                s.append(']');
            }
            case 8 -> {
                s.append("w = ");
                expression(s, r, depth - 1);
            }
            default -> primary(s, r, depth);
        }
    }

    private static void primary(StringBuilder s, Random r, int depth) {
        switch (r.nextInt(depth > 0 ? 12 : 7)) {
            case 0 -> s.append(r.nextInt(100));
            case 1 -> s.append(List.of("1.5", ".25", "2.", "1e3", "3.5E-2").get(r.nextInt(5)));
            case 2 -> s.append("\"s").append(r.nextInt(3)).append('"');
            case 3 -> s.append(r.nextBoolean() ? "true" : "false");
            case 4, 5, 6 -> s.append(List.of("x", "v0", "vec3", "pi", "t", "rgb").get(r.nextInt(6)));
            case 7 -> {
                s.append("Sphere {");
                for (int i = r.nextInt(3); i > 0; i--) {
                    s.append(List.of(" radius", " center", " scale").get(r.nextInt(3))).append(" -> ");
                    expression(s, r, depth - 1);
                }
                s.append(" }");
            }
            case 8 -> {
                s.append("Macro (");
                if (r.nextBoolean()) s.append(r.nextBoolean() ? "a" : "a, b");
                s.append(") { ");
                statement(s, r, depth - 1);
                s.append('}');
            }
            case 9 -> {
                s.append('[');
                for (int i = r.nextInt(4); i > 0; i--) {
                    expression(s, r, depth - 1);
                    if (i > 1) s.append(", ");
                }
                s.append(']');
            }
            default -> {
                s.append('(');
                expression(s, r, depth - 1);
                s.append(')');
            }
        }
    }
}
