package dev.crt.lang.syntax;

import dev.crt.lang.Diagnostic;
import dev.crt.lang.Severity;
import dev.crt.lang.TextPositions;
import dev.crt.lang.parser.CRTLexer;
import dev.crt.lang.parser.CRTParser;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.Iterator;
import java.util.List;
import java.util.Set;
import org.antlr.v4.runtime.BailErrorStrategy;
import org.antlr.v4.runtime.CharStream;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.CommonTokenStream;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.TokenStream;
import org.antlr.v4.runtime.atn.PredictionMode;

/**
 * Reads a whole script once: a script without mistakes by {@link QuickParser}, one with
 * mistakes by ANTLR, which reports every syntax error (up to a limit) as a diagnostic. The
 * statements of a script without errors are handed out in order to be run.
 */
public final class ScriptParser {
    /** The most syntax errors reported for one file; more only add noise. */
    public static final int MAX_ERRORS = 20;

    private ScriptParser() {}

    /**
     * The outcome of the syntax check: the top-level statements (null when there were syntax
     * errors), the syntax diagnostics in source order, and every name the script assigns or binds
     * as a macro parameter.
     */
    public record Parsed(Iterator<CRTParser.StatementContext> statements, List<Diagnostic> errors, Set<String> assignedNames) {}

    /** Parses with no time limit. */
    public static Parsed parse(TextPositions positions) {
        return parse(positions, new ParseClock(System.nanoTime(), Duration.ofNanos(Long.MAX_VALUE)));
    }

    /**
     * Parses, stopping with a diagnostic once {@code clock}'s budget is spent: the time budget of
     * a compile covers its parse, which on a huge script is most of the compile.
     */
    public static Parsed parse(TextPositions positions, ParseClock clock) { return parse(positions, clock, false); }

    /**
     * The same; with {@code writtenObjects}, top-level object literals of plain values are handed
     * out as {@link WrittenStatement}s, built from their tokens.
     */
    public static Parsed parse(TextPositions positions, ParseClock clock, boolean writtenObjects) {
        try {
            return parseWithin(positions, clock, writtenObjects);
        } catch (ParseClock.OutOfTime out) {
            SyntaxErrors stopped = new SyntaxErrors(positions);
            stopped.add(out.at(), out.getMessage());
            return new Parsed(null, stopped.diagnostics(), Set.of());
        }
    }

    private static Parsed parseWithin(TextPositions positions, ParseClock clock, boolean writtenObjects) {
        // A script without mistakes, nearly every one that is compiled, is read once by hand.
        QuickParser.Result quick = QuickParser.parse(positions.text(), clock, writtenObjects);
        if (quick != null) return new Parsed(quick, List.of(), quick.assignedNames());

        // A script with a mistake is read once by ANTLR, with full LL prediction and the error
        // recovery that finds every mistake (up to the limit) and says each one for people.
        CharStream chars = CharStreams.fromString(positions.text());
        CRTLexer lexer = clock.lexer(chars);
        lexer.removeErrorListeners();
        CommonTokenStream tokens = new CommonTokenStream(lexer);
        tokens.fill();
        SyntaxErrors errors = new SyntaxErrors(positions);
        reportLexicalMistakes(tokens, errors);
        Set<String> assigned = assignedNames(tokens.getTokens());
        CRTParser parser = checkingParser(tokens, clock);
        parser.setBuildParseTree(true);
        parser.getInterpreter().setPredictionMode(PredictionMode.LL);
        parser.setErrorHandler(new HumanErrorStrategy(positions));
        parser.addErrorListener(errors);
        CRTParser.ScriptContext script = null;
        try {
            script = parser.script();
        } catch (SyntaxErrors.TooManyErrors tooMany) {
            // The first errors are all anyone reads.
        }
        List<Diagnostic> found = errors.diagnostics();
        if (!found.isEmpty()) return new Parsed(null, limit(found), assigned);
        // A script the quick reader refused but the grammar accepts: ANTLR's tree serves.
        List<CRTParser.StatementContext> statements = new ArrayList<>(script.statement());
        for (CRTParser.StatementContext statement : statements) statement.parent = null;
        return new Parsed(handedOut(statements), List.of(), assigned);
    }

    /** A parser with SLL prediction that builds no tree and gives up at the first error. */
    static CRTParser checkingParser(TokenStream tokens, ParseClock clock) {
        CRTParser parser = clock.parser(tokens);
        GreedyOperators.install(parser);
        parser.removeErrorListeners();
        parser.setBuildParseTree(false);
        parser.getInterpreter().setPredictionMode(PredictionMode.SLL);
        parser.setErrorHandler(new BailErrorStrategy());
        return parser;
    }

    /** The statements in order, each let go once handed out, so that a run tree can be collected. */
    private static Iterator<CRTParser.StatementContext> handedOut(List<CRTParser.StatementContext> statements) {
        return new Iterator<>() {
            private int next;

            @Override
            public boolean hasNext() { return next < statements.size(); }

            @Override
            public CRTParser.StatementContext next() {
                CRTParser.StatementContext statement = statements.get(next);
                statements.set(next++, null);
                return statement;
            }
        };
    }

    private static void reportLexicalMistakes(CommonTokenStream tokens, SyntaxErrors errors) {
        for (Token token : tokens.getTokens()) {
            if (token.getType() == CRTLexer.UNTERMINATED_STRING) {
                errors.add(token, "unterminated string (a string ends with \" on the line it starts)");
            } else if (token.getType() == CRTLexer.BAD_CHARACTER) {
                errors.add(token, "unexpected character " + describeCharacter(token.getText()));
            } else if (token.getType() == CRTLexer.FLOAT && "eE+-".indexOf(token.getText().charAt(token.getText().length() - 1)) >= 0) {
                errors.add(token, "malformed number '" + token.getText() + "': an exponent needs digits, as in 1e3 or 2.5e-4");
            }
        }
    }

    /** Names assigned ({@code name =}) or bound as macro parameters ({@code Macro (a, b)}), read off the tokens. */
    static Set<String> assignedNames(List<Token> tokens) {
        Set<String> names = new HashSet<>();
        List<Token> visible = new ArrayList<>();
        for (Token t : tokens) if (t.getChannel() == Token.DEFAULT_CHANNEL) visible.add(t);
        for (int i = 0; i + 1 < visible.size(); i++) {
            int type = visible.get(i).getType();
            if (type == CRTLexer.IDENT && visible.get(i + 1).getType() == CRTLexer.ASSIGN) {
                names.add(visible.get(i).getText());
            } else if (type == CRTLexer.MACRO && visible.get(i + 1).getType() == CRTLexer.LPAREN) {
                for (int j = i + 2; j < visible.size() && visible.get(j).getType() != CRTLexer.RPAREN; j++) {
                    if (visible.get(j).getType() == CRTLexer.IDENT) names.add(visible.get(j).getText());
                }
            }
        }
        return names;
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
        kept.add(new Diagnostic(Severity.NOTE, "too many errors; stopped after " + MAX_ERRORS, last.span(), List.of()));
        return kept;
    }
}
