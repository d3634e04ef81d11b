package dev.crt.lang.eval;

import dev.crt.lang.Severity;
import dev.crt.scene.SourceSpan;
import java.util.List;

/**
 * Ends the whole evaluation: a budget ran out (an error), or there were too many errors (a note,
 * since the errors it stops after are already recorded and counted).
 */
final class EvaluationStopped extends ScriptError {
    private final Severity severity;

    EvaluationStopped(String message, SourceSpan span, List<String> callChain) {
        this(Severity.ERROR, message, span, callChain);
    }

    private EvaluationStopped(Severity severity, String message, SourceSpan span, List<String> callChain) {
        super(message, span, callChain);
        this.severity = severity;
    }

    static EvaluationStopped tooManyErrors(int count, SourceSpan span) {
        return new EvaluationStopped(Severity.NOTE, "too many errors; stopped after " + count, span, List.of());
    }

    Severity severity() { return severity; }
}
