package dev.crt.lang.syntax;

import dev.crt.lang.parser.CRTParser;
import org.antlr.v4.runtime.ParserRuleContext;

/**
 * A top-level statement that is an object literal of plain values ({@code Sphere { center ->
 * vec3(1, 2, 3) radius -> 0.5 }}), or an assignment of one, kept as its tokens: the reading has
 * checked that the grammar accepts it, and the evaluator builds the object straight from the
 * tokens. Its parse tree, the very one the general reading makes, is built only when asked for
 * (to report a mistake, or for a source map). Token 0 is the statement's first; the last token
 * is the one after the statement.
 */
public final class WrittenStatement extends CRTParser.StatementContext {
    private final String script;
    private final ScriptToken[] tokens;
    private final boolean assigns;

    WrittenStatement(String script, ScriptToken[] tokens, ParserRuleContext parent, boolean assigns) {
        this.script = script;
        this.tokens = tokens;
        this.assigns = assigns;
        this.parent = parent;
        this.start = tokens[0];
        this.stop = tokens[tokens.length - 2];
    }

    /** Whether the statement is {@code name = Type { … }}: the object literal then starts at token 2. */
    public boolean assigns() { return assigns; }

    /** The name assigned (when {@link #assigns}). */
    public String assignedName() { return tokens[0].getText(); }

    /** The number of tokens of the statement. */
    public int size() { return tokens.length - 1; }

    /** The token type of token {@code i} (the constants of the generated parser). */
    public int type(int i) { return tokens[i].getType(); }

    /** Token {@code i}'s text: shared for names and keywords, cut from the script for the rest. */
    public String text(int i) { return tokens[i].getText(); }

    /** Where token {@code i} starts, as the generated lexer counts (code points). */
    public int startIndex(int i) { return tokens[i].getStartIndex(); }

    /** Where token {@code i} ends (inclusive), as the generated lexer counts. */
    public int stopIndex(int i) { return tokens[i].getStopIndex(); }

    /** The script the tokens are from. */
    public String script() { return script; }

    /** The statement's parse tree, as the general reading builds it (a fresh one on each call). */
    public CRTParser.StatementContext tree() { return new QuickParser(script, tokens).tree((ParserRuleContext) parent); }
}
