package dev.crt.render;

import dev.crt.geom.Aabb;
import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.Cone;
import dev.crt.scene.Cylinder;

/**
 * Cones, frusta and cylinders (a cylinder is a cone whose two radii are equal): one kind, CONE,
 * intersected in a local frame where the axis runs from z = 0 ({@code from}) to z = 1
 * ({@code to}) and x, y measure scene units across it, so the side is x² + y² = R(z)² with
 * R(z) = r0 + (r1 − r0)·z. Faces: 0 the side, 1 the cap at z = 0, 2 the cap at z = 1. Uncapped
 * shapes are surfaces: their crossings come back as single points ({@link LineSpan#surface}).
 *
 * <p>Data after the {@link Affine} placement: r0, r1, capped (1 or 0), the larger radius.
 */
final class ConeShape {
    static final int SIDE = 0;
    static final int FROM_CAP = 1;
    static final int TO_CAP = 2;

    private ConeShape() {}

    static void add(Shapes out, int s, Cylinder c, Transform t) {
        add(out, s, c.from(), c.to(), c.radius(), c.radius(), c.capped(), t);
    }

    static void add(Shapes out, int s, Cone c, Transform t) {
        add(out, s, c.from(), c.to(), c.radius(), c.radius2(), c.capped(), t);
    }

    private static void add(Shapes out, int s, Vec3 from, Vec3 to, double r0, double r1, boolean capped, Transform t) {
        Vec3 w = to.minus(from);
        double length = w.length();
        if (!(length > 0) || !(r0 > 0 || r1 > 0)) {
            out.kind[s] = Shapes.EMPTY;
            return;
        }
        Vec3[] axes = Transform.axes(w.div(length));
        out.kind[s] = Shapes.CONE;
        out.pushMatrices(Transform.frame(axes[0], axes[1], w, from).then(t));
        double rm = Math.max(r0, r1);
        out.push(r0, r1, capped ? 1 : 0, rm);
        Aabb b = out.bounds(s);
        out.scale[s] = Math.max(Shapes.maxAbs(b.min()), Shapes.maxAbs(b.max()));
    }

    static Aabb bounds(double[] a, int o) {
        double rm = a[o + Affine.SIZE + 3];
        return Affine.bounds(a, o, -rm, -rm, 0, rm, rm, 1);
    }

    static boolean span(double[] a, int o, Ray ray, LineSpan out) {
        ray.toLocal(a, o);
        int p = o + Affine.SIZE;
        double r0 = a[p], k = a[p + 1] - r0;
        boolean capped = a[p + 2] != 0;
        double dx = ray.ldx, dy = ray.ldy, dz = ray.ldz;
        // Moved to the line's closest approach to the middle of the axis, so that the quadratic's
        // coefficients are of the shape's size however far away the ray starts.
        double t0 = -(ray.lox * dx + ray.loy * dy + (ray.loz - 0.5) * dz) / (dx * dx + dy * dy + dz * dz);
        double cx = ray.lox + t0 * dx, cy = ray.loy + t0 * dy, cz = ray.loz + t0 * dz;
        double sLo, sHi;
        int fLo, fHi;
        if (dz == 0) {
            if (cz < 0 || cz > 1) return false;
            sLo = Double.NEGATIVE_INFINITY;
            sHi = Double.POSITIVE_INFINITY;
            fLo = SIDE;
            fHi = SIDE;
        } else {
            double s0 = -cz / dz, s1 = (1 - cz) / dz;
            if (s0 <= s1) {
                sLo = s0;
                sHi = s1;
                fLo = FROM_CAP;
                fHi = TO_CAP;
            } else {
                sLo = s1;
                sHi = s0;
                fLo = TO_CAP;
                fHi = FROM_CAP;
            }
        }
        double rho = r0 + k * cz, kappa = k * dz;
        double qa = dx * dx + dy * dy - kappa * kappa;
        double qb = cx * dx + cy * dy - rho * kappa;
        double qc = cx * cx + cy * cy - rho * rho;
        // The roots of qa·s² + 2qb·s + qc, in order; NaN when there are none.
        double x1 = Double.NaN, x2 = Double.NaN;
        if (qa != 0) {
            double disc = qb * qb - qa * qc;
            if (disc >= 0) {
                double q = qb >= 0 ? -qb - Math.sqrt(disc) : -qb + Math.sqrt(disc);
                if (q == 0) {
                    x1 = 0;
                    x2 = 0;
                } else {
                    x1 = Math.min(q / qa, qc / q);
                    x2 = Math.max(q / qa, qc / q);
                }
            }
        } else if (qb != 0) {
            x1 = -qc / (2 * qb);
        }
        if (!capped) {
            out.count = 0;
            out.surface = true;
            if (x1 >= sLo && x1 <= sHi) out.add(x1 + t0, x1 + t0, SIDE, SIDE);
            if (x2 >= sLo && x2 <= sHi && x2 != x1) out.add(x2 + t0, x2 + t0, SIDE, SIDE);
            return out.count > 0;
        }
        // Where the line is inside the double cone, as one or two pieces; the solid is their part
        // within the slab 0 ≤ z ≤ 1, where R ≥ 0, so at most one piece meets it (a frustum is convex).
        double aLo, aHi, bLo = 1, bHi = 0;
        if (qa > 0) {
            if (Double.isNaN(x1)) return false;
            aLo = x1;
            aHi = x2;
        } else if (qa < 0) {
            if (Double.isNaN(x1)) {
                aLo = Double.NEGATIVE_INFINITY;
                aHi = Double.POSITIVE_INFINITY;
            } else {
                aLo = Double.NEGATIVE_INFINITY;
                aHi = x1;
                bLo = x2;
                bHi = Double.POSITIVE_INFINITY;
            }
        } else if (qb == 0) {
            if (qc > 0) return false;
            aLo = Double.NEGATIVE_INFINITY;
            aHi = Double.POSITIVE_INFINITY;
        } else if (qb > 0) {
            aLo = Double.NEGATIVE_INFINITY;
            aHi = x1;
        } else {
            aLo = x1;
            aHi = Double.POSITIVE_INFINITY;
        }
        double lo = Math.max(aLo, sLo), hi = Math.min(aHi, sHi);
        double lo2 = Math.max(bLo, sLo), hi2 = Math.min(bHi, sHi);
        if (lo2 <= hi2 && !(lo <= hi && hi - lo >= hi2 - lo2)) {
            lo = lo2;
            hi = hi2;
            aLo = bLo;
            aHi = bHi;
        }
        if (!(lo <= hi)) return false;
        out.one(lo + t0, hi + t0, aLo > sLo ? SIDE : fLo, aHi < sHi ? SIDE : fHi);
        return true;
    }

