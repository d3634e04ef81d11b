package dev.crt.studio;

import javax.swing.SwingUtilities;

/**
 * Measures how long the Event Dispatch Thread keeps events waiting: every 10 ms it posts an empty
 * event and times how long the EDT takes to run it. The longest wait is the longest stall the user
 * would have felt while the watchdog ran.
 *
 * <p>A stall during which the EDT is found in {@code XToolkit.syncNativeQueue} is the test's own
 * {@code Robot.waitForIdle()}: it makes the EDT wait for up to 20 round trips to the X server,
 * which on a loaded machine took up to a second. Those are counted apart ({@link #robotSyncMillis}),
 * as no user ever causes them; for any other stall of 250 ms or more the EDT's stack is printed.
 */
final class EdtWatchdog implements AutoCloseable {
    private final Thread thread;
    private volatile boolean running = true;
    /** The Event Dispatch Thread, as the last event the watchdog posted found it. */
    private volatile Thread edt;
    private final java.util.concurrent.atomic.AtomicLong longestNanos = new java.util.concurrent.atomic.AtomicLong();
    private final java.util.concurrent.atomic.AtomicLong robotSyncNanos = new java.util.concurrent.atomic.AtomicLong();

    /** Stalls longer than this have their stack printed (-Dcrt.watchdog.printMs; 250 ms unless set). */
    private static final long PRINT_NANOS = Long.getLong("crt.watchdog.printMs", 250) * 1_000_000L;

    EdtWatchdog() {
        thread = new Thread(() -> {
            while (running) {
                long start = System.nanoTime();
                java.util.concurrent.CountDownLatch ran = new java.util.concurrent.CountDownLatch(1);
                SwingUtilities.invokeLater(() -> {
                    edt = Thread.currentThread();
                    ran.countDown();
                });
                boolean robotSync = false;
                String stack = null;
                try {
                    // Past 50 ms, look at what the EDT is doing every 50 ms until it is free.
                    while (!ran.await(50, java.util.concurrent.TimeUnit.MILLISECONDS)) {
                        String now = edtStack();
                        if (now.contains("syncNativeQueue")) robotSync = true;
                        if (stack == null && System.nanoTime() - start > PRINT_NANOS) stack = now;
                    }
                } catch (InterruptedException e) {
                    return;
                }
                long waited = System.nanoTime() - start;
                if (robotSync) {
                    robotSyncNanos.accumulateAndGet(waited, Math::max);
                } else {
                    longestNanos.accumulateAndGet(waited, Math::max);
                    if (stack != null) {
                        // The JVM's uptime at the stall's start, to line it up with -Xlog:gc's stamps.
                        long began = java.lang.management.ManagementFactory.getRuntimeMXBean().getUptime() - waited / 1_000_000;
                        System.out.println("EDT watchdog: a stall of " + waited / 1_000_000 + " ms from " + began / 1000.0 + " s of uptime; "
                                + PRINT_NANOS / 1_000_000 + " ms into it the EDT was at:\n" + stack);
                    }
                }
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

    /**
     * The EDT's stack, asked of that thread alone: every thread's stack at once
     * ({@code Thread.getAllStackTraces}) stops the whole JVM at a safepoint, which took 2 to 48 ms
     * on the loaded machine, every 50 ms of a stall, and so lengthened the stalls it measured.
     */
    private String edtStack() {
        Thread t = edt;
        StringBuilder b = new StringBuilder();
        if (t == null) return "";
        StackTraceElement[] frames = t.getStackTrace();
        for (int i = 0; i < Math.min(frames.length, Integer.getInteger("crt.watchdog.frames", 14)); i++) b.append("    at ").append(frames[i]).append('\n');
        return b.toString();
    }

    long longestMillis() { return longestNanos.get() / 1_000_000; }

    /** The longest wait caused by the test robot's own waitForIdle, not counted in {@link #longestMillis}. */
    long robotSyncMillis() { return robotSyncNanos.get() / 1_000_000; }

    /** Prints the longest stall of the test just run, the robot's own waits apart (the figure issue 7 asks to report). */
    void report(String testName) {
        System.out.println("EDT watchdog, " + testName + ": longest stall " + longestMillis()
                + " ms (robot's waitForIdle apart: " + robotSyncMillis() + " ms)");
    }

    /** Starts a new measurement (an event already waiting counts in the new one). */
    void reset() {
        longestNanos.set(0);
        robotSyncNanos.set(0);
    }

    @Override
    public void close() {
        running = false;
        thread.interrupt();
    }
}
