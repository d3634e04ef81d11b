package dev.crt.lang.syntax;

import dev.crt.lang.Diagnostic;
import dev.crt.lang.Severity;
import dev.crt.lang.TextPositions;
import java.util.ArrayList;
import java.util.List;
import org.antlr.v4.runtime.BaseErrorListener;
import org.antlr.v4.runtime.RecognitionException;
import org.antlr.v4.runtime.Recognizer;
import org.antlr.v4.runtime.Token;

/** Collects syntax errors as diagnostics in place of ANTLR's console output. */
final class SyntaxErrors extends BaseErrorListener {
    /** Thrown to stop parsing once there are more errors than anyone will read. */
    static final class TooManyErrors extends RuntimeException {
        TooManyErrors() { super(null, null, false, false); }
    }

    private final TextPositions positions;
    private final List<Diagnostic> diagnostics = new ArrayList<>();

    SyntaxErrors(TextPositions positions) { this.positions = positions; }

    @Override
    public void syntaxError(Recognizer<?, ?> recognizer, Object offendingSymbol, int line, int column,
            String message, RecognitionException e) {
        add((Token) offendingSymbol, message);
        if (diagnostics.size() > ScriptParser.MAX_ERRORS) throw new TooManyErrors();
    }

    void add(Token token, String message) {
        int start = positions.charOffset(token.getStartIndex());
        int end = token.getType() == Token.EOF ? start : positions.charOffset(token.getStopIndex() + 1);
        diagnostics.add(new Diagnostic(Severity.ERROR, message, positions.span(start, end), List.of()));
    }

    List<Diagnostic> diagnostics() { return diagnostics; }
}
