package dev.crt.lang;

import dev.crt.scene.Scene;
import java.util.List;

/**
 * The outcome of a compile: a scene when there was no error, and every diagnostic in source order.
 * {@code outOfMemory} says that the compile stopped because the Java heap was full: the errors then
 * are about the machine (give Java more memory), not necessarily about the script.
 */
public record CompileResult(Scene scene, List<Diagnostic> diagnostics, boolean outOfMemory) {
    public CompileResult {
        diagnostics = List.copyOf(diagnostics);
    }

    public CompileResult(Scene scene, List<Diagnostic> diagnostics) {
        this(scene, diagnostics, false);
    }

    public boolean hasErrors() { return diagnostics.stream().anyMatch(Diagnostic::isError); }

    public long errorCount() { return diagnostics.stream().filter(Diagnostic::isError).count(); }

    public long warningCount() { return diagnostics.stream().filter(Diagnostic::isWarning).count(); }
}
