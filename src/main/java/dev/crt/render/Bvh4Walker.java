package dev.crt.render;

/**
 * The walk of a {@link Bvh4}, handing out leaves one at a time as {@link BvhWalker} does for the
 * binary tree (same leaf codes, same {@link BvhWalker#END}, nothing allocated per ray).
 *
 * <p>Each step tests the four boxes of a node, written out with the ray in locals (the near and
 * far plane of each axis are slots fixed per ray), and then goes on without a data-dependent branch
 * per child: every child is written to the stack and the stack top moves past it only if the ray
 * enters it. {@link #nextNearest} first sorts the four children by entry distance with a sorting
 * network of min/max on integer keys (the distance's bits, which order as the doubles do, with the
 * slot in the two low bits), so the nearest entered child is popped next; {@link #nextAny} pushes
 * them in reverse slot order, so the leaves come in the binary walk's depth-first, left-to-right
 * order (a shadow ray's product of transmittances is then taken in the same order, to the bit).
 */
final class Bvh4Walker {
    /** A key that sorts after every entered child's. */
    private static final long MISS = Long.MAX_VALUE;
    /** The walk's next step is to pop the stack. */
    private static final int POP = Integer.MAX_VALUE;

    private final int[] stack;
    private final double[] stackT;
    /** Per slot, the entry distance of the current node's child (read back by the slot of a sorted key). */
    private final double[] entry = new double[Bvh4.WIDTH];
    private int top;
    private int node;
    private double[] boxes;
    private int[] children;
    private double ox, oy, oz, ix, iy, iz;
    /** Per axis, the slot in a node of child 0's near plane and of its far plane. */
    private int nearX, farX, nearY, farY, nearZ, farZ;
    private double tMin;

    Bvh4Walker(int depth) {
        // Each level pops one entry and pushes up to four; one more slot takes the write past the
        // top of a child not entered.
        int size = 3 * Math.max(1, depth) + 2;
        stack = new int[size];
        stackT = new double[size];
    }

    /**
     * Starts a walk of {@code bvh} along {@code ray} between {@code tMin} and {@code tMax};
     * returns false (and nothing to walk) when the ray misses the root box.
     */
    boolean start(Bvh4 bvh, Ray ray, double tMin, double tMax) {
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
        int w = Bvh4.WIDTH;
        nearX = ix >= 0 ? 0 : Bvh4.MAX;
        nearY = w + (iy >= 0 ? 0 : Bvh4.MAX);
        nearZ = 2 * w + (iz >= 0 ? 0 : Bvh4.MAX);
        farX = nearX ^ Bvh4.MAX;
        farY = w + ((nearY - w) ^ Bvh4.MAX);
        farZ = 2 * w + ((nearZ - 2 * w) ^ Bvh4.MAX);
        this.tMin = tMin;
        top = 0;
        node = 0;
        return true;
    }

