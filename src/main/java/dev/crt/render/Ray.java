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
}
