package dev.crt.render;

import dev.crt.geom.Aabb;
import dev.crt.geom.Vec3;

/**
 * The placement of a shape stored in its own coordinates: at offset {@code o} of the shape data,
 * the world-to-local matrix (3×4, row-major, 12 doubles), then the local-to-world one (12 more).
 * Shared by every kind that is intersected in a canonical local frame.
 */
final class Affine {
    /** Doubles the two matrices take; a shape's own parameters follow them. */
    static final int SIZE = 24;

    private Affine() {}

    /** Writes the local point (x, y, z) mapped to world space as the surface point of {@code out}. */
    static void pointToWorld(double[] a, int o, double x, double y, double z, SurfacePoint out) {
        int m = o + 12;
        out.px = a[m] * x + a[m + 1] * y + a[m + 2] * z + a[m + 3];
        out.py = a[m + 4] * x + a[m + 5] * y + a[m + 6] * z + a[m + 7];
        out.pz = a[m + 8] * x + a[m + 9] * y + a[m + 10] * z + a[m + 11];
    }

    /** Normals map by the inverse transpose: the world normal's i-th component is Σj inv[j][i]·n[j]. */
    static void normalToWorld(double[] a, int o, double x, double y, double z, SurfacePoint out) {
        double nx = a[o] * x + a[o + 4] * y + a[o + 8] * z;
        double ny = a[o + 1] * x + a[o + 5] * y + a[o + 9] * z;
        double nz = a[o + 2] * x + a[o + 6] * y + a[o + 10] * z;
        double inv = 1 / Math.sqrt(nx * nx + ny * ny + nz * nz);
        out.nx = nx * inv;
        out.ny = ny * inv;
        out.nz = nz * inv;
    }

    /** Maps the local tangents dp/du and dp/dv to world space (by the linear part of the matrix). */
    static void tangentsToWorld(double[] a, int o, double ux, double uy, double uz, double vx, double vy, double vz,
            SurfacePoint out) {
        int m = o + 12;
        out.tangents(a[m] * ux + a[m + 1] * uy + a[m + 2] * uz, a[m + 4] * ux + a[m + 5] * uy + a[m + 6] * uz,
                a[m + 8] * ux + a[m + 9] * uy + a[m + 10] * uz,
                a[m] * vx + a[m + 1] * vy + a[m + 2] * vz, a[m + 4] * vx + a[m + 5] * vy + a[m + 6] * vz,
                a[m + 8] * vx + a[m + 9] * vy + a[m + 10] * vz);
    }

    /** World bounds of the local box [lo, hi] under the placement: the box of its eight corners. */
    static Aabb bounds(double[] a, int o, double x0, double y0, double z0, double x1, double y1, double z1) {
        int m = o + 12;
        double[] lo = new double[3], hi = new double[3];
        for (int i = 0; i < 3; i++) {
            // Per world axis, each local axis contributes its smaller and larger end independently.
            double c = a[m + 4 * i + 3], l = c, h = c;
            double[] from = {x0, y0, z0}, to = {x1, y1, z1};
            for (int j = 0; j < 3; j++) {
                double e0 = a[m + 4 * i + j] * from[j], e1 = a[m + 4 * i + j] * to[j];
                l += Math.min(e0, e1);
                h += Math.max(e0, e1);
            }
            lo[i] = l;
            hi[i] = h;
        }
        return new Aabb(new Vec3(lo[0], lo[1], lo[2]), new Vec3(hi[0], hi[1], hi[2]));
    }
}
