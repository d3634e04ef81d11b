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
 *
 * <p>Both children of a node are tested together, written out in the loop with the ray in
 * locals: the two slab tests are independent, so the processor overlaps them, and the near and
 * far plane of each axis are slots fixed per ray (by the direction's signs) rather than chosen
 * per node.
 */
final class BvhWalker {
    /** Returned when no leaf is left; leaves are negative and node 0 is never a child. */
    static final int END = 0;
    /** The walk's next step is to pop the stack. */
    private static final int POP = Integer.MAX_VALUE;
    /**
     * 2γ₃ (γₙ = nε / (1 − nε), ε = 2⁻⁵³): twice the relative error of a slab distance, a
     * subtraction and a product each. A line through a box's edge or face, such as a ray through
     * the edge two triangles of a mesh share, must not fall outside both boxes by rounding, so the
     * test is widened by a bound of that error (Ize, "Robust BVH Ray Traversal", JCGT 2013).
     */
    static final double SLAB_ERROR = 2 * 3 * 0x1p-53 / (1 - 3 * 0x1p-53);

    private final int[] stack;
    private final double[] stackT;
    private int top;
    private int node;
    private double[] boxes;
    private int[] children;
    private double ox, oy, oz, ix, iy, iz;
    /** Per axis, the slot in a node of the left child's near plane and of its far plane. */
    private int nearX, farX, nearY, farY, nearZ, farZ;
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
        ox = ray.ox;
        oy = ray.oy;
        oz = ray.oz;
        ix = ray.ix;
        iy = ray.iy;
        iz = ray.iz;
        // The same choice as Ray.set: a direction component of −0 counts as negative (1/−0 = −∞).
        nearX = ix >= 0 ? 0 : Bvh.MAX;
        nearY = 2 + (iy >= 0 ? 0 : Bvh.MAX);
        nearZ = 4 + (iz >= 0 ? 0 : Bvh.MAX);
        farX = nearX ^ Bvh.MAX;
        farY = 2 + ((nearY - 2) ^ Bvh.MAX);
        farZ = 4 + ((nearZ - 4) ^ Bvh.MAX);
        this.tMin = tMin;
        top = 0;
        node = 0;
        return true;
    }

    /** Inner nodes {@link #nextNearest} has opened, counted for ever: what a reflected-ray list is weighed against. */
    int nearestSteps;

    /** The next leaf, nearest child first, skipping boxes entered at or beyond {@code tMax}; {@link #END} when done. */
    int nextNearest(double tMax) {
        int node = this.node, top = this.top, steps = 0;
        int[] stack = this.stack, children = this.children;
        double[] stackT = this.stackT;
        double[] b = this.boxes;
        double ox = this.ox, oy = this.oy, oz = this.oz, ix = this.ix, iy = this.iy, iz = this.iz;
        int nx = nearX, fx = farX, ny = nearY, fy = farY, nz = nearZ, fz = farZ;
        double tMin = this.tMin;
        while (true) {
            if (node == POP) {
                do {
                    if (top == 0) {
                        this.node = POP;
                        this.top = 0;
                        nearestSteps += steps;
                        return END;
                    }
                    node = stack[--top];
                } while (stackT[top] >= tMax);
            }
            if (Bvh.isLeaf(node)) {
                this.node = POP;
                this.top = top;
                nearestSteps += steps;
                return node;
            }
            steps++;
            int k = Bvh.NODE * node;
            double ln = tMin, lf = tMax, rn = tMin, rf = tMax, t;
            if ((t = (b[k + nx] - ox) * ix) > ln) ln = t;
            if ((t = (b[k + nx + 1] - ox) * ix) > rn) rn = t;
            if ((t = (b[k + fx] - ox) * ix) < lf) lf = t;
            if ((t = (b[k + fx + 1] - ox) * ix) < rf) rf = t;
            if ((t = (b[k + ny] - oy) * iy) > ln) ln = t;
            if ((t = (b[k + ny + 1] - oy) * iy) > rn) rn = t;
            if ((t = (b[k + fy] - oy) * iy) < lf) lf = t;
            if ((t = (b[k + fy + 1] - oy) * iy) < rf) rf = t;
            if ((t = (b[k + nz] - oz) * iz) > ln) ln = t;
            if ((t = (b[k + nz + 1] - oz) * iz) > rn) rn = t;
            if ((t = (b[k + fz] - oz) * iz) < lf) lf = t;
            if ((t = (b[k + fz + 1] - oz) * iz) < rf) rf = t;
            // A slab the ray runs exactly along gives NaN, which the comparisons ignore
            // (conservatively a hit); an infinite far end gives NaN here: a miss.
            boolean hl = ln <= lf + SLAB_ERROR * (Math.abs(ln) + Math.abs(lf));
            boolean hr = rn <= rf + SLAB_ERROR * (Math.abs(rn) + Math.abs(rf));
            if (hl) {
                if (hr) {
                    if (ln <= rn) {
                        stack[top] = children[2 * node + 1];
                        stackT[top++] = rn;
                        node = children[2 * node];
                    } else {
                        stack[top] = children[2 * node];
                        stackT[top++] = ln;
                        node = children[2 * node + 1];
                    }
                } else {
                    node = children[2 * node];
                }
            } else if (hr) {
                node = children[2 * node + 1];
            } else {
                node = POP;
            }
        }
    }

    /** Inner nodes {@link #nextAny} has opened, counted for ever: what a shadow list is weighed against. */
    int anySteps;

    /** The next leaf whose box the segment (tMin, tMax) passes through, in no useful order; {@link #END} when done. */
    int nextAny(double tMax) {
        int node = this.node, top = this.top, steps = 0;
        int[] stack = this.stack, children = this.children;
        double[] b = this.boxes;
        double ox = this.ox, oy = this.oy, oz = this.oz, ix = this.ix, iy = this.iy, iz = this.iz;
        int nx = nearX, fx = farX, ny = nearY, fy = farY, nz = nearZ, fz = farZ;
        double tMin = this.tMin;
        while (true) {
            if (node == POP) {
                if (top == 0) {
                    this.node = POP;
                    this.top = 0;
                    anySteps += steps;
                    return END;
                }
                node = stack[--top];
            }
            if (Bvh.isLeaf(node)) {
                this.node = POP;
                this.top = top;
                anySteps += steps;
                return node;
            }
            steps++;
            int k = Bvh.NODE * node;
            double ln = tMin, lf = tMax, rn = tMin, rf = tMax, t;
            if ((t = (b[k + nx] - ox) * ix) > ln) ln = t;
            if ((t = (b[k + nx + 1] - ox) * ix) > rn) rn = t;
            if ((t = (b[k + fx] - ox) * ix) < lf) lf = t;
            if ((t = (b[k + fx + 1] - ox) * ix) < rf) rf = t;
            if ((t = (b[k + ny] - oy) * iy) > ln) ln = t;
            if ((t = (b[k + ny + 1] - oy) * iy) > rn) rn = t;
            if ((t = (b[k + fy] - oy) * iy) < lf) lf = t;
            if ((t = (b[k + fy + 1] - oy) * iy) < rf) rf = t;
            if ((t = (b[k + nz] - oz) * iz) > ln) ln = t;
            if ((t = (b[k + nz + 1] - oz) * iz) > rn) rn = t;
            if ((t = (b[k + fz] - oz) * iz) < lf) lf = t;
            if ((t = (b[k + fz + 1] - oz) * iz) < rf) rf = t;
            boolean hl = ln <= lf + SLAB_ERROR * (Math.abs(ln) + Math.abs(lf));
            boolean hr = rn <= rf + SLAB_ERROR * (Math.abs(rn) + Math.abs(rf));
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
