package dev.crt.render;

/**
 * The 2015 program's model (shared/original-shading.md, docs/rendering.md "Scenes from CRT 2015"),
 * for {@code shading -> "original"}: one-sided planes, ambient Cℓ·a·(1 − r) without the material
 * colour, diffuse with N·L unclamped and kd = 1 − r unless {@code diffuse} is given, specular tinted
 * by the material colour, all-or-nothing shadows, falloff by the whole path length from the camera,
 * and mirror reflection. Refraction and emission, which the 2015 language could not set, are CRT's
 * own terms, and so are the second wave's spot and area lights (their cone and sample weights
 * scale each sample's terms). One per render thread; it uses its Tracer for the geometry and adds into the Tracer's
 * accumulator, so the pixel sampler treats both models alike. Scenes in CRT's model never create one.
 */
final class OriginalShading {
    /** How far a ParallelLight's shadow ray looks, as the 2015 program did. */
    static final double PARALLEL_SHADOW_REACH = 10_000;

    private final Tracer tracer;
    private final Shapes shapes;
    private final double[] materials;
    private final Lights lights;
    private final BackgroundShader background;
    private final SurfacePoint surface = new SurfacePoint();
    private final double[] colour = new double[3];
    private final LightSample sample = new LightSample();
    /** What {@link #nearest} travelled before the ray it left in the tracer: back-facing planes passed through. */
    private double skipped;
    /** Whether shadow rays may take {@link Tracer#blocked} (no unbounded items). */
    private final boolean blockedApplies;
    /** Per light, the item that blocked its last blocked shadow ray, or {@link Tracer#NONE}. */
    private final int[] lastBlocker;

    OriginalShading(Tracer tracer, SceneGeometry geometry, Lights lights, BackgroundShader background) {
        this.tracer = tracer;
        blockedApplies = tracer.blockedApplies();
        lastBlocker = new int[lights.count];
        java.util.Arrays.fill(lastBlocker, Tracer.NONE);
        this.shapes = geometry.shapes;
        this.materials = geometry.materials.data;
        this.lights = lights;
        this.background = background;
    }

    /**
     * Adds (wr, wg, wb) ⊙ trace(o + t·d, depth) to the tracer's accumulator; {@code path} is the
     * length of the path from the camera to o (it sets the falloff of the lights).
     */
    void trace(double ox, double oy, double oz, double dx, double dy, double dz, int depth, double path,
            double wr, double wg, double wb) {
        Tracer t = tracer;
        if (!nearest(ox, oy, oz, dx, dy, dz, Double.POSITIVE_INFINITY)) {
            background.shade(dx, dy, dz, colour);
            t.accR += wr * colour[0];
            t.accG += wg * colour[1];
            t.accB += wb * colour[2];
            return;
        }
        double travelled = path + skipped + t.hit.t;
        int s = t.hit.shape;
        shapes.surface(s, t.hit.face, t.hit.t, t.ray, surface);
        double px = surface.px, py = surface.py, pz = surface.pz;
        double nx = surface.nx, ny = surface.ny, nz = surface.nz;
        if (t.hit.flip) {
            nx = -nx;
            ny = -ny;
            nz = -nz;
        }
        double dn = dx * nx + dy * ny + dz * nz;
        boolean entering = dn < 0;
        if (!entering) {
            nx = -nx;
            ny = -ny;
            nz = -nz;
        }
        double delta = Tracer.OFFSET * Math.max(Math.max(Math.abs(px), Math.abs(py)), Math.max(Math.abs(pz), shapes.scale[s]));
        int m = shapes.material[s] * Materials.STRIDE;
        double[] mat = materials;
        double kr = mat[m + Materials.REFLECTIVITY], kt = mat[m + Materials.TRANSPARENCY];
        double local = 1 - kt;
        if (local != 0) {
            shadeLocal(m, px, py, pz, nx, ny, nz, -dx, -dy, -dz, travelled, delta);
            t.accR += wr * local * colour[0];
            t.accG += wg * local * colour[1];
            t.accB += wb * local * colour[2];
        }
        if (depth == 0) return;
        double dDotN = dx * nx + dy * ny + dz * nz;
        double rdx = dx - 2 * dDotN * nx, rdy = dy - 2 * dDotN * ny, rdz = dz - 2 * dDotN * nz;
        if (kr > 0) {
            t.reflectedRays++;
            trace(px + delta * nx, py + delta * ny, pz + delta * nz, rdx, rdy, rdz, depth - 1, travelled,
                    wr * kr, wg * kr, wb * kr);
        }
        if (kt > 0) {
            t.refractedRays++;
            double eta = entering ? 1 / mat[m + Materials.IOR] : mat[m + Materials.IOR];
            double cosI = -dDotN;
            double k = 1 - eta * eta * (1 - cosI * cosI);
            if (k < 0) {
                trace(px + delta * nx, py + delta * ny, pz + delta * nz, rdx, rdy, rdz, depth - 1, travelled,
                        wr * kt, wg * kt, wb * kt);
            } else {
                double c = eta * cosI - Math.sqrt(k);
                trace(px - delta * nx, py - delta * ny, pz - delta * nz, eta * dx + c * nx, eta * dy + c * ny,
                        eta * dz + c * nz, depth - 1, travelled, wr * kt, wg * kt, wb * kt);
            }
        }
    }

