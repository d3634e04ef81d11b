package dev.crt.scene;

/**
 * Where something was written in a script: 1-based line and column of its first character and
 * the 0-based character offsets [start, end) of the whole construct.
 */
public record SourceSpan(String file, int line, int column, int start, int end) {
    /** For things that no script wrote (defaults, objects built in code). */
    public static final SourceSpan NONE = new SourceSpan("", 0, 0, 0, 0);

    @Override
    public String toString() { return file + ":" + line + ":" + column; }
}
