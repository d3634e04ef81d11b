package dev.crt.render;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * Up to {@link BvhBuilder#MORTON_ABOVE} items (every scene's own hierarchy and every mesh of up to
 * that many triangles), the builder gives the very tree of {@link ReferenceBvhBuilder}, the
 * previous builder, to the bit, so every picture stays the same.
 */
class BvhBuilderSameTreeTest {
    @Test
    void sameTreesAsThePreviousBuilder() {
        int set = 0;
        for (int n : new int[] {5, 6, 7, 9, 17, 100, 1000, 5000, 20_000, 70_000, BvhBuilder.MORTON_ABOVE}) {
            for (int kind = 0; kind < 4; kind++) {
                double[] boxes = boxes(kind, n, ++set);
                int[] expectedOrder = new int[n], order = new int[n];
                Bvh expected = ReferenceBvhBuilder.build(boxes, n, expectedOrder);
                Bvh actual = BvhBuilder.build(boxes.clone(), n, order);
                String what = "kind " + kind + ", " + n + " items";
                assertThat(order).as(what).isEqualTo(expectedOrder);
                assertThat(actual.nodeCount).as(what).isEqualTo(expected.nodeCount);
                assertThat(actual.depth).as(what).isEqualTo(expected.depth);
                assertThat(actual.root).as(what).isEqualTo(expected.root);
                assertThat(actual.children).as(what).isEqualTo(expected.children);
                assertThat(actual.box).as(what).isEqualTo(expected.box);
            }
        }
    }

    /** Random small boxes, random boxes with clusters and flat ones, a grid, and triangles of a ball. */
    static double[] boxes(int kind, int n, long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        double[] b = new double[6 * n];
        int side = (int) Math.ceil(Math.cbrt(n));
        for (int i = 0; i < n; i++) {
            for (int a = 0; a < 3; a++) {
                double lo, hi;
                switch (kind) {
                    case 0 -> {
                        lo = r.nextDouble(-10, 10);
                        hi = lo + 16 / Math.sqrt(n);
                    }
                    case 1 -> {
                        lo = i % 7 == 0 ? 5 : r.nextDouble() * 100;
                        hi = lo + (i % 5 == 0 ? 0 : r.nextDouble() * 2);
                    }
                    case 2 -> {
                        int cell = a == 0 ? i % side : a == 1 ? i / side % side : i / side / side;
                        lo = cell;
                        hi = cell + 0.5;
                    }
                    default -> {
                        double t = 2 * Math.PI * i / n, u = Math.PI * (i * 0.618034 % 1);
                        double c = a == 0 ? Math.cos(t) * Math.sin(u) : a == 1 ? Math.cos(u) : Math.sin(t) * Math.sin(u);
                        lo = c - r.nextDouble(0, 0.01);
                        hi = c + r.nextDouble(0, 0.01);
                    }
                }
                b[6 * i + a] = Math.nextDown(lo);
                b[6 * i + 3 + a] = Math.nextUp(hi);
            }
        }
        return b;
    }
}
