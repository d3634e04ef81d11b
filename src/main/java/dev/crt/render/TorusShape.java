package dev.crt.render;

import dev.crt.geom.Aabb;
import dev.crt.geom.Quartic;
import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.Torus;

/**
 * The torus, intersected in a local frame where it lies about the origin with its axis along z
 * (scene units). A line is first moved to its closest approach to the centre and its direction
 * made unit: the quartic in the distance s from there is then depressed (no cubic term) and its
 * coefficients are of the torus's size however far away the ray starts. Its roots are sought only
 * where the line is inside the slab, cylinder and sphere around the torus at once (a line that
 * misses that stretch costs no quartic), by {@link Quartic#isolate} (the measurements of
 * docs/benchmarks.md chose it). CSG's {@link #span} reads the intervals inside the solid from the
 * inside test at the midpoints between all roots, so a spindle torus's inner sheet and a doubled
 * tangent root cannot swap inside for outside; a closest hit or a shadow ray ({@link #firstHit})
 * refines only the first root in its window that lies on the solid's boundary.
 *
 * <p>Data after the {@link Affine} placement: R (major), r (minor).
 */
final class TorusShape {
    /** The quartic method tori use (docs/benchmarks.md, "Torus roots"). */
    static final int METHOD = Quartic.ISOLATE;
    /** What {@link #roots} is asked for: every root, the first that bounds the solid, or whether there is one. */
    static final int ALL = 0, FIRST = 1, ANY = 2;

    private TorusShape() {}

    static void add(Shapes out, int s, Torus t, Transform toWorld) {
        double length = t.axis().length();
        if (!(length > 0) || !(t.major() > 0) || !(t.minor() > 0)) {
            out.kind[s] = Shapes.EMPTY;
            return;
        }
        Vec3[] axes = Transform.axes(t.axis().div(length));
        out.kind[s] = Shapes.TORUS;
        out.pushMatrices(Transform.frame(axes[0], axes[1], axes[2], t.center()).then(toWorld));
        out.push(t.major(), t.minor());
        // The scale for ray offsets is that of the local box's corners, as it always was.
        int o = out.offset[s];
        double e = t.major() + t.minor();
        Aabb b = Affine.bounds(out.data, o, -e, -e, -t.minor(), e, e, t.minor());
        out.scale[s] = Math.max(Shapes.maxAbs(b.min()), Shapes.maxAbs(b.max()));
    }

    /**
     * The torus's own box: the placed torus is the ring circle's image (an ellipse) swept by the
     * tube's (an ellipsoid), so along world axis i it reaches R·|(A_i0, A_i1)| + r·|A_i| from its
     * centre, A the placement's linear part. A turned torus's box is then far smaller than the box
     * of its local box's corners (a third narrower per axis for an axis along (1, 1, 1)), so fewer
     * rays reach the quartic and the BVH over many tori is tighter. Widened by 2⁻³⁰ for rounding.
     */
    static Aabb bounds(double[] a, int o) {
        double big = a[o + Affine.SIZE], small = a[o + Affine.SIZE + 1];
        int m = o + 12;
        double[] lo = new double[3], hi = new double[3];
        for (int i = 0; i < 3; i++) {
            double ax = a[m + 4 * i], ay = a[m + 4 * i + 1], az = a[m + 4 * i + 2];
            double ring = Math.sqrt(ax * ax + ay * ay);
            double half = (big * ring + small * Math.sqrt(ring * ring + az * az)) * (1 + 0x1p-30);
            double c = a[m + 4 * i + 3];
            lo[i] = c - half;
            hi[i] = c + half;
        }
        return new Aabb(new Vec3(lo[0], lo[1], lo[2]), new Vec3(hi[0], hi[1], hi[2]));
    }

    static boolean span(double[] a, int o, Ray ray, LineSpan out, double[] roots) {
        ray.toLocal(a, o);
        double big = a[o + Affine.SIZE], small = a[o + Affine.SIZE + 1];
        double dx = ray.ldx, dy = ray.ldy, dz = ray.ldz;
        double length = Math.sqrt(dx * dx + dy * dy + dz * dz);
        dx /= length;
        dy /= length;
        dz /= length;
        double s0 = -(ray.lox * dx + ray.loy * dy + ray.loz * dz);
        double ox = ray.lox + s0 * dx, oy = ray.loy + s0 * dy, oz = ray.loz + s0 * dz;
        int n = roots(METHOD, ox, oy, oz, dx, dy, dz, big, small, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY,
                ALL, roots);
        if (n == 0) return false;
        out.count = 0;
        out.surface = false;
        // The line is outside before the first root and after the last; between roots, the
        // inside test at the midpoint decides.
        double start = Double.NaN;
        for (int i = 0; i + 1 < n; i++) {
            double m = 0.5 * (roots[i] + roots[i + 1]);
            boolean in = inside(ox + m * dx, oy + m * dy, oz + m * dz, big, small);
            if (in && start != start) start = roots[i];
            if (!in && start == start) {
                out.add((start + s0) / length, (roots[i] + s0) / length, 0, 0);
                start = Double.NaN;
            }
        }
        if (start == start) out.add((start + s0) / length, (roots[n - 1] + s0) / length, 0, 0);
        return out.count > 0;
    }

