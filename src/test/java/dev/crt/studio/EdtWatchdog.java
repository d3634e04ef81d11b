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
 *
 * <p>A collector's pause stops the EDT too, but the empty event only sees the part of a pause that
 * falls while it waits: a pause that begins while the watchdog sleeps between its events holds that
 * thread as well, and the next event is posted after it. So the collectors' own pause figures
 * (their MXBeans, read after every event) count as stalls as well.
 */
final class EdtWatchdog implements AutoCloseable {
    private final Thread thread;
    private volatile boolean running = true;
    /** The Event Dispatch Thread, as the last event the watchdog posted found it. */
    private volatile Thread edt;
    private final java.util.concurrent.atomic.AtomicLong longestNanos = new java.util.concurrent.atomic.AtomicLong();
    private final java.util.concurrent.atomic.AtomicLong robotSyncNanos = new java.util.concurrent.atomic.AtomicLong();
    /** The longest collector pause that began since the last reset, in ms. */
    private final java.util.concurrent.atomic.AtomicLong longestPauseMillis = new java.util.concurrent.atomic.AtomicLong();
    private final java.util.Map<String, Long> pausesSeen = new java.util.concurrent.ConcurrentHashMap<>();

    /** Stalls longer than this have their stack printed (-Dcrt.watchdog.printMs; 250 ms unless set). */
    private static final long PRINT_NANOS = Long.getLong("crt.watchdog.printMs", 250) * 1_000_000L;

    EdtWatchdog() {
        countPauses();
        longestPauseMillis.set(0);
        thread = new Thread(() -> {
            while (running) {
                countPauses();
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

    long longestMillis() {
        countPauses();
        return Math.max(longestNanos.get() / 1_000_000, longestPauseMillis.get());
    }

    /**
     * Reads each collector's last pause, if it is new since the last look. A collector whose bean
     * times whole concurrent cycles (ZGC's and Shenandoah's "Cycles") is skipped: those are not
     * pauses. Read every 10 ms, so two pauses of one collector between two looks are unlikely. A
     * pause is new when the collector's count has grown since the last look (no reset can run
     * during a pause, which stops its thread too), so no clock has to match the collector's.
     */
    private synchronized void countPauses() {
        for (var bean : java.lang.management.ManagementFactory.getGarbageCollectorMXBeans()) {
            if (bean.getName().contains("Cycles") || !(bean instanceof com.sun.management.GarbageCollectorMXBean gc)) continue;
            long count = gc.getCollectionCount();
            Long seen = pausesSeen.put(gc.getName(), count);
            if (seen == null || seen == count) continue;
            com.sun.management.GcInfo info = gc.getLastGcInfo();
            if (info == null) continue;
            long pause = info.getDuration();
            longestPauseMillis.accumulateAndGet(pause, Math::max);
            if (pause * 1_000_000L > PRINT_NANOS) {
                System.out.println("EDT watchdog: a collector pause of " + pause + " ms, seen at " + uptimeMillis() / 1000.0
                        + " s of uptime (" + gc.getName() + ", " + (count - seen) + " since the last look): the EDT stopped with every thread");
            }
        }
    }

    private static long uptimeMillis() { return java.lang.management.ManagementFactory.getRuntimeMXBean().getUptime(); }

    /** The longest wait caused by the test robot's own waitForIdle, not counted in {@link #longestMillis}. */
    long robotSyncMillis() { return robotSyncNanos.get() / 1_000_000; }

    /** Prints the longest stall of the test just run, the robot's own waits apart (the figure issue 7 asks to report). */
    void report(String testName) {
        System.out.println("EDT watchdog, " + testName + ": longest stall " + longestMillis()
                + " ms (robot's waitForIdle apart: " + robotSyncMillis() + " ms; of it the longest collector pause " + longestPauseMillis.get() + " ms)");
    }

    /** Starts a new measurement (an event already waiting counts in the new one). */
    void reset() {
        countPauses();
        longestPauseMillis.set(0);
        longestNanos.set(0);
        robotSyncNanos.set(0);
    }

    @Override
    public void close() {
        running = false;
        thread.interrupt();
    }
}
