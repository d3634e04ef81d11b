package dev.crt.render;

import java.util.Arrays;

/**
 * A {@link Bvh} collapsed into nodes of four children: one walk step tests four boxes at once, so a
 * ray takes about half the steps (and half the hard-to-predict choices of where to go next) of the
 * binary walk. Each node holds its children's boxes in one run of 24 doubles at {@code 24·n}, plane
 * by plane with the four children side by side (minX of children 0–3, minY, minZ, maxX, maxY,
 * maxZ), as the binary layout does for two. Its children are {@code children[4n]} …
 * {@code children[4n + 3]}, coded as in {@link Bvh} (an inner node ≥ 0, a leaf &lt; 0, the same
 * items); an unused slot has an empty box (min +∞, max −∞) that no ray enters. The children keep
 * the binary tree's left-to-right order, so a walk of them in slot order meets the leaves in the
 * order the binary walk does. The root (node 0) is always an inner node.
 */
final class Bvh4 {
    static final int WIDTH = 4;
    /** Doubles per node in {@link #box}. */
    static final int NODE = 6 * WIDTH;
    /** Offset of the max planes after the min planes within a node. */
    static final int MAX = 3 * WIDTH;
    /** The child of an unused slot: a leaf of no items, behind a box no ray enters. */
    static final int NONE = Bvh.leaf(0, 0);

    final double[] box;
    final int[] children;
    /** The root's box (the binary tree's, six doubles: min x, y, z, max x, y, z). */
    final double[] root;
    /** Inner nodes. */
    final int nodeCount;
    /** Levels of inner nodes, the root included. */
    final int depth;

    private Bvh4(double[] box, int[] children, double[] root, int nodeCount, int depth) {
        this.box = box;
        this.children = children;
        this.root = root;
        this.nodeCount = nodeCount;
        this.depth = depth;
    }

    /** Bound {@code a} (0–2 min x, y, z; 3–5 max x, y, z) of child slot {@code c} (0–3) of node {@code n}. */
    double bound(int n, int c, int a) {
        return box[NODE * n + a * WIDTH + c];
    }

    /**
     * The four-wide tree of {@code bvh}: each binary node becomes a wide node whose slots start as
     * its two children, and the inner slot of largest surface area is replaced, in place, by its
     * own two children until four slots are used or only leaves are left (the surface area stands
     * for the chance that a ray enters the box, so the boxes opened are the ones a ray would
     * otherwise most often step through).
     */
    static Bvh4 collapse(Bvh bvh) {
        // At most one wide node per binary inner node; far fewer in practice (about a third).
        int binaryInner = Math.max(1, (bvh.nodeCount + 1) / 2);
        Builder b = new Builder(bvh, binaryInner);
        b.emit(0, 1);
        return new Bvh4(Arrays.copyOf(b.box, NODE * b.count), Arrays.copyOf(b.children, WIDTH * b.count),
                bvh.root.clone(), b.count, b.depth);
    }

    private static final class Builder {
        final Bvh bvh;
        double[] box;
        int[] children;
        int count;
        int depth;

        Builder(Bvh bvh, int capacity) {
            this.bvh = bvh;
            box = new double[NODE * capacity];
            children = new int[WIDTH * capacity];
        }

        /** Writes the wide node of binary inner node {@code binary} and those below it; returns its index. */
        int emit(int binary, int level) {
            depth = Math.max(depth, level);
            // Slot i: the binary child link and the binary parent and side its box is read from.
            int[] link = new int[WIDTH], parent = new int[WIDTH], side = new int[WIDTH];
            int used = 2;
            for (int c = 0; c < 2; c++) {
                link[c] = bvh.children[2 * binary + c];
                parent[c] = binary;
                side[c] = c;
            }
            while (used < WIDTH) {
                int open = -1;
                double largest = -1;
                for (int i = 0; i < used; i++) {
                    if (Bvh.isLeaf(link[i])) continue;
                    double area = area(parent[i], side[i]);
                    if (area > largest) {
                        largest = area;
                        open = i;
                    }
                }
                if (open < 0) break;
                int inner = link[open];
                System.arraycopy(link, open + 1, link, open + 2, used - open - 1);
                System.arraycopy(parent, open + 1, parent, open + 2, used - open - 1);
                System.arraycopy(side, open + 1, side, open + 2, used - open - 1);
                for (int c = 0; c < 2; c++) {
                    link[open + c] = bvh.children[2 * inner + c];
                    parent[open + c] = inner;
                    side[open + c] = c;
                }
                used++;
            }
            int n = count++;
            for (int i = 0; i < WIDTH; i++) {
                for (int a = 0; a < 6; a++) {
                    box[NODE * n + a * WIDTH + i] = i < used ? bvh.bound(parent[i], side[i], a)
                            : a < 3 ? Double.POSITIVE_INFINITY : Double.NEGATIVE_INFINITY;
                }
                children[WIDTH * n + i] = i < used ? link[i] : NONE;
            }
            for (int i = 0; i < used; i++) {
                if (!Bvh.isLeaf(link[i])) children[WIDTH * n + i] = emit(link[i], level + 1);
            }
            return n;
        }

        /** Half the surface area of child {@code c} of binary node {@code n}. */
        private double area(int n, int c) {
            double x = bvh.bound(n, c, 3) - bvh.bound(n, c, 0);
            double y = bvh.bound(n, c, 4) - bvh.bound(n, c, 1);
            double z = bvh.bound(n, c, 5) - bvh.bound(n, c, 2);
            return x * y + y * z + z * x;
        }
    }
}
