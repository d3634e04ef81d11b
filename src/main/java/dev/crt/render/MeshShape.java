package dev.crt.render;

import dev.crt.geom.Aabb;
import dev.crt.geom.Transform;
import dev.crt.scene.Mesh;

/**
 * Triangle meshes: an instance is its {@link Affine} placement and the index of its shared
 * {@link MeshGeometry} in {@link Shapes#meshes}; the ray goes into the mesh's coordinates and
 * walks the mesh's own BVH (the second level under the scene's). For CSG every crossing along the
 * line is found ({@link #span}); a closed mesh's inside is where the line has crossed an odd number
 * of times, an open mesh is a surface (each crossing one point). A mesh standing alone stops at its
 * nearest triangle ({@link #firstHit}) or at any triangle in the shadow ray's segment ({@link #anyHit}).
 *
 * <p>The ray–triangle test is the watertight one of Woop, Benthin and Wald (JCGT 2013): the
 * vertices are sheared into the ray's frame and the three edge functions are products of the
 * same doubles for both triangles that share an edge, so their signs agree exactly and no ray
 * slips between neighbours. A ray exactly on a shared edge or vertex (an edge function exactly 0)
 * is given to exactly one triangle by the top-left rule of rasterisers, applied in each
 * triangle's counter-clockwise orientation seen along the ray: a crossing is never counted twice,
 * which the inside test by parity needs.
 *
 * <p>A face number is 2·triangle + flip, flip set when the triangle's winding normal points into
 * a closed mesh there (so meshes wound either way are solids with outward normals).
 *
 * <p>Data after the placement: the mesh index, smooth (1 or 0).
 */
final class MeshShape {
    private MeshShape() {}

    static void add(Shapes out, int s, Mesh m, Transform t) {
        MeshGeometry g = out.mesh(m.data());
        if (g.count == 0) {
            // Every triangle had no area: nothing to hit.
            out.kind[s] = Shapes.EMPTY;
            return;
        }
        out.kind[s] = Shapes.MESH;
        out.pushMatrices(t);
        out.push(out.meshIndex(g), m.smooth() ? 1 : 0);
        Aabb b = out.bounds(s);
        out.scale[s] = Math.max(Shapes.maxAbs(b.min()), Shapes.maxAbs(b.max()));
    }

    static Aabb bounds(double[] a, int o, MeshGeometry g) {
        Aabb b = g.bounds;
        return Affine.bounds(a, o, b.min().x(), b.min().y(), b.min().z(), b.max().x(), b.max().y(), b.max().z());
    }

    static boolean span(double[] a, int o, Ray ray, LineSpan out, MeshGeometry g) {
        LineSpan.Crossings c = shear(a, o, ray, out);
        c.count = 0;
        if (g.bvh == null) {
            for (int t = 0; t < g.count; t++) triangle(g, t, c);
        } else {
            BvhWalker walk = c.walker(g.bvh.depth + 2);
            if (walk.start(g.bvh, local(ray, c), Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY)) {
                for (int leaf = walk.nextAny(Double.POSITIVE_INFINITY); leaf != BvhWalker.END;
                        leaf = walk.nextAny(Double.POSITIVE_INFINITY)) {
                    for (int t = Bvh.leafFirst(leaf), end = t + Bvh.leafCount(leaf); t < end; t++) triangle(g, t, c);
                }
            }
        }
        int n = c.count;
        if (n == 0) return false;
        c.sort();
        out.count = 0;
        if (!g.closed) {
            out.surface = true;
            for (int i = 0; i < n; i++) out.add(c.t[i], c.t[i], 2 * c.triangle[i], 2 * c.triangle[i]);
            return true;
        }
        out.surface = false;
        // Entering where the parity turns odd: the outward normal must face the ray there.
        for (int i = 0; i + 1 < n; i += 2) {
            int in = 2 * c.triangle[i] + (c.facing[i] > 0 ? 1 : 0);
            int leave = 2 * c.triangle[i + 1] + (c.facing[i + 1] < 0 ? 1 : 0);
            out.add(c.t[i], c.t[i + 1], in, leave);
        }
        return out.count > 0;
    }

