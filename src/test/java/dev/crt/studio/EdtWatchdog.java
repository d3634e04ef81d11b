package dev.crt.studio;

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
                java.util.concurrent.CountDownLatch ran = new java.util.concurrent.CountDownLatch(1);
                SwingUtilities.invokeLater(ran::countDown);
                try {
                    // A stall of 250 ms or more: say what the EDT is doing meanwhile, to find the cause.
                    if (!ran.await(250, java.util.concurrent.TimeUnit.MILLISECONDS)) {
                        String stack = edtStack();
                        ran.await();
                        long ms = (System.nanoTime() - start) / 1_000_000;
                        System.out.println("EDT watchdog: a stall of " + ms + " ms; 250 ms into it the EDT was at:\n" + stack);
                    }
                } catch (InterruptedException e) {
                    return;
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

    private static String edtStack() {
        StringBuilder b = new StringBuilder();
        for (var e : Thread.getAllStackTraces().entrySet()) {
            if (!e.getKey().getName().startsWith("AWT-EventQueue")) continue;
            StackTraceElement[] frames = e.getValue();
            for (int i = 0; i < Math.min(frames.length, 25); i++) b.append("    at ").append(frames[i]).append('\n');
        }
        return b.toString();
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
