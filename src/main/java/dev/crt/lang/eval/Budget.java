package dev.crt.lang.eval;

import java.time.Duration;

/**
 * The evaluation budget: loop iterations in total and wall-clock time. Loops and macro calls tick
 * it; the clock is read only every 1024 ticks so that checking costs next to nothing.
 */
final class Budget {
    private final long loopLimit;
    private final long timeLimitNanos;
    private final long startNanos;
    private final Duration timeLimit;
    private long iterations;
    private int ticks;
    private volatile boolean cancelled;

    Budget(long loopLimit, Duration timeLimit, long startNanos) {
        this.loopLimit = loopLimit;
        this.timeLimit = timeLimit;
        this.timeLimitNanos = nanos(timeLimit);
        this.startNanos = startNanos;
    }

    /** Why evaluation must stop now, or null to go on. */
    String loopIteration() {
        if (++iterations > loopLimit) {
            return String.format("evaluation stopped: loops ran %,d iterations (is the loop condition ever false?)",
                    loopLimit);
        }
        return tick();
    }

    /** Why evaluation must stop now, or null to go on. */
    /** Said when the loops' values fill the heap before the iteration budget is spent. */
    String outOfMemory() {
        return String.format("evaluation stopped: the loops' values filled the memory after %,d iterations"
                + " (is the loop condition ever false? if not, give Java more memory: CRT_JAVA_OPTS=-Xmx2g ./crt …)", iterations);
    }

    String tick() {
        if ((++ticks & 1023) != 0) return null;
        if (cancelled) return "evaluation stopped: the compile was cancelled";
        if (System.nanoTime() - startNanos > timeLimitNanos) {
            return "evaluation stopped: it took longer than the time budget of " + describe(timeLimit)
                    + " (is a loop or a recursion endless?)";
        }
        return null;
    }

    void cancel() { cancelled = true; }

    /** A budget too long to count in nanoseconds is as good as none. */
    private static long nanos(Duration d) {
        try {
            return Math.max(0, d.toNanos());
        } catch (ArithmeticException tooLong) {
            return Long.MAX_VALUE;
        }
    }

    private static String describe(Duration d) {
        long ms = d.toMillis();
        return ms % 1000 == 0 ? ms / 1000 + " s" : ms + " ms";
    }
}
