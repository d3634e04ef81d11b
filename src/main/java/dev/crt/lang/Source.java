package dev.crt.lang;

import java.nio.file.Path;

/**
 * A script's text with the name diagnostics print for it and, when it came from a file, the file
 * (assets are looked up relative to its folder).
 */
public record Source(String name, String text, Path file) {
    /** A script that is not a file (tests, the studio's unsaved buffer): assets resolve from the working directory. */
    public static Source of(String name, String text) { return new Source(name, text, null); }
}
