package dev.crt.lang;

import dev.crt.scene.SourceSpan;
import java.util.List;

/**
 * One message about a script, as data: its severity, text, the span it is about (file, 1-based
 * line and column, 0-based character offsets [start, end)), and, for errors raised inside macros,
 * the call chain from the innermost call outwards ("in macro 'row' called at 40:5").
 */
public record Diagnostic(Severity severity, String message, SourceSpan span, List<String> callChain) {
    public Diagnostic {
        callChain = List.copyOf(callChain);
    }

    public boolean isError() { return severity == Severity.ERROR; }

    public boolean isWarning() { return severity == Severity.WARNING; }
}
