package dev.crt.lang.syntax;

import org.antlr.v4.runtime.CharStream;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.TokenSource;
import org.antlr.v4.runtime.tree.TerminalNodeImpl;

/**
 * A token of {@link QuickParser}, which is also its leaf of the parse tree (one object instead of
 * a token and a node: a written-out scene has millions): the positions ANTLR's lexer would give
 * it, and its text either shared (keywords, operators, names) or cut from the script only when
 * asked for (numbers and strings, which the compiler reads once and caches as values).
 */
final class ScriptToken extends TerminalNodeImpl implements Token {
    private final String script;
    private final String text;
    private final int type;
    private final int start;
    private final int stop;
    private final int line;
    private final int column;
    private final int index;

    ScriptToken(String script, String text, int type, int start, int stop, int line, int column, int index) {
        super(null);
        symbol = this;
        this.script = script;
        this.text = text;
        this.type = type;
        this.start = start;
        this.stop = stop;
        this.line = line;
        this.column = column;
        this.index = index;
    }

    @Override
    public String getText() {
        if (text != null) return text;
        return type == EOF ? "<EOF>" : script.substring(start, stop + 1);
    }

    @Override
    public int getType() { return type; }

    @Override
    public int getLine() { return line; }

    @Override
    public int getCharPositionInLine() { return column; }

    @Override
    public int getChannel() { return DEFAULT_CHANNEL; }

    @Override
    public int getTokenIndex() { return index; }

    @Override
    public int getStartIndex() { return start; }

    @Override
    public int getStopIndex() { return stop; }

    @Override
    public TokenSource getTokenSource() { return null; }

    @Override
    public CharStream getInputStream() { return null; }

    @Override
    public String toString() { return "[@" + index + "," + start + ":" + stop + "='" + getText() + "',<" + type + ">," + line + ":" + column + "]"; }
}