    /**
     * The nearest crossing of the torus's surface with 0 &lt; t &lt; tMax, or NaN: the first root of
     * the quartic in that window that bounds the solid, without refining the roots behind it or
     * beyond it. It is the same double as the first crossing {@link #span} gives (both refine the
     * same brackets), so a torus looks the same alone and in CSG.
     */
    static double firstHit(double[] a, int o, Ray ray, double tMax, double[] roots) {
        return crossing(a, o, ray, tMax, FIRST, roots) ? roots[0] : Double.NaN;
    }

    /**
     * Whether the surface crosses the ray with 0 &lt; t &lt; tMax, as {@link #firstHit} would find:
     * the question of a shadow ray, where a sign change of the quartic inside the window answers
     * without refining its root (on a ring torus every root bounds the solid).
     */
    static boolean anyHit(double[] a, int o, Ray ray, double tMax, double[] roots) {
        return crossing(a, o, ray, tMax, ANY, roots);
    }

    /** Whether there is a crossing with 0 &lt; t &lt; tMax; its t into roots[0] when refined (NaN when not). */
    private static boolean crossing(double[] a, int o, Ray ray, double tMax, int want, double[] roots) {
        ray.toLocal(a, o);
        double big = a[o + Affine.SIZE], small = a[o + Affine.SIZE + 1];
        double dx = ray.ldx, dy = ray.ldy, dz = ray.ldz;
        // Most rays that reach the torus's box pass outside its sphere: |o × d|² / |d|² is the
        // squared distance of the line from the centre, tested before any square root or division
        // (with room for its rounding; the exact test follows).
        double cx = ray.loy * dz - ray.loz * dy, cy = ray.loz * dx - ray.lox * dz, cz = ray.lox * dy - ray.loy * dx;
        double dd = dx * dx + dy * dy + dz * dz, reach = big + small;
        if (cx * cx + cy * cy + cz * cz > reach * reach * dd * (1 + 0x1p-20)
                + 0x1p-40 * (ray.lox * ray.lox + ray.loy * ray.loy + ray.loz * ray.loz) * dd) {
            return false;
        }
        double length = Math.sqrt(dd);
        dx /= length;
        dy /= length;
        dz /= length;
        double s0 = -(ray.lox * dx + ray.loy * dy + ray.loz * dz);
        double ox = ray.lox + s0 * dx, oy = ray.loy + s0 * dy, oz = ray.loz + s0 * dz;
        if (roots(METHOD, ox, oy, oz, dx, dy, dz, big, small, -s0, tMax * length - s0, want, roots) == 0) return false;
        if (roots[0] != roots[0]) return true;
        double t = (roots[0] + s0) / length;
        roots[0] = t;
        return t > 0 && t < tMax;
    }