    /**
     * The nearest crossing with 0 &lt; t &lt; tMax into {@code hit}: the mesh's BVH is walked nearest
     * box first and the far end shrinks to each hit found, so a ray stops at the first surface it
     * meets. The same triangle test as {@link #span}, so the nearest crossing is the same one, at
     * the same t. A closed mesh's face is flipped as where the ray enters it (the winding normal
     * faced along the ray): the parity of the crossings behind is not known here, which is why
     * materials that read the side take {@link #span} instead (Shapes#parity).
     */
    static boolean firstHit(double[] a, int o, Ray ray, double tMax, LineSpan scratch, MeshGeometry g, int s, Hit hit) {
        LineSpan.Crossings c = shear(a, o, ray, scratch);
        c.nearT = tMax;
        c.nearTriangle = -1;
        if (g.bvh == null) {
            for (int t = 0; t < g.count; t++) nearer(g, t, c);
        } else {
            BvhWalker walk = c.walker(g.bvh.depth + 2);
            if (walk.start(g.bvh, local(ray, c), 0, tMax)) {
                for (int leaf = walk.nextNearest(c.nearT); leaf != BvhWalker.END; leaf = walk.nextNearest(c.nearT)) {
                    for (int t = Bvh.leafFirst(leaf), end = t + Bvh.leafCount(leaf); t < end; t++) nearer(g, t, c);
                }
            }
        }
        if (c.nearTriangle < 0) return false;
        hit.t = c.nearT;
        hit.shape = s;
        // The side, as the span's parity says: entering when an even number of crossings lie at t ≤ 0.
        int flip = 0;
        if (g.closed) flip = (crossingsBehind(g, c) & 1) == 0 ? (c.nearFacing > 0 ? 1 : 0) : (c.nearFacing < 0 ? 1 : 0);
        hit.face = 2 * c.nearTriangle + flip;
        hit.flip = false;
        return true;
    }

    /**
     * How many crossings of the line of {@code c} lie at t ≤ 0, for a ray that hits the mesh ahead.
     * None when the origin lies outside the mesh's box (widened by 2⁻³⁰ of its size): the line meets
     * the box in one piece, which then lies wholly ahead. Otherwise the walk of (−∞, nearest hit]
     * counts them with the same triangle test as {@link #span}.
     */
    private static int crossingsBehind(MeshGeometry g, LineSpan.Crossings c) {
        double[] o = c.o;
        double[] b = g.box;
        double margin = 0x1p-30 * (b[6] + Math.abs(o[0]) + Math.abs(o[1]) + Math.abs(o[2]));
        if (o[0] < b[0] - margin || o[1] < b[1] - margin || o[2] < b[2] - margin || o[0] > b[3] + margin
                || o[1] > b[4] + margin || o[2] > b[5] + margin) {
            return 0;
        }
        int n = 0;
        if (g.bvh == null) {
            for (int t = 0; t < g.count; t++) {
                if (crossing(g, t, c) <= 0) n++;
            }
            return n;
        }
        BvhWalker walk = c.walker(g.bvh.depth + 2);
        if (!walk.start(g.bvh, c.localRay, Double.NEGATIVE_INFINITY, c.nearT)) return 0;
        for (int leaf = walk.nextAny(c.nearT); leaf != BvhWalker.END; leaf = walk.nextAny(c.nearT)) {
            for (int t = Bvh.leafFirst(leaf), end = t + Bvh.leafCount(leaf); t < end; t++) {
                if (crossing(g, t, c) <= 0) n++;
            }
        }
        return n;
    }

    /** Whether some triangle crosses the ray with 0 &lt; t &lt; tMax: the walk ends at the first one found. */
    static boolean anyHit(double[] a, int o, Ray ray, double tMax, LineSpan scratch, MeshGeometry g) {
        LineSpan.Crossings c = shear(a, o, ray, scratch);
        c.nearT = tMax;
        c.nearTriangle = -1;
        if (g.bvh == null) {
            for (int t = 0; t < g.count; t++) {
                if (nearer(g, t, c)) return true;
            }
            return false;
        }
        BvhWalker walk = c.walker(g.bvh.depth + 2);
        if (!walk.start(g.bvh, local(ray, c), 0, tMax)) return false;
        for (int leaf = walk.nextAny(tMax); leaf != BvhWalker.END; leaf = walk.nextAny(tMax)) {
            for (int t = Bvh.leafFirst(leaf), end = t + Bvh.leafCount(leaf); t < end; t++) {
                if (nearer(g, t, c)) return true;
            }
        }
        return false;
    }

