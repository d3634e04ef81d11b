package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.Background;
import dev.crt.scene.Cone;
import dev.crt.scene.CsgOperation;
import dev.crt.scene.Cylinder;
import dev.crt.scene.Entity;
import dev.crt.scene.Material;
import dev.crt.scene.Mesh;
import dev.crt.scene.Settings;
import dev.crt.scene.SourceSpan;
import dev.crt.scene.Torus;
import dev.crt.scene.Sphere;
import java.util.List;
import java.util.SplittableRandom;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;

/**
 * Every intersection routine against an independent slower computation: the exact distance from a
 * sphere's centre to the line, and for every entity (transformed primitives and CSG trees) a march
 * along the ray with the entity's inside test, refined by bisection. Rays are random, aimed, far
 * away (1e5), starting inside, and grazing or tangent.
 */
class IntersectionPropertiesTest {
    private static final Material M = matte(rgb(0.5, 0.5, 0.5));
    /** A closed, non-convex triangle mesh: a line crosses it up to four times. */
    private static final dev.crt.scene.MeshData MESH_TORUS = Meshes.torus(1, 0.45, 8, 5);

    @Property(tries = 3000)
    void sphereSpanMatchesTheDistanceFromTheCentreToTheLine(@ForAll long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        double scale = Math.pow(10, r.nextInt(-4, 5));
        Vec3 c = unit(r).times(r.nextBoolean() ? 1e5 : r.nextDouble() * 3 * scale);
        double radius = scale * (0.1 + r.nextDouble());
        Vec3 d = unit(r);
        Vec3 o;
        switch (r.nextInt(4)) {
            case 0 -> o = c.plus(unit(r).times(radius * 4 * r.nextDouble()));
            case 1 -> o = c.minus(d.times(radius * (1 + r.nextDouble() * 1e5)));
            case 2 -> {
                // Tangent: the line touches the sphere at c + radius·n.
                Vec3 n = unit(r);
                Vec3 tangent = n.cross(unit(r)).normalize();
                d = tangent;
                o = c.plus(n.times(radius)).minus(tangent.times(radius * 3 * r.nextDouble()));
            }
            default -> o = c.plus(unit(r).times(radius * 0.9 * r.nextDouble()));
        }
        Shapes shapes = new Shapes();
        int s = shapes.add(new Sphere(c, radius, M, Transform.IDENTITY, dev.crt.scene.SourceSpan.NONE), Transform.IDENTITY, 0);
        Ray ray = new Ray();
        ray.set(o.x(), o.y(), o.z(), d.x(), d.y(), d.z());
        LineSpan span = new LineSpan();
        boolean hit = shapes.span(s, ray, span);
        Vec3 oc = o.minus(c);
        double dist = oc.cross(d).length();
        if (dist < radius * (1 - 1e-9)) assertThat(hit).isTrue();
        if (dist > radius * (1 + 1e-9)) assertThat(hit).isFalse();
        if (!hit || dist > radius * (1 - 1e-6)) return;
        double mid = -oc.dot(d), half = Math.sqrt((radius - dist) * (radius + dist));
        double tol = 1e-9 * (Math.abs(mid) + radius);
        assertThat(Math.abs(span.tIn[0] - (mid - half))).isLessThanOrEqualTo(tol);
        assertThat(Math.abs(span.tOut[0] - (mid + half))).isLessThanOrEqualTo(tol);
        SurfacePoint p = new SurfacePoint();
        shapes.surface(s, span.faceIn[0], span.tIn[0], ray, p);
        Vec3 n = new Vec3(p.nx, p.ny, p.nz);
        assertThat(Math.abs(n.length() - 1)).isLessThan(1e-12);
        Vec3 expectedN = o.plus(d.times(mid - half)).minus(c).normalize();
        assertThat(n.minus(expectedN).length()).isLessThan(1e-6);
        assertThat(Math.abs(new Vec3(p.px, p.py, p.pz).minus(c).length() - radius)).isLessThanOrEqualTo(1e-14 * (c.length() + radius) * 8);
    }

