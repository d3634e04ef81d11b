package dev.crt.render;

/**
 * A bounding volume hierarchy as flat arrays in depth-first order. Each inner node holds the boxes
 * of both its children in one run of 12 doubles at {@code 12·n} in {@link #box}, plane by plane
 * with the two children side by side: minX of the left child then of the right one, minY, minZ,
 * maxX, maxY, maxZ (so one ray reads both children's near planes of an axis from adjacent slots,
 * and the near side of an axis, min or max by the sign of the direction, is an offset fixed per
 * ray). Floats would halve the memory but were slower (box field 1.16× the double layout's time
 * on Java 17: the conversions cost more than the cache misses they save). Its children are
 * {@code children[2n]} and {@code children[2n + 1]}. A child ≥ 0 is an inner node; a child &lt; 0
 * is a leaf {@code ~(first << 3 | count)} holding items first … first + count − 1 in the item
 * order the builder chose. The root (node 0) is always an inner node. A large tree may leave a
 * few node numbers unused ({@link BvhBuilder#GAPS_KEPT}): no child names them.
 */
final class Bvh {
    static final int LEAF_COUNT_BITS = 3;
    static final int MAX_LEAF_COUNT = (1 << LEAF_COUNT_BITS) - 1;
    /** Doubles per inner node in {@link #box}. */
    static final int NODE = 12;
    /** Offset of the max planes after the min planes within a node. */
    static final int MAX = 6;

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

    /** Bound {@code a} (0–2 min x, y, z; 3–5 max x, y, z) of child {@code c} (0 left, 1 right) of inner node {@code n}. */
    double bound(int n, int c, int a) {
        return box[NODE * n + (a < 3 ? 2 * a : MAX + 2 * (a - 3)) + c];
    }

    /** Writes box {@code b} (six doubles at {@code k}: min x, y, z, max x, y, z) as child {@code c} of node {@code n}. */
    static void putChild(double[] box, int n, int c, double[] b, int k) {
        for (int a = 0; a < 3; a++) {
            box[NODE * n + 2 * a + c] = b[k + a];
            box[NODE * n + MAX + 2 * a + c] = b[k + 3 + a];
        }
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
