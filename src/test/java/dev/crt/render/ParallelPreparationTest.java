package dev.crt.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.CsgOperation;
import dev.crt.scene.Entity;
import dev.crt.scene.Material;
import dev.crt.scene.Mesh;
import dev.crt.scene.MeshData;
import dev.crt.scene.Sphere;
import dev.crt.scene.SourceSpan;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.atomic.AtomicIntegerArray;
import java.util.function.Supplier;
import org.junit.jupiter.api.Test;

/**
 * The passes of a scene's preparation that run on several cores (the BVH's renumbering and boxes,
 * a mesh's triangle boxes, degenerate-triangle count and reordering, the plain spheres' bounds and
 * materials, the scene's shapes placed in traversal order) give the same result to the bit for one
 * thread and several, on inputs below and above {@link Parallel#MIN_CHUNK}.
 */
class ParallelPreparationTest {
    @Test
    void chunksCoverTheRangeOnceInOrder() {
        for (int n : new int[] {0, 1, Parallel.MIN_CHUNK - 1, Parallel.MIN_CHUNK, 2 * Parallel.MIN_CHUNK + 1, 1_000_003}) {
            for (int threads : new int[] {1, 2, 3, 8}) {
                withThreads(threads, () -> {
                    AtomicIntegerArray seen = new AtomicIntegerArray(n);
                    int chunks = Parallel.chunks(n);
                    int[] starts = new int[chunks + 1];
                    Parallel.forChunks(n, chunks, (chunk, from, to) -> {
                        starts[chunk] = from;
                        if (chunk == chunks - 1) starts[chunks] = to;
                        for (int i = from; i < to; i++) seen.incrementAndGet(i);
                    });
                    for (int i = 0; i < n; i++) assertThat(seen.get(i)).as("item %d of %d, %d threads", i, n, threads).isEqualTo(1);
                    assertThat(starts[0]).isZero();
                    assertThat(starts[chunks]).isEqualTo(n);
                    for (int c = 0; c < chunks; c++) assertThat(starts[c + 1]).isGreaterThanOrEqualTo(starts[c]);
                    if (n < Parallel.MIN_CHUNK) assertThat(chunks).isEqualTo(1);
                    return null;
                });
            }
        }
    }

    @Test
    void aChunksFailureIsThrownToTheCallerAfterTheOthersAreDone() {
        for (int threads : new int[] {1, 2, 4}) {
            AtomicIntegerArray ran = new AtomicIntegerArray(4);
            int n = 4 * Parallel.MIN_CHUNK;
            assertThatThrownBy(() -> withThreads(threads, () -> {
                int chunks = Parallel.chunks(n);
                Parallel.forChunks(n, chunks, (chunk, from, to) -> {
                    ran.incrementAndGet(chunk);
                    if (chunk == chunks - 1) throw new IllegalArgumentException("chunk " + chunk);
                });
                return null;
            })).as("%d threads", threads).isInstanceOf(IllegalArgumentException.class).hasMessage("chunk " + (Math.min(threads, 4) - 1));
            for (int k = 0; k < Math.min(threads, 4); k++) assertThat(ran.get(k)).as("chunk %d, %d threads", k, threads).isEqualTo(1);
        }
    }