    @Property(tries = 1500)
    void boxRaysAlongFacesAndEdgesNeverGiveNaN(@ForAll long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        Vec3 lo = new Vec3(-1, -2, -0.5), hi = new Vec3(2, 1, 0.5);
        Entity b = box(lo, hi, M);
        Tracer t = tracer(b);
        // Origin exactly on a face plane, direction parallel to it.
        int axis = r.nextInt(3);
        double[] o = {r.nextDouble() * 6 - 3, r.nextDouble() * 6 - 3, r.nextDouble() * 6 - 3};
        o[axis] = r.nextBoolean() ? lo.get(axis) : hi.get(axis);
        double[] d = {r.nextDouble() - 0.5, r.nextDouble() - 0.5, r.nextDouble() - 0.5};
        d[axis] = r.nextBoolean() ? 0.0 : -0.0;
        Vec3 dir = new Vec3(d[0], d[1], d[2]).normalize();
        boolean hit = t.closestHit(o[0], o[1], o[2], dir.x(), dir.y(), dir.z(), Double.POSITIVE_INFINITY);
        // Grazing along a face may count as a hit or not, but never with a NaN or negative distance.
        if (hit) assertThat(Double.isFinite(t.hit.t) && t.hit.t > 0).isTrue();
        // From one unit outside that face, aimed at a point well inside the box, the ray must hit,
        // before that point, on the box's surface: an intersector that always misses fails here.
        o[axis] += o[axis] == lo.get(axis) ? -1 : 1;
        Vec3 origin = new Vec3(o[0], o[1], o[2]);
        Vec3 inner = new Vec3(lo.x() + 0.1 + r.nextDouble() * (hi.x() - lo.x() - 0.2),
                lo.y() + 0.1 + r.nextDouble() * (hi.y() - lo.y() - 0.2), lo.z() + 0.1 + r.nextDouble() * (hi.z() - lo.z() - 0.2));
        Vec3 toInner = inner.minus(origin).normalize();
        assertThat(t.closestHit(origin.x(), origin.y(), origin.z(), toInner.x(), toInner.y(), toInner.z(),
                Double.POSITIVE_INFINITY)).as("a ray from outside to a point inside the box hits it").isTrue();
        assertThat(t.hit.t).isPositive().isLessThan(inner.minus(origin).length());
        Vec3 p = origin.plus(toInner.times(t.hit.t));
        double outside = 0, onFace = Double.POSITIVE_INFINITY;
        for (int k = 0; k < 3; k++) {
            outside = Math.max(outside, Math.max(lo.get(k) - p.get(k), p.get(k) - hi.get(k)));
            onFace = Math.min(onFace, Math.min(Math.abs(p.get(k) - lo.get(k)), Math.abs(p.get(k) - hi.get(k))));
        }
        assertThat(outside).as("the hit point is not outside the box").isLessThan(1e-9);
        assertThat(onFace).as("the hit point lies on a face").isLessThan(1e-9);
    }