    /**
     * E + Σℓ Cℓ·aℓ·(1 − r) + Σ over lit lights of isl·(Cℓ·(N·L) ⊙ C·kd + Cℓ ⊙ C·ks·max(R·V, 0)^n) into
     * {@code colour}, with isl = falloff / (dℓ + path)² for a point light with falloff, else 1.
     */
    private void shadeLocal(int m, double px, double py, double pz, double nx, double ny, double nz,
            double vx, double vy, double vz, double path, double delta) {
        double[] mat = materials;
        double cr = mat[m + Materials.R], cg = mat[m + Materials.G], cb = mat[m + Materials.B];
        double kd = mat[m + Materials.ORIGINAL_DIFFUSE], ks = mat[m + Materials.SPECULAR];
        double shininess = mat[m + Materials.SHININESS], unreflected = 1 - mat[m + Materials.REFLECTIVITY];
        Lights l = lights;
        double r = mat[m + Materials.ER] + l.ambientR * unreflected;
        double g = mat[m + Materials.EG] + l.ambientG * unreflected;
        double b = mat[m + Materials.EB] + l.ambientB * unreflected;
        LightSample ls = sample;
        for (int i = 0; i < l.count; i++) {
            for (int k = 0, samples = l.sampleCount(i); k < samples; k++) {
                l.sample(i, k, px, py, pz, tracer.lightRandom, ls);
                if (ls.weight == 0) continue;
                double wx = ls.wx, wy = ls.wy, wz = ls.wz, reach, isl;
                if (!ls.finite) {
                    reach = PARALLEL_SHADOW_REACH;
                    isl = 1;
                } else {
                    double dist = ls.dist;
                    if (dist == 0) continue;
                    double margin = Math.max(delta, Tracer.OFFSET * Math.max(Math.max(Math.abs(ls.tx), Math.abs(ls.ty)), Math.abs(ls.tz)));
                    reach = dist - margin;
                    double far = dist + path;
                    isl = ls.falloff > 0 ? ls.falloff / (far * far) : 1;
                }
                isl *= ls.weight;
                // The shadow ray leaves along itself, so the surface it starts on is never between the point and the light.
                tracer.shadowRays++;
                if (reach > delta && shadowed(i, px + delta * wx, py + delta * wy, pz + delta * wz, wx, wy, wz, reach - delta)) {
                    continue;
                }
                double nw = nx * wx + ny * wy + nz * wz;
                double diffuse = kd * nw * isl;
                double specular = 0;
                if (ks > 0) {
                    double rv = 2 * nw * (nx * vx + ny * vy + nz * vz) - (wx * vx + wy * vy + wz * vz);
                    if (rv > 0) specular = ks * Tracer.power(rv, shininess) * isl;
                }
                r += l.r[i] * cr * (diffuse + specular);
                g += l.g[i] * cg * (diffuse + specular);
                b += l.b[i] * cb * (diffuse + specular);
            }
        }
        colour[0] = r;
        colour[1] = g;
        colour[2] = b;
    }

    /**
     * Whether the shadow ray o + t·w, 0 &lt; t &lt; tMax, towards light {@code light} meets a surface
     * ({@link #nearest} finds one). Neighbouring shadow rays to a light are mostly blocked by the
     * same item, so with no planes about (nearest is then the tracer's closest hit) that item is
     * tested first and the walk stops at its first hit ({@link Tracer#blocked}: the same answer).
     */
    private boolean shadowed(int light, double ox, double oy, double oz, double wx, double wy, double wz, double tMax) {
        Tracer t = tracer;
        if (!blockedApplies) return nearest(ox, oy, oz, wx, wy, wz, tMax);
        if (!t.blocked(ox, oy, oz, wx, wy, wz, tMax, lastBlocker[light])) return false;
        lastBlocker[light] = t.blocker;
        return true;
    }

    /**
     * The nearest surface along o + t·d, 0 < t < tMax, into the tracer's hit and ray, with planes
     * one-sided: a plane met from behind (its normal along d) is passed through. {@link #skipped}
     * says how far the returned ray's origin lies along d from o.
     */
    private boolean nearest(double ox, double oy, double oz, double dx, double dy, double dz, double tMax) {
        Tracer t = tracer;
        skipped = 0;
        while (t.closestHit(ox, oy, oz, dx, dy, dz, tMax)) {
            int s = t.hit.shape;
            if (!shapes.isPlane(s)) return true;
            shapes.surface(s, t.hit.face, t.hit.t, t.ray, surface);
            if (surface.nx * dx + surface.ny * dy + surface.nz * dz < 0) return true;
            double step = t.hit.t + Tracer.OFFSET * Math.max(Math.max(Math.abs(surface.px), Math.abs(surface.py)),
                    Math.max(Math.abs(surface.pz), shapes.scale[s]));
            ox += step * dx;
            oy += step * dy;
            oz += step * dz;
            tMax -= step;
            skipped += step;
            if (!(tMax > 0)) return false;
        }
        return false;
    }
}