    @Test
    void sameTreeForOneThreadAndSeveral() {
        // Small builds (one chunk), builds binned to the leaves, and Morton-finished ones.
        int set = 100;
        for (int n : new int[] {5, 9, 1000, Parallel.MIN_CHUNK + 7, BvhBuilder.MORTON_ABOVE + 1}) {
            for (int kind = 0; kind < 4; kind++) {
                double[] boxes = BvhBuilderSameTreeTest.boxes(kind, n, ++set);
                int[] oneOrder = new int[n];
                Bvh one = withThreads(1, () -> BvhBuilder.build(boxes.clone(), n, oneOrder));
                for (int threads : new int[] {2, 3}) {
                    int[] order = new int[n];
                    Bvh several = withThreads(threads, () -> BvhBuilder.build(boxes.clone(), n, order));
                    String what = "kind " + kind + ", " + n + " items, " + threads + " threads";
                    assertThat(order).as(what).isEqualTo(oneOrder);
                    assertThat(several.nodeCount).as(what).isEqualTo(one.nodeCount);
                    assertThat(several.depth).as(what).isEqualTo(one.depth);
                    assertThat(several.root).as(what).isEqualTo(one.root);
                    assertThat(several.children).as(what).isEqualTo(one.children);
                    assertThat(several.box).as(what).isEqualTo(one.box);
                }
            }
        }
    }

    @Test
    void sameMeshGeometryForOneThreadAndSeveral() {
        for (int n : new int[] {3, 1000, 3 * Parallel.MIN_CHUNK + 1, 200_000}) {
            for (boolean withDegenerate : new boolean[] {false, true}) {
                MeshData data = strip(n, withDegenerate, n);
                MeshGeometry one = withThreads(1, () -> new MeshGeometry(data));
                MeshGeometry several = withThreads(2, () -> new MeshGeometry(data));
                String what = n + " triangles" + (withDegenerate ? " with degenerate ones" : "");
                assertThat(several.count).as(what).isEqualTo(one.count);
                if (withDegenerate && n > 5) assertThat(one.count).as(what).isLessThan(n);
                assertThat(several.triangles).as(what).isEqualTo(one.triangles);
                assertThat(several.box).as(what).isEqualTo(one.box);
                assertThat(several.bounds).as(what).isEqualTo(one.bounds);
                if (one.bvh == null) {
                    assertThat(several.bvh).as(what).isNull();
                } else {
                    assertThat(several.bvh.children).as(what).isEqualTo(one.bvh.children);
                    assertThat(several.bvh.box).as(what).isEqualTo(one.bvh.box);
                }
            }
        }
    }

    @Test
    void sameSceneGeometryForOneThreadAndSeveral() {
        // Spheres in runs long enough to be placed in chunks, broken by boxes, transformed
        // spheres, mesh instances, CSG trees and planes, with a palette of materials.
        SplittableRandom r = new SplittableRandom(7);
        Material[] paints = {Scenes.matte(Scenes.rgb(1, 0, 0)), Scenes.matte(Scenes.rgb(0, 1, 0)), Scenes.matte(Scenes.rgb(0, 0, 1))};
        MeshData mesh = strip(500, false, 3);
        List<Entity> entities = new ArrayList<>();
        for (int i = 0; i < 3 * Parallel.MIN_CHUNK; i++) {
            Vec3 c = Scenes.v(r.nextDouble(-10, 10), r.nextDouble(-10, 10), r.nextDouble(-10, 10));
            Material m = paints[i % 3];
            if (i % 5000 == 17) entities.add(Scenes.box(c, c.plus(Scenes.v(0.1, 0.2, 0.3)), m));
            else if (i % 7000 == 3) entities.add(new Sphere(c, 0.05, m, Transform.scaling(Scenes.v(1, 2, 3)), SourceSpan.NONE));
            else if (i % 9000 == 5) entities.add(new Mesh(mesh, true, m, Transform.translation(c), SourceSpan.NONE));
            else if (i % 11000 == 8) entities.add(Scenes.csg(CsgOperation.DIFFERENCE, Scenes.sphere(c, 0.2, m), Scenes.box(c, c.plus(Scenes.v(1, 1, 1)), m)));
            else if (i % 20000 == 9) entities.add(Scenes.plane(Scenes.v(0, 1, 0), c, m));
            else entities.add(Scenes.sphere(c, 0.03, m));
        }
        SceneGeometry one = withThreads(1, () -> new SceneGeometry(entities));
        for (int threads : new int[] {2, 3}) {
            SceneGeometry several = withThreads(threads, () -> new SceneGeometry(entities));
            assertSameGeometry(several, one, threads + " threads");
            assertThat(several.shapes.meshes).hasSize(1);
        }
        // Every entity but the planes' is in the hierarchy, each of its shapes owned by it.
        assertThat(one.items.length + one.unbounded.length).isEqualTo(entities.size());
        assertThat(one.bvh).isNotNull();
    }

