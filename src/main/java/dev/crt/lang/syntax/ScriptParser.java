package dev.crt.lang.syntax;

import dev.crt.lang.Diagnostic;
import dev.crt.lang.Severity;
import dev.crt.lang.TextPositions;
import dev.crt.lang.parser.CRTLexer;
import dev.crt.lang.parser.CRTParser;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.antlr.v4.runtime.BailErrorStrategy;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.CommonToken;
import org.antlr.v4.runtime.CommonTokenStream;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.atn.PredictionMode;
import org.antlr.v4.runtime.misc.ParseCancellationException;

/** Parses a script into a tree, or reports every syntax error (up to a limit) as diagnostics. */
public final class ScriptParser {
    /** The most syntax errors reported for one file; more only add noise. */
    public static final int MAX_ERRORS = 20;

    // The text of every keyword and operator token, from the grammar's vocabulary.
    private static final String[] FIXED_TEXT = new String[CRTLexer.VOCABULARY.getMaxTokenType() + 1];

    static {
        for (int type = 1; type < FIXED_TEXT.length; type++) {
            String literal = CRTLexer.VOCABULARY.getLiteralName(type);
            if (literal != null) FIXED_TEXT[type] = literal.substring(1, literal.length() - 1);
        }
    }

    private ScriptParser() {}

    /** The parse tree (null when there were syntax errors) and the syntax diagnostics in source order. */
    public record Parsed(CRTParser.ScriptContext tree, List<Diagnostic> errors) {}

    public static Parsed parse(TextPositions positions) {
        CRTLexer lexer = new CRTLexer(CharStreams.fromString(positions.text()));
        lexer.removeErrorListeners();
        CommonTokenStream tokens = new CommonTokenStream(lexer);
        tokens.fill();
        SyntaxErrors errors = new SyntaxErrors(positions);
        reportLexicalMistakes(tokens, errors);

        // Two stages, as ANTLR recommends: the fast SLL prediction succeeds for almost every script;
        // only a script it fails on is parsed again with full LL and error recovery.
        CRTParser parser = new CRTParser(tokens);
        parser.removeErrorListeners();
        // Child lists trimmed to their size: a huge script's parse tree then fits the heap with room to spare.
        parser.setTrimParseTree(true);
        parser.getInterpreter().setPredictionMode(PredictionMode.SLL);
        parser.setErrorHandler(new BailErrorStrategy());
        CRTParser.ScriptContext tree;
        try {
            tree = parser.script();
        } catch (ParseCancellationException sllFailed) {
            tokens.seek(0);
            parser.reset();
            parser.getInterpreter().setPredictionMode(PredictionMode.LL);
            parser.setErrorHandler(new HumanErrorStrategy(positions));
            parser.addErrorListener(errors);
            try {
                tree = parser.script();
            } catch (SyntaxErrors.TooManyErrors enough) {
                tree = null;
            }
        }
        List<Diagnostic> found = errors.diagnostics();
        if (found.isEmpty()) return new Parsed(tree, List.of());
        return new Parsed(null, limit(found));
    }

    private static void reportLexicalMistakes(CommonTokenStream tokens, SyntaxErrors errors) {
        // Names and operators are fixed on their tokens once, shared, so that evaluating them in loops neither
        // copies characters again nor rehashes new strings.
        Map<String, String> names = new HashMap<>();
        for (Token token : tokens.getTokens()) {
            int type = token.getType();
            if (type == CRTLexer.IDENT || type == CRTLexer.NAME) {
                ((CommonToken) token).setText(names.computeIfAbsent(token.getText(), n -> n));
            } else if (type > 0 && type < FIXED_TEXT.length && FIXED_TEXT[type] != null) {
                ((CommonToken) token).setText(FIXED_TEXT[type]);
            }
            if (token.getType() == CRTLexer.UNTERMINATED_STRING) {
                errors.add(token, "unterminated string (a string ends with \" on the line it starts)");
            } else if (token.getType() == CRTLexer.BAD_CHARACTER) {
                errors.add(token, "unexpected character " + describeCharacter(token.getText()));
            }
        }
    }

    private static String describeCharacter(String text) {
        int cp = text.codePointAt(0);
        if (Character.isISOControl(cp) || Character.isWhitespace(cp)) return String.format("U+%04X", cp);
        return "'" + text + "'";
    }

    private static List<Diagnostic> limit(List<Diagnostic> found) {
        List<Diagnostic> sorted = new ArrayList<>(found);
        sorted.sort(Comparator.comparingInt(d -> d.span().start()));
        if (sorted.size() <= MAX_ERRORS) return sorted;
        List<Diagnostic> kept = new ArrayList<>(sorted.subList(0, MAX_ERRORS));
        Diagnostic last = kept.get(MAX_ERRORS - 1);
        kept.add(new Diagnostic(Severity.ERROR, "too many errors; stopped after " + MAX_ERRORS, last.span(), List.of()));
        return kept;
    }
}
