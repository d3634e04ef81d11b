package dev.crt.animation;

import java.util.Locale;

/**
 * Refuses, before any work, a render whose image cannot fit in the Java heap: better one sentence
 * that names the figure and the way out at once than an OutOfMemoryError after an hour.
 */
public final class MemoryCheck {
    /** Bytes of the frame buffer per pixel: three floats of linear light. */
    static final long BYTES_PER_PIXEL = 12;
    /** What the threads' scratch state and the image writer's rows take besides, at least. */
    static final long HEADROOM = 8L << 20;

    private MemoryCheck() {}

    /** The bytes a render of {@code width × height} pixels needs: its frame buffer and the headroom. */
    static long needed(int width, int height) {
        return BYTES_PER_PIXEL * width * height + HEADROOM;
    }

    /** Fails with a usage error when the heap has less room than a {@code width × height} render needs. */
    public static void check(int width, int height, Runtime runtime) throws FrameFailure {
        long needed = needed(width, height);
        if (needed <= free(runtime)) return;
        // What looked used may be garbage: collect it before refusing.
        System.gc();
        long free = free(runtime);
        if (needed <= free) return;
        long used = runtime.maxMemory() - free;
        long suggest = (needed + used + (1L << 30) - 1) >> 30 << 30;
        throw new FrameFailure(FrameFailure.Kind.SETTINGS, String.format(Locale.ROOT,
                "a %d×%d render needs about %s of memory and the Java heap has %s free: give Java more"
                        + " (CRT_JAVA_OPTS=-Xmx%dg ./crt …) or render fewer pixels (--width, --height)",
                width, height, gib(needed), gib(free), Math.max(1, suggest >> 30)));
    }

    private static long free(Runtime runtime) {
        return runtime.maxMemory() - (runtime.totalMemory() - runtime.freeMemory());
    }

    /** A byte count in GiB with one decimal (MiB below 1 GiB). */
    public static String gib(long bytes) {
        if (bytes < (1L << 30)) return String.format(Locale.ROOT, "%d MiB", bytes >> 20);
        return String.format(Locale.ROOT, "%.1f GiB", bytes / (double) (1L << 30));
    }
}
