package dev.crt.render;

/**
 * A mutable ray o + t·d with its precomputed inverse direction; one per thread, reused for every
 * intersection query so the hot path allocates nothing.
 */
final class Ray {
    double ox, oy, oz;
    double dx, dy, dz;
    double ix, iy, iz;
    /** Offsets (0 or 3) of the near slab plane per axis in a node's min/max box, by direction sign. */
    int nearX, nearY, nearZ;
    /** The ray in a shape's own coordinates, written by {@link #toLocal} (t keeps its meaning: the map is affine). */
    double lox, loy, loz, ldx, ldy, ldz;

    void set(double ox, double oy, double oz, double dx, double dy, double dz) {
        this.ox = ox;
        this.oy = oy;
        this.oz = oz;
        this.dx = dx;
        this.dy = dy;
        this.dz = dz;
        ix = 1 / dx;
        iy = 1 / dy;
        iz = 1 / dz;
        nearX = ix >= 0 ? 0 : 3;
        nearY = iy >= 0 ? 0 : 3;
        nearZ = iz >= 0 ? 0 : 3;
    }

    /**
     * Where the ray enters the box at {@code k} in {@code b} within [tMin, tMax], or +∞ when it
     * misses. A slab the ray runs exactly along gives NaN, which the comparisons ignore
     * (conservatively a hit).
     */
    double entry(double[] b, int k, double tMin, double tMax) {
        double near = tMin, far = tMax;
        double t0 = (b[k + nearX] - ox) * ix, t1 = (b[k + 3 - nearX] - ox) * ix;
        if (t0 > near) near = t0;
        if (t1 < far) far = t1;
        t0 = (b[k + 1 + nearY] - oy) * iy;
        t1 = (b[k + 4 - nearY] - oy) * iy;
        if (t0 > near) near = t0;
        if (t1 < far) far = t1;
        t0 = (b[k + 2 + nearZ] - oz) * iz;
        t1 = (b[k + 5 - nearZ] - oz) * iz;
        if (t0 > near) near = t0;
        if (t1 < far) far = t1;
        // Widened by the bound of the slab distances' rounding error, as in BvhWalker. An
        // infinite far end gives NaN: a miss.
        double e = BvhWalker.SLAB_ERROR;
        return near <= far + e * (Math.abs(near) + Math.abs(far)) ? near : Double.POSITIVE_INFINITY;
    }

    /** Whether the line passes through the box at {@code k} in {@code b} for some tMin ≤ t ≤ tMax. */
    boolean enters(double[] b, int k, double tMin, double tMax) {
        return entry(b, k, tMin, tMax) != Double.POSITIVE_INFINITY;
    }

    /** Maps the ray by the affine world-to-local matrix (3×4, row-major) at {@code o} in {@code a}. */
    void toLocal(double[] a, int o) {
        lox = a[o] * ox + a[o + 1] * oy + a[o + 2] * oz + a[o + 3];
        loy = a[o + 4] * ox + a[o + 5] * oy + a[o + 6] * oz + a[o + 7];
        loz = a[o + 8] * ox + a[o + 9] * oy + a[o + 10] * oz + a[o + 11];
        ldx = a[o] * dx + a[o + 1] * dy + a[o + 2] * dz;
        ldy = a[o + 4] * dx + a[o + 5] * dy + a[o + 6] * dz;
        ldz = a[o + 8] * dx + a[o + 9] * dy + a[o + 10] * dz;
    }
}
