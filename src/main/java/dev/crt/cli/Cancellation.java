package dev.crt.cli;

import dev.crt.render.RenderMonitor;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * Turns Ctrl-C into a clean cancel: the shutdown hook raises the flag renders poll, then waits for
 * the command to finish its current step, so no output is left half-written.
 */
final class Cancellation implements AutoCloseable {
    private final AtomicBoolean cancelled = new AtomicBoolean();
    private final CountDownLatch finished = new CountDownLatch(1);
    private final Thread hook = new Thread(this::cancelAndWait, "crt-cancel");

    private Cancellation() {}

    static Cancellation install() {
        Cancellation c = new Cancellation();
        Runtime.getRuntime().addShutdownHook(c.hook);
        return c;
    }

    private void cancelAndWait() {
        cancelled.set(true);
        try {
            finished.await(10, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    boolean isCancelled() { return cancelled.get(); }

    /** A monitor that reports progress to {@code progress} and cancels when Ctrl-C was pressed. */
    RenderMonitor monitor(Progress progress) {
        return new RenderMonitor() {
            @Override
            public void progress(long done, long total) { progress.update(done, total); }

            @Override
            public boolean isCancelled() { return cancelled.get(); }
        };
    }

    @Override
    public void close() {
        finished.countDown();
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException shuttingDown) {
            // The hook is running: it waits on the latch released above.
        }
    }
}
