package dev.crt.render;

/**
 * One render thread's tracer: finds the nearest surface along a ray (BVH walk plus the unbounded
 * items), shades it by the model of rendering-model.md and follows reflected and refracted rays.
 * All scratch state lives here, so tracing allocates nothing; ray counts are per thread and summed
 * when the render ends.
 *
 * <p>Colours are accumulated rather than returned: trace(ray, weight) adds weight × colour of the
 * ray to the accumulator, which is exact because the colour of a ray is linear in the colours of
 * its reflected and refracted rays.
 */
final class Tracer {
    /**
     * Secondary rays start this far (relative to the hit point's largest coordinate or the
     * primitive's own size, whichever is larger) off the surface along its geometric normal.
     * About 65,000 units in the last place of a double: far above the rounding error of hit
     * points snapped onto their surface, far below any feature of the scene, and the same at
     * every scale, so a scene moved or scaled renders the same picture.
     */
    static final double OFFSET = 0x1p-36;
    /** No item: shape indices are ≥ 0 and CSG trees are ≤ −1. */
    private static final int NONE = Integer.MIN_VALUE;

    private final SceneGeometry geometry;
    private final Shapes shapes;
    private final CsgSolids csg;
    private final double[] materials;
    private final int[] items;
    private final int[] unbounded;
    private final Bvh bvh;
    private final Lights lights;
    private final BackgroundShader background;

    final Ray ray = new Ray();
    private final LineSpan span = new LineSpan();
    final Hit hit = new Hit();
    private final SurfacePoint surface = new SurfacePoint();
    private final CsgSolids.Scratch csgScratch;
    private final BvhWalker walker;
    private final double[] colour = new double[3];
    /**
     * Per light, the last opaque item that blocked it: neighbouring shadow rays usually share their
     * occluder, so testing it first often ends the shadow ray at once. The answer is the same
     * either way, since one opaque crossing makes the shadow factor 0.
     */
    private final int[] lastOccluder;

    double accR, accG, accB;
    long primaryRays, shadowRays, reflectedRays, refractedRays;

    Tracer(SceneGeometry geometry, Lights lights, BackgroundShader background) {
        this.geometry = geometry;
        this.shapes = geometry.shapes;
        this.csg = geometry.csg;
        this.materials = geometry.materials.data;
        this.items = geometry.items;
        this.unbounded = geometry.unbounded;
        this.bvh = geometry.bvh;
        this.lights = lights;
        this.background = background;
        csgScratch = new CsgSolids.Scratch(csg);
        lastOccluder = new int[lights.count];
        java.util.Arrays.fill(lastOccluder, NONE);
        walker = new BvhWalker(bvh == null ? 1 : bvh.depth + 2);
    }

    Shapes shapes() { return shapes; }

    /** Adds (wr, wg, wb) ⊙ trace(o + t·d, depth) to the accumulator. */
    void trace(double ox, double oy, double oz, double dx, double dy, double dz, int depth,
            double wr, double wg, double wb) {
        if (!closestHit(ox, oy, oz, dx, dy, dz, Double.POSITIVE_INFINITY)) {
            background.shade(dx, dy, dz, colour);
            accR += wr * colour[0];
            accG += wg * colour[1];
            accB += wb * colour[2];
            return;
        }
        int s = hit.shape;
        shapes.surface(s, hit.face, hit.t, ray, surface);
        double px = surface.px, py = surface.py, pz = surface.pz;
        double gx = surface.nx, gy = surface.ny, gz = surface.nz;
        if (hit.flip) {
            gx = -gx;
            gy = -gy;
            gz = -gz;
        }
        double dn = dx * gx + dy * gy + dz * gz;
        boolean entering = dn < 0;
        double nx = entering ? gx : -gx, ny = entering ? gy : -gy, nz = entering ? gz : -gz;
        // The shading normal (interpolated on smooth meshes, else the geometric one), turned to
        // the ray's side; the geometric normal keeps deciding entering and the offsets.
        double snx = nx, sny = ny, snz = nz;
        if (surface.shaded) {
            double sign = surface.snx * nx + surface.sny * ny + surface.snz * nz < 0 ? -1 : 1;
            snx = sign * surface.snx;
            sny = sign * surface.sny;
            snz = sign * surface.snz;
        }
        double delta = OFFSET * Math.max(Math.max(Math.abs(px), Math.abs(py)), Math.max(Math.abs(pz), shapes.scale[s]));
        int m = shapes.material[s] * Materials.STRIDE;
        double[] mat = materials;
        double kt = mat[m + Materials.TRANSPARENCY];
        double kr = mat[m + Materials.REFLECTIVITY];
        double local = 1 - kt;
        if (local != 0) {
            if (surface.shaded) {
                shadeLocal(m, surface.lx, surface.ly, surface.lz, nx, ny, nz, snx, sny, snz, -dx, -dy, -dz, delta);
            } else {
                shadeLocal(m, px, py, pz, nx, ny, nz, snx, sny, snz, -dx, -dy, -dz, delta);
            }
            accR += wr * local * colour[0];
            accG += wg * local * colour[1];
            accB += wb * local * colour[2];
        }
        if (depth == 0) return;
        double dDotN = dx * snx + dy * sny + dz * snz;
        double rdx = dx - 2 * dDotN * snx, rdy = dy - 2 * dDotN * sny, rdz = dz - 2 * dDotN * snz;
        if (kr > 0) {
            reflectedRays++;
            trace(px + delta * nx, py + delta * ny, pz + delta * nz, rdx, rdy, rdz, depth - 1, wr * kr, wg * kr, wb * kr);
        }
        if (kt > 0) {
            refractedRays++;
            double eta = entering ? 1 / mat[m + Materials.IOR] : mat[m + Materials.IOR];
            double cosI = -dDotN;
            double k = 1 - eta * eta * (1 - cosI * cosI);
            if (k < 0) {
                trace(px + delta * nx, py + delta * ny, pz + delta * nz, rdx, rdy, rdz, depth - 1, wr * kt, wg * kt, wb * kt);
            } else {
                double c = eta * cosI - Math.sqrt(k);
                trace(px - delta * nx, py - delta * ny, pz - delta * nz,
                        eta * dx + c * snx, eta * dy + c * sny, eta * dz + c * snz, depth - 1, wr * kt, wg * kt, wb * kt);
            }
        }
    }