    @Test
    void sameSceneGeometryForOneThreadAndSeveralOnTinyAndOddScenes() {
        Material red = Scenes.matte(Scenes.rgb(1, 0, 0)), blue = Scenes.matte(Scenes.rgb(0, 0, 1));
        Entity plain = Scenes.sphere(Scenes.v(1, 2, 3), 0.5, red);
        Entity far = Scenes.sphere(Scenes.v(1e308, 0, 0), 1e308, blue);
        Entity flat = Scenes.sphere(Scenes.v(0, 0, 0), 0, red);
        Entity plane = Scenes.plane(Scenes.v(0, 1, 0), Scenes.v(0, -1, 0), blue);
        Entity cut = Scenes.csg(CsgOperation.DIFFERENCE, Scenes.sphere(Scenes.v(0, 0, 0), 1, red), Scenes.box(Scenes.v(0, 0, 0), Scenes.v(2, 2, 2), blue));
        List<List<Entity>> scenes = List.of(List.of(), List.of(plain), List.of(plane), List.of(cut), List.of(far, flat),
                List.of(plain, far, flat, plane, cut, plain, plain, plain, plain, cut),
                List.of(plain, plain, plain, plain, plain, plain));
        for (List<Entity> entities : scenes) {
            SceneGeometry one = withThreads(1, () -> new SceneGeometry(entities));
            for (int threads : new int[] {2, 3}) {
                SceneGeometry several = withThreads(threads, () -> new SceneGeometry(entities));
                assertSameGeometry(several, one, entities.size() + " entities, " + threads + " threads");
            }
        }
        SceneGeometry odd = new SceneGeometry(scenes.get(4));
        assertThat(odd.items).isEmpty();
        assertThat(odd.unbounded).as("a sphere of infinite bounds is tested by every ray; one of radius 0 nowhere").hasSize(1);
    }

    @Test
    void plainSpheresArePlacedAsTheGeneralPathPlacesThem() {
        // The same spheres, once untransformed (measured in chunks, written from the entity) and
        // once under a transform equal to the identity but not it (flattened by Shapes.add and
        // copied): the same shapes, materials and tree, only the matrices' places differ.
        SplittableRandom r = new SplittableRandom(11);
        Material[] paints = {Scenes.matte(Scenes.rgb(1, 0, 0)), Scenes.matte(Scenes.rgb(0, 1, 0)), Scenes.matte(Scenes.rgb(0, 0, 1))};
        Transform same = Transform.translation(Scenes.v(0, 0, 0));
        List<Entity> plain = new ArrayList<>(), general = new ArrayList<>();
        for (int i = 0; i < 2 * Parallel.MIN_CHUNK + 5; i++) {
            Vec3 c = Scenes.v(r.nextDouble(-10, 10), r.nextDouble(-10, 10), r.nextDouble(-10, 10));
            double radius = r.nextDouble(0.01, 0.1);
            plain.add(Scenes.sphere(c, radius, paints[i % 3]));
            general.add(new Sphere(c, radius, paints[i % 3], same, SourceSpan.NONE));
        }
        for (int threads : new int[] {1, 2}) {
            SceneGeometry a = withThreads(threads, () -> new SceneGeometry(plain));
            SceneGeometry b = withThreads(threads, () -> new SceneGeometry(general));
            String what = threads + " threads";
            assertThat(a.items).as(what).isEqualTo(b.items);
            assertThat(a.owner).as(what).isEqualTo(b.owner);
            assertThat(a.bvh.children).as(what).isEqualTo(b.bvh.children);
            assertThat(a.bvh.box).as(what).isEqualTo(b.bvh.box);
            assertSameShapes(a.shapes, b.shapes, what);
            assertThat(a.materials.data).as(what).isEqualTo(b.materials.data);
            assertThat(a.shapes.placement[0]).as("the identity's place").isZero();
        }
    }

