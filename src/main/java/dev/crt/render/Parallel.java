package dev.crt.render;

import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinTask;

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
     * Runs {@code work} over the {@link #chunks}(n) chunks of [0, n), the first on the calling
     * thread and the others on the common fork/join pool, and returns when all are done; chunk k
     * covers [n·k / chunks, n·(k + 1) / chunks).
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
        ForkJoinTask<?>[] tasks = new ForkJoinTask<?>[c];
        for (int k = 1; k < c; k++) {
            int chunk = k, from = start(n, c, k), to = start(n, c, k + 1);
            // The common pool's own threads number cores − 1: with the caller, every core works.
            tasks[k] = ForkJoinPool.commonPool().submit(() -> work.run(chunk, from, to));
        }
        work.run(0, 0, start(n, c, 1));
        for (int k = 1; k < c; k++) tasks[k].join();
    }

    /** Where chunk {@code k} of {@code c} over [0, n) starts. */
    static int start(int n, int c, int k) {
        return (int) ((long) n * k / c);
    }
}
