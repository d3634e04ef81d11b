package dev.crt.render;

import dev.crt.scene.Texture;
import dev.crt.scene.TexturePoint;

/**
 * The textured channels of a material at a hit (docs/rendering.md, "Textures" and "Bump
 * mapping"): fills a {@link TexturePoint} from the surface (entity point just inside the solid,
 * entity normal, uv and footprint when asked for), reads each textured channel, and tilts the
 * shading normal by the bump map's gradient. Only materials with a texture come here. One per
 * render thread; it allocates nothing.
 */
final class TextureShading {
    private final Shapes shapes;
    private final double[] mat;
    private final Texture[] textures;
    private final TexturePoint point = new TexturePoint();
    private final SurfacePoint scratch = new SurfacePoint();
    private final double[] rgb = new double[3];
    /** Saved lookup point while the bump map is probed around it. */
    private double baseX, baseY, baseZ, baseU, baseV;

    /** The channel values after {@link #shade}: colour, emission, ks, kr, kt and the ray-facing shading normal. */
    double cr, cg, cb, er, eg, eb, ks, kr, kt, snx, sny, snz;

    TextureShading(Shapes shapes, double[] materials, Texture[] textures) {
        this.shapes = shapes;
        this.mat = materials;
        this.textures = textures;
    }

    /**
     * Evaluates the channels of material m on shape s at {@code surface} (hit on {@code face}),
     * with outward geometric normal g, ray-facing shading normal sn, the ray's footprint
     * {@code width} on the surface (world units) and the offset {@code delta}.
     */
    void shade(int s, int face, int m, SurfacePoint surface, double gx, double gy, double gz, double snx0, double sny0,
            double snz0, double width, double delta) {
        double[] a = mat;
        cr = a[m + Materials.R];
        cg = a[m + Materials.G];
        cb = a[m + Materials.B];
        er = a[m + Materials.ER];
        eg = a[m + Materials.EG];
        eb = a[m + Materials.EB];
        ks = a[m + Materials.SPECULAR];
        kr = a[m + Materials.REFLECTIVITY];
        kt = a[m + Materials.TRANSPARENCY];
        snx = snx0;
        sny = sny0;
        snz = snz0;
        boolean bump = Features.BUMP && a[m + Materials.TEX_BUMP] != 0;
        locate(s, surface.px - delta * gx, surface.py - delta * gy, surface.pz - delta * gz, gx, gy, gz, width);
        if (a[m + Materials.NEEDS_UV] != 0 || bump) {
            shapes.frame(s, face, surface);
            uv(surface, width);
        }
        TexturePoint p = point;
        int k;
        if ((k = (int) a[m + Materials.TEX_COLOR]) != 0) {
            textures[k].evaluate(p, rgb);
            cr = rgb[0];
            cg = rgb[1];
            cb = rgb[2];
        }
        if ((k = (int) a[m + Materials.TEX_EMISSION]) != 0) {
            textures[k].evaluate(p, rgb);
            er = rgb[0];
            eg = rgb[1];
            eb = rgb[2];
        }
        if ((k = (int) a[m + Materials.TEX_SPECULAR]) != 0) ks = scalar(k);
        if ((k = (int) a[m + Materials.TEX_REFLECTIVITY]) != 0) kr = clamp(scalar(k));
        if ((k = (int) a[m + Materials.TEX_TRANSPARENCY]) != 0) kt = clamp(scalar(k));
        if (bump) bump(s, (int) a[m + Materials.TEX_BUMP], a[m + Materials.BUMPSCALE], surface, gx, gy, gz, width, delta / Tracer.OFFSET);
    }

    /** The texture's luminance at the current point. */
    private double scalar(int k) {
        textures[k].evaluate(point, rgb);
        return Texture.luminance(rgb[0], rgb[1], rgb[2]);
    }

    private static double clamp(double x) { return x < 0 ? 0 : x > 1 ? 1 : x; }

    /** The entity point and normal of world point q and outward normal g on shape s, and the footprint in entity units. */
    private void locate(int s, double qx, double qy, double qz, double gx, double gy, double gz, double width) {
        double[] e = shapes.placements.toEntity;
        int t = shapes.placement[s];
        TexturePoint p = point;
        p.x = e[t] * qx + e[t + 1] * qy + e[t + 2] * qz + e[t + 3];
        p.y = e[t + 4] * qx + e[t + 5] * qy + e[t + 6] * qz + e[t + 7];
        p.z = e[t + 8] * qx + e[t + 9] * qy + e[t + 10] * qz + e[t + 11];
        // Normals map by the inverse transpose of toEntity, the transpose of toWorld; for the box
        // mapping's choice of face the direction is all that matters.
        double nx = e[t] * gx + e[t + 1] * gy + e[t + 2] * gz;
        double ny = e[t + 4] * gx + e[t + 5] * gy + e[t + 6] * gz;
        double nz = e[t + 8] * gx + e[t + 9] * gy + e[t + 10] * gz;
        p.nx = nx;
        p.ny = ny;
        p.nz = nz;
        double det = e[t] * (e[t + 5] * e[t + 10] - e[t + 6] * e[t + 9]) - e[t + 1] * (e[t + 4] * e[t + 10] - e[t + 6] * e[t + 8])
                + e[t + 2] * (e[t + 4] * e[t + 9] - e[t + 5] * e[t + 8]);
        p.width = width * Math.cbrt(Math.abs(det));
        p.u = 0;
        p.v = 0;
        p.widthU = 0;
        p.widthV = 0;
    }

