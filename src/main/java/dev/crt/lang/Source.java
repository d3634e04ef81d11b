package dev.crt.lang;

import java.nio.file.Path;

/**
 * A script's text with the name diagnostics print for it and, when it came from a file, the file
 * (assets are looked up relative to its folder). {@code decodingProblem} is null for proper text;
 * for a file that is not UTF-8 text it says why ("not a text file (invalid UTF-8 at byte 17)"),
 * and compiling the source reports it, at the character offset {@code problemOffset} of the text
 * (where the bad byte decoded to), instead of compiling whatever the bytes decoded to.
 */
public record Source(String name, String text, Path file, String decodingProblem, int problemOffset) {
    public Source(String name, String text, Path file) {
        this(name, text, file, null, 0);
    }

    /** A source whose decoding problem is reported at the start of the text. */
    public Source(String name, String text, Path file, String decodingProblem) {
        this(name, text, file, decodingProblem, 0);
    }

    /** A script that is not a file (tests, the studio's unsaved buffer): assets resolve from the working directory. */
    public static Source of(String name, String text) { return new Source(name, text, null); }

    public boolean isText() { return decodingProblem == null; }
}
