package dev.crt.studio;

import dev.crt.image.FrameBuffer;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import dev.crt.render.RenderCancelledException;
import dev.crt.render.RenderMonitor;
import dev.crt.render.Renderer;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import java.awt.image.BufferedImage;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.UnaryOperator;
import javax.swing.SwingUtilities;

/**
 * Coarse pictures of single frames for scrubbing: compiled at t and traced at 1/{@value AnimationPanel#PREVIEW}
 * of the size without supersampling, on one background thread. Only the latest request counts:
 * a newer one cancels the one in flight.
 */
final class PreviewRenderer {
    /** Told on the Event Dispatch Thread: the picture, or why there is none. */
    interface Result {
        void done(BufferedImage picture, String error);
    }

    private final ExecutorService worker = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "crt-studio-preview");
        t.setDaemon(true);
        return t;
    });
    private final AtomicLong latest = new AtomicLong();

    void request(Source source, int frame, UnaryOperator<Scene> session, Result result) {
        long me = latest.incrementAndGet();
        worker.submit(() -> {
            if (latest.get() != me) return;
            try {
                CompileResult compiled = CrtCompiler.compile(source, LiveCompiler.OPTIONS.withTime(frame));
                if (compiled.scene() == null || compiled.hasErrors()) {
                    SwingUtilities.invokeLater(() -> result.done(null, "the script has errors at this t"));
                    return;
                }
                Scene scene = session.apply(compiled.scene());
                Settings s = scene.settings();
                int w = Math.max(1, (s.width() + AnimationPanel.PREVIEW - 1) / AnimationPanel.PREVIEW);
                int h = Math.max(1, (s.height() + AnimationPanel.PREVIEW - 1) / AnimationPanel.PREVIEW);
                FrameBuffer coarse = Renderer.prepare(scene).withImage(w, h, 1, 1).render(0, new RenderMonitor() {
                    @Override public boolean isCancelled() { return latest.get() != me; }
                });
                BufferedImage picture = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
                for (int y = 0; y < h; y++) {
                    for (int x = 0; x < w; x++) picture.setRGB(x, y, RenderJob.rgb(coarse, x, y, s.outputGamma()));
                }
                SwingUtilities.invokeLater(() -> result.done(picture, null));
            } catch (RenderCancelledException e) {
                // A newer scrub position took over.
            } catch (RuntimeException | OutOfMemoryError e) {
                SwingUtilities.invokeLater(() -> result.done(null, "cannot preview: " + e));
            }
        });
    }

    void shutdown() { worker.shutdownNow(); }
}
