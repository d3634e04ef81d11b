package dev.crt.render;

import dev.crt.geom.Aabb;
import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.Sphere;

/**
 * The sphere: stored in world space as centre, radius and radius² when its transform keeps it a
 * sphere (translation, rotation, uniform scale), else as the unit ball under an {@link Affine}
 * placement (kind MAPPED_SPHERE). Its uv are longitude and colatitude about the local y axis.
 */
final class SphereShape {
    /** The doubles of a SPHERE's data: centre, radius, radius². */
    static final int SIZE = 5;

    private SphereShape() {}

    /** Writes the data of an untransformed sphere about (x, y, z) of radius {@code r} &gt; 0 at {@code at}, as {@link #add} pushes it. */
    static void write(double[] data, int at, double x, double y, double z, double r) {
        data[at] = x;
        data[at + 1] = y;
        data[at + 2] = z;
        data[at + 3] = r;
        data[at + 4] = r * r;
    }

    /**
     * Writes shape {@code s} of {@code out}, claimed, as the untransformed sphere whose data
     * {@link #write} wrote at {@code from} of {@code source}, with its data from {@code at}: what
     * {@link #add} makes of it.
     */
    static void place(Shapes out, int s, int at, double[] source, int from, int material) {
        double x = source[from], y = source[from + 1], z = source[from + 2], r = source[from + 3];
        out.kind[s] = Shapes.SPHERE;
        out.material[s] = material;
        out.offset[s] = at;
        out.placement[s] = 0;
        double[] d = out.data;
        d[at] = x;
        d[at + 1] = y;
        d[at + 2] = z;
        d[at + 3] = r;
        d[at + 4] = source[from + 4];
        out.scale[s] = Shapes.maxAbs(x, y, z) + r;
    }

    static void add(Shapes out, int s, Sphere sp, Transform t) {
        if (!(sp.radius() > 0)) {
            out.kind[s] = Shapes.EMPTY;
            return;
        }
        if (t == Transform.IDENTITY) {
            double x = sp.x(), y = sp.y(), z = sp.z(), r = sp.radius();
            out.kind[s] = Shapes.SPHERE;
            out.push(x, y, z, r, r * r);
            out.scale[s] = Shapes.maxAbs(x, y, z) + r;
            return;
        }
        double[] m = t.matrix();
        double c0 = m[0] * m[0] + m[4] * m[4] + m[8] * m[8];
        double c1 = m[1] * m[1] + m[5] * m[5] + m[9] * m[9];
        double c2 = m[2] * m[2] + m[6] * m[6] + m[10] * m[10];
        double d01 = m[0] * m[1] + m[4] * m[5] + m[8] * m[9];
        double d02 = m[0] * m[2] + m[4] * m[6] + m[8] * m[10];
        double d12 = m[1] * m[2] + m[5] * m[6] + m[9] * m[10];
        double tol = 1e-14 * c0;
        boolean similarity = Math.abs(c1 - c0) <= tol && Math.abs(c2 - c0) <= tol
                && Math.abs(d01) <= tol && Math.abs(d02) <= tol && Math.abs(d12) <= tol;
        if (similarity) {
            Vec3 c = t.applyToPoint(sp.center());
            double r = sp.radius() * Math.sqrt(c0);
            out.kind[s] = Shapes.SPHERE;
            out.push(c.x(), c.y(), c.z(), r, r * r);
            out.scale[s] = Shapes.maxAbs(c) + r;
        } else {
            // Object space is the unit ball at the origin.
            Transform unit = Transform.scaling(new Vec3(sp.radius(), sp.radius(), sp.radius()))
                    .then(Transform.translation(sp.center())).then(t);
            out.kind[s] = Shapes.MAPPED_SPHERE;
            out.pushMatrices(unit);
            Aabb b = mappedBounds(out.data, out.offset[s]);
            out.scale[s] = Math.max(Shapes.maxAbs(b.min()), Shapes.maxAbs(b.max()));
        }
    }

    static Aabb bounds(double[] a, int o) {
        double r = a[o + 3];
        return new Aabb(new Vec3(a[o] - r, a[o + 1] - r, a[o + 2] - r), new Vec3(a[o] + r, a[o + 1] + r, a[o + 2] + r));
    }

    static Aabb mappedBounds(double[] a, int o) {
        // The ellipsoid M·(unit ball) + t reaches |row i of M| along world axis i.
        int m = o + 12;
        double[] lo = new double[3], hi = new double[3];
        for (int i = 0; i < 3; i++) {
            double x = a[m + i * 4], y = a[m + i * 4 + 1], z = a[m + i * 4 + 2];
            double e = Math.sqrt(x * x + y * y + z * z);
            lo[i] = a[m + i * 4 + 3] - e;
            hi[i] = a[m + i * 4 + 3] + e;
        }
        return new Aabb(new Vec3(lo[0], lo[1], lo[2]), new Vec3(hi[0], hi[1], hi[2]));
    }

