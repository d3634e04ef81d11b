package dev.crt.render;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The four-wide tree against the binary one it is collapsed from (the same leaves in the same
 * left-to-right order, each behind the binary tree's own box), and its walks against the binary
 * walks and against testing every item.
 */
class Bvh4Test {
    private static double[] randomBoxes(int n, long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        double[] b = new double[6 * n];
        for (int i = 0; i < n; i++) {
            for (int a = 0; a < 3; a++) {
                // Clusters, duplicates and flat boxes, as in BvhBuilderTest.
                double c = i % 7 == 0 ? 5 : r.nextDouble() * 100;
                double e = i % 5 == 0 ? 0 : r.nextDouble() * 2;
                b[6 * i + a] = c;
                b[6 * i + 3 + a] = c + e;
            }
        }
        return b;
    }

    /** The binary tree's leaves left to right, each with its box. */
    private static void binaryLeaves(Bvh bvh, int node, List<Integer> leaves, List<double[]> boxes) {
        for (int c = 0; c < 2; c++) {
            int child = bvh.children[2 * node + c];
            if (Bvh.isLeaf(child)) {
                leaves.add(child);
                double[] box = new double[6];
                for (int a = 0; a < 6; a++) box[a] = bvh.bound(node, c, a);
                boxes.add(box);
            } else {
                binaryLeaves(bvh, child, leaves, boxes);
            }
        }
    }

    /** The same for the wide tree; also checks each wide box is the union of what is below it. */
    private static int wideLeaves(Bvh4 wide, int node, List<Integer> leaves, List<double[]> boxes, int level) {
        int depth = level;
        int used = 0;
        for (int c = 0; c < Bvh4.WIDTH; c++) {
            int child = wide.children[Bvh4.WIDTH * node + c];
            double[] box = new double[6];
            for (int a = 0; a < 6; a++) box[a] = wide.bound(node, c, a);
            if (child == Bvh4.NONE) {
                assertThat(box).containsExactly(Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
                        Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY,
                        Double.NEGATIVE_INFINITY);
                continue;
            }
            // Unused slots only at the end, so slot order is left-to-right order.
            assertThat(c).isEqualTo(used++);
            if (Bvh.isLeaf(child)) {
                leaves.add(child);
                boxes.add(box);
            } else {
                assertThat(child).as("depth-first order").isGreaterThan(node);
                int first = boxes.size();
                depth = Math.max(depth, wideLeaves(wide, child, leaves, boxes, level + 1));
                for (int i = first; i < boxes.size(); i++) {
                    for (int a = 0; a < 3; a++) {
                        assertThat(boxes.get(i)[a]).isGreaterThanOrEqualTo(box[a]);
                        assertThat(boxes.get(i)[3 + a]).isLessThanOrEqualTo(box[3 + a]);
                    }
                }
            }
        }
        assertThat(used).isGreaterThanOrEqualTo(2);
        return depth;
    }

    @Test
    void collapseKeepsTheLeavesTheirOrderAndTheirBoxes() {
        for (int n : new int[] {5, 6, 9, 17, 100, 1000, 20_000}) {
            double[] boxes = randomBoxes(n, n);
            Bvh bvh = BvhBuilder.build(boxes, n, new int[n]);
            Bvh4 wide = Bvh4.collapse(bvh);
            List<Integer> binary = new ArrayList<>(), collapsed = new ArrayList<>();
            List<double[]> binaryBoxes = new ArrayList<>(), collapsedBoxes = new ArrayList<>();
            binaryLeaves(bvh, 0, binary, binaryBoxes);
            int depth = wideLeaves(wide, 0, collapsed, collapsedBoxes, 1);
            assertThat(collapsed).as("n = %d", n).isEqualTo(binary);
            for (int i = 0; i < binary.size(); i++) assertThat(collapsedBoxes.get(i)).isEqualTo(binaryBoxes.get(i));
            assertThat(wide.depth).isEqualTo(depth).isLessThan(bvh.depth);
            assertThat(wide.root).isEqualTo(bvh.root);
            if (n >= 100) assertThat(wide.nodeCount).isLessThan(bvh.nodeCount / 3);
        }
    }

    /** A ray from around the items' cube towards a point inside it, some along axes, some from a clustered box's plane. */
    private static Ray randomRay(SplittableRandom r) {
        Ray ray = new Ray();
        double ox = r.nextInt(4) == 0 ? 5 : r.nextDouble(-50, 150), oy = r.nextDouble(-50, 150), oz = r.nextDouble(-50, 150);
        double dx = r.nextDouble(0, 100) - ox, dy = r.nextDouble(0, 100) - oy, dz = r.nextDouble(0, 100) - oz;
        switch (r.nextInt(8)) {
            case 0 -> dx = 0;
            case 1 -> dy = -0.0;
            case 2 -> { dx = 0; dz = 0; }
            default -> { }
        }
        ray.set(ox, oy, oz, dx, dy, dz);
        return ray;
    }

    @Test
    void anyWalkMeetsTheBinaryWalksLeavesInItsOrder() {
        int n = 3000;
        Bvh bvh = BvhBuilder.build(randomBoxes(n, 7), n, new int[n]);
        Bvh4 wide = Bvh4.collapse(bvh);
        BvhWalker binary = new BvhWalker(bvh.depth + 2);
        Bvh4Walker walker = new Bvh4Walker(wide.depth);
        SplittableRandom r = new SplittableRandom(11);
        int nonEmpty = 0;
        for (int i = 0; i < 3000; i++) {
            Ray ray = randomRay(r);
            double tMin = i % 3 == 0 ? Double.NEGATIVE_INFINITY : 0;
            double tMax = i % 2 == 0 ? Double.POSITIVE_INFINITY : r.nextDouble(0, 200);
            List<Integer> expected = new ArrayList<>(), got = new ArrayList<>();
            if (binary.start(bvh, ray, tMin, tMax)) {
                for (int leaf = binary.nextAny(tMax); leaf != BvhWalker.END; leaf = binary.nextAny(tMax)) expected.add(leaf);
            }
            if (walker.start(wide, ray, tMin, tMax)) {
                for (int leaf = walker.nextAny(tMax); leaf != BvhWalker.END; leaf = walker.nextAny(tMax)) got.add(leaf);
            }
            if (ray.dx != 0 && ray.dy != 0 && ray.dz != 0) {
                assertThat(got).as("ray %d", i).isEqualTo(expected);
            } else {
                // A ray along a box's plane counts as inside it (NaN ignored), which can let a leaf
                // pass whose binary parent fails: the wide walk may meet more leaves, never fewer.
                if (!expected.isEmpty()) assertThat(got).as("ray %d", i).containsSubsequence(expected);
            }
            if (!got.isEmpty()) nonEmpty++;
        }
        assertThat(nonEmpty).isGreaterThan(1000);
    }

    @Test
    void nearestWalkFindsTheNearestItemAsTestingEveryItemDoes() {
        int n = 3000;
        double[] boxes = randomBoxes(n, 5);
        int[] order = new int[n];
        Bvh bvh = BvhBuilder.build(boxes, n, order);
        Bvh4 wide = Bvh4.collapse(bvh);
        Bvh4Walker walker = new Bvh4Walker(wide.depth);
        BvhWalker binary = new BvhWalker(bvh.depth + 2);
        SplittableRandom r = new SplittableRandom(3);
        int hits = 0;
        long wideLeaves = 0, binaryLeaves = 0;
        for (int i = 0; i < 3000; i++) {
            Ray ray = randomRay(r);
            double tMax = i % 2 == 0 ? Double.POSITIVE_INFINITY : r.nextDouble(0, 200);
            // The items are the boxes themselves, hit where the ray enters them (after 0).
            double best = tMax;
            for (int k = 0; k < n; k++) best = Math.min(best, ray.entry(boxes, 6 * k, 0, best));
            double found = tMax;
            int leaves = 0;
            if (walker.start(wide, ray, 0, tMax)) {
                for (int leaf = walker.nextNearest(found); leaf != BvhWalker.END; leaf = walker.nextNearest(found)) {
                    leaves++;
                    for (int k = Bvh.leafFirst(leaf), end = k + Bvh.leafCount(leaf); k < end; k++) {
                        found = Math.min(found, ray.entry(boxes, 6 * order[k], 0, found));
                    }
                }
            }
            assertThat(found).as("ray %d", i).isEqualTo(best);
            if (best < tMax) hits++;
            wideLeaves += leaves;
            double bound = tMax;
            if (binary.start(bvh, ray, 0, tMax)) {
                for (int leaf = binary.nextNearest(bound); leaf != BvhWalker.END; leaf = binary.nextNearest(bound)) {
                    binaryLeaves++;
                    for (int k = Bvh.leafFirst(leaf), end = k + Bvh.leafCount(leaf); k < end; k++) {
                        bound = Math.min(bound, ray.entry(boxes, 6 * order[k], 0, bound));
                    }
                }
            }
        }
        assertThat(hits).isGreaterThan(500);
        // Nearest first as the binary walk: about as few leaves opened (any other order opens many more).
        assertThat((double) wideLeaves).isLessThan(1.2 * binaryLeaves);
    }
}
