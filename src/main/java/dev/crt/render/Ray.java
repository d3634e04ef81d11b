package dev.crt.render;

/**
 * A mutable ray o + t·d with its precomputed inverse direction; one per thread, reused for every
 * intersection query so the hot path allocates nothing.
 */
final class Ray {
    double ox, oy, oz;
    double dx, dy, dz;
    double ix, iy, iz;

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
    }
}
