package dev.crt.render;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.scene.MeshData;
import java.util.SplittableRandom;
import java.util.concurrent.atomic.AtomicIntegerArray;
import java.util.function.Supplier;
import org.junit.jupiter.api.Test;

/**
 * The passes of a scene's preparation that run on several cores (the BVH's renumbering and boxes,
 * a mesh's triangle boxes, degenerate-triangle count and reordering) give the same result to the
 * bit for one thread and several, on inputs below and above {@link Parallel#MIN_CHUNK}.
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
