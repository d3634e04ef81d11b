package dev.crt.studio;

import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import java.time.Duration;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.SwingUtilities;
import javax.swing.Timer;

/**
 * Recompiles a script in the background a short while after typing stops. A newer edit cancels the
 * compile in flight (the compiler stops its evaluation when interrupted), and the loop and time
 * budgets end a runaway {@code while}, so typing never waits for the compiler.
 *
 * <p>The pause is not fixed: the diagnostics are meant to appear {@link #TARGET_MS} after the last
 * keystroke, so the pause is that target less the script's last compile time (never under
 * {@link #MIN_DELAY_MS}). A short script waits almost the whole target; a 2,500-line one, whose
 * compile alone takes a few hundred milliseconds here, starts compiling after the minimum.
 */
final class LiveCompiler implements StudioModel.Listener {
    /** From the last keystroke to its diagnostics, when the compile is fast enough to allow it. */
    static final int TARGET_MS = 250;
    /** The shortest quiet time after a keystroke before a compile starts. */
    static final int MIN_DELAY_MS = 50;
    /**
     * Live compiles stop sooner than the command line's (the script is being typed) and record the
     * source map the navigator and property sheet work from.
     */
    static final CompileOptions OPTIONS = new CompileOptions(0, List.of(), CompileOptions.DEFAULT_LOOP_BUDGET,
            Duration.ofSeconds(2), true);

    private final ExecutorService worker = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "crt-studio-compile");
        t.setDaemon(true);
        return t;
    });
    private final Map<ScriptDocument, Timer> timers = new HashMap<>();
    private final Map<ScriptDocument, Future<?>> running = new HashMap<>();
    private final Map<ScriptDocument, Long> compileNanos = new HashMap<>();
    private long editNanos;
    private volatile long lastLatencyNanos = -1;

    @Override
    public void opened(ScriptDocument d) {
        Timer timer = new Timer(TARGET_MS, e -> start(d));
        timer.setRepeats(false);
        timers.put(d, timer);
        start(d);
    }

    @Override
    public void closed(ScriptDocument d) {
        Timer timer = timers.remove(d);
        if (timer != null) timer.stop();
        Future<?> compile = running.remove(d);
        if (compile != null) compile.cancel(true);
        compileNanos.remove(d);
    }

    /** The pause after a keystroke in {@code d} before its compile starts. */
    int delayMillis(ScriptDocument d) {
        long last = compileNanos.getOrDefault(d, 0L) / 1_000_000;
        return (int) Math.max(MIN_DELAY_MS, TARGET_MS - last);
    }

    @Override
    public void documentChanged(ScriptDocument d) {
        if (d.resultIsCurrent()) return;
        editNanos = System.nanoTime();
        Timer timer = timers.get(d);
        if (timer != null) {
            timer.setInitialDelay(delayMillis(d));
            timer.restart();
        }
    }

    /** Compiles {@code d} now (on the worker), replacing the compile of an older text of it still in flight. */
    void start(ScriptDocument d) {
        Timer timer = timers.get(d);
        if (timer != null) timer.stop();
        Future<?> previous = running.remove(d);
        if (previous != null) previous.cancel(true);
        Source source = d.source();
        long version = d.version();
        long since = editNanos;
        AtomicReference<Future<?>> self = new AtomicReference<>();
        Runnable compile = () -> {
            long began = System.nanoTime();
            CompileResult result = CrtCompiler.compile(source, OPTIONS);
            // An interrupt stops a compile part-way. Meant for this one (a newer text of the document
            // replaced it), the partial result is dropped; meant for the compile before it (a cancel
            // that came as that one finished), this text is compiled again.
            while (Thread.interrupted()) {
                Future<?> me = self.get();
                if (me != null && me.isCancelled()) return;
                result = CrtCompiler.compile(source, OPTIONS);
            }
            CompileResult done = result;
            long took = System.nanoTime() - began;
            // The live view converts on the EDT; what is slow in that (large meshes' hierarchies) is done here.
            if (done.scene() != null) dev.crt.live.SceneConverter.prepare(done.scene());
            SwingUtilities.invokeLater(() -> {
                if (!timers.containsKey(d)) return;
                compileNanos.put(d, took);
                if (d.version() != version) return;
                running.remove(d);
                d.compiled(done, version);
                if (since != 0) lastLatencyNanos = System.nanoTime() - since;
            });
        };
        Future<?> submitted = worker.submit(compile);
        self.set(submitted);
        running.put(d, submitted);
    }

    /** From the last keystroke to its diagnostics in the document, for the speed figures. */
    long lastLatencyNanos() { return lastLatencyNanos; }

    void shutdown() { worker.shutdownNow(); }
}