    /**
     * E + Σℓ aℓ(Cℓ⊙C) + Sℓ·Aℓ·(kd·max(0,N·ω)(Cℓ⊙C) + ks·max(0,R·V)^n·Cℓ) into {@code colour}. A light
     * whose diffuse and specular terms are both zero here casts no shadow ray. N is the shading
     * normal (n); shadow rays start off the surface along the geometric normal (g).
     */
    private void shadeLocal(int m, double px, double py, double pz, double gx, double gy, double gz,
            double nx, double ny, double nz, double vx, double vy, double vz, double delta) {
        double[] mat = materials;
        double cr = mat[m + Materials.R], cg = mat[m + Materials.G], cb = mat[m + Materials.B];
        double kd = mat[m + Materials.DIFFUSE], ks = mat[m + Materials.SPECULAR];
        double shininess = mat[m + Materials.SHININESS];
        double r = mat[m + Materials.ER] + lights.ambientR * cr;
        double g = mat[m + Materials.EG] + lights.ambientG * cg;
        double b = mat[m + Materials.EB] + lights.ambientB * cb;
        double nv = nx * vx + ny * vy + nz * vz;
        Lights l = lights;
        for (int i = 0; i < l.count; i++) {
            double wx, wy, wz, dist, att;
            if (l.parallel[i]) {
                wx = l.x[i];
                wy = l.y[i];
                wz = l.z[i];
                dist = Double.POSITIVE_INFINITY;
                att = 1;
            } else {
                wx = l.x[i] - px;
                wy = l.y[i] - py;
                wz = l.z[i] - pz;
                double d2 = wx * wx + wy * wy + wz * wz;
                dist = Math.sqrt(d2);
                wx /= dist;
                wy /= dist;
                wz /= dist;
                att = l.falloff[i] > 0 ? l.falloff[i] / d2 : 1;
            }
            double nw = nx * wx + ny * wy + nz * wz;
            double diffuse = nw > 0 ? kd * nw : 0;
            double specular = 0;
            if (ks != 0) {
                double rv = 2 * nw * nv - (wx * vx + wy * vy + wz * vz);
                if (rv > 0) specular = ks * power(rv, shininess);
            }
            if (diffuse == 0 && specular == 0) continue;
            double side = nw > 0 ? delta : -delta;
            double ox = px + side * gx, oy = py + side * gy, oz = pz + side * gz;
            double s;
            if (l.parallel[i]) {
                s = transmittance(ox, oy, oz, wx, wy, wz, dist, i);
            } else {
                // Aimed from the moved origin at the light itself and stopped short of it by the same
                // relative margin, so a light lying on a surface is not shadowed by that surface.
                double sx = l.x[i] - ox, sy = l.y[i] - oy, sz = l.z[i] - oz;
                double reach = Math.sqrt(sx * sx + sy * sy + sz * sz);
                double margin = Math.max(delta, OFFSET * Math.max(Math.max(Math.abs(l.x[i]), Math.abs(l.y[i])), Math.abs(l.z[i])));
                s = reach > margin ? transmittance(ox, oy, oz, sx / reach, sy / reach, sz / reach, reach - margin, i) : 1;
            }
            if (s == 0) continue;
            double f = s * att;
            r += f * (diffuse * l.r[i] * cr + specular * l.r[i]);
            g += f * (diffuse * l.g[i] * cg + specular * l.g[i]);
            b += f * (diffuse * l.b[i] * cb + specular * l.b[i]);
        }
        colour[0] = r;
        colour[1] = g;
        colour[2] = b;
    }

