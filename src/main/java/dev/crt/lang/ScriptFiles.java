package dev.crt.lang;

import java.io.IOException;
import java.nio.file.Path;

/** Reads script files into Sources. */
public final class ScriptFiles {
    private ScriptFiles() {}

    public static Source read(Path file) throws IOException {
        throw new UnsupportedOperationException("lands with issue 2");
    }
}
