package dev.crt.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Set;

/** Checks an output path before any work is spent on it. */
final class OutputFiles {
    static final Set<String> IMAGE_TYPES = Set.of("png", "ppm", "pfm");

    private OutputFiles() {}

    static String extension(Path file) {
        String name = file.getFileName() == null ? "" : file.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return dot < 0 ? "" : name.substring(dot + 1).toLowerCase(Locale.ROOT);
    }

    /**
     * Fails with a file error when {@code out} is a folder or its folder cannot take files, or a
     * usage error for an unknown image type. Missing folders are created, as crt animate does.
     */
    static void checkWritableImage(Path out) throws CliFailure {
        if (Files.isDirectory(out)) {
            throw new CliFailure(ExitCode.FILE_ERROR, "cannot write " + out + ": it is a folder (give a file name, such as "
                    + out.resolve("scene.png") + ")");
        }
        String ext = extension(out);
        if (!IMAGE_TYPES.contains(ext)) {
            throw new CliFailure(ExitCode.USAGE, "cannot write " + out + ": unsupported image type '"
                    + (ext.isEmpty() ? "(none)" : "." + ext) + "' (use .png, .ppm or .pfm)");
        }
        FrameFiles.prepareFolders(List.of(out));
    }
}