    private static void assertSameGeometry(SceneGeometry several, SceneGeometry one, String what) {
        assertThat(several.items).as(what).isEqualTo(one.items);
        assertThat(several.unbounded).as(what).isEqualTo(one.unbounded);
        assertThat(several.owner).as(what).isEqualTo(one.owner);
        if (one.bvh == null) {
            assertThat(several.bvh).as(what).isNull();
        } else {
            assertThat(several.bvh.children).as(what).isEqualTo(one.bvh.children);
            assertThat(several.bvh.box).as(what).isEqualTo(one.bvh.box);
        }
        assertSameShapes(several.shapes, one.shapes, what);
        assertThat(Arrays.copyOf(several.shapes.placement, one.shapes.count())).as(what)
                .isEqualTo(Arrays.copyOf(one.shapes.placement, one.shapes.count()));
        assertThat(several.shapes.meshes).as(what).hasSameSizeAs(one.shapes.meshes);
        assertThat(several.materials.data).as(what).isEqualTo(one.materials.data);
    }

    /** The same shapes: kinds, offsets, materials, scales, data, and the matrices of their placements by value (−0 = 0). */
    private static void assertSameShapes(Shapes b, Shapes a, String what) {
        assertThat(b.count()).as(what).isEqualTo(a.count());
        assertThat(b.dataSize()).as(what).isEqualTo(a.dataSize());
        assertThat(Arrays.copyOf(b.kind, b.count())).as(what).isEqualTo(Arrays.copyOf(a.kind, a.count()));
        assertThat(Arrays.copyOf(b.offset, b.count())).as(what).isEqualTo(Arrays.copyOf(a.offset, a.count()));
        assertThat(Arrays.copyOf(b.material, b.count())).as(what).isEqualTo(Arrays.copyOf(a.material, a.count()));
        assertThat(Arrays.copyOf(b.scale, b.count())).as(what).isEqualTo(Arrays.copyOf(a.scale, a.count()));
        assertThat(Arrays.copyOf(b.data, b.dataSize())).as(what).isEqualTo(Arrays.copyOf(a.data, a.dataSize()));
        for (int s = 0; s < a.count(); s++) {
            for (int k = 0; k < 12; k++) {
                // == rather than equals: the general path's matrix of a translation by zero has −0 where the identity has 0.
                double x = b.placements.toEntity[b.placement[s] + k], y = a.placements.toEntity[a.placement[s] + k];
                assertThat(x == y).as("%s, shape %d, matrix entry %d: %s against %s", what, s, k, x, y).isTrue();
            }
        }
    }

    /** A random triangle strip of {@code n} triangles; with {@code degenerate}, every 97th has a repeated vertex. */
    private static MeshData strip(int n, boolean degenerate, long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        double[] p = new double[3 * (n + 2)];
        for (int i = 0; i < p.length; i++) p[i] = r.nextDouble(-50, 50);
        int[] t = new int[3 * n];
        for (int i = 0; i < n; i++) {
            t[3 * i] = i;
            t[3 * i + 1] = i + 1;
            t[3 * i + 2] = degenerate && i % 97 == 5 ? i : i + 2;
        }
        double[] normals = new double[p.length];
        return new MeshData("strip", p, t, normals, null, false);
    }

    static <T> T withThreads(int threads, Supplier<T> work) {
        int before = Parallel.threads;
        Parallel.threads = threads;
        try {
            return work.get();
        } finally {
            Parallel.threads = before;
        }
    }
}
