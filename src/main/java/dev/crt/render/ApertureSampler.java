package dev.crt.render;

import dev.crt.scene.ApertureShape;

/**
 * Uniform points of the unit aperture: the disc, or the regular polygon inscribed in it with one
 * vertex pointing up (+y). A polygon is sampled by picking one of its equal centre triangles, then
 * a uniform point of that triangle.
 */
final class ApertureSampler {
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
            double r = Math.sqrt(u1), a = 2 * Math.PI * u2;
            out[0] = r * Math.cos(a);
            out[1] = r * Math.sin(a);
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
