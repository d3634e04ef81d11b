package dev.crt.studio;

import dev.crt.image.FrameBuffer;
import dev.crt.image.ImageFiles;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import dev.crt.render.RenderCancelledException;
import dev.crt.render.RenderMonitor;
import dev.crt.render.Renderer;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import dev.crt.scene.Shading;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.util.concurrent.atomic.AtomicBoolean;
import javax.swing.SwingUtilities;

/**
 * One render of a script for the studio, on its own thread: compile (unless the editor's latest
 * compile is of the same text), a coarse pass of about {@value #COARSE_PIXELS} pixels shown at once, then
 * the real render whose tiles replace the coarse picture as they finish. Cancel stops it within a row.
 */
final class RenderJob {
    /** The coarse pass renders every COARSE-th pixel in each direction at least, without supersampling. */
    static final int COARSE = 8;
    /**
     * The coarse pass's pixels at most (about): its time is what the first picture waits for, and a
     * scene with soft shadows and glossy finishes traces dozens of rays per pixel even then.
     */
    static final int COARSE_PIXELS = 2000;

    /** The coarse pass's step for a {@code width}×{@code height} picture: every n-th pixel each way. */
    static int coarseStep(int width, int height) {
        return Math.max(COARSE, (int) Math.ceil(Math.sqrt((double) width * height / COARSE_PIXELS)));
    }

    /** Told about the render on the Event Dispatch Thread. */
    interface Listener {
        /** A picture to show; render threads go on writing into it, calling {@link #tilesChanged}. */
        void picture(BufferedImage image, boolean coarse);

        /** More pixels are final; {@code dirty} bounds the picture pixels written since the last call. */
        void tilesChanged(long donePixels, long totalPixels, java.awt.Rectangle dirty);

        void finished(Result result);

        /** The script did not compile; its diagnostics are in {@code compile}. */
        void compileFailed(CompileResult compile);

        void failed(String message);

        void cancelled();
    }

    /** A finished render: the scene and the prepared renderer (for picking), the picture, and timings. */
    record Result(Scene scene, Renderer renderer, FrameBuffer image, BufferedImage picture, long firstPictureNanos,
            long totalNanos) {}

    private final AtomicBoolean cancelled = new AtomicBoolean();
    private final AtomicBoolean updatePending = new AtomicBoolean();
    private final java.util.concurrent.atomic.AtomicLong latestDone = new java.util.concurrent.atomic.AtomicLong();
    /** Picture pixels written since the last update reached the EDT (guarded by itself). */
    private final java.awt.Rectangle dirty = new java.awt.Rectangle();
    private final Thread thread;
    private final long startNanos = System.nanoTime();
    private volatile long firstPictureNanos = -1;

    /** The shading model chosen in the Render menu for this session, or null for the script's own. */
    private final Shading shading;
    /** Render → Settings… for this session only: sizes, sampling and threads that replace the script's. */
    private final SessionSettings session;

    /** Where the render's rays are counted, tile by tile, for the System panel. */
    private final Throughput throughput;

    RenderJob(Source source, CompileResult compiled, Shading shading, SessionSettings session, Throughput throughput, Listener listener) {
        this.shading = shading;
        this.throughput = throughput;
        this.session = session;
        thread = new Thread(() -> run(source, compiled, listener), "crt-studio-render");
        thread.setDaemon(true);
    }

    void start() { thread.start(); }

    /** Asks the render to stop; the listener hears {@code cancelled} once it has. */
    void cancel() {
        cancelled.set(true);
        thread.interrupt();
    }

    boolean isCancelled() { return cancelled.get(); }

    long startNanos() { return startNanos; }

