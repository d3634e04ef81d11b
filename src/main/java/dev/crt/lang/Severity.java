package dev.crt.lang;

/**
 * How bad a diagnostic is: an error stops the compile, a warning does not, and a note only adds
 * information (such as where the compiler stopped reporting) and counts as neither.
 */
public enum Severity {
    ERROR, WARNING, NOTE;

    /** The word compilers print: "error", "warning" or "note". */
    public String label() {
        return switch (this) {
            case ERROR -> "error";
            case WARNING -> "warning";
            case NOTE -> "note";
        };
    }
}
