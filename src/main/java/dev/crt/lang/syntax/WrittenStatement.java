package dev.crt.lang.syntax;

import dev.crt.lang.parser.CRTParser;
import org.antlr.v4.runtime.ParserRuleContext;

/**
 * A top-level statement that is an object literal of plain values ({@code Sphere { center ->
 * vec3(1, 2, 3) radius -> 0.5 }}), or an assignment of one, kept as its tokens: the reading has
 * checked that the grammar accepts it, and the evaluator builds the object straight from the
 * tokens. Its parse tree, the very one the general reading makes, is built only when asked for
 * (to report a mistake). Its tokens are numbered from 0, its first.
 */
public final class WrittenStatement extends CRTParser.StatementContext {
    private final QuickParser reader;
    private final int from;
    private final int size;
    private final boolean assigns;

    WrittenStatement(QuickParser reader, int from, int end, ParserRuleContext parent, boolean assigns) {
        this.reader = reader;
        this.from = from;
        this.size = end - from;
        this.assigns = assigns;
        this.parent = parent;
    }

    /** Whether the statement is {@code name = Type { … }}: the object literal then starts at token 2. */
    public boolean assigns() { return assigns; }

    /** The name assigned (when {@link #assigns}). */
    public String assignedName() { return reader.textOf(from); }

    /** The number of tokens of the statement. */
    public int size() { return size; }

    /** The token type of token {@code i} (the constants of the generated parser); i = size() is the token after. */
    public int type(int i) { return reader.typeOf(from + i); }

    /** Token {@code i}'s text: shared for names and keywords, cut from the script for the rest. */
    public String text(int i) { return reader.textOf(from + i); }

    /** Where token {@code i} starts, as the generated lexer counts (code points). */
    public int startIndex(int i) { return reader.startOf(from + i); }

    /** Where token {@code i} ends (inclusive), as the generated lexer counts. */
    public int stopIndex(int i) { return reader.stopOf(from + i); }

    /** The script the tokens are from. */
    public String script() { return reader.script(); }

    /** The statement's parse tree, as the general reading builds it (a fresh one on each call). */
    public CRTParser.StatementContext tree() { return reader.tree(from, (ParserRuleContext) parent); }
}
