package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.Entity;
import dev.crt.scene.Material;
import dev.crt.scene.Mesh;
import dev.crt.scene.MeshData;
import dev.crt.scene.SourceSpan;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The watertight ray–triangle test, the parity inside of closed meshes, and shared instances. */
class MeshTest {
    private static final Material M = matte(rgb(0.5, 0.5, 0.5));

    private static int crossings(Shapes shapes, int s, Vec3 o, Vec3 d) {
        Ray ray = new Ray();
        ray.set(o.x(), o.y(), o.z(), d.x(), d.y(), d.z());
        LineSpan span = new LineSpan();
        return shapes.span(s, ray, span) ? span.count : 0;
    }

    /**
     * Rays aimed exactly at the grid's vertices (where up to six triangles meet), at points of its
     * shared edges (sides and diagonals) and at random points, straight and slanted: each crosses
     * the open grid exactly once, never zero times (a crack) or twice (counted by both neighbours).
     */
    @Test
    void raysThroughSharedEdgesAndVerticesCrossExactlyOnce() {
        Shapes shapes = new Shapes();
        int s = shapes.add(new Mesh(Meshes.grid(6), false, M, Transform.IDENTITY, SourceSpan.NONE), Transform.IDENTITY, 0);
        SplittableRandom r = new SplittableRandom(7);
        int tested = 0;
        for (int i = 1; i < 6; i++) {
            for (int j = 1; j < 6; j++) {
                Vec3[] targets = {v(i, j, 0), v(i + 0.5, j, 0), v(i, j + 0.25, 0), v(i + 0.5, j + 0.5, 0),
                    v(i + 0.375, j + 0.625, 0), v(i + r.nextDouble(), j + r.nextDouble(), 0)};
                for (Vec3 target : targets) {
                    for (Vec3 d : new Vec3[] {v(0, 0, 1), v(0, 0, -1), v(0.25, -0.5, 1).normalize(),
                        v(-0.3, 0.1, -1).normalize(), v(r.nextDouble() - 0.5, r.nextDouble() - 0.5, 1).normalize()}) {
                        Vec3 o = target.minus(d.times(3));
                        assertThat(crossings(shapes, s, o, d)).as("at %s along %s", target, d).isEqualTo(1);
                        tested++;
                    }
                }
            }
        }
        assertThat(tested).isEqualTo(750);
    }

    /**
     * A closed mesh seen from anywhere is crossed an even number of times, also through its
     * vertices and edges; between crossings the winding number agrees with the parity.
     */
    @Test
    void aClosedMeshIsCrossedEvenlyAndItsInsideMatchesTheWindingNumber() {
        MeshData torus = Meshes.torus(1, 0.4, 12, 8);
        Shapes shapes = new Shapes();
        Mesh m = new Mesh(torus, false, M, Transform.IDENTITY, SourceSpan.NONE);
        int s = shapes.add(m, Transform.IDENTITY, 0);
        SplittableRandom r = new SplittableRandom(11);
        double[] p = torus.positions();
        int[] t = torus.triangles();
        for (int k = 0; k < 3000; k++) {
            // Through a vertex, an edge's midpoint, or anywhere near.
            int tri = r.nextInt(t.length / 3);
            Vec3 a = new Vec3(p[3 * t[3 * tri]], p[3 * t[3 * tri] + 1], p[3 * t[3 * tri] + 2]);
            Vec3 b = new Vec3(p[3 * t[3 * tri + 1]], p[3 * t[3 * tri + 1] + 1], p[3 * t[3 * tri + 1] + 2]);
            Vec3 target = switch (k % 3) {
                case 0 -> a;
                case 1 -> a.plus(b).times(0.5);
                default -> new Vec3(r.nextDouble() * 3 - 1.5, r.nextDouble() * 3 - 1.5, r.nextDouble() - 0.5);
            };
            Vec3 d = new Vec3(r.nextDouble() - 0.5, r.nextDouble() - 0.5, r.nextDouble() - 0.5).normalize();
            Vec3 o = target.minus(d.times(5));
            Ray ray = new Ray();
            ray.set(o.x(), o.y(), o.z(), d.x(), d.y(), d.z());
            LineSpan span = new LineSpan();
            if (!shapes.span(s, ray, span)) continue;
            for (int i = 0; i < span.count; i++) {
                assertThat(span.tIn[i]).isLessThanOrEqualTo(span.tOut[i]);
                double mid = 0.5 * (span.tIn[i] + span.tOut[i]);
                if (span.tOut[i] - span.tIn[i] > 1e-6) {
                    assertThat(Solids.inside(m, o.plus(d.times(mid)))).as("inside at %s", mid).isTrue();
                }
                if (i + 1 < span.count && span.tIn[i + 1] - span.tOut[i] > 1e-6) {
                    double gap = 0.5 * (span.tOut[i] + span.tIn[i + 1]);
                    assertThat(Solids.inside(m, o.plus(d.times(gap)))).as("outside at %s", gap).isFalse();
                }
            }
        }
    }