    static void surface(double[] a, int o, int face, double px, double py, double pz, SurfacePoint out) {
        double lx = a[o] * px + a[o + 1] * py + a[o + 2] * pz + a[o + 3];
        double ly = a[o + 4] * px + a[o + 5] * py + a[o + 6] * pz + a[o + 7];
        double lz = a[o + 8] * px + a[o + 9] * py + a[o + 10] * pz + a[o + 11];
        int p = o + Affine.SIZE;
        double r0 = a[p], k = a[p + 1] - r0;
        if (face == SIDE) {
            lz = Math.max(0, Math.min(1, lz));
            double r = r0 + k * lz;
            double rho = Math.sqrt(lx * lx + ly * ly);
            if (rho > 0 && r > 0) {
                lx *= r / rho;
                ly *= r / rho;
                Affine.pointToWorld(a, o, lx, ly, lz, out);
                Affine.normalToWorld(a, o, lx / r, ly / r, -k, out);
            } else {
                // The apex: the axis direction, the only one the point's neighbourhood agrees on.
                Affine.pointToWorld(a, o, 0, 0, lz, out);
                Affine.normalToWorld(a, o, 0, 0, k > 0 ? -1 : 1, out);
            }
        } else {
            double z = face == FROM_CAP ? 0 : 1;
            Affine.pointToWorld(a, o, lx, ly, z, out);
            Affine.normalToWorld(a, o, 0, 0, face == FROM_CAP ? -1 : 1, out);
        }
    }

    /**
     * Side: u = φ/2π around the axis (from the local x axis towards y), v = z from {@code from} to
     * {@code to}. Caps: u, v from 0 to 1 across the disc's bounding square.
     */
    static void frame(double[] a, int o, int face, SurfacePoint out) {
        double px = out.px, py = out.py, pz = out.pz;
        double lx = a[o] * px + a[o + 1] * py + a[o + 2] * pz + a[o + 3];
        double ly = a[o + 4] * px + a[o + 5] * py + a[o + 6] * pz + a[o + 7];
        double lz = a[o + 8] * px + a[o + 9] * py + a[o + 10] * pz + a[o + 11];
        int p = o + Affine.SIZE;
        double r0 = a[p], k = a[p + 1] - r0;
        if (face == SIDE) {
            double phi = Math.atan2(ly, lx);
            if (phi < 0) phi += 2 * Math.PI;
            out.u = phi / (2 * Math.PI);
            out.v = lz;
            double r = r0 + k * lz;
            double c = Math.cos(phi), s = Math.sin(phi);
            Affine.tangentsToWorld(a, o, -2 * Math.PI * r * s, 2 * Math.PI * r * c, 0, k * c, k * s, 1, out);
        } else {
            double r = face == FROM_CAP ? r0 : a[p + 1];
            out.u = 0.5 + lx / (2 * r);
            out.v = 0.5 + ly / (2 * r);
            Affine.tangentsToWorld(a, o, 2 * r, 0, 0, 0, 2 * r, 0, out);
        }
    }
}