    /** An entity of the chosen kind with random placement. */
    private static Entity entity(SplittableRandom r, int kind, double spread) {
        return switch (kind) {
            case 0 -> sphere(unit(r).times(r.nextDouble() * spread), 0.3 + r.nextDouble() * 1.5, M);
            case 1 -> box(unit(r).times(spread * r.nextDouble()), unit(r).times(1 + r.nextDouble()), M);
            case 2 -> plane(unit(r), unit(r).times(r.nextDouble()), M);
            case 3 -> sphere(unit(r).times(0.5), 0.5 + r.nextDouble(), M).transformed(Solids.randomTransform(r, true, spread));
            case 4 -> box(unit(r).times(-1), unit(r).times(1).plus(v(1.2, 1.2, 1.2)), M)
                    .transformed(Solids.randomTransform(r, true, spread));
            case 6 -> new Cylinder(unit(r).times(r.nextDouble() * spread), unit(r).times(1 + r.nextDouble() * spread),
                    0.2 + r.nextDouble(), true, M, Transform.IDENTITY, SourceSpan.NONE)
                    .transformed(r.nextBoolean() ? Transform.IDENTITY : Solids.randomTransform(r, true, spread));
            case 7 -> new Cone(unit(r).times(r.nextDouble() * spread), unit(r).times(1 + r.nextDouble() * spread),
                    r.nextInt(4) == 0 ? 0 : 0.2 + r.nextDouble(), r.nextInt(3) == 0 ? 0 : 0.1 + r.nextDouble(), true, M,
                    Transform.IDENTITY, SourceSpan.NONE)
                    .transformed(r.nextBoolean() ? Transform.IDENTITY : Solids.randomTransform(r, true, spread));
            case 8 -> new Torus(unit(r).times(r.nextDouble() * spread), unit(r), 0.5 + r.nextDouble(),
                    r.nextInt(4) == 0 ? 0.6 + r.nextDouble() : 0.1 + 0.4 * r.nextDouble(), M, Transform.IDENTITY, SourceSpan.NONE)
                    .transformed(r.nextBoolean() ? Transform.IDENTITY : Solids.randomTransform(r, true, spread));
            case 9 -> new Mesh(MESH_TORUS, r.nextBoolean(), M, Transform.IDENTITY, SourceSpan.NONE)
                    .transformed(Solids.randomTransform(r, r.nextBoolean(), spread));
            default -> box(v(-1, -0.5, -0.7), v(0.8, 1.1, 0.4), M)
                    .transformed(Transform.rotation(v(90 * r.nextInt(4), 90 * r.nextInt(4), 90 * r.nextInt(4)))
                            .then(Transform.scaling(v(0.5 + r.nextDouble(), 0.5 + r.nextDouble(), 0.5 + r.nextDouble())))
                            .then(Transform.translation(unit(r).times(spread))));
        };
    }

    private static Entity tree(SplittableRandom r, int depth) {
        if (depth == 0 || r.nextInt(4) == 0) return entity(r, r.nextInt(16) == 0 ? 9 : r.nextInt(9), 1.5);
        CsgOperation op = CsgOperation.values()[r.nextInt(3)];
        Entity e = csg(op, tree(r, depth - 1), tree(r, depth - 1));
        return r.nextInt(3) == 0 ? e.transformed(Solids.randomTransform(r, true, 1)) : e;
    }

    /**
     * A tree the way scripts build large solids: chains of one operation grown in a loop
     * ({@code u = u + s}, {@code d = d - s}), right-nested groups ({@code a - (b + (c + d))}) and
     * mixed operations, with enough small leaves scattered about that most rays miss most of them.
     */
    private static Entity wideTree(SplittableRandom r) {
        int leaves = 5 + r.nextInt(30);
        Entity acc = entity(r, r.nextInt(6), 2);
        for (int i = 1; i < leaves; i++) {
            Entity leaf = r.nextInt(8) == 0 ? entity(r, 2, 2) : small(r);
            CsgOperation op = r.nextInt(5) < 3 ? CsgOperation.UNION : CsgOperation.values()[r.nextInt(3)];
            acc = r.nextInt(4) == 0 ? csg(op, leaf, acc) : csg(op, acc, leaf);
            if (r.nextInt(10) == 0) acc = acc.transformed(Solids.randomTransform(r, true, 0.5));
        }
        return acc;
    }

    private static Entity small(SplittableRandom r) {
        Vec3 c = unit(r).times(3 * r.nextDouble());
        double s = 0.2 + 0.6 * r.nextDouble();
        return r.nextBoolean() ? sphere(c, s, M) : box(c.minus(unit(r).times(s)), c.plus(v(s, s, s)), M);
    }

    static Tracer tracer(Entity... entities) {
        Settings s = settings(camera(v(0, 0, -5), Vec3.ZERO, 60), List.of(), Background.BLACK, 4, 4);
        SceneGeometry g = new SceneGeometry(List.of(entities));
        return new Tracer(g, new Lights(s.lights()), new BackgroundShader(s.background(), 1));
    }

