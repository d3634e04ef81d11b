package dev.crt.render;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;

/**
 * Splits a loop over [0, n) into contiguous chunks run on the cores at once, for the passes of a
 * scene's preparation whose chunks write disjoint parts of their output: the result is the same
 * for any number of threads, chunks being independent and merged in chunk order by the caller.
 */
final class Parallel {
    /** Loops shorter than this run on the calling thread alone: a task costs more than their work. */
    static final int MIN_CHUNK = 1 << 15;
    /** Threads to use; tests set it to compare the results of one thread and several. */
    static volatile int threads = Runtime.getRuntime().availableProcessors();

    private Parallel() {}

    /** The work of one chunk: items [from, to), chunk number {@code chunk}. */
    interface Chunk {
        void run(int chunk, int from, int to);
    }

    /** The number of chunks {@link #forChunks} cuts [0, n) into (1 below {@link #MIN_CHUNK} items). */
    static int chunks(int n) {
        return (int) Math.max(1, Math.min(threads, n / (long) MIN_CHUNK));
    }

    /**
     * Runs {@code work} over the {@link #chunks}(n) chunks of [0, n), on the calling thread and
     * the common fork/join pool's, and returns when all are done; chunk k covers
     * [n·k / chunks, n·(k + 1) / chunks). A chunk's exception is thrown here, after all are done.
     */
    static void forChunks(int n, Chunk work) {
        forChunks(n, chunks(n), work);
    }

    /** {@link #forChunks(int, Chunk)} in {@code c} chunks, as a caller that sized its per-chunk results by {@link #chunks} gives them. */
    static void forChunks(int n, int c, Chunk work) {
        if (c == 1) {
            work.run(0, 0, n);
            return;
        }
        // Chunks are claimed, not assigned: the calling thread and the pool's threads take the
        // next unclaimed one until none is left, and the caller waits only for chunks under way.
        // On a loaded machine a pool thread may start late or not at all; the caller then does
        // its chunks instead of waiting for it.
        AtomicInteger next = new AtomicInteger();
        CountDownLatch done = new CountDownLatch(c);
        AtomicReference<Throwable> failure = new AtomicReference<>();
        Runnable worker = () -> {
            for (int k; (k = next.getAndIncrement()) < c; ) {
                try {
                    work.run(k, start(n, c, k), start(n, c, k + 1));
                } catch (Throwable t) {
                    failure.compareAndSet(null, t);
                } finally {
                    done.countDown();
                }
            }
        };
        // The common pool's own threads number cores − 1: with the caller, every core works.
        for (int k = 1; k < c; k++) ForkJoinPool.commonPool().execute(worker);
        worker.run();
        try {
            done.await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while preparing the scene", e);
        }
        Throwable t = failure.get();
        if (t instanceof RuntimeException r) throw r;
        if (t instanceof Error e) throw e;
        if (t != null) throw new IllegalStateException(t);
    }

    /** Where chunk {@code k} of {@code c} over [0, n) starts. */
    static int start(int n, int c, int k) {
        return (int) ((long) n * k / c);
    }
}