    private void uv(SurfacePoint surface, double width) {
        TexturePoint p = point;
        p.u = surface.u;
        p.v = surface.v;
        double lu = Math.sqrt(surface.dpdux * surface.dpdux + surface.dpduy * surface.dpduy + surface.dpduz * surface.dpduz);
        double lv = Math.sqrt(surface.dpdvx * surface.dpdvx + surface.dpdvy * surface.dpdvy + surface.dpdvz * surface.dpdvz);
        p.widthU = lu > 0 ? width / lu : 0;
        p.widthV = lv > 0 ? width / lv : 0;
    }

    /**
     * Tilts the shading normal by the gradient of the height h = bumpscale·luminance(texture),
     * taken by central differences one footprint either side (clamped to 10⁻⁶…10⁻² of the larger of the
     * point's coordinates and the shape's size) along
     * the tangent frame T (dp/du made perpendicular to N) and B = N × T: N' = normalize(N − ∂h/∂T·T
     * − ∂h/∂B·B), with N the shading normal turned outward, then turned back to the ray's side.
     */
    private void bump(int s, int k, double scale, SurfacePoint surface, double gx, double gy, double gz, double width,
            double size) {
        double sign = snx * gx + sny * gy + snz * gz < 0 ? -1 : 1;
        double nx = sign * snx, ny = sign * sny, nz = sign * snz;
        double ux = surface.dpdux, uy = surface.dpduy, uz = surface.dpduz;
        double un = ux * nx + uy * ny + uz * nz;
        double tx = ux - un * nx, ty = uy - un * ny, tz = uz - un * nz;
        double tl = Math.sqrt(tx * tx + ty * ty + tz * tz);
        if (!(tl > 0)) {
            // No usable dp/du (a pole, a degenerate triangle): any tangent will do for a gradient.
            if (Math.abs(nx) < 0.9) {
                tx = 0;
                ty = nz;
                tz = -ny;
            } else {
                tx = -nz;
                ty = 0;
                tz = nx;
            }
            tl = Math.sqrt(tx * tx + ty * ty + tz * tz);
        }
        tx /= tl;
        ty /= tl;
        tz /= tl;
        double bx = ny * tz - nz * ty, by = nz * tx - nx * tz, bz = nx * ty - ny * tx;
        double eps = Math.min(width, 1e-2 * size);
        if (!(eps > 1e-6 * size)) eps = size > 0 ? 1e-6 * size : 1e-6;
        TexturePoint p = point;
        baseX = p.x;
        baseY = p.y;
        baseZ = p.z;
        baseU = p.u;
        baseV = p.v;
        double dT = scale * (probe(s, k, surface, tx, ty, tz, eps) - probe(s, k, surface, tx, ty, tz, -eps)) / (2 * eps);
        double dB = scale * (probe(s, k, surface, bx, by, bz, eps) - probe(s, k, surface, bx, by, bz, -eps)) / (2 * eps);
        p.x = baseX;
        p.y = baseY;
        p.z = baseZ;
        p.u = baseU;
        p.v = baseV;
        double mx = nx - dT * tx - dB * bx, my = ny - dT * ty - dB * by, mz = nz - dT * tz - dB * bz;
        double inv = sign / Math.sqrt(mx * mx + my * my + mz * mz);
        snx = mx * inv;
        sny = my * inv;
        snz = mz * inv;
    }

    /** The bump texture's luminance a distance eps along the world direction w from the saved point. */
    private double probe(int s, int k, SurfacePoint surface, double wx, double wy, double wz, double eps) {
        double[] e = shapes.placements.toEntity;
        int t = shapes.placement[s];
        TexturePoint p = point;
        p.x = baseX + eps * (e[t] * wx + e[t + 1] * wy + e[t + 2] * wz);
        p.y = baseY + eps * (e[t + 4] * wx + e[t + 5] * wy + e[t + 6] * wz);
        p.z = baseZ + eps * (e[t + 8] * wx + e[t + 9] * wy + e[t + 10] * wz);
        double ux = surface.dpdux, uy = surface.dpduy, uz = surface.dpduz;
        double vx = surface.dpdvx, vy = surface.dpdvy, vz = surface.dpdvz;
        double uu = ux * ux + uy * uy + uz * uz, vv = vx * vx + vy * vy + vz * vz;
        p.u = baseU + (uu > 0 ? eps * (wx * ux + wy * uy + wz * uz) / uu : 0);
        p.v = baseV + (vv > 0 ? eps * (wx * vx + wy * vy + wz * vz) / vv : 0);
        return scalar(k);
    }

    /**
     * The transparency of textured material m where the ray crosses shape s at t on {@code face}
     * (for shadow rays): the texture read at the crossing as a camera ray would, without footprint.
     */
    double transparencyAt(int s, int face, int m, double t, Ray ray) {
        SurfacePoint q = scratch;
        shapes.surface(s, face, t, ray, q);
        double delta = Tracer.OFFSET * Math.max(Math.max(Math.abs(q.px), Math.abs(q.py)), Math.max(Math.abs(q.pz), shapes.scale[s]));
        locate(s, q.px - delta * q.nx, q.py - delta * q.ny, q.pz - delta * q.nz, q.nx, q.ny, q.nz, 0);
        if (mat[m + Materials.NEEDS_UV] != 0) {
            shapes.frame(s, face, q);
            uv(q, 0);
        }
        return clamp(scalar((int) mat[m + Materials.TEX_TRANSPARENCY]));
    }
}
