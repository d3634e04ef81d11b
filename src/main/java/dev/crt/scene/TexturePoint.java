package dev.crt.scene;

/**
 * Where a texture is looked up: the hit point in the entity's own coordinates (before its
 * modifiers; moved a tiny distance into the solid), the entity-space unit normal there, the
 * surface's own (u, v) when the texture asked for them, and the ray's footprint: the width of
 * the ray cone at the hit in entity units, and in u and v units. Per-thread scratch.
 */
public final class TexturePoint {
    public double x, y, z;
    public double nx, ny, nz;
    public double u, v;
    /** Footprint width in entity units, in u units and in v units (0: a point sample). */
    public double width, widthU, widthV;

    /** Sets the point and normal, with no footprint and no uv. */
    public TexturePoint at(double x, double y, double z, double nx, double ny, double nz) {
        this.x = x;
        this.y = y;
        this.z = z;
        this.nx = nx;
        this.ny = ny;
        this.nz = nz;
        u = 0;
        v = 0;
        width = 0;
        widthU = 0;
        widthV = 0;
        return this;
    }
}