    /** The next leaf, nearest child first, skipping boxes entered at or beyond {@code tMax}; {@link BvhWalker#END} when done. */
    int nextNearest(double tMax) {
        int top = this.top;
        int[] stack = this.stack, children = this.children;
        double[] stackT = this.stackT, entry = this.entry;
        double[] b = this.boxes;
        double ox = this.ox, oy = this.oy, oz = this.oz, ix = this.ix, iy = this.iy, iz = this.iz;
        int nx = nearX, fx = farX, ny = nearY, fy = farY, nz = nearZ, fz = farZ;
        double tMin = this.tMin;
        int node = this.node;
        while (true) {
            if (node == POP) {
                do {
                    if (top == 0) {
                        this.node = POP;
                        this.top = 0;
                        return BvhWalker.END;
                    }
                    node = stack[--top];
                } while (stackT[top] >= tMax);
            }
            if (Bvh.isLeaf(node)) {
                this.node = POP;
                this.top = top;
                return node;
            }
            int k = Bvh4.NODE * node;
            double n0 = tMin, n1 = tMin, n2 = tMin, n3 = tMin, f0 = tMax, f1 = tMax, f2 = tMax, f3 = tMax, t;
            if ((t = (b[k + nx] - ox) * ix) > n0) n0 = t;
            if ((t = (b[k + nx + 1] - ox) * ix) > n1) n1 = t;
            if ((t = (b[k + nx + 2] - ox) * ix) > n2) n2 = t;
            if ((t = (b[k + nx + 3] - ox) * ix) > n3) n3 = t;
            if ((t = (b[k + fx] - ox) * ix) < f0) f0 = t;
            if ((t = (b[k + fx + 1] - ox) * ix) < f1) f1 = t;
            if ((t = (b[k + fx + 2] - ox) * ix) < f2) f2 = t;
            if ((t = (b[k + fx + 3] - ox) * ix) < f3) f3 = t;
            if ((t = (b[k + ny] - oy) * iy) > n0) n0 = t;
            if ((t = (b[k + ny + 1] - oy) * iy) > n1) n1 = t;
            if ((t = (b[k + ny + 2] - oy) * iy) > n2) n2 = t;
            if ((t = (b[k + ny + 3] - oy) * iy) > n3) n3 = t;
            if ((t = (b[k + fy] - oy) * iy) < f0) f0 = t;
            if ((t = (b[k + fy + 1] - oy) * iy) < f1) f1 = t;
            if ((t = (b[k + fy + 2] - oy) * iy) < f2) f2 = t;
            if ((t = (b[k + fy + 3] - oy) * iy) < f3) f3 = t;
            if ((t = (b[k + nz] - oz) * iz) > n0) n0 = t;
            if ((t = (b[k + nz + 1] - oz) * iz) > n1) n1 = t;
            if ((t = (b[k + nz + 2] - oz) * iz) > n2) n2 = t;
            if ((t = (b[k + nz + 3] - oz) * iz) > n3) n3 = t;
            if ((t = (b[k + fz] - oz) * iz) < f0) f0 = t;
            if ((t = (b[k + fz + 1] - oz) * iz) < f1) f1 = t;
            if ((t = (b[k + fz + 2] - oz) * iz) < f2) f2 = t;
            if ((t = (b[k + fz + 3] - oz) * iz) < f3) f3 = t;
            entry[0] = n0;
            entry[1] = n1;
            entry[2] = n2;
            entry[3] = n3;
            // As in BvhWalker: NaN from a slab the ray runs along is ignored, NaN here is a miss.
            long k0 = n0 <= f0 + BvhWalker.SLAB_ERROR * (Math.abs(n0) + Math.abs(f0)) ? key(n0) : MISS;
            long k1 = n1 <= f1 + BvhWalker.SLAB_ERROR * (Math.abs(n1) + Math.abs(f1)) ? key(n1) | 1 : MISS;
            long k2 = n2 <= f2 + BvhWalker.SLAB_ERROR * (Math.abs(n2) + Math.abs(f2)) ? key(n2) | 2 : MISS;
            long k3 = n3 <= f3 + BvhWalker.SLAB_ERROR * (Math.abs(n3) + Math.abs(f3)) ? key(n3) | 3 : MISS;
            int c = Bvh4.WIDTH * node;
            int entered = (k0 != MISS ? 1 : 0) + (k1 != MISS ? 1 : 0) + (k2 != MISS ? 1 : 0) + (k3 != MISS ? 1 : 0);
            if (entered == 0) {
                node = POP;
                continue;
            }
            if (entered == 1) {
                node = children[c + ((int) Math.min(Math.min(k0, k1), Math.min(k2, k3)) & 3)];
                continue;
            }
            // Sorting network on four keys: (0,1) (2,3) (0,2) (1,3) (1,2).
            long lo = Math.min(k0, k1), hi = Math.max(k0, k1);
            k0 = lo;
            k1 = hi;
            lo = Math.min(k2, k3);
            hi = Math.max(k2, k3);
            k2 = lo;
            k3 = hi;
            lo = Math.min(k0, k2);
            hi = Math.max(k0, k2);
            k0 = lo;
            k2 = hi;
            lo = Math.min(k1, k3);
            hi = Math.max(k1, k3);
            k1 = lo;
            k3 = hi;
            lo = Math.min(k1, k2);
            hi = Math.max(k1, k2);
            k1 = lo;
            k2 = hi;
            // Farthest first; a key past the entered ones is written and then overwritten.
            top = push(stack, stackT, entry, children, c, top, k3);
            top = push(stack, stackT, entry, children, c, top, k2);
            top = push(stack, stackT, entry, children, c, top, k1);
            node = children[c + ((int) k0 & 3)];
        }
    }

    private static int push(int[] stack, double[] stackT, double[] entry, int[] children, int c, int top, long key) {
        int slot = (int) key & 3;
        stack[top] = children[c + slot];
        stackT[top] = entry[slot];
        return key == MISS ? top : top + 1;
    }