    static boolean span(double[] a, int o, Ray ray, LineSpan out) {
        return ball(ray.ox - a[o], ray.oy - a[o + 1], ray.oz - a[o + 2], ray.dx, ray.dy, ray.dz, a[o + 4], out);
    }

    static boolean mappedSpan(double[] a, int o, Ray ray, LineSpan out) {
        ray.toLocal(a, o);
        return ball(ray.lox, ray.loy, ray.loz, ray.ldx, ray.ldy, ray.ldz, 1, out);
    }

    /**
     * The ball |p| ≤ √r2 about the origin against the line oc + t·d, in the numerically stable
     * form: the discriminant is taken from the closest approach oc − (b/a)d, which keeps its
     * precision for far-away origins, and the small root comes from c/q without cancellation.
     */
    private static boolean ball(double ocx, double ocy, double ocz, double dx, double dy, double dz, double r2,
            LineSpan out) {
        double a = dx * dx + dy * dy + dz * dz;
        double b = ocx * dx + ocy * dy + ocz * dz;
        double k = b / a;
        double fx = ocx - k * dx, fy = ocy - k * dy, fz = ocz - k * dz;
        double disc = r2 - (fx * fx + fy * fy + fz * fz);
        if (!(disc >= 0)) return false;
        double c = ocx * ocx + ocy * ocy + ocz * ocz - r2;
        double q = b >= 0 ? -b - Math.sqrt(a * disc) : -b + Math.sqrt(a * disc);
        double t0, t1;
        if (q == 0) {
            t0 = 0;
            t1 = 0;
        } else {
            t0 = c / q;
            t1 = q / a;
            if (t0 > t1) {
                double x = t0;
                t0 = t1;
                t1 = x;
            }
        }
        out.one(t0, t1, 0, 0);
        return true;
    }

    static void surface(double[] a, int o, double px, double py, double pz, SurfacePoint out) {
        double vx = px - a[o], vy = py - a[o + 1], vz = pz - a[o + 2];
        double inv = 1 / Math.sqrt(vx * vx + vy * vy + vz * vz);
        double nx = vx * inv, ny = vy * inv, nz = vz * inv;
        double r = a[o + 3];
        out.nx = nx;
        out.ny = ny;
        out.nz = nz;
        out.px = a[o] + nx * r;
        out.py = a[o + 1] + ny * r;
        out.pz = a[o + 2] + nz * r;
    }

    static void mappedSurface(double[] a, int o, double px, double py, double pz, SurfacePoint out) {
        double lx = a[o] * px + a[o + 1] * py + a[o + 2] * pz + a[o + 3];
        double ly = a[o + 4] * px + a[o + 5] * py + a[o + 6] * pz + a[o + 7];
        double lz = a[o + 8] * px + a[o + 9] * py + a[o + 10] * pz + a[o + 11];
        double inv = 1 / Math.sqrt(lx * lx + ly * ly + lz * lz);
        lx *= inv;
        ly *= inv;
        lz *= inv;
        Affine.pointToWorld(a, o, lx, ly, lz, out);
        Affine.normalToWorld(a, o, lx, ly, lz, out);
    }

    /** u = φ/2π with φ = atan2(x, z) from +z towards +x, v = θ/π with θ the angle from +y; r the radius. */
    static void frame(double x, double y, double z, double r, SurfacePoint out) {
        double phi = Math.atan2(x, z);
        if (phi < 0) phi += 2 * Math.PI;
        double theta = Math.acos(Math.max(-1, Math.min(1, y / r)));
        out.u = phi / (2 * Math.PI);
        out.v = theta / Math.PI;
        double rho = Math.sqrt(x * x + z * z);
        double sinPhi = rho > 0 ? x / rho : 0, cosPhi = rho > 0 ? z / rho : 1;
        // dp/du = 2π(z, 0, −x)·…: the derivative of (ρ sinφ, y, ρ cosφ) in φ, times dφ/du.
        out.tangents(2 * Math.PI * z, 0, -2 * Math.PI * x,
                Math.PI * y * sinPhi, -Math.PI * rho, Math.PI * y * cosPhi);
    }

    static void frame(double[] a, int o, SurfacePoint out) {
        frame(out.px - a[o], out.py - a[o + 1], out.pz - a[o + 2], a[o + 3], out);
    }

    static void mappedFrame(double[] a, int o, SurfacePoint out) {
        double px = out.px, py = out.py, pz = out.pz;
        double lx = a[o] * px + a[o + 1] * py + a[o + 2] * pz + a[o + 3];
        double ly = a[o + 4] * px + a[o + 5] * py + a[o + 6] * pz + a[o + 7];
        double lz = a[o + 8] * px + a[o + 9] * py + a[o + 10] * pz + a[o + 11];
        frame(lx, ly, lz, Math.sqrt(lx * lx + ly * ly + lz * lz), out);
        Affine.tangentsToWorld(a, o, out.dpdux, out.dpduy, out.dpduz, out.dpdvx, out.dpdvy, out.dpdvz, out);
    }
}
