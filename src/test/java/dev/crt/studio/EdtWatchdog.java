package dev.crt.studio;

import java.lang.reflect.InvocationTargetException;
import javax.swing.SwingUtilities;

/**
 * Measures how long the Event Dispatch Thread keeps events waiting: every 10 ms it posts an empty
 * event and times how long the EDT takes to run it. The longest wait is the longest stall the user
 * would have felt while the watchdog ran.
 */
final class EdtWatchdog implements AutoCloseable {
    private final Thread thread;
    private volatile boolean running = true;
    private final java.util.concurrent.atomic.AtomicLong longestNanos = new java.util.concurrent.atomic.AtomicLong();

    EdtWatchdog() {
        thread = new Thread(() -> {
            while (running) {
                long start = System.nanoTime();
                try {
                    SwingUtilities.invokeAndWait(() -> {});
                } catch (InterruptedException e) {
                    return;
                } catch (InvocationTargetException e) {
                    throw new IllegalStateException(e);
                }
                long waited = System.nanoTime() - start;
                longestNanos.accumulateAndGet(waited, Math::max);
                try {
                    Thread.sleep(10);
                } catch (InterruptedException e) {
                    return;
                }
            }
        }, "edt-watchdog");
        thread.setDaemon(true);
        thread.start();
    }

    long longestMillis() { return longestNanos.get() / 1_000_000; }

    /** Starts a new measurement (an event already waiting counts in the new one). */
    void reset() { longestNanos.set(0); }

    @Override
    public void close() {
        running = false;
        thread.interrupt();
    }
}