    /** Bits of {@code t} that order as the doubles do (signed), the two low ones cleared for the slot. */
    private static long key(double t) {
        long bits = Double.doubleToRawLongBits(t);
        return (bits ^ (bits >> 63 & Long.MAX_VALUE)) & ~3L;
    }

    /** The next leaf whose box the segment (tMin, tMax) passes through, in depth-first left-to-right order; {@link BvhWalker#END} when done. */
    int nextAny(double tMax) {
        int top = this.top;
        int[] stack = this.stack, children = this.children;
        double[] b = this.boxes;
        double ox = this.ox, oy = this.oy, oz = this.oz, ix = this.ix, iy = this.iy, iz = this.iz;
        int nx = nearX, fx = farX, ny = nearY, fy = farY, nz = nearZ, fz = farZ;
        double tMin = this.tMin;
        int node = this.node;
        while (true) {
            if (node == POP) {
                if (top == 0) {
                    this.node = POP;
                    this.top = 0;
                    return BvhWalker.END;
                }
                node = stack[--top];
            }
            if (Bvh.isLeaf(node)) {
                this.node = POP;
                this.top = top;
                return node;
            }
            int k = Bvh4.NODE * node;
            double n0 = tMin, n1 = tMin, n2 = tMin, n3 = tMin, f0 = tMax, f1 = tMax, f2 = tMax, f3 = tMax, t;
            if ((t = (b[k + nx] - ox) * ix) > n0) n0 = t;
            if ((t = (b[k + nx + 1] - ox) * ix) > n1) n1 = t;
            if ((t = (b[k + nx + 2] - ox) * ix) > n2) n2 = t;
            if ((t = (b[k + nx + 3] - ox) * ix) > n3) n3 = t;
            if ((t = (b[k + fx] - ox) * ix) < f0) f0 = t;
            if ((t = (b[k + fx + 1] - ox) * ix) < f1) f1 = t;
            if ((t = (b[k + fx + 2] - ox) * ix) < f2) f2 = t;
            if ((t = (b[k + fx + 3] - ox) * ix) < f3) f3 = t;
            if ((t = (b[k + ny] - oy) * iy) > n0) n0 = t;
            if ((t = (b[k + ny + 1] - oy) * iy) > n1) n1 = t;
            if ((t = (b[k + ny + 2] - oy) * iy) > n2) n2 = t;
            if ((t = (b[k + ny + 3] - oy) * iy) > n3) n3 = t;
            if ((t = (b[k + fy] - oy) * iy) < f0) f0 = t;
            if ((t = (b[k + fy + 1] - oy) * iy) < f1) f1 = t;
            if ((t = (b[k + fy + 2] - oy) * iy) < f2) f2 = t;
            if ((t = (b[k + fy + 3] - oy) * iy) < f3) f3 = t;
            if ((t = (b[k + nz] - oz) * iz) > n0) n0 = t;
            if ((t = (b[k + nz + 1] - oz) * iz) > n1) n1 = t;
            if ((t = (b[k + nz + 2] - oz) * iz) > n2) n2 = t;
            if ((t = (b[k + nz + 3] - oz) * iz) > n3) n3 = t;
            if ((t = (b[k + fz] - oz) * iz) < f0) f0 = t;
            if ((t = (b[k + fz + 1] - oz) * iz) < f1) f1 = t;
            if ((t = (b[k + fz + 2] - oz) * iz) < f2) f2 = t;
            if ((t = (b[k + fz + 3] - oz) * iz) < f3) f3 = t;
            int c = Bvh4.WIDTH * node;
            stack[top] = children[c + 3];
            if (n3 <= f3 + BvhWalker.SLAB_ERROR * (Math.abs(n3) + Math.abs(f3))) top++;
            stack[top] = children[c + 2];
            if (n2 <= f2 + BvhWalker.SLAB_ERROR * (Math.abs(n2) + Math.abs(f2))) top++;
            stack[top] = children[c + 1];
            if (n1 <= f1 + BvhWalker.SLAB_ERROR * (Math.abs(n1) + Math.abs(f1))) top++;
            stack[top] = children[c];
            if (n0 <= f0 + BvhWalker.SLAB_ERROR * (Math.abs(n0) + Math.abs(f0))) top++;
            node = POP;
        }
    }
}
