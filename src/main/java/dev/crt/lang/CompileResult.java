package dev.crt.lang;

import dev.crt.scene.Scene;
import java.util.List;

/** The outcome of a compile: a scene when there was no error, and every diagnostic in source order. */
public record CompileResult(Scene scene, List<Diagnostic> diagnostics) {
    public CompileResult {
        diagnostics = List.copyOf(diagnostics);
    }

    public boolean hasErrors() { return diagnostics.stream().anyMatch(Diagnostic::isError); }

    public long errorCount() { return diagnostics.stream().filter(Diagnostic::isError).count(); }

    public long warningCount() { return diagnostics.stream().filter(Diagnostic::isWarning).count(); }
}
