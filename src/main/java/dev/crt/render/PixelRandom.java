package dev.crt.render;

/**
 * A small SplitMix64 generator seeded from pixel coordinates and a scene seed, so that every random
 * choice of a pixel (lens samples…) is the same whatever thread renders it and in whatever order.
 */
final class PixelRandom {
    static final long SCENE_SEED = 0x43525452656e6465L;

    private long state;

    /** Seeds the generator for pixel (i, j) of a scene with seed {@code sceneSeed} (0: wave 1's sequence). */
    void seed(int i, int j, long sceneSeed) {
        state = pixelHash(i, j, sceneSeed);
    }

    /** A well-mixed 64-bit value from a pixel's coordinates and the scene seed. */
    static long pixelHash(int i, int j, long sceneSeed) {
        return mix((SCENE_SEED ^ sceneSeed) ^ mix(((long) j << 32) | (i & 0xffffffffL)));
    }

    /** Uniform in [0, 1). */
    double next() {
        state += 0x9E3779B97F4A7C15L;
        return (mix(state) >>> 11) * 0x1.0p-53;
    }

    static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }
}
