package dev.crt.render;

/** A point on a primitive's surface with the primitive's outward unit normal there. Per-thread scratch. */
final class SurfacePoint {
    double px, py, pz;
    double nx, ny, nz;
}
