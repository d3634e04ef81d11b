package dev.crt.render;

/**
 * A bounding volume hierarchy as flat arrays in depth-first order: node n's left child is n + 1.
 * For an inner node {@code link[n]} is the right child and {@code count[n]} is 0; for a leaf
 * {@code link[n]} is the first of its {@code count[n]} items in the item order the builder chose.
 */
final class Bvh {
    /** minX, minY, minZ, maxX, maxY, maxZ per node. */
    final double[] box;
    final int[] link;
    final int[] count;
    final int nodeCount;
    final int depth;

    Bvh(double[] box, int[] link, int[] count, int nodeCount, int depth) {
        this.box = box;
        this.link = link;
        this.count = count;
        this.nodeCount = nodeCount;
        this.depth = depth;
    }
}
