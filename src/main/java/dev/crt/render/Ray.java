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
        return near <= far ? near : Double.POSITIVE_INFINITY;
    }

    /** Whether the line passes through the box at {@code k} in {@code b} for some tMin ≤ t ≤ tMax. */
    boolean enters(double[] b, int k, double tMin, double tMax) {
        return entry(b, k, tMin, tMax) != Double.POSITIVE_INFINITY;
    }
}