    /**
     * The ray in mesh coordinates and the shear of the watertight test, into the thread's
     * crossing scratch: kz is the dominant axis of d, kx and ky follow it, swapped when d points
     * down kz so that the winding seen along the ray is kept.
     */
    private static LineSpan.Crossings shear(double[] a, int o, Ray ray, LineSpan out) {
        ray.toLocal(a, o);
        double ox = ray.lox, oy = ray.loy, oz = ray.loz, dx = ray.ldx, dy = ray.ldy, dz = ray.ldz;
        double ax = Math.abs(dx), ay = Math.abs(dy), az = Math.abs(dz);
        int kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
        int kx = kz == 2 ? 0 : kz + 1, ky = kx == 2 ? 0 : kx + 1;
        double dkz = kz == 0 ? dx : kz == 1 ? dy : dz;
        if (dkz < 0) {
            int swap = kx;
            kx = ky;
            ky = swap;
        }
        double dkx = kx == 0 ? dx : kx == 1 ? dy : dz, dky = ky == 0 ? dx : ky == 1 ? dy : dz;
        LineSpan.Crossings c = out.crossings();
        c.set(ox, oy, oz, dx, dy, dz, kx, ky, kz, dkx / dkz, dky / dkz, 1 / dkz);
        return c;
    }

    /** The ray in mesh coordinates as a {@link Ray}, for walking the mesh's BVH. */
    private static Ray local(Ray ray, LineSpan.Crossings c) {
        Ray r = c.localRay;
        r.set(ray.lox, ray.loy, ray.loz, ray.ldx, ray.ldy, ray.ldz);
        return r;
    }

    /** Tests triangle {@code t} (in leaf order) and records a crossing in {@code c}. */
    private static void triangle(MeshGeometry g, int t, LineSpan.Crossings c) {
        double tt = crossing(g, t, c);
        if (tt == tt) c.add(tt, t, facing(g, t, c));
    }

    /**
     * Tests triangle {@code t} and, when it crosses the ray with 0 &lt; t &lt; c.nearT, makes it the
     * nearest crossing of {@code c}; returns whether it did.
     */
    private static boolean nearer(MeshGeometry g, int t, LineSpan.Crossings c) {
        double tt = crossing(g, t, c);
        if (!(tt > 0 && tt < c.nearT)) return false;
        c.nearT = tt;
        c.nearTriangle = t;
        c.nearFacing = facing(g, t, c);
        return true;
    }

