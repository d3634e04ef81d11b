package dev.crt.studio;

import java.io.IOException;
import java.io.StringReader;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.UUID;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import javax.swing.Timer;

/**
 * Keeps a copy of every unsaved buffer in the recovery folder, so that nothing typed is lost when
 * the studio dies: {@code ID.crt} is the text as plain UTF-8, {@code ID.properties} says which file
 * it belongs to and which process wrote it. Copies are written every {@value #PERIOD_MS} ms when
 * the text changed (so at most that long after the last keystroke), off the Event Dispatch Thread,
 * and deleted when the buffer is saved, closed or discarded.
 */
final class Recovery implements StudioModel.Listener {
    static final int PERIOD_MS = 2000;

    /** A recovery copy left by a studio that is no longer running. */
    record Orphan(String id, Path textFile, Path file, String name, String text) {}

    private record Entry(String id, long writtenVersion) {}

    private final Path folder;
    private final Map<ScriptDocument, Entry> entries = new HashMap<>();
    private final ExecutorService writer = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "crt-studio-recovery");
        t.setDaemon(true);
        return t;
    });
    private final Timer timer;
    private Consumer<String> problems = m -> {};

    Recovery(Path folder, StudioModel model) {
        this.folder = folder;
        timer = new Timer(PERIOD_MS, e -> writeChanged(model));
    }

    void onProblem(Consumer<String> sink) { problems = sink; }

    void start() { timer.start(); }

    /** Gives {@code d} the id of a recovered copy, so its next copy replaces that one. */
    void adopt(ScriptDocument d, String id) { entries.put(d, new Entry(id, -1)); }

    /** Writes now the copies of changed buffers (on the writer thread), as the timer does. */
    void writeChanged(StudioModel model) {
        for (ScriptDocument d : model.documents()) {
            if (!d.isModified()) continue;
            Entry e = entries.get(d);
            if (e != null && e.writtenVersion() == d.version()) continue;
            String id = e == null ? UUID.randomUUID().toString() : e.id();
            entries.put(d, new Entry(id, d.version()));
            String text = d.content();
            Properties meta = new Properties();
            if (d.file() != null) meta.setProperty("file", d.file().toAbsolutePath().toString());
            meta.setProperty("name", d.name());
            meta.setProperty("pid", Long.toString(ProcessHandle.current().pid()));
            writer.execute(() -> {
                try {
                    AtomicText.write(folder.resolve(id + ".crt"), text);
                    StringWriter w = new StringWriter();
                    meta.store(w, "crt studio recovery copy");
                    AtomicText.write(folder.resolve(id + ".properties"), w.toString());
                } catch (IOException ex) {
                    problems.accept("cannot write the recovery copy of " + d.name() + ": " + ex.getMessage());
                }
            });
        }
    }

    /** Deletes the copy of {@code d}: it was saved, closed or discarded. */
    void forget(ScriptDocument d) {
        Entry e = entries.remove(d);
        if (e != null) delete(e.id());
    }

    @Override
    public void documentChanged(ScriptDocument d) {
        if (!d.isModified()) forget(d);
    }

    @Override
    public void closed(ScriptDocument d) { forget(d); }

    private void delete(String id) {
        writer.execute(() -> {
            try {
                Files.deleteIfExists(folder.resolve(id + ".crt"));
                Files.deleteIfExists(folder.resolve(id + ".properties"));
            } catch (IOException ex) {
                problems.accept("cannot delete the recovery copy " + id + ": " + ex.getMessage());
            }
        });
    }

    /** Deletes a copy found at start and not recovered. */
    void discard(Orphan o) { delete(o.id()); }

    /** Waits for pending writes and deletions, then stops. */
    void stop() {
        timer.stop();
        writer.shutdown();
        try {
            writer.awaitTermination(5, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Copies in the folder written by studios that are no longer running. */
    static List<Orphan> orphans(Path folder) {
        List<Orphan> found = new ArrayList<>();
        if (!Files.isDirectory(folder)) return found;
        try (DirectoryStream<Path> files = Files.newDirectoryStream(folder, "*.properties")) {
            for (Path metaFile : files) {
                String name = metaFile.getFileName().toString();
                String id = name.substring(0, name.length() - ".properties".length());
                Path textFile = folder.resolve(id + ".crt");
                if (!Files.isRegularFile(textFile)) continue;
                Properties meta = new Properties();
                meta.load(new StringReader(Files.readString(metaFile, StandardCharsets.UTF_8)));
                long pid = parsePid(meta.getProperty("pid"));
                if (pid == ProcessHandle.current().pid() || ProcessHandle.of(pid).map(ProcessHandle::isAlive).orElse(false)) continue;
                String file = meta.getProperty("file");
                found.add(new Orphan(id, textFile, file == null ? null : Path.of(file), meta.getProperty("name", id + ".crt"),
                        Files.readString(textFile, StandardCharsets.UTF_8)));
            }
        } catch (IOException | IllegalArgumentException e) {
            // An unreadable copy is left where it is, for the user to look at by hand.
        }
        return found;
    }

    private static long parsePid(String s) {
        try {
            return s == null ? -1 : Long.parseLong(s);
        } catch (NumberFormatException e) {
            return -1;
        }
    }
}
