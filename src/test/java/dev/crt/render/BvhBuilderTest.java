package dev.crt.render;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The hierarchy's invariants: every item in exactly one leaf, every box containing what is below it. */
class BvhBuilderTest {
    private static double[] randomBoxes(int n, long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        double[] b = new double[6 * n];
        for (int i = 0; i < n; i++) {
            for (int a = 0; a < 3; a++) {
                // Clusters, duplicates and flat boxes, to reach the degenerate splits too.
                double c = i % 7 == 0 ? 5 : r.nextDouble() * 100;
                double e = i % 5 == 0 ? 0 : r.nextDouble() * 2;
                b[6 * i + a] = c;
                b[6 * i + 3 + a] = c + e;
            }
        }
        return b;
    }

    private static void check(int n) {
        double[] boxes = randomBoxes(n, n);
        int[] order = new int[n];
        Bvh bvh = BvhBuilder.build(boxes, n, order);
        int[] seen = new int[n];
        int leaves = walk(bvh, 0, boxes, order, seen, null);
        for (int i = 0; i < n; i++) assertThat(seen[i]).as("item %d", i).isEqualTo(1);
        assertThat(leaves).isGreaterThan(0);
        assertThat(bvh.nodeCount).isLessThan(2 * n);
    }

    /** Checks node {@code at} against its parent box and returns how many leaves lie below it. */
    private static int walk(Bvh bvh, int at, double[] boxes, int[] order, int[] seen, double[] parent) {
        double[] box = java.util.Arrays.copyOfRange(bvh.box, 6 * at, 6 * at + 6);
        if (parent != null) {
            for (int a = 0; a < 3; a++) {
                assertThat(box[a]).isGreaterThanOrEqualTo(parent[a]);
                assertThat(box[3 + a]).isLessThanOrEqualTo(parent[3 + a]);
            }
        }
        if (bvh.count[at] > 0) {
            for (int k = bvh.link[at]; k < bvh.link[at] + bvh.count[at]; k++) {
                int item = order[k];
                seen[item]++;
                for (int a = 0; a < 3; a++) {
                    assertThat(boxes[6 * item + a]).isGreaterThanOrEqualTo(box[a]);
                    assertThat(boxes[6 * item + 3 + a]).isLessThanOrEqualTo(box[3 + a]);
                }
            }
            return 1;
        }
        return walk(bvh, at + 1, boxes, order, seen, box) + walk(bvh, bvh.link[at], boxes, order, seen, box);
    }

    @Test
    void smallHierarchiesHoldEveryItemOnce() {
        for (int n : new int[] {1, 2, 3, 5, 17, 100, 1000}) check(n);
    }

    @Test
    void parallelBuildOfALargeSetHoldsEveryItemOnce() {
        check(40_000);
    }
}
