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
    static final int NONE = Integer.MIN_VALUE;

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
    /** Null without a BVH. */
    final Candidates candidates;
    /** Set by the pixel sampler: the next ray traced is a camera ray of the current block of {@link #candidates}. */
    boolean blockRay;
    /** The shape whose surface is being shaded (its shadow rays may take its list), or {@link #NONE}. */
    int shading = NONE;
    /** The face of {@link #shading}'s surface being shaded. */
    int shadingFace;
    /** Set before a mirror-reflected ray is traced: the shape (and face) it leaves, whose list of {@link #candidates} it may take; else {@link #NONE}. */
    private int reflectedFrom = NONE, reflectedFace;
    /** Shadow rays that walked the BVH, and the items they tested (weighed as {@link Candidates#weight}). */
    private int walks, tested;
    /** The item that made the last {@link #blocked} true. */
    int blocker = NONE;

    private final PhongShading phong;
    /** Null unless some material shades with the Gooch model. */
    private final GoochShading gooch;
    /** The generator of the lights' random choices (area light jitter), seeded per pixel. */
    final PixelRandom lightRandom = new PixelRandom();
    /** Keeps the lights' stream apart from the pixel sampler's, which is seeded from the same pixel. */
    private static final long LIGHT_STREAM = 0x4c69676874734c6cL;
    /** Whether some material is glossy (roughness > 0): only then is the lobes' generator seeded. */
    private final boolean glossy;
    /** The generator of glossy lobe directions, seeded per pixel apart from the lights' stream. */
    private final PixelRandom glossRandom = new PixelRandom();
    private static final long GLOSS_STREAM = 0x476c6f7373794c62L;
    /** Whether the current ray descends from a sampled lobe: lobes below it take one sample. */
    private boolean insideLobe;
    /** Whether some material has a texture: only then do rays carry a footprint (a ray cone). */
    final boolean footprints;
    /** The ray cone's spread (radians) of the current camera ray, set by the pixel sampler when {@link #footprints}. */
    double spread;
    /** The length of the ray path from the camera to the current ray's origin: the cone's width there is spread × it. */
    private double travelled;
    private final TextureShading textured;
    /** Whether some material absorbs (Beer's law): only then do rays and shadow rays track distances inside solids. */
    final boolean absorbing;
    /** The optical depth a·s per channel gathered by the current shadow ray. */
    private double depthR, depthG, depthB;
    /** The Beer's-law factors exp(−a·s) of the last {@link #shadow} ray, when {@link #absorbing}. */
    double shadowR = 1, shadowG = 1, shadowB = 1;

    /** The pixel's sum so far: each ray adds its weight times its colour. */
    double accR, accG, accB;
    /**
     * Whether tracing may stop once the pixel's sum reaches 1 in every channel ({@link Renderer#forClampedOutput}
     * on a scene whose colours are all non-negative, so that the sum only grows): such a pixel is
     * white in the file whatever else it would add.
     */
    boolean saturating;
    /** The weights (wr, wg, wb)·(1 − kt) of the local colour being shaded: what it is added to the sum with, and what {@link PhongShading} tests the sum with. */
    double localR, localG, localB;
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
        candidates = bvh == null ? null : new Candidates(bvh, items, shapes, lights);
        absorbing = geometry.materials.absorbing();
        csgScratch.absorbing = absorbing;
        footprints = !geometry.materials.textures.isEmpty();
        glossy = geometry.materials.glossy();
        textured = footprints ? new TextureShading(shapes, materials, geometry.materials.prepared()) : null;
        phong = new PhongShading(this, materials, lights);
        gooch = geometry.materials.gooch() ? new GoochShading(materials, lights, lightRandom) : null;
    }

    Shapes shapes() { return shapes; }

    /** The BVH's items in its order (shape index ≥ 0, or −1 − tree for a CSG tree). */
    int[] items() { return items; }

    /** Adds (wr, wg, wb) ⊙ trace(o + t·d, depth) to the accumulator. */
    void trace(double ox, double oy, double oz, double dx, double dy, double dz, int depth,
            double wr, double wg, double wb) {
        boolean block = blockRay;
        blockRay = false;
        int from = reflectedFrom;
        reflectedFrom = NONE;
        if (saturating && saturated()) return;
        if (!(block ? blockHit(ox, oy, oz, dx, dy, dz)
                : from != NONE ? reflectedHit(from, reflectedFace, ox, oy, oz, dx, dy, dz)
                : closestHit(ox, oy, oz, dx, dy, dz, Double.POSITIVE_INFINITY))) {
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
        if (Features.SHAPES && surface.shaded) {
            double sign = surface.snx * nx + surface.sny * ny + surface.snz * nz < 0 ? -1 : 1;
            snx = sign * surface.snx;
            sny = sign * surface.sny;
            snz = sign * surface.snz;
        }
        double delta = OFFSET * Math.max(Math.max(Math.abs(px), Math.abs(py)), Math.max(Math.abs(pz), shapes.scale[s]));
        int m = shapes.material[s] * Materials.STRIDE;
        double[] mat = materials;
        if (Features.ABSORPTION && !entering && absorbing) {
            // The segment just travelled lay inside this surface's solid: Beer's law over its length.
            double t = hit.t;
            wr *= Math.exp(-mat[m + Materials.AR] * t);
            wg *= Math.exp(-mat[m + Materials.AG] * t);
            wb *= Math.exp(-mat[m + Materials.AB] * t);
        }
        double kt = mat[m + Materials.TRANSPARENCY];
        double kr = mat[m + Materials.REFLECTIVITY];
        double ks = mat[m + Materials.SPECULAR];
        double cr = mat[m + Materials.R], cg = mat[m + Materials.G], cb = mat[m + Materials.B];
        double er = mat[m + Materials.ER], eg = mat[m + Materials.EG], eb = mat[m + Materials.EB];
        double start = Features.TEXTURES ? travelled : 0;
        if (Features.TEXTURES && mat[m + Materials.TEXTURED] != 0) {
            TextureShading ts = textured;
            // The cone's width where it meets the surface, stretched by the slant (a grazing ray covers a long strip).
            double width = spread * (start + hit.t) / Math.max(Math.abs(dn), 1e-9);
            ts.shade(s, hit.face, m, surface, gx, gy, gz, snx, sny, snz, width, delta);
            kt = ts.kt;
            kr = ts.kr;
            ks = ts.ks;
            cr = ts.cr;
            cg = ts.cg;
            cb = ts.cb;
            er = ts.er;
            eg = ts.eg;
            eb = ts.eb;
            snx = ts.snx;
            sny = ts.sny;
            snz = ts.snz;
        }
        double local = 1 - kt;
        if (local != 0) {
            // On smooth meshes the lights are looked at from the shading point and along the shading
            // normal; shadow rays still leave along the geometric normal.
            shading = s;
            shadingFace = hit.face;
            localR = wr * local;
            localG = wg * local;
            localB = wb * local;
            if (Features.GOOCH && gooch != null && mat[m + Materials.MODEL] == Materials.GOOCH) {
                gooch.shade(m, cr, cg, cb, ks, er, eg, eb, px, py, pz, snx, sny, snz, -dx, -dy, -dz, colour);
            } else if (Features.SHAPES && surface.shaded) {
                phong.shade(m, cr, cg, cb, ks, er, eg, eb, surface.lx, surface.ly, surface.lz, nx, ny, nz, snx, sny, snz,
                        -dx, -dy, -dz, delta, colour);
            } else {
                phong.shade(m, cr, cg, cb, ks, er, eg, eb, px, py, pz, nx, ny, nz, snx, sny, snz, -dx, -dy, -dz, delta,
                        colour);
            }
            shading = NONE;
            accR += localR * colour[0];
            accG += localG * colour[1];
            accB += localB * colour[2];
        }
        if (depth == 0 || kr == 0 && kt == 0) return;
        if (Features.TEXTURES) travelled = start + hit.t;
        // The reflected and refracted rays are traced from here rather than from a helper: deep
        // mirror recursion then costs one stack frame per bounce (a glossy lobe adds one).
        double rough = Features.GLOSSY ? mat[m + Materials.ROUGHNESS] : 0;
        int samples = Features.GLOSSY ? (int) mat[m + Materials.GLOSSY_SAMPLES] : 1;
        // Mirror and refraction directions follow the shading normal; the offsets, the geometric one.
        double dDotN = dx * snx + dy * sny + dz * snz;
        double rdx = dx - 2 * dDotN * snx, rdy = dy - 2 * dDotN * sny, rdz = dz - 2 * dDotN * snz;
        if (Features.FRESNEL && kt > 0 && mat[m + Materials.FRESNEL] != 0) {
            fresnel(px, py, pz, dx, dy, dz, nx, ny, nz, snx, sny, snz, rdx, rdy, rdz, entering, delta, depth, kr, kt,
                    mat[m + Materials.IOR], rough, samples, wr, wg, wb);
            if (Features.TEXTURES) travelled = start;
            return;
        }
        if (kr > 0) {
            if (rough == 0) {
                reflectedRays++;
                if (candidates != null) {
                    reflectedFrom = s;
                    reflectedFace = hit.face;
                }
                trace(px + delta * nx, py + delta * ny, pz + delta * nz, rdx, rdy, rdz, depth - 1, wr * kr, wg * kr, wb * kr);
            } else {
                spawn(px, py, pz, rdx, rdy, rdz, nx, ny, nz, delta, depth, rough, samples, wr * kr, wg * kr, wb * kr);
            }
        }
        if (kt > 0) {
            double eta = entering ? 1 / mat[m + Materials.IOR] : mat[m + Materials.IOR];
            double cosI = -dDotN;
            double k = 1 - eta * eta * (1 - cosI * cosI);
            if (k < 0) {
                if (rough == 0) {
                    refractedRays++;
                    trace(px + delta * nx, py + delta * ny, pz + delta * nz, rdx, rdy, rdz, depth - 1, wr * kt, wg * kt, wb * kt);
                } else {
                    spawn(px, py, pz, rdx, rdy, rdz, nx, ny, nz, delta, depth, rough, samples, wr * kt, wg * kt, wb * kt);
                }
            } else {
                double c = eta * cosI - Math.sqrt(k);
                if (rough == 0) {
                    refractedRays++;
                    trace(px - delta * nx, py - delta * ny, pz - delta * nz, eta * dx + c * snx, eta * dy + c * sny,
                            eta * dz + c * snz, depth - 1, wr * kt, wg * kt, wb * kt);
                } else {
                    spawn(px, py, pz, eta * dx + c * snx, eta * dy + c * sny, eta * dz + c * snz, nx, ny, nz, -delta, depth,
                            rough, samples, wr * kt, wg * kt, wb * kt);
                }
            }
        }
        if (Features.TEXTURES) travelled = start;
    }

    /** Whether the pixel's sum has reached 1 in every channel: with {@link #saturating}, the pixel is finished. */
    boolean saturated() {
        return accR >= 1 && accG >= 1 && accB >= 1;
    }

    /**
     * The reflected and refracted terms of a {@code fresnel -> true} material:
     * kt·(Fr·trace(reflected) + (1 − Fr)·trace(refracted)) + kr·trace(reflected), Fr = 1 under total
     * internal reflection; the two reflected terms share one ray. The angles come from the shading
     * normal s; the rays leave along the geometric normal n.
     */
    private void fresnel(double px, double py, double pz, double dx, double dy, double dz, double nx, double ny, double nz,
            double sx, double sy, double sz, double rdx, double rdy, double rdz, boolean entering, double delta, int depth,
            double kr, double kt, double ior, double rough, int samples, double wr, double wg, double wb) {
        double eta = entering ? 1 / ior : ior;
        double cosI = -(dx * sx + dy * sy + dz * sz);
        double k = 1 - eta * eta * (1 - cosI * cosI);
        double cosT = k < 0 ? 0 : Math.sqrt(k);
        double fr = k < 0 ? 1 : Fresnel.reflectance(cosI, cosT, eta);
        double reflect = kr + kt * fr, refract = kt * (1 - fr);
        if (reflect > 0) {
            spawn(px, py, pz, rdx, rdy, rdz, nx, ny, nz, delta, depth, rough, samples, wr * reflect, wg * reflect, wb * reflect);
        }
        if (refract > 0) {
            double c = eta * cosI - cosT;
            spawn(px, py, pz, eta * dx + c * sx, eta * dy + c * sy, eta * dz + c * sz, nx, ny, nz, -delta, depth, rough, samples,
                    wr * refract, wg * refract, wb * refract);
        }
    }

    /**
     * Traces the secondary ray leaving p along r on the side {@code side} of the ray-facing
     * geometric normal n (side = +delta: reflected, −delta: refracted). With roughness ρ > 0 it is
     * spread over a lobe instead: {@code samples} directions (one inside a lobe already being
     * sampled, so cost grows linearly with depth, not exponentially) drawn uniformly from the cone of
     * half-angle ρ·90° about r, stratified in cos θ, each turned back across the tangent plane when it
     * points to the wrong side, each weighted 1/samples.
     */
    private void spawn(double px, double py, double pz, double rx, double ry, double rz, double nx, double ny, double nz,
            double side, int depth, double rough, int samples, double wr, double wg, double wb) {
        if (side > 0) reflectedRays++;
        else refractedRays++;
        double ox = px + side * nx, oy = py + side * ny, oz = pz + side * nz;
        if (rough == 0) {
            trace(ox, oy, oz, rx, ry, rz, depth - 1, wr, wg, wb);
            return;
        }
        int n = insideLobe ? 1 : samples;
        boolean outer = !insideLobe;
        insideLobe = true;
        // An orthonormal frame (a, b, r) about the lobe's axis.
        double ax, ay, az;
        if (Math.abs(rx) < 0.9) {
            ax = 0;
            ay = rz;
            az = -ry;
        } else {
            ax = -rz;
            ay = 0;
            az = rx;
        }
        double al = Math.sqrt(ax * ax + ay * ay + az * az);
        ax /= al;
        ay /= al;
        az /= al;
        double bx = ry * az - rz * ay, by = rz * ax - rx * az, bz = rx * ay - ry * ax;
        double cosMax = Math.cos(rough * Math.PI / 2);
        double w = 1.0 / n;
        double sign = side > 0 ? 1 : -1;
        for (int k = 0; k < n; k++) {
            if (k > 0) {
                if (side > 0) reflectedRays++;
                else refractedRays++;
            }
            double cos = 1 - (k + glossRandom.next()) / n * (1 - cosMax);
            double sin = Math.sqrt(Math.max(0, 1 - cos * cos));
            double phi = 2 * Math.PI * glossRandom.next();
            double ca = sin * Math.cos(phi), cb = sin * Math.sin(phi);
            double gx = ca * ax + cb * bx + cos * rx, gy = ca * ay + cb * by + cos * ry, gz = ca * az + cb * bz + cos * rz;
            double across = sign * (gx * nx + gy * ny + gz * nz);
            if (across < 0) {
                gx -= 2 * sign * across * nx;
                gy -= 2 * sign * across * ny;
                gz -= 2 * sign * across * nz;
            }
            trace(ox, oy, oz, gx, gy, gz, depth - 1, wr * w, wg * w, wb * w);
        }
        if (outer) insideLobe = false;
    }

    /**
     * The shadow factor Sℓ of light sample {@code ls} seen from p: the shadow ray leaves p moved by
     * {@code side} along n (to the side the light is on) and is aimed at the sample's point, stopped
     * short of it by the same relative margin, so a light lying on a surface is not shadowed by that
     * surface. With absorbing materials in the scene, {@link #shadowR}, G, B hold the ray's
     * Beer's-law factors.
     */
    double shadow(LightSample ls, double px, double py, double pz, double nx, double ny, double nz, double side, int light) {
        double ox = px + side * nx, oy = py + side * ny, oz = pz + side * nz;
        if (ls.finite) return shadowTo(ox, oy, oz, ls.tx, ls.ty, ls.tz, side, light);
        if (Features.ABSORPTION && absorbing) {
            depthR = 0;
            depthG = 0;
            depthB = 0;
        }
        double s = listedTransmittance(ox, oy, oz, ls.wx, ls.wy, ls.wz, Double.POSITIVE_INFINITY, light,
                lights.kind[light] == Lights.PARALLEL);
        if (Features.ABSORPTION && absorbing) absorbed();
        return s;
    }

    /** The shadow factor of the segment from o (already moved off the surface by {@code side}) to the light point q. */
    double shadowTo(double ox, double oy, double oz, double qx, double qy, double qz, double side, int light) {
        if (Features.ABSORPTION && absorbing) {
            depthR = 0;
            depthG = 0;
            depthB = 0;
        }
        double sx = qx - ox, sy = qy - oy, sz = qz - oz;
        double reach = Math.sqrt(sx * sx + sy * sy + sz * sz);
        double margin = Math.max(Math.abs(side), OFFSET * Math.max(Math.max(Math.abs(qx), Math.abs(qy)), Math.abs(qz)));
        double s = reach > margin ? listedTransmittance(ox, oy, oz, sx / reach, sy / reach, sz / reach, reach - margin, light,
                qx == lights.x[light] && qy == lights.y[light] && qz == lights.z[light] && lights.kind[light] != Lights.PARALLEL)
                : 1;
        if (Features.ABSORPTION && absorbing) absorbed();
        return s;
    }

    /**
     * {@link #transmittance} through the shadow list of the shape being shaded and this light, when
     * {@code listable} (the ray aims at a point light's own point, or along a parallel light) and
     * {@link #candidates} has one for the ray's origin; else by the walk, whose cost the list's
     * trial is told.
     */
    private double listedTransmittance(double ox, double oy, double oz, double wx, double wy, double wz, double tMax, int light,
            boolean listable) {
        if (!listable || shading == NONE || candidates == null) return transmittance(ox, oy, oz, wx, wy, wz, tMax, light, -1);
        int list = candidates.shadow(shading, shadingFace, light, ox, oy, oz);
        if (list >= 0) return transmittance(ox, oy, oz, wx, wy, wz, tMax, light, list);
        int walks = this.walks, tested = this.tested + walker.anySteps;
        double s = transmittance(ox, oy, oz, wx, wy, wz, tMax, light, -1);
        candidates.walked(this.walks - walks, this.tested + walker.anySteps - tested);
        return s;
    }

    private void absorbed() {
        shadowR = Math.exp(-depthR);
        shadowG = Math.exp(-depthG);
        shadowB = Math.exp(-depthB);
    }

    /** Seeds the light generator for pixel (i, j) and pass {@code pass}, when some light needs one. */
    void startPixel(int i, int j, long seed, int pass) {
        if (Features.LIGHTS && lights.random) lightRandom.seed(i, j, seed ^ (LIGHT_STREAM + pass));
        if (Features.GLOSSY && glossy) glossRandom.seed(i, j, seed ^ (GLOSS_STREAM + pass));
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
        return closestHit(ox, oy, oz, dx, dy, dz, tMax, false);
    }

    /** {@link #closestHit}; with {@code count}, adding the items it tests to {@link #tested}, weighed as {@link Candidates#weight}. */
    private boolean closestHit(double ox, double oy, double oz, double dx, double dy, double dz, double tMax, boolean count) {
        ray.set(ox, oy, oz, dx, dy, dz);
        boolean found = unboundedHit(tMax);
        if (found) tMax = hit.t;
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
                if (count) tested += candidates.weight(items[k]);
                if (hitItem(items[k], tMax)) {
                    found = true;
                    tMax = hit.t;
                }
            }
        }
        return found;
    }

    /** The nearest of the unbounded items with 0 < t < tMax into {@link #hit}, for the ray in {@link #ray}. */
    private boolean unboundedHit(double tMax) {
        boolean found = false;
        for (int item : unbounded) {
            if (hitItem(item, tMax)) {
                found = true;
                tMax = hit.t;
            }
        }
        return found;
    }

    /**
     * {@link #closestHit} (tMax = +∞) of a camera ray of the current block of {@link #candidates}:
     * its list holds every item the block's rays can meet, nearest lower bound first, so the same
     * hit is found (where two items give exactly the same t, the one listed first).
     */
    boolean blockHit(double ox, double oy, double oz, double dx, double dy, double dz) {
        ray.set(ox, oy, oz, dx, dy, dz);
        double tMax = Double.POSITIVE_INFINITY;
        boolean found = unboundedHit(tMax);
        if (found) tMax = hit.t;
        Candidates c = candidates;
        int[] list = c.blockItems;
        double[] near = c.blockNear;
        for (int k = 0, n = c.blockCount; k < n && near[k] < tMax; k++) {
            if (mayMeet(list[k], tMax) && hitItem(list[k], tMax)) {
                found = true;
                tMax = hit.t;
            }
        }
        return found;
    }

    /**
     * {@link #closestHit} (tMax = +∞) of a mirror-reflected ray leaving {@code shape}'s face
     * {@code face}: through the list of {@link #candidates} for it when there is one (every item the
     * ray can meet, nearest lower bound first, so the same hit is found; where two items give exactly
     * the same t, the one listed first), else by the walk, whose cost the list's trial is told.
     */
    boolean reflectedHit(int shape, int face, double ox, double oy, double oz, double dx, double dy, double dz) {
        Candidates c = candidates;
        int list = c.reflected(shape, face, ox, oy, oz, dx, dy, dz);
        if (list < 0) {
            int steps = walker.nearestSteps, tested = this.tested;
            boolean found = closestHit(ox, oy, oz, dx, dy, dz, Double.POSITIVE_INFINITY, c.onTrial());
            c.walked(1, walker.nearestSteps - steps + this.tested - tested);
            return found;
        }
        ray.set(ox, oy, oz, dx, dy, dz);
        double tMax = Double.POSITIVE_INFINITY;
        boolean found = unboundedHit(tMax);
        if (found) tMax = hit.t;
        int[] items = c.pool;
        double[] near = c.near;
        for (int k = list + 1, end = k + items[list]; k < end && near[k] < tMax; k++) {
            if (mayMeet(items[k], tMax) && hitItem(items[k], tMax)) {
                found = true;
                tMax = hit.t;
            }
        }
        return found;
    }

    /**
     * Whether {@link #closestHit} finds any surface along o + t·w, 0 &lt; t &lt; tMax (the 2015 model's
     * shadow rays, in scenes without unbounded items), found sooner: item {@code cached} first (the
     * caller's last blocker, or {@link #NONE}), then the same walk stopped at its first hit rather
     * than narrowed to the nearest. Leaves {@link #blocker} the item that answered.
     *
     * <p>The same answer as closestHit's: until something is found its far end stays tMax, so the
     * leaves it would visit are fixed (those whose boxes pass the walk's tests, less the farther
     * child of a pair when it is entered at or beyond tMax) and it finds something iff one of their
     * items is hit before tMax, in whatever order. The cached item is tested with a far end shorter
     * by 2⁻⁴⁰ of tMax, so the boxes around a hit it reports are entered well before tMax (none of
     * them is culled) and, as every walk takes for granted of an item's hit point and its boxes'
     * widened tests, pass those tests: its leaf is among those visited.
     */
    boolean blocked(double ox, double oy, double oz, double wx, double wy, double wz, double tMax, int cached) {
        ray.set(ox, oy, oz, wx, wy, wz);
        if (cached != NONE && hitItem(cached, tMax * (1 - 0x1p-40))) {
            blocker = cached;
            return true;
        }
        BvhWalker walk = walker;
        if (!walk.start(bvh, ray, 0, tMax)) return false;
        for (int leaf = walk.nextNearest(tMax); leaf != BvhWalker.END; leaf = walk.nextNearest(tMax)) {
            for (int k = Bvh.leafFirst(leaf), end = k + Bvh.leafCount(leaf); k < end; k++) {
                if (hitItem(items[k], tMax)) {
                    blocker = items[k];
                    return true;
                }
            }
        }
        return false;
    }

    /** Whether {@link #blocked} can stand for closestHit: a BVH and no unbounded items (the 2015 model's planes are one-sided). */
    boolean blockedApplies() {
        return bvh != null && unbounded.length == 0;
    }

    /**
     * False only when the segment 0 < t < tMax of {@link #ray} misses the box of {@code item} (a
     * box is its own; a CSG tree's bounds), by the widened slab test of a BVH walk: the item then
     * has no hit and the factor 1 there. A list tests each item's box first, as the walk tests a
     * leaf's: most of a list's items are missed, and this is a fraction of their own tests.
     */
    private boolean mayMeet(int item, double tMax) {
        if (item < 0) return csg.mayMeet(-item - 1, ray, tMax);
        return shapes.kind[item] != Shapes.BOX || ray.enters(shapes.data, shapes.offset[item], 0, tMax);
    }

    private boolean hitItem(int item, double tMax) {
        if (item < 0) return csg.closestHit(-item - 1, ray, tMax, shapes, geometry.materials, span, csgScratch, hit);
        return shapes.firstHit(item, ray, tMax, span, hit);
    }

    /**
     * The shadow factor of the segment o + t·w, 0 < t < tMax: the product of kt over every surface
     * it crosses, stopping at the first opaque one. With a shadow list of {@link #candidates} ({@code list}
     * ≥ 0, one holding every item the segment can meet) its items are tested instead of walking: they
     * are in the walk's leaf order, and an item the segment does not cross gives the factor 1, so the
     * product is the walk's to the bit.
     */
    double transmittance(double ox, double oy, double oz, double wx, double wy, double wz, double tMax, int light, int list) {
        shadowRays++;
        ray.set(ox, oy, oz, wx, wy, wz);
        int cached = lastOccluder[light];
        // A list holds every item the segment can meet: an occluder not in it is not tested. When
        // it does not block, its factor stands in for its test in the loops below (the same
        // product, and its absorption counted once).
        double cachedFactor = -1;
        if (cached != NONE && (list < 0 || listed(list, cached))) {
            cachedFactor = itemTransmittance(cached, tMax);
            if (cachedFactor == 0) return 0;
        } else {
            cached = NONE;
        }
        double product = 1;
        for (int item : unbounded) {
            product *= item == cached ? cachedFactor : itemTransmittance(item, tMax);
            if (product == 0) return blockedBy(light, item);
        }
        if (bvh == null) {
            for (int item : items) {
                product *= item == cached ? cachedFactor : itemTransmittance(item, tMax);
                if (product == 0) return blockedBy(light, item);
            }
            return product;
        }
        if (list >= 0) {
            int[] pool = candidates.pool;
            for (int k = list + 1, end = k + pool[list]; k < end; k++) {
                int item = pool[k];
                // An item whose box the segment misses has the factor 1 (× 1 keeps the product's bits).
                if (item != cached && !mayMeet(item, tMax)) continue;
                product *= item == cached ? cachedFactor : itemTransmittance(item, tMax);
                if (product == 0) return blockedBy(light, item);
            }
            return product;
        }
        BvhWalker walk = walker;
        walks++;
        if (!walk.start(bvh, ray, 0, tMax)) return product;
        for (int leaf = walk.nextAny(tMax); leaf != BvhWalker.END; leaf = walk.nextAny(tMax)) {
            for (int k = Bvh.leafFirst(leaf), end = k + Bvh.leafCount(leaf); k < end; k++) {
                int item = items[k];
                tested += candidates.weight(item);
                product *= item == cached ? cachedFactor : itemTransmittance(item, tMax);
                if (product == 0) return blockedBy(light, item);
            }
        }
        return product;
    }

    /** Adds the optical depth of the segment's stretches inside the solid of {@link #span}, of material m. */
    private void absorb(int m, double tMax) {
        double inside = 0;
        for (int i = 0; i < span.count; i++) {
            double a = Math.max(span.tIn[i], 0), b = Math.min(span.tOut[i], tMax);
            if (b > a) inside += b - a;
        }
        depthR += materials[m + Materials.AR] * inside;
        depthG += materials[m + Materials.AG] * inside;
        depthB += materials[m + Materials.AB] * inside;
    }

    /** Whether the list at {@code list} of {@link Candidates#pool} holds {@code item}. */
    private boolean listed(int list, int item) {
        int[] pool = candidates.pool;
        for (int k = list + 1, end = k + pool[list]; k < end; k++) if (pool[k] == item) return true;
        return false;
    }

    private double blockedBy(int light, int item) {
        lastOccluder[light] = item;
        return 0;
    }

    private double itemTransmittance(int item, double tMax) {
        if (item < 0) {
            if (!Features.ABSORPTION || !absorbing) return csg.transmittance(-item - 1, ray, tMax, shapes, geometry.materials, span, csgScratch);
            CsgSolids.Scratch sc = csgScratch;
            sc.depthR = 0;
            sc.depthG = 0;
            sc.depthB = 0;
            double kt = csg.transmittance(-item - 1, ray, tMax, shapes, geometry.materials, span, sc);
            depthR += sc.depthR;
            depthG += sc.depthG;
            depthB += sc.depthB;
            return kt;
        }
        int m = shapes.material[item] * Materials.STRIDE;
        if (materials[m + Materials.TRANSPARENCY] == 0 && (!Features.TEXTURES || materials[m + Materials.TEX_TRANSPARENCY] == 0)) {
            return shapes.anyHit(item, ray, tMax, span) ? 0 : 1;
        }
        if (!shapes.span(item, ray, span)) return 1;
        int crossings = 0;
        for (int i = 0; i < span.count; i++) {
            if (span.tIn[i] > 0 && span.tIn[i] < tMax) crossings++;
            if (span.tOut[i] > 0 && span.tOut[i] < tMax && !span.surface) crossings++;
        }
        if (crossings == 0) return 1;
        if (Features.TEXTURES && materials[m + Materials.TEX_TRANSPARENCY] != 0) return texturedTransmittance(item, m, tMax);
        double kt = materials[m + Materials.TRANSPARENCY];
        if (Features.ABSORPTION && absorbing && kt != 0 && !span.surface) absorb(m, tMax);
        double product = kt;
        for (int k = 1; k < crossings; k++) product *= kt;
        return product;
    }

    /** As {@link #itemTransmittance} for a material whose transparency is a texture: kt read at each crossing of {@link #span}. */
    private double texturedTransmittance(int item, int m, double tMax) {
        if (absorbing && !span.surface) absorb(m, tMax);
        double product = 1;
        // The crossings are read before transparencyAt reuses the ray's scratch.
        for (int i = 0; i < span.count && product != 0; i++) {
            double in = span.tIn[i], out = span.tOut[i];
            int faceIn = span.faceIn[i], faceOut = span.faceOut[i];
            boolean open = span.surface;
            if (in > 0 && in < tMax) product *= textured.transparencyAt(item, faceIn, m, in, ray);
            if (!open && out > 0 && out < tMax && product != 0) product *= textured.transparencyAt(item, faceOut, m, out, ray);
        }
        return product;
    }
}
