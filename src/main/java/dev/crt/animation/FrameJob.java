package dev.crt.animation;

import dev.crt.image.FrameBuffer;
import dev.crt.image.ImageFiles;
import dev.crt.render.FeatureSwitchedOffException;
import dev.crt.render.RenderMonitor;
import dev.crt.render.RenderStats;
import dev.crt.render.Renderer;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import java.io.IOException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.function.BiConsumer;

/** Renders one compiled scene and writes it atomically to an image file: the unit render and animate share. */
public final class FrameJob {
    /** What one frame cost: the renderer's counts and times plus the time to write the file. */
    public record Outcome(RenderStats stats, long writeNanos) {}

    private FrameJob() {}

    /**
     * Renders {@code scene} on {@code threads} threads (0: all cores) and writes it to {@code out};
     * a size, sampling or memory the render cannot meet, or a file that cannot be written, is a
     * {@link FrameFailure}; a cancel through {@code monitor} leaves no file.
     */
    public static Outcome run(Scene scene, Path out, int threads, RenderMonitor monitor) throws FrameFailure {
        return run(scene, out, threads, monitor, (image, stats) -> {});
    }

    /** As {@link #run(Scene, Path, int, RenderMonitor)}, handing the picture and its counts to {@code written} once it is in its file. */
    public static Outcome run(Scene scene, Path out, int threads, RenderMonitor monitor,
            BiConsumer<FrameBuffer, RenderStats> written) throws FrameFailure {
        int w = scene.settings().width(), h = scene.settings().height();
        if ((long) w * h > FrameBuffer.MAX_PIXELS) {
            throw new FrameFailure(FrameFailure.Kind.SETTINGS, String.format(Locale.ROOT,
                    "an image of %d×%d pixels is too large to render (at most %,d pixels)", w, h, FrameBuffer.MAX_PIXELS));
        }
        Sampling.check(scene.settings());
        MemoryCheck.check(w, h, Runtime.getRuntime());
        Renderer renderer;
        try {
            renderer = Renderer.prepare(scene);
        } catch (FeatureSwitchedOffException e) {
            throw new FrameFailure(FrameFailure.Kind.SETTINGS, e.getMessage());
        }
        if (ImageFiles.clampsColours(out)) renderer = renderer.forClampedOutput();
        FrameBuffer image = renderer.render(threads, monitor);
        long start = System.nanoTime();
        try {
            ImageFiles.write(image, out, scene.settings().outputGamma(), textChunks(scene.settings()));
        } catch (IOException e) {
            // ImageFiles' messages already say "cannot write OUT: why".
            String m = e.getMessage();
            throw new FrameFailure(FrameFailure.Kind.FILE, m == null || m.isBlank() ? e.getClass().getSimpleName() : m);
        }
        long writeNanos = System.nanoTime() - start;
        written.accept(image, renderer.stats());
        return new Outcome(renderer.stats(), writeNanos);
    }

    /** PNG text chunks from the scene's metadata, with the standard keywords. */
    public static Map<String, String> textChunks(Settings s) {
        Map<String, String> text = new LinkedHashMap<>();
        putIfSet(text, "Title", s.title());
        putIfSet(text, "Author", s.author());
        putIfSet(text, "Creation Time", s.date());
        putIfSet(text, "Description", s.notes());
        String version = FrameJob.class.getPackage().getImplementationVersion();
        text.put("Software", "CRT " + (version == null ? "development build" : version));
        return text;
    }

    private static void putIfSet(Map<String, String> text, String key, String value) {
        if (value != null && !value.isEmpty()) text.put(key, value);
    }
}
