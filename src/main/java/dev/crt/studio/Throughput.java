package dev.crt.studio;

import java.util.TreeMap;

/**
 * The rays the studio's renders traced, by second: each finished render (F5 or an animation frame)
 * spreads its rays evenly over the seconds it took, so a chart of it reads in rays per second.
 * Thread-safe: render threads record, the System panel reads.
 */
final class Throughput {
    /** Seconds of history kept. */
    static final int KEEP_SECONDS = 600;

    private final TreeMap<Long, Double> raysBySecond = new TreeMap<>();

    /** A render traced {@code rays} rays between the two {@link System#nanoTime()} instants. */
    synchronized void record(long rays, long startNanos, long endNanos) {
        if (rays <= 0 || endNanos <= startNanos) return;
        double perNano = (double) rays / (endNanos - startNanos);
        long at = startNanos;
        while (at < endNanos) {
            long second = Math.floorDiv(at, 1_000_000_000L);
            long next = Math.min(endNanos, (second + 1) * 1_000_000_000L);
            raysBySecond.merge(second, perNano * (next - at), Double::sum);
            at = next;
        }
        long oldest = Math.floorDiv(endNanos, 1_000_000_000L) - KEEP_SECONDS;
        raysBySecond.headMap(oldest).clear();
    }

    /** Millions of rays traced during second {@code second} (of {@link System#nanoTime()}). */
    synchronized double megaRays(long second) {
        Double r = raysBySecond.get(second);
        return r == null ? 0 : r / 1e6;
    }
}
