package dev.crt.render;

/**
 * The one walk of a {@link Bvh}, shared by the scene and by CSG trees: it hands out, one at a
 * time, the leaves whose boxes a ray passes through, and the caller tests the leaf's items and
 * may shorten the ray before asking for the next. No callback, so each caller's item test stays
 * in its own loop without a virtual call, and nothing is allocated: the stack is per thread.
 *
 * <p>Two orders: {@link #nextNearest} visits children nearest first and skips subtrees that
 * start beyond the (shrinking) far end, for the closest hit; {@link #nextAny} visits every leaf
 * the segment passes through, for shadow rays and CSG's gathering of crossings.
 */
final class BvhWalker {
    /** Returned when no leaf is left; leaves are negative and node 0 is never a child. */
    static final int END = 0;
    /** The walk's next step is to pop the stack. */
    private static final int POP = Integer.MAX_VALUE;

    private int[] stack;
    private double[] stackT;
    private int top;
    private int node;
    private double[] boxes;
    private int[] children;
    private Ray ray;
    private double tMin;

    BvhWalker(int depth) {
        stack = new int[Math.max(1, depth)];
        stackT = new double[Math.max(1, depth)];
    }

    /**
     * Starts a walk of {@code bvh} along {@code ray} between {@code tMin} and {@code tMax};
     * returns false (and nothing to walk) when the ray misses the root box.
     */
    boolean start(Bvh bvh, Ray ray, double tMin, double tMax) {
        if (!ray.enters(bvh.root, 0, tMin, tMax)) return false;
        boxes = bvh.box;
        children = bvh.children;
        this.ray = ray;
        this.tMin = tMin;
        top = 0;
        node = 0;
        return true;
    }

    /** The next leaf, nearest child first, skipping boxes entered at or beyond {@code tMax}; {@link #END} when done. */
    int nextNearest(double tMax) {
        int node = this.node, top = this.top;
        int[] stack = this.stack, children = this.children;
        double[] stackT = this.stackT, boxes = this.boxes;
        Ray ray = this.ray;
        double tMin = this.tMin;
        while (true) {
            if (node == POP) {
                do {
                    if (top == 0) {
                        this.node = POP;
                        this.top = 0;
                        return END;
                    }
                    node = stack[--top];
                } while (stackT[top] >= tMax);
            }
            if (Bvh.isLeaf(node)) {
                this.node = POP;
                this.top = top;
                return node;
            }
            int left = children[2 * node], right = children[2 * node + 1];
            double tl = ray.entry(boxes, 12 * node, tMin, tMax), tr = ray.entry(boxes, 12 * node + 6, tMin, tMax);
            if (tl != Double.POSITIVE_INFINITY) {
                if (tr != Double.POSITIVE_INFINITY) {
                    if (tl <= tr) {
                        stack[top] = right;
                        stackT[top++] = tr;
                        node = left;
                    } else {
                        stack[top] = left;
                        stackT[top++] = tl;
                        node = right;
                    }
                } else {
                    node = left;
                }
            } else if (tr != Double.POSITIVE_INFINITY) {
                node = right;
            } else {
                node = POP;
            }
        }
    }

    /** The next leaf whose box the segment (tMin, tMax) passes through, in no useful order; {@link #END} when done. */
    int nextAny(double tMax) {
        int node = this.node, top = this.top;
        int[] stack = this.stack, children = this.children;
        double[] boxes = this.boxes;
        Ray ray = this.ray;
        double tMin = this.tMin;
        while (true) {
            if (node == POP) {
                if (top == 0) {
                    this.node = POP;
                    this.top = 0;
                    return END;
                }
                node = stack[--top];
            }
            if (Bvh.isLeaf(node)) {
                this.node = POP;
                this.top = top;
                return node;
            }
            boolean hl = ray.enters(boxes, 12 * node, tMin, tMax);
            boolean hr = ray.enters(boxes, 12 * node + 6, tMin, tMax);
            if (hl) {
                if (hr) stack[top++] = children[2 * node + 1];
                node = children[2 * node];
            } else if (hr) {
                node = children[2 * node + 1];
            } else {
                node = POP;
            }
        }
    }
}