    /**
     * The roots s of the torus quartic along the line o + s·d (|d| = 1, o the closest approach to
     * the centre, so o·d = 0) that lie in (from, to), in increasing order, into {@code out}: with
     * g = |o|² and k = g + R² − r²,
     * s⁴ + (2k − 4R²(dx² + dy²))s² − 8R²(ox·dx + oy·dy)s + k² − 4R²(ox² + oy²) = 0.
     * Every root lies where the line is within the slab |z| ≤ r, the cylinder ρ ≤ R + r and the
     * sphere |p| ≤ R + r at once: a line that misses that stretch (widened by 2⁻²⁰ of R + r, so
     * that a grazing root stays inside) has no root, and {@link Quartic#ISOLATE} searches that
     * stretch only (the other methods, compared in docs/benchmarks.md, all of [−(R + r), R + r]).
     * With {@link #FIRST}, only the first root that bounds the solid is written: a spindle
     * torus's inner sheet, the quartic's points with |p|² &lt; r² − R², lies inside the solid
     * and is passed over; with {@link #ANY}, a NaN in its place means there is one, unrefined.
     */
    static int roots(int method, double ox, double oy, double oz, double dx, double dy, double dz, double big,
            double small, double from, double to, int want, double[] out) {
        double g = ox * ox + oy * oy + oz * oz;
        double reach = big + small;
        if (g > reach * reach) return 0;
        double slack = 0x1p-30 * reach;
        double lo = Double.NEGATIVE_INFINITY, hi = Double.POSITIVE_INFINITY;
        if (dz == 0) {
            if (Math.abs(oz) > small + slack) return 0;
        } else {
            double p = (-small - slack - oz) / dz, q = (small + slack - oz) / dz;
            lo = Math.min(p, q);
            hi = Math.max(p, q);
        }
        double qa = dx * dx + dy * dy;
        double qb = ox * dx + oy * dy;
        double wide = reach + slack;
        double qc = ox * ox + oy * oy - wide * wide;
        if (qa == 0) {
            if (qc > 0) return 0;
        } else {
            double disc = qb * qb - qa * qc;
            if (disc < 0) return 0;
            double root = Math.sqrt(disc);
            lo = Math.max(lo, (-qb - root) / qa);
            hi = Math.min(hi, (-qb + root) / qa);
        }
        double half = Math.sqrt(Math.max(0, reach * reach - g));
        double margin = 0x1p-20 * reach;
        lo = Math.max(lo, -half) - margin;
        hi = Math.min(hi, half) + margin;
        if (!(lo <= hi) || !(from < hi) || !(to > lo)) return 0;
        double k = g + (big - small) * (big + small);
        double r2 = 4 * big * big;
        double c2 = 2 * k - r2 * qa;
        double c1 = -2 * r2 * qb;
        double c0 = k * k - r2 * (ox * ox + oy * oy);
        if (method != Quartic.ISOLATE) {
            int n = Quartic.solve(method, c2, c1, c0, reach * (1 + 0x1p-40), out);
            int kept = 0;
            for (int i = 0; i < n; i++) {
                if (out[i] > from && out[i] < to && !(want != ALL && out[i] * out[i] < -k)) out[kept++] = out[i];
            }
            return want != ALL ? Math.min(kept, 1) : kept;
        }
        if (want == ALL) return Quartic.isolate(c2, c1, c0, lo, hi, from, to, 4, out);
        // A line with k > 0 (every line, on a ring torus) misses the inner sheet: any root will do.
        if (want == ANY && k > 0) return Quartic.crosses(c2, c1, c0, lo, hi, from, to, out) ? 1 : 0;
        // |p|² = g + s² on this line, and r² − R² − g = −k: the inner sheet is where s² < −k.
        while (Quartic.isolate(c2, c1, c0, lo, hi, from, to, 1, out) == 1) {
            if (!(out[0] * out[0] < -k)) return 1;
            from = out[0];
        }
        return 0;
    }

    private static boolean inside(double x, double y, double z, double big, double small) {
        double rho = Math.sqrt(x * x + y * y) - big;
        return rho * rho + z * z <= small * small;
    }

    static void surface(double[] a, int o, double px, double py, double pz, SurfacePoint out) {
        double lx = a[o] * px + a[o + 1] * py + a[o + 2] * pz + a[o + 3];
        double ly = a[o + 4] * px + a[o + 5] * py + a[o + 6] * pz + a[o + 7];
        double lz = a[o + 8] * px + a[o + 9] * py + a[o + 10] * pz + a[o + 11];
        double big = a[o + Affine.SIZE], small = a[o + Affine.SIZE + 1];
        double rho = Math.sqrt(lx * lx + ly * ly);
        // The nearest point of the ring circle, then the tube's surface along the way to it.
        double cx = rho > 0 ? lx / rho : 1, cy = rho > 0 ? ly / rho : 0;
        double vx = lx - big * cx, vy = ly - big * cy, vz = lz;
        double v = Math.sqrt(vx * vx + vy * vy + vz * vz);
        double nx = v > 0 ? vx / v : cx, ny = v > 0 ? vy / v : cy, nz = v > 0 ? vz / v : 0;
        Affine.pointToWorld(a, o, big * cx + small * nx, big * cy + small * ny, small * nz, out);
        Affine.normalToWorld(a, o, nx, ny, nz, out);
    }

    /** u = φ/2π around the axis (from local x towards y), v = ψ/2π around the tube (from its outer equator towards +z). */
    static void frame(double[] a, int o, SurfacePoint out) {
        double px = out.px, py = out.py, pz = out.pz;
        double lx = a[o] * px + a[o + 1] * py + a[o + 2] * pz + a[o + 3];
        double ly = a[o + 4] * px + a[o + 5] * py + a[o + 6] * pz + a[o + 7];
        double lz = a[o + 8] * px + a[o + 9] * py + a[o + 10] * pz + a[o + 11];
        double big = a[o + Affine.SIZE], small = a[o + Affine.SIZE + 1];
        double phi = Math.atan2(ly, lx);
        if (phi < 0) phi += 2 * Math.PI;
        double rho = Math.sqrt(lx * lx + ly * ly);
        double psi = Math.atan2(lz, rho - big);
        if (psi < 0) psi += 2 * Math.PI;
        out.u = phi / (2 * Math.PI);
        out.v = psi / (2 * Math.PI);
        double c = Math.cos(phi), s = Math.sin(phi), cp = Math.cos(psi), sp = Math.sin(psi);
        double w = 2 * Math.PI;
        Affine.tangentsToWorld(a, o, -w * ly, w * lx, 0, -w * small * sp * c, -w * small * sp * s, w * small * cp, out);
    }
}