    /**
     * x^n, by repeated squaring when n is a small whole number (the usual Phong exponents), which
     * is several times faster than Math.pow and agrees with it to a few units in the last place.
     */
    static double power(double x, double n) {
        int k = (int) n;
        if (k != n || k < 0 || k > 4096) return Math.pow(x, n);
        double result = 1, base = x;
        while (k != 0) {
            if ((k & 1) != 0) result *= base;
            base *= base;
            k >>>= 1;
        }
        return result;
    }

    /** The nearest surface with 0 < t < tMax into {@link #hit}; {@link #ray} keeps the ray for the surface query. */
    boolean closestHit(double ox, double oy, double oz, double dx, double dy, double dz, double tMax) {
        ray.set(ox, oy, oz, dx, dy, dz);
        boolean found = false;
        for (int item : unbounded) {
            if (hitItem(item, tMax)) {
                found = true;
                tMax = hit.t;
            }
        }
        if (bvh == null) {
            for (int item : items) {
                if (hitItem(item, tMax)) {
                    found = true;
                    tMax = hit.t;
                }
            }
            return found;
        }
        BvhWalker walk = walker;
        if (!walk.start(bvh, ray, 0, tMax)) return found;
        for (int leaf = walk.nextNearest(tMax); leaf != BvhWalker.END; leaf = walk.nextNearest(tMax)) {
            for (int k = Bvh.leafFirst(leaf), end = k + Bvh.leafCount(leaf); k < end; k++) {
                if (hitItem(items[k], tMax)) {
                    found = true;
                    tMax = hit.t;
                }
            }
        }
        return found;
    }

    private boolean hitItem(int item, double tMax) {
        if (item < 0) return csg.closestHit(-item - 1, ray, tMax, shapes, geometry.materials, span, csgScratch, hit);
        if (!shapes.span(item, ray, span)) return false;
        for (int i = 0; i < span.count; i++) {
            double t;
            int face;
            if (span.tIn[i] > 0) {
                t = span.tIn[i];
                face = span.faceIn[i];
            } else if (span.tOut[i] > 0) {
                t = span.tOut[i];
                face = span.faceOut[i];
            } else {
                continue;
            }
            if (!(t < tMax)) return false;
            hit.t = t;
            hit.shape = item;
            hit.face = face;
            hit.flip = false;
            return true;
        }
        return false;
    }

    /**
     * The shadow factor of the segment o + t·w, 0 < t < tMax: the product of kt over every surface
     * it crosses, stopping at the first opaque one.
     */
    double transmittance(double ox, double oy, double oz, double wx, double wy, double wz, double tMax, int light) {
        shadowRays++;
        ray.set(ox, oy, oz, wx, wy, wz);
        int cached = lastOccluder[light];
        if (cached != NONE && itemTransmittance(cached, tMax) == 0) return 0;
        double product = 1;
        for (int item : unbounded) {
            product *= itemTransmittance(item, tMax);
            if (product == 0) return blockedBy(light, item);
        }
        if (bvh == null) {
            for (int item : items) {
                product *= itemTransmittance(item, tMax);
                if (product == 0) return blockedBy(light, item);
            }
            return product;
        }
        BvhWalker walk = walker;
        if (!walk.start(bvh, ray, 0, tMax)) return product;
        for (int leaf = walk.nextAny(tMax); leaf != BvhWalker.END; leaf = walk.nextAny(tMax)) {
            for (int k = Bvh.leafFirst(leaf), end = k + Bvh.leafCount(leaf); k < end; k++) {
                product *= itemTransmittance(items[k], tMax);
                if (product == 0) return blockedBy(light, items[k]);
            }
        }
        return product;
    }

    private double blockedBy(int light, int item) {
        lastOccluder[light] = item;
        return 0;
    }

    private double itemTransmittance(int item, double tMax) {
        if (item < 0) {
            return csg.transmittance(-item - 1, ray, tMax, shapes, geometry.materials, span, csgScratch);
        }
        if (!shapes.span(item, ray, span)) return 1;
        int crossings = 0;
        for (int i = 0; i < span.count; i++) {
            if (span.tIn[i] > 0 && span.tIn[i] < tMax) crossings++;
            if (span.tOut[i] > 0 && span.tOut[i] < tMax && !span.surface) crossings++;
        }
        if (crossings == 0) return 1;
        double kt = materials[shapes.material[item] * Materials.STRIDE + Materials.TRANSPARENCY];
        double product = kt;
        for (int k = 1; k < crossings; k++) product *= kt;
        return product;
    }
}
