package dev.crt.lang.eval;

import dev.crt.scene.SourceSpan;
import java.util.List;

/** An error that ends the whole evaluation: a budget ran out or there were too many errors. */
final class EvaluationStopped extends ScriptError {
    EvaluationStopped(String message, SourceSpan span, List<String> callChain) {
        super(message, span, callChain);
    }
}
