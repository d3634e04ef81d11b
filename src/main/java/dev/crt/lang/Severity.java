package dev.crt.lang;

/** How bad a diagnostic is: an error stops the compile, a warning does not. */
public enum Severity {
    ERROR, WARNING;

    /** The word compilers print: "error" or "warning". */
    public String label() { return this == ERROR ? "error" : "warning"; }
}
