package dev.crt.geom;

/**
 * The first five dimensions of the Sobol low-discrepancy sequence (direction numbers of Joe and
 * Kuo), with Owen scrambling by the hash-based nested uniform scramble of Burley (2020): each seed
 * gives an independent randomisation that keeps the sequence's stratification, so the first 2^k
 * points of dimensions 0 and 1 put exactly one point in every elementary interval of area 2^-k.
 */
public final class Sobol {
    /** How many dimensions {@link #sample} knows. */
    public static final int DIMENSIONS = 5;
    private static final int BITS = 32;
    /** Direction numbers, BITS per dimension, as unsigned 32-bit fractions. */
    private static final int[] V = new int[DIMENSIONS * BITS];

    static {
        // Dimension 0 is van der Corput's: the index's bits mirrored about the binary point.
        for (int i = 0; i < BITS; i++) V[i] = 1 << (BITS - 1 - i);
        // Dimensions 1–4: degree s, coefficients a and initial m_i of the primitive polynomials.
        int[] s = {1, 2, 3, 3};
        int[] a = {0, 1, 1, 2};
        int[][] m = {{1}, {1, 3}, {1, 3, 1}, {1, 1, 1}};
        for (int d = 1; d < DIMENSIONS; d++) {
            int deg = s[d - 1], coef = a[d - 1], base = d * BITS;
            for (int i = 0; i < BITS; i++) {
                if (i < deg) {
                    V[base + i] = m[d - 1][i] << (BITS - 1 - i);
                } else {
                    int v = V[base + i - deg] ^ (V[base + i - deg] >>> deg);
                    for (int k = 1; k < deg; k++) {
                        if (((coef >>> (deg - 1 - k)) & 1) != 0) v ^= V[base + i - k];
                    }
                    V[base + i] = v;
                }
            }
        }
    }

    private Sobol() {}

    /** Point {@code index} of dimension {@code dim}, unscrambled, as 32 fraction bits. */
    public static int bits(int index, int dim) {
        int x = 0;
        int base = dim * BITS;
        for (int i = 0; index != 0; i++, index >>>= 1) {
            if ((index & 1) != 0) x ^= V[base + i];
        }
        return x;
    }

    /** Point {@code index} of dimension {@code dim}, Owen-scrambled by {@code seed}, in [0, 1). */
    public static double sample(int index, int dim, int seed) {
        return (scramble(bits(index, dim), seed) & 0xffffffffL) * 0x1p-32;
    }

    /**
     * Burley's nested uniform scramble: in bit-reversed order, each bit is flipped by a hash of the
     * bits above it (a Laine–Karras permutation), which is Owen's scrambling of a base-2 digit tree.
     */
    static int scramble(int x, int seed) {
        x = Integer.reverse(x);
        x += seed;
        x ^= x * 0x6c50b47c;
        x ^= x * 0xb82f1e52;
        x ^= x * 0xc7afe638;
        x ^= x * 0x8d22f6e6;
        return Integer.reverse(x);
    }
}