    /** Where triangle {@code t} (in leaf order) crosses the line of {@code c}, or NaN when it does not. */
    private static double crossing(MeshGeometry g, int t, LineSpan.Crossings c) {
        double[] p = g.positions;
        int[] tri = g.triangles;
        int ia = 3 * tri[3 * t], ib = 3 * tri[3 * t + 1], ic = 3 * tri[3 * t + 2];
        int kx = c.kx, ky = c.ky, kz = c.kz;
        double ox = c.o[kx], oy = c.o[ky], oz = c.o[kz];
        double azr = p[ia + kz] - oz, bzr = p[ib + kz] - oz, czr = p[ic + kz] - oz;
        double axs = p[ia + kx] - ox - c.sx * azr, ays = p[ia + ky] - oy - c.sy * azr;
        double bxs = p[ib + kx] - ox - c.sx * bzr, bys = p[ib + ky] - oy - c.sy * bzr;
        double cxs = p[ic + kx] - ox - c.sx * czr, cys = p[ic + ky] - oy - c.sy * czr;
        double u = cxs * bys - cys * bxs;
        double v = axs * cys - ays * cxs;
        double w = bxs * ays - bys * axs;
        if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) return Double.NaN;
        double det = u + v + w;
        if (det == 0) return Double.NaN;
        double sign = det > 0 ? 1 : -1;
        // Edges in the counter-clockwise order of the positive orientation: C→B (u), A→C (v), B→A (w).
        if (u == 0 && !topLeft(sign * (bxs - cxs), sign * (bys - cys))) return Double.NaN;
        if (v == 0 && !topLeft(sign * (cxs - axs), sign * (cys - ays))) return Double.NaN;
        if (w == 0 && !topLeft(sign * (axs - bxs), sign * (ays - bys))) return Double.NaN;
        return (u * azr + v * bzr + w * czr) * c.sz / det;
    }

    /** Which side the winding normal (B − A) × (C − A) of triangle {@code t} faces, seen along the ray: the sign of d·n. */
    private static double facing(MeshGeometry g, int t, LineSpan.Crossings c) {
        double[] p = g.positions;
        int[] tri = g.triangles;
        int ia = 3 * tri[3 * t], ib = 3 * tri[3 * t + 1], ic = 3 * tri[3 * t + 2];
        double e1x = p[ib] - p[ia], e1y = p[ib + 1] - p[ia + 1], e1z = p[ib + 2] - p[ia + 2];
        double e2x = p[ic] - p[ia], e2y = p[ic + 1] - p[ia + 1], e2z = p[ic + 2] - p[ia + 2];
        return (e1y * e2z - e1z * e2y) * c.dx + (e1z * e2x - e1x * e2z) * c.dy + (e1x * e2y - e1y * e2x) * c.dz;
    }

    /** The top-left rule for an edge (ex, ey) of a counter-clockwise triangle: left edges go down, top edges go left. */
    private static boolean topLeft(double ex, double ey) {
        return ey < 0 || (ey == 0 && ex < 0);
    }

    static void surface(double[] a, int o, int face, double px, double py, double pz, SurfacePoint out, MeshGeometry g) {
        double lx = a[o] * px + a[o + 1] * py + a[o + 2] * pz + a[o + 3];
        double ly = a[o + 4] * px + a[o + 5] * py + a[o + 6] * pz + a[o + 7];
        double lz = a[o + 8] * px + a[o + 9] * py + a[o + 10] * pz + a[o + 11];
        int t = face >> 1;
        double flip = (face & 1) == 0 ? 1 : -1;
        double[] p = g.positions;
        int[] tri = g.triangles;
        int ia = 3 * tri[3 * t], ib = 3 * tri[3 * t + 1], ic = 3 * tri[3 * t + 2];
        double e1x = p[ib] - p[ia], e1y = p[ib + 1] - p[ia + 1], e1z = p[ib + 2] - p[ia + 2];
        double e2x = p[ic] - p[ia], e2y = p[ic + 1] - p[ia + 1], e2z = p[ic + 2] - p[ia + 2];
        double wx = lx - p[ia], wy = ly - p[ia + 1], wz = lz - p[ia + 2];
        double d00 = e1x * e1x + e1y * e1y + e1z * e1z, d01 = e1x * e2x + e1y * e2y + e1z * e2z;
        double d11 = e2x * e2x + e2y * e2y + e2z * e2z;
        double d20 = wx * e1x + wy * e1y + wz * e1z, d21 = wx * e2x + wy * e2y + wz * e2z;
        double denom = d00 * d11 - d01 * d01;
        double b1 = denom != 0 ? (d11 * d20 - d01 * d21) / denom : 0;
        double b2 = denom != 0 ? (d00 * d21 - d01 * d20) / denom : 0;
        b1 = Math.max(0, Math.min(1, b1));
        b2 = Math.max(0, Math.min(1 - b1, b2));
        double b0 = 1 - b1 - b2;
        Affine.pointToWorld(a, o, p[ia] + b1 * e1x + b2 * e2x, p[ia + 1] + b1 * e1y + b2 * e2y,
                p[ia + 2] + b1 * e1z + b2 * e2z, out);
        double nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
        Affine.normalToWorld(a, o, flip * nx, flip * ny, flip * nz, out);
        out.u = b1;
        out.v = b2;
        if (a[o + Affine.SIZE + 1] != 0 && g.normals != null) {
            double[] n = g.normals;
            double sx = b0 * n[ia] + b1 * n[ib] + b2 * n[ic];
            double sy = b0 * n[ia + 1] + b1 * n[ib + 1] + b2 * n[ic + 1];
            double sz = b0 * n[ia + 2] + b1 * n[ib + 2] + b2 * n[ic + 2];
            // By the inverse transpose, as the geometric normal.
            double wnx = a[o] * sx + a[o + 4] * sy + a[o + 8] * sz;
            double wny = a[o + 1] * sx + a[o + 5] * sy + a[o + 9] * sz;
            double wnz = a[o + 2] * sx + a[o + 6] * sy + a[o + 10] * sz;
            double len = Math.sqrt(wnx * wnx + wny * wny + wnz * wnz);
            if (len > 0) {
                out.shaded = true;
                out.snx = wnx / len;
                out.sny = wny / len;
                out.snz = wnz / len;
                lift(a, o, b0, b1, b2, ia, ib, ic, p, n, e1x, e1y, e1z, e2x, e2y, e2z, out);
            }
        }
    }

    /**
     * Where lights are looked at from on a smooth triangle (Hanika, "Hacking the shadow
     * terminator", Ray Tracing Gems II, 2021): the flat point moved onto the smooth surface the
     * vertex normals describe, as the barycentric blend of its projections onto the tangent
     * planes of the three corners, each only when the point lies below that plane. Shadow rays
     * then leave from the bulge the shading shows, instead of from under it, so a coarse smooth
     * mesh has no stair-stepped shadow along its terminator.
     */
    private static void lift(double[] a, int o, double b0, double b1, double b2, int ia, int ib, int ic, double[] p,
            double[] n, double e1x, double e1y, double e1z, double e2x, double e2y, double e2z, SurfacePoint out) {
        double x = p[ia] + b1 * e1x + b2 * e2x, y = p[ia + 1] + b1 * e1y + b2 * e2y, z = p[ia + 2] + b1 * e1z + b2 * e2z;
        double da = b0 * below(x, y, z, p, n, ia), db = b1 * below(x, y, z, p, n, ib), dc = b2 * below(x, y, z, p, n, ic);
        double lx = x - da * n[ia] - db * n[ib] - dc * n[ic];
        double ly = y - da * n[ia + 1] - db * n[ib + 1] - dc * n[ic + 1];
        double lz = z - da * n[ia + 2] - db * n[ib + 2] - dc * n[ic + 2];
        int m = o + 12;
        out.lx = a[m] * lx + a[m + 1] * ly + a[m + 2] * lz + a[m + 3];
        out.ly = a[m + 4] * lx + a[m + 5] * ly + a[m + 6] * lz + a[m + 7];
        out.lz = a[m + 8] * lx + a[m + 9] * ly + a[m + 10] * lz + a[m + 11];
    }

    /** How far (x, y, z) lies below the tangent plane of corner v (0 when above it), as a negative distance. */
    private static double below(double x, double y, double z, double[] p, double[] n, int v) {
        return Math.min(0, (x - p[v]) * n[v] + (y - p[v + 1]) * n[v + 1] + (z - p[v + 2]) * n[v + 2]);
    }

    /** uv from the file interpolated at the point, or the barycentric coordinates when the file has none. */
    static void frame(double[] a, int o, int face, SurfacePoint out, MeshGeometry g) {
        int t = face >> 1;
        double b1 = out.u, b2 = out.v, b0 = 1 - b1 - b2;
        double[] p = g.positions;
        int[] tri = g.triangles;
        int va = tri[3 * t], vb = tri[3 * t + 1], vc = tri[3 * t + 2];
        double ua = 0, ub = 1, uc = 0, wa = 0, wb = 0, wc = 1;
        if (g.uvs != null) {
            ua = g.uvs[2 * va];
            wa = g.uvs[2 * va + 1];
            ub = g.uvs[2 * vb];
            wb = g.uvs[2 * vb + 1];
            uc = g.uvs[2 * vc];
            wc = g.uvs[2 * vc + 1];
        }
        out.u = b0 * ua + b1 * ub + b2 * uc;
        out.v = b0 * wa + b1 * wb + b2 * wc;
        // dp/du and dp/dv from the triangle's edges and the uv differences along them.
        double du1 = ub - ua, du2 = uc - ua, dv1 = wb - wa, dv2 = wc - wa;
        double det = du1 * dv2 - du2 * dv1;
        double e1x = p[3 * vb] - p[3 * va], e1y = p[3 * vb + 1] - p[3 * va + 1], e1z = p[3 * vb + 2] - p[3 * va + 2];
        double e2x = p[3 * vc] - p[3 * va], e2y = p[3 * vc + 1] - p[3 * va + 1], e2z = p[3 * vc + 2] - p[3 * va + 2];
        if (det == 0) {
            Affine.tangentsToWorld(a, o, e1x, e1y, e1z, e2x, e2y, e2z, out);
            return;
        }
        double inv = 1 / det;
        Affine.tangentsToWorld(a, o, (dv2 * e1x - dv1 * e2x) * inv, (dv2 * e1y - dv1 * e2y) * inv,
                (dv2 * e1z - dv1 * e2z) * inv, (du1 * e2x - du2 * e1x) * inv, (du1 * e2y - du2 * e1y) * inv,
                (du1 * e2z - du2 * e1z) * inv, out);
    }
}
