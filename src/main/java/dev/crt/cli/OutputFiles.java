package dev.crt.cli;

import java.nio.file.Files;
import java.nio.file.Path;
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

    /** Fails with a usage error for an unknown image type, or a file error when the folder cannot take it. */
    static void checkWritableImage(Path out) throws CliFailure {
        String ext = extension(out);
        if (!IMAGE_TYPES.contains(ext)) {
            throw new CliFailure(ExitCode.USAGE, "cannot write " + out + ": unsupported image type '"
                    + (ext.isEmpty() ? "(none)" : "." + ext) + "' (use .png, .ppm or .pfm)");
        }
        if (Files.isDirectory(out)) {
            throw new CliFailure(ExitCode.FILE_ERROR, "cannot write " + out + ": it is a folder");
        }
        Path dir = out.toAbsolutePath().getParent();
        if (dir != null && !Files.isDirectory(dir)) {
            throw new CliFailure(ExitCode.FILE_ERROR, "cannot write " + out + ": folder " + dir + " does not exist");
        }
        if (dir != null && !Files.isWritable(dir)) {
            throw new CliFailure(ExitCode.FILE_ERROR, "cannot write " + out + ": folder " + dir + " is not writable");
        }
    }
}
