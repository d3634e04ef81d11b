package dev.crt.render;

import dev.crt.scene.ApertureShape;

/**
 * Uniform points of the unit aperture: the disc, or the regular polygon inscribed in it with one
 * vertex pointing up (+y). A polygon is sampled by picking one of its equal centre triangles, then
 * a uniform point of that triangle.
 */
final class ApertureSampler {
    /**
     * sin x = x + x³·S(x²) and cos x = 1 − x²/2 + x⁴·C(x²) for |x| ≤ π/4, S and C of degree 5 fitted at
     * Chebyshev nodes (largest error 1.1e-16; {@code CameraAndBackgroundTest} checks them against the library).
     */
    private static final double S5 = 1.5918129294866608e-10, S4 = -2.5051131845003624e-08, S3 = 2.755731610255244e-06,
            S2 = -0.00019841269836758574, S1 = 0.008333333333330948, S0 = -0.16666666666666666;
    private static final double C5 = -1.1382632425521717e-11, C4 = 2.08761462684032e-09, C3 = -2.7557317271729793e-07,
            C2 = 2.480158729876569e-05, C1 = -0.0013888888888887398, C0 = 0.041666666666666664;
    /** cos and sin of k quarter turns. */
    private static final double[] QUARTER_COS = {1, 0, -1, 0}, QUARTER_SIN = {0, 1, 0, -1};

    private final int sides;
    private final double[] vx, vy;

    ApertureSampler(ApertureShape shape) {
        sides = shape.sides();
        vx = new double[sides + 1];
        vy = new double[sides + 1];
        for (int k = 0; k <= sides; k++) {
            double a = Math.PI / 2 + 2 * Math.PI * k / Math.max(1, sides);
            vx[k] = Math.cos(a);
            vy[k] = Math.sin(a);
        }
    }

    /** Writes a lens point into {@code out[0..1]} from three uniform numbers in [0, 1). */
    void sample(double u1, double u2, double u3, double[] out) {
        if (sides == 0) {
            double r = Math.sqrt(u1);
            // cos and sin of 2π·u2: the quarter turn q nearest it, exactly, and the rest, at most
            // π/4, by polynomials (the library's two calls were most of a lens sample's cost).
            double t = 4 * u2, q = Math.rint(t);
            int k = (int) q & 3;
            double x = (t - q) * (Math.PI / 2), x2 = x * x;
            double s = S5;
            s = s * x2 + S4;
            s = s * x2 + S3;
            s = s * x2 + S2;
            s = s * x2 + S1;
            s = s * x2 + S0;
            s = x + x * x2 * s;
            double c = C5;
            c = c * x2 + C4;
            c = c * x2 + C3;
            c = c * x2 + C2;
            c = c * x2 + C1;
            c = c * x2 + C0;
            c = 1 - 0.5 * x2 + x2 * x2 * c;
            out[0] = r * (c * QUARTER_COS[k] - s * QUARTER_SIN[k]);
            out[1] = r * (s * QUARTER_COS[k] + c * QUARTER_SIN[k]);
            return;
        }
        int k = Math.min((int) (u3 * sides), sides - 1);
        // Uniform in the triangle (0, v_k, v_k+1): fold the unit square onto it.
        double s = u1, t = u2;
        if (s + t > 1) {
            s = 1 - s;
            t = 1 - t;
        }
        out[0] = s * vx[k] + t * vx[k + 1];
        out[1] = s * vy[k] + t * vy[k + 1];
    }
}
