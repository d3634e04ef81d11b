package dev.crt.studio;

import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import dev.crt.scene.Scene;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.SwingUtilities;

/**
 * The live view's compiles of the current script at the Animation panel's time t (the background
 * compile is at t = 0). One compile runs at a time on a thread of its own and only the latest
 * request waits behind it, so scrubbing or playing faster than the script compiles skips times
 * instead of queueing them. The scenes of the script's current text are kept by t (the last
 * {@link #KEPT} of them), so scrubbing back over a range shows it without compiling again.
 * {@link #request} and the delivery run on the Event Dispatch Thread.
 */
final class SceneAtTime {
    /** Scenes kept for one text of the script: a scrub range of a couple of seconds at 24 frames/s. */
    static final int KEPT = 48;

    /** Receives a finished compile on the Event Dispatch Thread, with what it was asked for. */
    interface Delivery {
        void compiled(ScriptDocument d, long version, double t, CompileResult result, long since);
    }

    private record Request(ScriptDocument document, long version, Source source, double t, long since) {}

    private final Delivery delivery;
    private final ExecutorService worker = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "crt-studio-live-time");
        t.setDaemon(true);
        return t;
    });
    private final AtomicReference<Request> latest = new AtomicReference<>();
    /** Which text of which script {@link #kept} belongs to. */
    private ScriptDocument keptDocument;
    private long keptVersion = -1;
    private final Map<Double, Scene> kept = new LinkedHashMap<>(16, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<Double, Scene> eldest) { return size() > KEPT; }
    };

    SceneAtTime(Delivery delivery) {
        this.delivery = delivery;
    }

    /**
     * The scene of {@code d} (text {@code version}) at {@code t} when it is at hand; otherwise null,
     * and its compile is started (replacing a request still waiting) and delivered when done.
     */
    Scene request(ScriptDocument d, long version, Source source, double t, long since) {
        if (d != keptDocument || version != keptVersion) {
            kept.clear();
            keptDocument = d;
            keptVersion = version;
        }
        Scene scene = kept.get(t);
        if (scene != null) {
            latest.set(null);
            return scene;
        }
        if (latest.getAndSet(new Request(d, version, source, t, since)) == null) worker.submit(this::drain);
        return null;
    }

    /** Drops a request still waiting (the studio went back to t = 0). */
    void forget() {
        latest.set(null);
    }

    private void drain() {
        Request r;
        while ((r = latest.getAndSet(null)) != null) {
            CompileOptions o = LiveCompiler.OPTIONS;
            // The view needs no source map: the navigator and property sheet read the t = 0 compile's.
            CompileResult result = CrtCompiler.compile(r.source(),
                    new CompileOptions(r.t(), o.assetDirs(), o.loopBudget(), o.timeBudget(), false));
            Request done = r;
            SwingUtilities.invokeLater(() -> {
                if (result.scene() != null && done.document() == keptDocument && done.version() == keptVersion) {
                    kept.put(done.t(), result.scene());
                }
                delivery.compiled(done.document(), done.version(), done.t(), result, done.since());
            });
        }
    }

    void close() {
        latest.set(null);
        worker.shutdownNow();
    }
}
