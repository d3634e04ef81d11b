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
    private volatile long longestNanos;

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
                longestNanos = Math.max(longestNanos, System.nanoTime() - start);
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

    long longestMillis() { return longestNanos / 1_000_000; }

    void reset() { longestNanos = 0; }

    @Override
    public void close() {
        running = false;
        thread.interrupt();
    }
}
