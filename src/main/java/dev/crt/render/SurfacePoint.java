package dev.crt.render;

/**
 * A point on a primitive's surface with the primitive's outward unit normal there, and, when
 * {@link Shapes#frame} has been asked for them, the surface's own coordinates (u, v) and their
 * tangents dp/du and dp/dv (world space, not normalised) for textures and bump maps. Per-thread scratch.
 */
final class SurfacePoint {
    double px, py, pz;
    double nx, ny, nz;
    /**
     * Whether (snx, sny, snz) is a shading normal apart from the geometric one (smooth meshes);
     * then (lx, ly, lz) is the point lights are looked at from, lifted onto the smooth surface.
     */
    boolean shaded;
    double snx, sny, snz;
    double lx, ly, lz;
    double u, v;
    double dpdux, dpduy, dpduz;
    double dpdvx, dpdvy, dpdvz;

    void tangents(double ux, double uy, double uz, double vx, double vy, double vz) {
        dpdux = ux;
        dpduy = uy;
        dpduz = uz;
        dpdvx = vx;
        dpdvy = vy;
        dpdvz = vz;
    }
}
