package dev.crt.lang;

/** Prints diagnostics as compilers do: location, message, the source line and a caret. */
public final class DiagnosticFormatter {
    private DiagnosticFormatter() {}

    public static String format(Diagnostic d, String sourceText) {
        throw new UnsupportedOperationException("lands with issue 2");
    }
}
