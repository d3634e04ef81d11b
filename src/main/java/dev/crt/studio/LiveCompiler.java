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
import javax.swing.SwingUtilities;
import javax.swing.Timer;

/**
 * Recompiles a script in the background a short while after typing stops. A newer edit cancels the
 * compile in flight (the compiler stops its evaluation when interrupted), and the loop and time
 * budgets end a runaway {@code while}, so typing never waits for the compiler.
 */
final class LiveCompiler implements StudioModel.Listener {
    /** Quiet time after the last keystroke before a compile starts. */
    static final int DELAY_MS = 300;
    /** Live compiles stop sooner than the command line's: the script is being typed. */
    static final CompileOptions OPTIONS = new CompileOptions(0, List.of(), CompileOptions.DEFAULT_LOOP_BUDGET,
            Duration.ofSeconds(2));

    private final ExecutorService worker = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "crt-studio-compile");
        t.setDaemon(true);
        return t;
    });
    private final Map<ScriptDocument, Timer> timers = new HashMap<>();
    private Future<?> running;
    private long editNanos;
    private volatile long lastLatencyNanos = -1;

    @Override
    public void opened(ScriptDocument d) {
        Timer timer = new Timer(DELAY_MS, e -> start(d));
        timer.setRepeats(false);
        timers.put(d, timer);
        start(d);
    }

    @Override
    public void closed(ScriptDocument d) {
        Timer timer = timers.remove(d);
        if (timer != null) timer.stop();
    }

    @Override
    public void documentChanged(ScriptDocument d) {
        if (d.resultIsCurrent()) return;
        editNanos = System.nanoTime();
        Timer timer = timers.get(d);
        if (timer != null) timer.restart();
    }

    /** Compiles {@code d} now (on the worker), replacing any compile in flight. */
    void start(ScriptDocument d) {
        Timer timer = timers.get(d);
        if (timer != null) timer.stop();
        if (running != null) running.cancel(true);
        Source source = d.source();
        long version = d.version();
        long since = editNanos;
        running = worker.submit(() -> {
            CompileResult result = CrtCompiler.compile(source, OPTIONS);
            if (Thread.currentThread().isInterrupted()) return;
            SwingUtilities.invokeLater(() -> {
                if (d.version() != version) return;
                d.compiled(result, version);
                if (since != 0) lastLatencyNanos = System.nanoTime() - since;
            });
        });
    }

    /** From the last keystroke to its diagnostics in the document, for the speed figures. */
    long lastLatencyNanos() { return lastLatencyNanos; }

    void shutdown() { worker.shutdownNow(); }
}
