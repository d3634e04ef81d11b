package dev.crt.lang.syntax;

import dev.crt.lang.Diagnostic;
import dev.crt.lang.Severity;
import dev.crt.lang.TextPositions;
import dev.crt.lang.parser.CRTLexer;
import dev.crt.lang.parser.CRTParser;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.antlr.v4.runtime.BailErrorStrategy;
import org.antlr.v4.runtime.CharStream;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.CommonToken;
import org.antlr.v4.runtime.CommonTokenFactory;
import org.antlr.v4.runtime.CommonTokenStream;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.TokenSource;
import org.antlr.v4.runtime.TokenStream;
import org.antlr.v4.runtime.UnbufferedTokenStream;
import org.antlr.v4.runtime.atn.PredictionMode;
import org.antlr.v4.runtime.misc.Pair;
import org.antlr.v4.runtime.misc.ParseCancellationException;

/**
 * Checks a whole script for syntax errors, reporting every one (up to a limit) as diagnostics;
 * a script without errors is then handed out one top-level statement at a time, so that a huge
 * script never holds all of its parse tree in memory at once.
 */
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
    public static Parsed parse(TextPositions positions, ParseClock clock) {
        try {
            return parseWithin(positions, clock);
        } catch (ParseClock.OutOfTime out) {
            SyntaxErrors stopped = new SyntaxErrors(positions);
            stopped.add(out.at(), out.getMessage());
            return new Parsed(null, stopped.diagnostics(), Set.of());
        }
    }

    private static Parsed parseWithin(TextPositions positions, ParseClock clock) {
        CharStream chars = CharStreams.fromString(positions.text());
        CRTLexer lexer = clock.lexer(chars);
        lexer.removeErrorListeners();
        CommonTokenStream tokens = new CommonTokenStream(lexer);
        tokens.fill();
        SyntaxErrors errors = new SyntaxErrors(positions);
        reportLexicalMistakes(tokens, errors);
        Set<String> assigned = assignedNames(tokens.getTokens());

        // Two stages, as ANTLR recommends: the fast SLL prediction, without building a tree,
        // succeeds for almost every script; only a script it fails on is parsed again with full
        // LL and error recovery, which reports the errors.
        CRTParser parser = checkingParser(tokens, clock);
        PredictionMode enough = PredictionMode.SLL;
        try {
            parser.script();
        } catch (ParseCancellationException sllFailed) {
            enough = PredictionMode.LL;
            tokens.seek(0);
            parser.reset();
            parser.setBuildParseTree(true);
            parser.getInterpreter().setPredictionMode(PredictionMode.LL);
            parser.setErrorHandler(new HumanErrorStrategy(positions));
            parser.addErrorListener(errors);
            try {
                parser.script();
            } catch (SyntaxErrors.TooManyErrors tooMany) {
                // The first errors are all anyone reads.
            }
        }
        List<Diagnostic> found = errors.diagnostics();
        if (!found.isEmpty()) return new Parsed(null, limit(found), assigned);
        return new Parsed(new Statements(chars, enough, clock), List.of(), assigned);
    }

    /** The parser of the first, fast stage: SLL prediction, no tree, it gives up at the first error. */
    static CRTParser checkingParser(TokenStream tokens, ParseClock clock) {
        CRTParser parser = clock.parser(tokens);
        GreedyOperators.install(parser);
        parser.removeErrorListeners();
        parser.setBuildParseTree(false);
        parser.getInterpreter().setPredictionMode(PredictionMode.SLL);
        parser.setErrorHandler(new BailErrorStrategy());
        return parser;
    }

    /** The statements of a script known to be free of syntax errors, parsed as they are asked for. */
    private static final class Statements implements Iterator<CRTParser.StatementContext> {
        private final CRTParser parser;

        /** {@code mode} is the prediction that sufficed for the whole script in the check. */
        Statements(CharStream chars, PredictionMode mode, ParseClock clock) {
            chars.seek(0);
            CRTLexer lexer = clock.lexer(chars);
            lexer.removeErrorListeners();
            lexer.setTokenFactory(new SharedTextTokens());
            // Unbuffered: tokens no longer needed by a statement's tree are garbage once it has run.
            parser = clock.parser(new UnbufferedTokenStream<>(lexer));
            GreedyOperators.install(parser);
            parser.removeErrorListeners();
            parser.setTrimParseTree(true);
            parser.getInterpreter().setPredictionMode(mode);
            parser.setErrorHandler(new BailErrorStrategy());
        }

        @Override
        public boolean hasNext() { return parser.getInputStream().LA(1) != Token.EOF; }

        @Override
        public CRTParser.StatementContext next() { return parser.statement(); }
    }

    /**
     * Tokens whose text is set once and shared: names through a table, keywords and operators
     * from the vocabulary. Evaluating them in loops then neither copies characters nor rehashes.
     */
    private static final class SharedTextTokens extends CommonTokenFactory {
        private final Map<String, String> names = new HashMap<>();

        @Override
        public CommonToken create(Pair<TokenSource, CharStream> source, int type, String text, int channel,
                int start, int stop, int line, int charPositionInLine) {
            CommonToken token = super.create(source, type, text, channel, start, stop, line, charPositionInLine);
            if (type == CRTLexer.IDENT || type == CRTLexer.NAME) {
                token.setText(names.computeIfAbsent(token.getText(), n -> n));
            } else if (type > 0 && type < FIXED_TEXT.length && FIXED_TEXT[type] != null) {
                token.setText(FIXED_TEXT[type]);
            }
            return token;
        }
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
    private static Set<String> assignedNames(List<Token> tokens) {
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
