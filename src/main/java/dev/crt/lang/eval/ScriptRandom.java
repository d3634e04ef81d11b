package dev.crt.lang.eval;

/**
 * The numbers of {@code rand}: the sequence {@link java.util.Random} gives for the same seed (its
 * 48-bit linear congruential generator and its {@code nextDouble}, which its documentation
 * specifies for every implementation), without its atomic seed. One script's evaluation runs on
 * one thread, and {@code Random}'s compare-and-set per draw was 8 % of compiling a million
 * random spheres.
 */
final class ScriptRandom {
    private static final long MULTIPLIER = 0x5DEECE66DL, ADDEND = 0xBL, MASK = (1L << 48) - 1;
    private static final double DOUBLE_UNIT = 0x1.0p-53;

    private long seed;

    ScriptRandom(long seed) {
        this.seed = (seed ^ MULTIPLIER) & MASK;
    }

    private int next(int bits) {
        seed = (seed * MULTIPLIER + ADDEND) & MASK;
        return (int) (seed >>> (48 - bits));
    }

    /** A number in [0, 1): {@code java.util.Random.nextDouble} of the same seed and draw. */
    double nextDouble() {
        return (((long) next(26) << 27) + next(27)) * DOUBLE_UNIT;
    }
}
