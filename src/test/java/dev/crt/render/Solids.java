package dev.crt.render;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.Box;
import dev.crt.scene.Cone;
import dev.crt.scene.Cylinder;
import dev.crt.scene.Csg;
import dev.crt.scene.Entity;
import dev.crt.scene.Mesh;
import dev.crt.scene.MeshData;
import dev.crt.scene.Plane;
import dev.crt.scene.Sphere;
import dev.crt.scene.Torus;

/**
 * The inside test of every entity written directly from its definition (point mapped back through
 * each transform), as the independent slow reference for intersection properties.
 */
final class Solids {
    private Solids() {}

    static boolean inside(Entity e, Vec3 p) {
        Vec3 q = e.transform().inverse().applyToPoint(p);
        if (e instanceof Sphere s) return q.minus(s.center()).length() <= s.radius();
        if (e instanceof Box b) {
            return q.x() >= b.min().x() && q.x() <= b.max().x() && q.y() >= b.min().y() && q.y() <= b.max().y()
                    && q.z() >= b.min().z() && q.z() <= b.max().z();
        }
        if (e instanceof Plane pl) return pl.normal().dot(q.minus(pl.position())) <= 0;
        if (e instanceof Torus t) {
            // (ρ − R)² + h² ≤ r² with h the height along the axis and ρ the distance from it.
            Vec3 v = q.minus(t.center());
            Vec3 a = t.axis().normalize();
            double h = v.dot(a);
            double rho = Math.sqrt(Math.max(0, v.dot(v) - h * h));
            return (rho - t.major()) * (rho - t.major()) + h * h <= t.minor() * t.minor();
        }
        if (e instanceof Mesh m) return Math.abs(winding(m.data(), q)) > 0.5;
        if (e instanceof Cylinder c) return insideCone(c.from(), c.to(), c.radius(), c.radius(), q);
        if (e instanceof Cone c) return insideCone(c.from(), c.to(), c.radius(), c.radius2(), q);
        Csg c = (Csg) e;
        boolean a = inside(c.left(), q), b = inside(c.right(), q);
        return switch (c.operation()) {
            case UNION -> a || b;
            case INTERSECTION -> a && b;
            case DIFFERENCE -> a && !b;
        };
    }

    /**
     * The generalised winding number of a closed mesh about q: the solid angles of its triangles
     * seen from q (Van Oosterom and Strackee) over 4π; ±1 inside, 0 outside, whichever way it is wound.
     */
    static double winding(MeshData m, Vec3 q) {
        double[] p = m.positions();
        int[] t = m.triangles();
        double sum = 0;
        for (int i = 0; i < t.length; i += 3) {
            Vec3 a = new Vec3(p[3 * t[i]], p[3 * t[i] + 1], p[3 * t[i] + 2]).minus(q);
            Vec3 b = new Vec3(p[3 * t[i + 1]], p[3 * t[i + 1] + 1], p[3 * t[i + 1] + 2]).minus(q);
            Vec3 c = new Vec3(p[3 * t[i + 2]], p[3 * t[i + 2] + 1], p[3 * t[i + 2] + 2]).minus(q);
            double la = a.length(), lb = b.length(), lc = c.length();
            double num = a.dot(b.cross(c));
            double den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
            sum += 2 * Math.atan2(num, den);
        }
        return sum / (4 * Math.PI);
    }

    /** Within the radius interpolated at the point's projection on the segment from a to b, by distance to the line. */
    private static boolean insideCone(Vec3 a, Vec3 b, double r0, double r1, Vec3 q) {
        Vec3 axis = b.minus(a);
        double s = q.minus(a).dot(axis) / axis.dot(axis);
        if (s < 0 || s > 1) return false;
        double distance = q.minus(a).cross(axis).length() / axis.length();
        return distance <= r0 + (r1 - r0) * s;
    }

    /** A random affine transform: scale (non-uniform when asked), rotation, translation. */
    static Transform randomTransform(java.util.SplittableRandom r, boolean nonUniform, double spread) {
        double s = 0.5 + r.nextDouble() * 1.5;
        Vec3 scale = nonUniform ? new Vec3(s, 0.4 + r.nextDouble() * 2, 0.4 + r.nextDouble() * 2) : new Vec3(s, s, s);
        Vec3 angles = new Vec3(r.nextDouble() * 360, r.nextDouble() * 360, r.nextDouble() * 360);
        Vec3 move = new Vec3((r.nextDouble() - 0.5) * spread, (r.nextDouble() - 0.5) * spread, (r.nextDouble() - 0.5) * spread);
        return Transform.scaling(scale).then(Transform.rotation(angles)).then(Transform.translation(move));
    }
}
