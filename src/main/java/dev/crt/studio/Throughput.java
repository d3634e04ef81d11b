package dev.crt.studio;

import java.util.TreeMap;

/**
 * The rays the studio's renders traced, by tenth of a second: render threads add each tile's rays
 * as the tile finishes (F5 and animation frames), so a chart of it reads in rays per second while
 * a render runs, not only after it. Thread-safe: render threads add, the System panel reads.
 */
final class Throughput {
    /** Seconds of history kept. */
    static final int KEEP_SECONDS = 600;
    private static final long BUCKET_NANOS = 100_000_000L;
    private static final int BUCKETS_PER_SECOND = 10;

    private final TreeMap<Long, Long> raysByBucket = new TreeMap<>();

    /** {@code rays} more rays were traced at the {@link System#nanoTime()} instant {@code atNanos}. */
    synchronized void add(long rays, long atNanos) {
        if (rays <= 0) return;
        long bucket = Math.floorDiv(atNanos, BUCKET_NANOS);
        raysByBucket.merge(bucket, rays, Long::sum);
        if (raysByBucket.firstKey() < bucket - (long) KEEP_SECONDS * BUCKETS_PER_SECOND) {
            raysByBucket.headMap(bucket - (long) KEEP_SECONDS * BUCKETS_PER_SECOND).clear();
        }
    }

    /** Millions of rays traced during second {@code second} (of {@link System#nanoTime()}). */
    synchronized double megaRays(long second) {
        long rays = 0;
        for (long r : raysByBucket.subMap(second * BUCKETS_PER_SECOND, (second + 1) * BUCKETS_PER_SECOND).values()) rays += r;
        return rays / 1e6;
    }

    /**
     * Millions of rays per second over the last whole second before {@code nowNanos}: the ten
     * tenths before the one under way, which is still filling.
     */
    synchronized double recentMegaRaysPerSecond(long nowNanos) {
        long current = Math.floorDiv(nowNanos, BUCKET_NANOS);
        long rays = 0;
        for (long r : raysByBucket.subMap(current - BUCKETS_PER_SECOND, current).values()) rays += r;
        return rays / 1e6;
    }
}