    private void run(Source source, CompileResult compiled, Listener listener) {
        try {
            CompileResult compile = compiled != null ? compiled : CrtCompiler.compile(source, LiveCompiler.OPTIONS);
            if (cancelled.get()) {
                SwingUtilities.invokeLater(listener::cancelled);
                return;
            }
            if (compile.scene() == null) {
                SwingUtilities.invokeLater(() -> listener.compileFailed(compile));
                return;
            }
            Scene scene = session.apply(shading == null ? compile.scene()
                    : compile.scene().withSettings(compile.scene().settings().withShading(shading)));
            Settings settings = scene.settings();
            int width = settings.width(), height = settings.height();
            double gamma = settings.outputGamma();
            BufferedImage picture = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
            int[] pixels = ((DataBufferInt) picture.getRaster().getDataBuffer()).getData();
            RenderMonitor stopper = new RenderMonitor() {
                @Override public boolean isCancelled() { return cancelled.get(); }
            };

            Renderer renderer = Renderer.prepare(scene);
            int step = coarseStep(width, height);
            int cw = Math.max(1, (width + step - 1) / step), ch = Math.max(1, (height + step - 1) / step);
            FrameBuffer coarse = renderer.withImage(cw, ch, 1, 1).render(0, stopper);
            for (int y = 0; y < height; y++) {
                int cy = Math.min(ch - 1, y * ch / height);
                for (int x = 0; x < width; x++) {
                    int cx = Math.min(cw - 1, x * cw / width);
                    pixels[y * width + x] = rgb(coarse, cx, cy, gamma);
                }
            }
            SwingUtilities.invokeLater(() -> {
                firstPictureNanos = System.nanoTime() - startNanos;
                listener.picture(picture, true);
            });

            long total = (long) width * height;
            FrameBuffer image = renderer.render(session.threads, new RenderMonitor() {
                @Override public void tileDone(FrameBuffer fb, int x0, int y0, int x1, int y1) {
                    for (int y = y0; y < y1; y++) {
                        for (int x = x0; x < x1; x++) pixels[y * width + x] = rgb(fb, x, y, gamma);
                    }
                    synchronized (dirty) {
                        if (dirty.isEmpty()) dirty.setBounds(x0, y0, x1 - x0, y1 - y0);
                        else dirty.add(new java.awt.Rectangle(x0, y0, x1 - x0, y1 - y0));
                    }
                }

                @Override public void progress(long done, long all) {
                    // One update waiting on the EDT at a time, carrying the latest count: tiles finish
                    // faster than a repaint, and a flood of events would delay the user's keys.
                    latestDone.accumulateAndGet(done, Math::max);
                    if (updatePending.compareAndSet(false, true)) {
                        SwingUtilities.invokeLater(() -> {
                            updatePending.set(false);
                            java.awt.Rectangle changed;
                            synchronized (dirty) {
                                changed = dirty.isEmpty() ? null : new java.awt.Rectangle(dirty);
                                dirty.setBounds(0, 0, 0, 0);
                            }
                            listener.tilesChanged(latestDone.get(), all, changed);
                        });
                    }
                }

                @Override public void raysTraced(long rays) { throughput.add(rays, System.nanoTime()); }

                @Override public boolean isCancelled() { return cancelled.get(); }
            });
            long totalNanos = System.nanoTime() - startNanos;
            SwingUtilities.invokeLater(() -> {
                listener.tilesChanged(total, total, null);
                listener.finished(new Result(scene, renderer, image, picture, firstPictureNanos, totalNanos));
            });
        } catch (RenderCancelledException e) {
            SwingUtilities.invokeLater(listener::cancelled);
        } catch (RuntimeException | OutOfMemoryError e) {
            String message = e instanceof OutOfMemoryError ? "the picture needs more memory than the Java heap has"
                    : "internal error while rendering: " + e;
            SwingUtilities.invokeLater(() -> listener.failed(message));
        }
    }

    /** The displayed colour of one pixel, encoded exactly as the PNG writer encodes it. */
    static int rgb(FrameBuffer fb, int x, int y, double gamma) {
        return ImageFiles.toByte(fb.get(x, y, 0), gamma) << 16 | ImageFiles.toByte(fb.get(x, y, 1), gamma) << 8
                | ImageFiles.toByte(fb.get(x, y, 2), gamma);
    }
}
