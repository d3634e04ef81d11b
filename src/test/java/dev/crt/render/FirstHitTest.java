package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.Cylinder;
import dev.crt.scene.Material;
import dev.crt.scene.Mesh;
import dev.crt.scene.MeshData;
import dev.crt.scene.Primitive;
import dev.crt.scene.SourceSpan;
import dev.crt.scene.Sphere;
import dev.crt.scene.Torus;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The first-hit and any-hit paths of shapes standing alone (meshes stop their walk at the nearest
 * triangle, tori refine only the first root in the ray's window) against the crossings of the
 * whole line that CSG uses: the same nearest crossing, bit for bit, and a shadow hit exactly when
 * some crossing lies in the segment. Rays come from around the shape, from far away, from points
 * just off its surface (as shadow and reflected rays do), grazing it, with and without a far end.
 */
class FirstHitTest {
    private static final Material M = matte(rgb(0.5, 0.5, 0.5));
    private static final Transform PLACED = Transform.rotation(new Vec3(20, 35, -10))
            .then(Transform.scaling(new Vec3(1.5, 0.75, 1.2))).then(Transform.translation(new Vec3(0.3, -0.2, 0.5)));

    @Test
    void closedMeshNearestCrossingIsTheFirstOfItsSpan() {
        check(new Mesh(Meshes.torus(1, 0.4, 24, 12), false, M, PLACED, SourceSpan.NONE), 4000);
    }

    @Test
    void openMeshNearestCrossingIsTheFirstOfItsSpan() {
        check(new Mesh(Meshes.grid(6), false, M, PLACED, SourceSpan.NONE), 4000);
    }

    @Test
    void smallMeshTestedWithoutHierarchy() {
        double[] p = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
        int[] t = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
        MeshData octahedron = new MeshData("octahedron", p, t, null, null, true);
        assertThat(new MeshGeometry(octahedron).bvh).isNull();
        check(new Mesh(octahedron, false, M, PLACED, SourceSpan.NONE), 4000);
    }

    @Test
    void torusNearestCrossingIsTheFirstOfItsSpan() {
        check(new Torus(new Vec3(0.2, 0.1, -0.3), new Vec3(0.3, 1, 0.2), 1, 0.35, M, PLACED, SourceSpan.NONE), 4000);
        // A spindle torus: its inner sheet is crossed without being a boundary of the solid.
        check(new Torus(Vec3.ZERO, new Vec3(0, 0, 1), 0.6, 0.9, M, Transform.IDENTITY, SourceSpan.NONE), 4000);
    }

    @Test
    void otherShapesReadTheFirstCrossingOfTheirSpan() {
        check(new Sphere(new Vec3(0.1, 0.2, 0.3), 0.8, M, PLACED, SourceSpan.NONE), 1000);
        check(new Cylinder(new Vec3(0, -1, 0), new Vec3(0.2, 1, 0.1), 0.5, true, M, PLACED, SourceSpan.NONE), 1000);
        check(new Cylinder(new Vec3(0, -1, 0), new Vec3(0.2, 1, 0.1), 0.5, false, M, PLACED, SourceSpan.NONE), 1000);
    }

    /** Compares firstHit and anyHit with the span on rays of every family; counts that each family hit. */
    private static void check(Primitive p, int rays) {
        Shapes shapes = new Shapes();
        int s = shapes.add(p, p.transform(), 0);
        var bounds = shapes.bounds(s);
        Vec3 centre = bounds.min().plus(bounds.max()).times(0.5);
        double size = bounds.max().minus(bounds.min()).length();
        SplittableRandom random = new SplittableRandom(12);
        Ray ray = new Ray();
        LineSpan span = new LineSpan(), reference = new LineSpan();
        Hit hit = new Hit();
        int hits = 0, blocked = 0, fromSurface = 0;
        for (int i = 0; i < rays; i++) {
            int family = i % 4;
            Vec3 d = unit(random);
            Vec3 o;
            if (family == 0) {
                o = centre.plus(unit(random).times(size * (0.1 + random.nextDouble())));
            } else if (family == 1) {
                // From 10⁴ sizes away, aimed near the centre.
                Vec3 aim = centre.plus(unit(random).times(0.4 * size * random.nextDouble()));
                o = aim.minus(d.times(1e4 * size));
            } else {
                // Just off a crossing of some line through the shape: as a shadow or reflected ray leaves it.
                Vec3 a = centre.plus(unit(random).times(0.5 * size * random.nextDouble()));
                Vec3 w = unit(random);
                ray.set(a.x(), a.y(), a.z(), w.x(), w.y(), w.z());
                if (!shapes.span(s, ray, reference) || reference.count == 0) {
                    o = a.minus(w.times(size));
                } else {
                    double t = reference.tIn[0];
                    if (!Double.isFinite(t)) t = reference.tOut[0];
                    Vec3 q = a.plus(w.times(t));
                    o = q.plus(unit(random).times(size * (family == 2 ? 0x1p-36 : 1e-9)));
                    if (family == 3) d = w.plus(unit(random).times(1e-7)).times(1);
                    fromSurface++;
                }
            }
            double tMax = random.nextInt(3) == 0 ? Double.POSITIVE_INFINITY : random.nextDouble() * 2 * size
                    + (family == 1 ? 1e4 * size : 0);
            ray.set(o.x(), o.y(), o.z(), d.x(), d.y(), d.z());
            boolean expected = shapes.span(s, ray, reference);
            double t = Double.NaN;
            int face = -1;
            boolean any = false;
            if (expected) {
                for (int k = 0; k < reference.count; k++) {
                    double in = reference.tIn[k], out = reference.tOut[k];
                    if (in > 0 && in < tMax || out > 0 && out < tMax) any = true;
                    if (t == t) continue;
                    if (in > 0) {
                        t = in;
                        face = reference.faceIn[k];
                    } else if (out > 0) {
                        t = out;
                        face = reference.faceOut[k];
                    }
                }
            }
            boolean first = t == t && t < tMax;
            ray.set(o.x(), o.y(), o.z(), d.x(), d.y(), d.z());
            boolean found = shapes.firstHit(s, ray, tMax, span, hit);
            assertThat(found).as("ray %d (family %d) hit", i, family).isEqualTo(first);
            if (first) {
                hits++;
                assertThat(hit.t).as("ray %d t", i).isEqualTo(t);
                assertThat(hit.shape).isEqualTo(s);
                assertThat(hit.flip).isFalse();
                // The face carries the side (a closed mesh's flip bit) as the span's parity gives it.
                assertThat(hit.face).as("ray %d face", i).isEqualTo(face);
            }
            ray.set(o.x(), o.y(), o.z(), d.x(), d.y(), d.z());
            assertThat(shapes.anyHit(s, ray, tMax, span)).as("ray %d (family %d) shadow", i, family).isEqualTo(any);
            if (any) blocked++;
        }
        // Each family reached the shape often enough for the comparison to mean something.
        assertThat(hits).isGreaterThan(rays / 10);
        assertThat(blocked).isGreaterThan(rays / 10);
        assertThat(fromSurface).isGreaterThan(rays / 8);
    }

    private static Vec3 unit(SplittableRandom random) {
        while (true) {
            double x = 2 * random.nextDouble() - 1, y = 2 * random.nextDouble() - 1, z = 2 * random.nextDouble() - 1;
            double l = x * x + y * y + z * z;
            if (l > 1e-4 && l <= 1) return new Vec3(x, y, z).div(Math.sqrt(l));
        }
    }
}
