package dev.crt.render;

/**
 * A bounding volume hierarchy as flat arrays in depth-first order. Each inner node holds the boxes
 * of both its children, so one step of a walk reads one run of memory: at {@code 12·n} in
 * {@link #box}, the left child's box (minX, minY, minZ, maxX, maxY, maxZ), then the right one's;
 * its children are {@code children[2n]} and {@code children[2n + 1]}. A child ≥ 0 is an inner
 * node; a child &lt; 0 is a leaf {@code ~(first << 3 | count)} holding items first … first +
 * count − 1 in the item order the builder chose. The root (node 0) is always an inner node.
 */
final class Bvh {
    static final int LEAF_COUNT_BITS = 3;
    static final int MAX_LEAF_COUNT = (1 << LEAF_COUNT_BITS) - 1;

    final double[] box;
    final int[] children;
    /** The root's box. */
    final double[] root;
    /** Inner nodes and leaves. */
    final int nodeCount;
    /** Levels, the root and the leaves included. */
    final int depth;

    Bvh(double[] box, int[] children, double[] root, int nodeCount, int depth) {
        this.box = box;
        this.children = children;
        this.root = root;
        this.nodeCount = nodeCount;
        this.depth = depth;
    }

    static boolean isLeaf(int child) {
        return child < 0;
    }

    static int leafFirst(int child) {
        return ~child >>> LEAF_COUNT_BITS;
    }

    static int leafCount(int child) {
        return ~child & MAX_LEAF_COUNT;
    }

    static int leaf(int first, int count) {
        return ~(first << LEAF_COUNT_BITS | count);
    }
}