    @Test
    void instancesOfOneMeshShareItsPreparedTriangles() {
        MeshData data = Meshes.torus(1, 0.3, 24, 12);
        Entity a = new Mesh(data, true, M, Transform.IDENTITY, SourceSpan.NONE);
        Entity b = a.transformed(Transform.translation(v(3, 0, 0)));
        Entity c = csg(dev.crt.scene.CsgOperation.DIFFERENCE, sphere(v(-3, 0, 0), 1.2, M),
                a.transformed(Transform.translation(v(-3, 0, 0))));
        SceneGeometry g = new SceneGeometry(List.of(a, b, c, sphere(v(0, 3, 0), 1, M), sphere(v(0, -3, 0), 1, M),
                sphere(v(0, 6, 0), 1, M)));
        assertThat(g.shapes.meshes).hasSize(1);
    }

    /**
     * Triangles of no area (a repeated vertex, three vertices on a line) are dropped when the mesh
     * is prepared: a mesh of only those renders as nothing beside a ball, without NaN or failure,
     * and one mixed into a grid leaves one crossing through the edge it lies on.
     */
    @Test
    void trianglesOfNoAreaAreDropped() {
        double[] p = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0};
        MeshData flat = new MeshData("flat", p, new int[] {0, 1, 2, 0, 0, 3, 3, 3, 3}, null, null, false);
        assertThat(new MeshGeometry(flat).count).isZero();
        var settings = settings(camera(v(0, 0, -5), v(0, 0, 0), 40), List.of(point(v(0, 5, -5), dev.crt.scene.Rgb.WHITE, 0, 0.1)),
                new dev.crt.scene.SolidBackground(rgb(0, 0, 1)), 32, 24);
        var fb = Renderer.prepare(scene(settings, new Mesh(flat, false, M, Transform.IDENTITY, SourceSpan.NONE),
                sphere(v(0, 0, 0), 1, M))).render(2, RenderMonitor.NONE);
        var alone = Renderer.prepare(scene(settings, sphere(v(0, 0, 0), 1, M))).render(2, RenderMonitor.NONE);
        assertThat(fb.data()).containsExactly(alone.data());
        MeshData grid = Meshes.grid(2);
        int[] t = java.util.Arrays.copyOf(grid.triangles(), grid.triangles().length + 3);
        // Along the shared side x = 1 of the first two cells: (1, 0), (1, 1), (1, 2).
        t[t.length - 3] = 3;
        t[t.length - 2] = 4;
        t[t.length - 1] = 5;
        Shapes shapes = new Shapes();
        int s = shapes.add(new Mesh(new MeshData("grid+sliver", grid.positions(), t, null, null, false), false, M,
                Transform.IDENTITY, SourceSpan.NONE), Transform.IDENTITY, 0);
        assertThat(crossings(shapes, s, v(1, 0.5, -1), v(0, 0, 1))).isEqualTo(1);
    }

    /**
     * On a smooth octahedron whose vertex normals point away from its centre, lights are looked at
     * from the point lifted towards the sphere those normals describe: outward from the flat face,
     * by at most the face's distance to that sphere, and not at all at a corner.
     */
    @Test
    void smoothTrianglesAreLitFromTheLiftedPoint() {
        double[] p = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
        int[] t = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
        MeshData octahedron = new MeshData("octahedron", p, t, p.clone(), null, true);
        Shapes shapes = new Shapes();
        int s = shapes.add(new Mesh(octahedron, true, M, Transform.IDENTITY, SourceSpan.NONE), Transform.IDENTITY, 0);
        Ray ray = new Ray();
        LineSpan span = new LineSpan();
        SurfacePoint q = new SurfacePoint();
        Vec3 centre = v(1, 1, 1).normalize();
        ray.set(3, 3, 3, -centre.x(), -centre.y(), -centre.z());
        assertThat(shapes.span(s, ray, span)).isTrue();
        shapes.surface(s, span.faceIn[0], span.tIn[0], ray, q);
        assertThat(q.shaded).isTrue();
        Vec3 flat = v(q.px, q.py, q.pz), lifted = v(q.lx, q.ly, q.lz);
        double rise = lifted.minus(flat).dot(centre);
        // The face's centre is 1/√3 from the origin; the sphere of the normals is at 1.
        assertThat(rise).isGreaterThan(0.05).isLessThanOrEqualTo(1 - 1 / Math.sqrt(3) + 1e-9);
        ray.set(3, 1e-9, 2e-9, -1, 0, 0);
        assertThat(shapes.span(s, ray, span)).isTrue();
        shapes.surface(s, span.faceIn[0], span.tIn[0], ray, q);
        assertThat(v(q.lx, q.ly, q.lz).minus(v(q.px, q.py, q.pz)).length()).isLessThan(1e-6);
    }
}
