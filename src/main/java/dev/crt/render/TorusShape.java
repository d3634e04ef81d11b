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
 * coefficients are of the torus's size however far away the ray starts; a line that passes
 * farther than R + r from the centre is dismissed before any quartic. The roots come from
 * {@link Quartic#isolate} (the measurements of docs/benchmarks.md chose it), and the intervals
 * inside the solid are read from the inside test at the midpoints between roots, so a spindle
 * torus's inner sheet (the quartic's other branch) and a doubled tangent root cannot swap inside
 * for outside.
 *
 * <p>Data after the {@link Affine} placement: R (major), r (minor).
 */
final class TorusShape {
    /** The quartic method tori use (docs/benchmarks.md, "Torus roots"). */
    static final int METHOD = Quartic.ISOLATE;

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
        Aabb b = out.bounds(s);
        out.scale[s] = Math.max(Shapes.maxAbs(b.min()), Shapes.maxAbs(b.max()));
    }

    static Aabb bounds(double[] a, int o) {
        double big = a[o + Affine.SIZE], small = a[o + Affine.SIZE + 1], e = big + small;
        return Affine.bounds(a, o, -e, -e, -small, e, e, small);
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
        double g = ox * ox + oy * oy + oz * oz;
        double reach = big + small;
        if (g > reach * reach) return false;
        if (!mayCross(ox, oy, oz, dx, dy, dz, reach, small)) return false;
        int n = roots(METHOD, ox, oy, oz, dx, dy, dz, big, small, roots);
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
     * Whether the ray can meet the torus with tMin &lt; t &lt; tMax: false when the part of its line
     * within the slab |z| ≤ r and the cylinder ρ ≤ R + r (widened as in {@link #mayCross}, and by
     * 2⁻²⁰ of R + r more) lies wholly outside that range. Every root {@link #span} would find lies
     * in that part, so a closest hit or shadow ray that cannot reach it skips the quartic.
     */
    static boolean mayHit(double[] a, int o, Ray ray, double tMin, double tMax) {
        ray.toLocal(a, o);
        double big = a[o + Affine.SIZE], small = a[o + Affine.SIZE + 1];
        double dx = ray.ldx, dy = ray.ldy, dz = ray.ldz;
        double length = Math.sqrt(dx * dx + dy * dy + dz * dz);
        dx /= length;
        dy /= length;
        dz /= length;
        double s0 = -(ray.lox * dx + ray.loy * dy + ray.loz * dz);
        double ox = ray.lox + s0 * dx, oy = ray.loy + s0 * dy, oz = ray.loz + s0 * dz;
        double reach = big + small;
        if (ox * ox + oy * oy + oz * oz > reach * reach) return false;
        double slack = 0x1p-30 * reach;
        double lo = Double.NEGATIVE_INFINITY, hi = Double.POSITIVE_INFINITY;
        if (dz == 0) {
            if (Math.abs(oz) > small + slack) return false;
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
            if (qc > 0) return false;
        } else {
            double disc = qb * qb - qa * qc;
            if (disc < 0) return false;
            double root = Math.sqrt(disc);
            lo = Math.max(lo, (-qb - root) / qa);
            hi = Math.min(hi, (-qb + root) / qa);
        }
        // Also within the sphere of radius R + r, where the quartic's roots are sought.
        double half = Math.sqrt(Math.max(0, reach * reach - (ox * ox + oy * oy + oz * oz)));
        lo = Math.max(lo, -half);
        hi = Math.min(hi, half);
        double margin = 0x1p-20 * reach;
        lo -= margin;
        hi += margin;
        if (!(lo <= hi)) return false;
        return (hi + s0) / length > tMin && (lo + s0) / length < tMax;
    }

    /**
     * Whether the line can meet the torus at all: it must be within the slab |z| ≤ r and within
     * the cylinder ρ ≤ R + r at once. Most lines that reach a torus's box but miss the torus fail
     * here, before any quartic; the test is widened by a hair so it never drops a grazing hit.
     */
    private static boolean mayCross(double ox, double oy, double oz, double dx, double dy, double dz, double reach,
            double small) {
        double slack = 0x1p-30 * reach;
        double lo = Double.NEGATIVE_INFINITY, hi = Double.POSITIVE_INFINITY;
        if (dz == 0) {
            if (Math.abs(oz) > small + slack) return false;
        } else {
            double a = (-small - slack - oz) / dz, b = (small + slack - oz) / dz;
            lo = Math.min(a, b);
            hi = Math.max(a, b);
        }
        double qa = dx * dx + dy * dy;
        double qb = ox * dx + oy * dy;
        double wide = reach + slack;
        double qc = ox * ox + oy * oy - wide * wide;
        if (qa == 0) return qc <= 0 && lo <= hi;
        double disc = qb * qb - qa * qc;
        if (disc < 0) return false;
        double root = Math.sqrt(disc);
        return Math.max(lo, (-qb - root) / qa) <= Math.min(hi, (-qb + root) / qa);
    }

    /**
     * The roots s of the torus quartic along the line o + s·d (|d| = 1, o the closest approach to
     * the centre, so o·d = 0): with g = |o|² and k = g + R² − r²,
     * s⁴ + (2k − 4R²(dx² + dy²))s² − 8R²(ox·dx + oy·dy)s + k² − 4R²(ox² + oy²) = 0.
     */
    static int roots(int method, double ox, double oy, double oz, double dx, double dy, double dz, double big,
            double small, double[] out) {
        double g = ox * ox + oy * oy + oz * oz;
        double k = g + (big - small) * (big + small);
        double r2 = 4 * big * big;
        double c2 = 2 * k - r2 * (dx * dx + dy * dy);
        double c1 = -2 * r2 * (ox * dx + oy * dy);
        double c0 = k * k - r2 * (ox * ox + oy * oy);
        double bound = (big + small) * (1 + 0x1p-40);
        return Quartic.solve(method, c2, c1, c0, bound, out);
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
