package dev.crt.render;

import dev.crt.geom.Aabb;
import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.Plane;

/**
 * The half-space n·p ≤ h, stored in world space as its unit normal n and h. Its uv are
 * coordinates along two unit tangents (scene units, not wrapped): e1 ⊥ n chosen from the axis
 * least aligned with n, and e2 = n × e1.
 */
final class PlaneShape {
    private PlaneShape() {}

    static void add(Shapes out, int s, Plane p, Transform t) {
        Vec3 n = t.applyToNormal(p.normal()).normalize();
        Vec3 q = t.applyToPoint(p.position());
        double h = n.dot(q);
        out.kind[s] = Shapes.PLANE;
        out.push(n.x(), n.y(), n.z(), h);
        out.scale[s] = Math.abs(h);
    }

    static Aabb bounds() {
        return Aabb.INFINITE;
    }

    static boolean span(double[] a, int o, Ray ray, LineSpan out) {
        double dn = a[o] * ray.dx + a[o + 1] * ray.dy + a[o + 2] * ray.dz;
        double on = a[o] * ray.ox + a[o + 1] * ray.oy + a[o + 2] * ray.oz;
        double h = a[o + 3];
        if (dn == 0) {
            out.one(Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY, 0, 0);
            return on <= h;
        }
        double t = (h - on) / dn;
        if (dn < 0) out.one(t, Double.POSITIVE_INFINITY, 0, 0);
        else out.one(Double.NEGATIVE_INFINITY, t, 0, 0);
        return true;
    }

    static void surface(double[] a, int o, double px, double py, double pz, SurfacePoint out) {
        double nx = a[o], ny = a[o + 1], nz = a[o + 2];
        double e = nx * px + ny * py + nz * pz - a[o + 3];
        out.px = px - e * nx;
        out.py = py - e * ny;
        out.pz = pz - e * nz;
        out.nx = nx;
        out.ny = ny;
        out.nz = nz;
    }

    static void frame(double[] a, int o, SurfacePoint out) {
        double nx = a[o], ny = a[o + 1], nz = a[o + 2];
        double ax = Math.abs(nx), ay = Math.abs(ny), az = Math.abs(nz);
        // e1 = normalize(axis × n) for the axis least aligned with n.
        double ex, ey, ez;
        if (ax <= ay && ax <= az) {
            ex = 0;
            ey = -nz;
            ez = ny;
        } else if (ay <= az) {
            ex = nz;
            ey = 0;
            ez = -nx;
        } else {
            ex = -ny;
            ey = nx;
            ez = 0;
        }
        double inv = 1 / Math.sqrt(ex * ex + ey * ey + ez * ez);
        ex *= inv;
        ey *= inv;
        ez *= inv;
        double fx = ny * ez - nz * ey, fy = nz * ex - nx * ez, fz = nx * ey - ny * ex;
        out.u = ex * out.px + ey * out.py + ez * out.pz;
        out.v = fx * out.px + fy * out.py + fz * out.pz;
        out.tangents(ex, ey, ez, fx, fy, fz);
    }
}
