package dev.crt.cli;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.DirectoryStream;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Pattern;

/**
 * The files of one animate run on disk: creating their folders, finding frames that exist already
 * and removing the temporary files a killed run left behind. Only the given files are touched, so
 * shards sharing a folder never disturb each other's work in progress.
 */
final class FrameFiles {
    /** What the writers put after ".tmp-": a non-negative long in lower-case hexadecimal. */
    private static final Pattern TEMPORARY_SUFFIX = Pattern.compile("[0-9a-f]{1,16}");

    private FrameFiles() {}

    /** Creates the folders of {@code files} and checks that each takes new files; fails with exit code 3. */
    static void prepareFolders(List<Path> files) throws CliFailure {
        Set<Path> folders = new LinkedHashSet<>();
        for (Path f : files) folders.add(f.toAbsolutePath().getParent());
        for (Path folder : folders) {
            try {
                Files.createDirectories(folder);
            } catch (FileAlreadyExistsException e) {
                throw new CliFailure(ExitCode.FILE_ERROR, "cannot create folder " + folder + ": a file of that name is in the way");
            } catch (IOException e) {
                throw new CliFailure(ExitCode.FILE_ERROR, "cannot create folder " + folder + ": " + why(e));
            }
            // Permission bits do not tell the whole story (read-only mounts, quotas, running as root), so try.
            try {
                Files.delete(Files.createTempFile(folder, ".crt-probe-", ".tmp"));
            } catch (IOException e) {
                throw new CliFailure(ExitCode.FILE_ERROR, "cannot write into folder " + folder + ": " + why(e));
            }
        }
    }

    /** The files among {@code files} that exist. */
    static List<Path> existing(List<Path> files) {
        List<Path> found = new ArrayList<>();
        for (Path f : files) if (Files.exists(f)) found.add(f);
        return found;
    }

    /**
     * Deletes what an interrupted write of any of {@code files} left: image and GIF writers write
     * {@code .NAME.tmp-SUFFIX} next to {@code NAME} and rename it when complete. Returns how many went.
     */
    static int removeLeftovers(List<Path> files) throws CliFailure {
        int removed = 0;
        Set<Path> folders = new LinkedHashSet<>();
        Set<String> prefixes = new LinkedHashSet<>();
        for (Path f : files) {
            folders.add(f.toAbsolutePath().getParent());
            prefixes.add(f.toAbsolutePath().getParent().resolve(temporaryPrefix(f)).toString());
        }
        for (Path folder : folders) {
            try (DirectoryStream<Path> entries = Files.newDirectoryStream(folder, ".*.tmp-*")) {
                for (Path entry : entries) {
                    String name = entry.toString();
                    int cut = name.lastIndexOf(".tmp-") + ".tmp-".length();
                    if (prefixes.contains(name.substring(0, cut)) && TEMPORARY_SUFFIX.matcher(name.substring(cut)).matches()
                            && Files.deleteIfExists(entry)) {
                        removed++;
                    }
                }
            } catch (IOException e) {
                throw new CliFailure(ExitCode.FILE_ERROR, "cannot clean up temporary files in " + folder + ": "
                        + ScriptCompilation.plain(e));
            }
        }
        return removed;
    }

    /** The reason in plain words: file system exceptions carry the path, which the message names already. */
    private static String why(IOException e) {
        if (e instanceof AccessDeniedException) return "permission denied";
        if (e instanceof FileSystemException f && f.getReason() != null) return f.getReason();
        if (e instanceof NoSuchFileException) return "files cannot be created there";
        return ScriptCompilation.plain(e);
    }

    /** The start of the name of a temporary file that becomes {@code file} (see ImageFiles.write). */
    static String temporaryPrefix(Path file) { return "." + file.getFileName() + ".tmp-"; }
}
