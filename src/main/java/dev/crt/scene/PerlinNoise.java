package dev.crt.scene;

/**
 * Perlin's improved noise (2002): gradient noise on the integer lattice with the quintic fade
 * 6t⁵ − 15t⁴ + 10t³ and the twelve cube-edge gradients, zero at every lattice point, in about
 * [−1, 1]; and the sums the solid textures build from it. The permutation is a fixed shuffle of
 * 0…255 (its own seed, so pictures never change between versions).
 */
public final class PerlinNoise {
    private static final int[] P = new int[512];

    static {
        int[] p = new int[256];
        for (int i = 0; i < 256; i++) p[i] = i;
        long state = 0x5EED_C0DE_2026L;
        for (int i = 255; i > 0; i--) {
            state += 0x9E3779B97F4A7C15L;
            long z = state;
            z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
            z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
            z ^= z >>> 31;
            int j = (int) Long.remainderUnsigned(z, i + 1);
            int t = p[i];
            p[i] = p[j];
            p[j] = t;
        }
        for (int i = 0; i < 512; i++) P[i] = p[i & 255];
    }

    private PerlinNoise() {}

    /** The noise at (x, y, z). */
    public static double noise(double x, double y, double z) {
        double fx = Math.floor(x), fy = Math.floor(y), fz = Math.floor(z);
        int X = (int) (long) fx & 255, Y = (int) (long) fy & 255, Z = (int) (long) fz & 255;
        x -= fx;
        y -= fy;
        z -= fz;
        double u = fade(x), v = fade(y), w = fade(z);
        int a = P[X] + Y, aa = P[a] + Z, ab = P[a + 1] + Z;
        int b = P[X + 1] + Y, ba = P[b] + Z, bb = P[b + 1] + Z;
        return lerp(w,
                lerp(v, lerp(u, grad(P[aa], x, y, z), grad(P[ba], x - 1, y, z)),
                        lerp(u, grad(P[ab], x, y - 1, z), grad(P[bb], x - 1, y - 1, z))),
                lerp(v, lerp(u, grad(P[aa + 1], x, y, z - 1), grad(P[ba + 1], x - 1, y, z - 1)),
                        lerp(u, grad(P[ab + 1], x, y - 1, z - 1), grad(P[bb + 1], x - 1, y - 1, z - 1))));
    }

    /** Σ_{i<octaves} noise(2ⁱ·p)/2ⁱ: fractal noise. */
    public static double fractal(double x, double y, double z, int octaves) {
        double sum = 0, f = 1;
        for (int i = 0; i < octaves; i++) {
            sum += noise(x * f, y * f, z * f) / f;
            f *= 2;
        }
        return sum;
    }

    /** Σ_{i<octaves} |noise(2ⁱ·p)|/2ⁱ: Perlin's turbulence. */
    public static double turbulence(double x, double y, double z, int octaves) {
        double sum = 0, f = 1;
        for (int i = 0; i < octaves; i++) {
            sum += Math.abs(noise(x * f, y * f, z * f)) / f;
            f *= 2;
        }
        return sum;
    }

    static double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }

    private static double lerp(double t, double a, double b) { return a + t * (b - a); }

    /** The dot product of (x, y, z) with one of the twelve cube-edge directions chosen by the hash. */
    private static double grad(int hash, double x, double y, double z) {
        int h = hash & 15;
        double u = h < 8 ? x : y;
        double v = h < 4 ? y : h == 12 || h == 14 ? x : z;
        return ((h & 1) == 0 ? u : -u) + ((h & 2) == 0 ? v : -v);
    }

    /** color1 + t·(color2 − color1) into out. */
    static void mix(Rgb c1, Rgb c2, double t, double[] out) {
        out[0] = c1.r() + t * (c2.r() - c1.r());
        out[1] = c1.g() + t * (c2.g() - c1.g());
        out[2] = c1.b() + t * (c2.b() - c1.b());
    }
}
