package dev.crt.lang.eval;

import dev.crt.scene.SourceSpan;
import java.util.List;

/** A mistake found while evaluating: the statement it happened in fails, later statements still run. */
class ScriptError extends RuntimeException {
    private final transient SourceSpan span;
    private final List<String> callChain;

    ScriptError(String message, SourceSpan span, List<String> callChain) {
        // No stack trace: these are messages for the script's author, thrown often in fuzzing.
        super(message, null, false, false);
        this.span = span;
        this.callChain = List.copyOf(callChain);
    }

    SourceSpan span() { return span; }

    List<String> callChain() { return callChain; }
}