    @Property(tries = 4000)
    void firstBoundaryMatchesAMarchWithTheInsideTest(@ForAll long seed, @ForAll @IntRange(min = 0, max = 12) int kind) {
        SplittableRandom r = new SplittableRandom(seed);
        Entity e = kind == 12 ? wideTree(r) : kind == 11 ? tree(r, 3) : entity(r, kind, 1.5);
        double far = r.nextInt(5) == 0 ? 1e5 : 0;
        Vec3 shift = unit(r).times(far);
        if (far > 0) e = e.transformed(Transform.translation(shift));
        Vec3 target = shift.plus(unit(r).times(r.nextDouble() * 2));
        Vec3 o = switch (r.nextInt(3)) {
            case 0 -> shift.plus(unit(r).times(6 + r.nextDouble() * 10));
            case 1 -> shift.plus(unit(r).times(r.nextDouble() * 2));
            default -> shift.plus(unit(r).times(r.nextBoolean() ? 1e3 : 1e5));
        };
        Vec3 d = target.minus(o).normalize();
        if (d.length() != 1 && !(Math.abs(d.length() - 1) < 1e-12)) return;
        Tracer t = tracer(e);
        boolean hit = t.closestHit(o.x(), o.y(), o.z(), d.x(), d.y(), d.z(), Double.POSITIVE_INFINITY);
        double span = o.minus(target).length() + 20;
        double step = span / 4000;
        double eps = 1e-9 * (o.length() + 10);
        // The reference: the first change of the inside-state along (0, span].
        boolean start = Solids.inside(e, o.plus(d.times(eps * 4)));
        double ref = Double.NaN;
        for (int k = 1; k <= 4000; k++) {
            double tk = k * step;
            if (Solids.inside(e, o.plus(d.times(tk))) != start) {
                double a = (k - 1) * step, b = tk;
                for (int it = 0; it < 200 && b - a > eps * 0.01; it++) {
                    double m = 0.5 * (a + b);
                    if (Solids.inside(e, o.plus(d.times(m))) == start) a = m;
                    else b = m;
                }
                ref = 0.5 * (a + b);
                break;
            }
        }
        double tol = 1e-7 * (o.length() + 10);
        if (!hit) {
            assertThat(ref).as("the march finds a boundary the routine missed").isNaN();
            return;
        }
        double th = t.hit.t;
        assertThat(th).isPositive();
        if (!Double.isNaN(ref) && Math.abs(th - ref) <= tol) {
            checkNormal(t, e, d);
            return;
        }
        // Either the routine found a sliver the march stepped over, or the boundary is the origin's own.
        assertThat(Double.isNaN(ref) || th < ref).as("hit at %s but the march says %s", th, ref).isTrue();
        Vec3 p = o.plus(d.times(th));
        boolean here = Solids.inside(e, p);
        boolean boundary = false;
        // Steps from the tolerance down: a slab thinner than the tolerance is crossed whole by the
        // largest step on both sides (a box 0.0026 thick seen from 1e5 away was).
        for (double h = tol; h >= tol * 1e-6; h *= 0.01) {
            for (Vec3 axis : new Vec3[] {Vec3.X, Vec3.Y, Vec3.Z, d}) {
                boundary |= Solids.inside(e, p.plus(axis.times(h))) != here || Solids.inside(e, p.minus(axis.times(h))) != here;
            }
        }
        assertThat(boundary).as("a hit at %s lies on the solid's boundary", th).isTrue();
    }

    private static void checkNormal(Tracer t, Entity e, Vec3 d) {
        SurfacePoint sp = new SurfacePoint();
        t.shapes().surface(t.hit.shape, t.hit.face, t.hit.t, t.ray, sp);
        Vec3 n = new Vec3(sp.nx, sp.ny, sp.nz);
        if (t.hit.flip) n = n.negate();
        assertThat(Math.abs(n.length() - 1)).isLessThan(1e-12);
        Vec3 p = new Vec3(sp.px, sp.py, sp.pz);
        double h = 1e-10 * (p.length() + 1);
        if (Math.abs(n.dot(d)) < 1e-3) return;
        assertThat(Solids.inside(e, p.plus(n.times(h)))).as("outside along the normal at %s, n=%s", p, n).isFalse();
        assertThat(Solids.inside(e, p.minus(n.times(h)))).as("inside against the normal at %s, n=%s", p, n).isTrue();
    }
}
