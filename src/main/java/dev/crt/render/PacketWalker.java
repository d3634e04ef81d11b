package dev.crt.render;

/**
 * The nearest-hit walk of a {@link Bvh} for a {@link RayPacket}: one walk of the tree for all its
 * rays, each node's boxes loaded once and tested against every ray still active there in a loop
 * of independent slab tests, the packet going down a child when any of its rays enters it. Like
 * {@link BvhWalker} it hands out leaves one at a time, with {@link #active} the rays to test there.
 *
 * <p>Each ray meets exactly the leaves its own {@link BvhWalker#nextNearest} walk would, in the same
 * order, with the same culling, so its nearest hit (ties in t included) is the lone walk's: the slab
 * tests are the same arithmetic on the same operands; a ray entering one child only is inactive in
 * the other (its far end does not change there); a subtree put off is culled per ray by that ray's
 * own entry distance (none for a ray that did not enter the sibling: its lone walk goes straight
 * down); and where rays entering both children disagree on which is nearer, the smaller party is
 * dropped from the walk ({@link #dropped}) for the caller to walk alone.
 */
final class PacketWalker {
    private static final int POP = Integer.MAX_VALUE;
    private static final int SIZE = RayPacket.SIZE;

    private final int[] stack;
    private final long[] stackMask;
    /** Per stack entry and ray, the bits of the entry distance that culls the subtree ({@code Long.MIN_VALUE}: never culled). */
    private final long[] stackT;
    private int top;
    private int node;
    private long mask;
    private double[] boxes;
    private int[] children;
    private RayPacket packet;
    /** The packet's slots of the near and far planes of the left child per axis: its rays share an octant. */
    private int nx, fx, ny, fy, nz, fz;
    /** The rays to test at the leaf just returned. */
    long active;
    /** The rays left out of the walk because they order some node's children otherwise than the packet. */
    long dropped;

    PacketWalker(int depth) {
        stack = new int[Math.max(1, depth)];
        stackMask = new long[Math.max(1, depth)];
        stackT = new long[Math.max(1, depth) * SIZE];
    }

    /**
     * Starts the walk of {@code rays} (a mask) of {@code p} through {@code bvh}, each between 0 and its
     * tMax. Rays whose direction has a zero component (their slab distances can be NaN, which the
     * lone walk's comparisons skip and a maximum would not) or whose octant is not the first such
     * ray's go to {@link #dropped} at once.
     */
    void start(Bvh bvh, RayPacket p, long rays) {
        long m = 0, drop = 0;
        int octant = -1;
        for (long a = rays; a != 0; a &= a - 1) {
            int r = Long.numberOfTrailingZeros(a);
            long bit = 1L << r;
            double x = p.ix[r], y = p.iy[r], z = p.iz[r];
            if (Double.isInfinite(x) || Double.isInfinite(y) || Double.isInfinite(z)) {
                drop |= bit;
                continue;
            }
            int o = (x >= 0 ? 0 : 1) | (y >= 0 ? 0 : 2) | (z >= 0 ? 0 : 4);
            if (octant < 0) octant = o;
            if (o != octant) {
                drop |= bit;
            } else if (p.rays[r].enters(bvh.root, 0, 0, p.tMax[r])) {
                m |= bit;
            }
        }
        if (m != 0) {
            int r = Long.numberOfTrailingZeros(m);
            nx = p.nearX[r];
            fx = p.farX[r];
            ny = p.nearY[r];
            fy = p.farY[r];
            nz = p.nearZ[r];
            fz = p.farZ[r];
        }
        boxes = bvh.box;
        children = bvh.children;
        packet = p;
        mask = m;
        node = m == 0 ? POP : 0;
        top = 0;
        dropped = drop;
    }

    /** The next leaf some active ray enters, with those rays in {@link #active}; {@link BvhWalker#END} when done. */
    int next() {
        int node = this.node, top = this.top;
        long mask = this.mask;
        RayPacket p = packet;
        double[] b = boxes, tMax = p.tMax, ox = p.ox, oy = p.oy, oz = p.oz, ix = p.ix, iy = p.iy, iz = p.iz;
        int nx = this.nx, fx = this.fx, ny = this.ny, fy = this.fy, nz = this.nz, fz = this.fz;
        long[] stT = stackT;
        while (true) {
            if (node == POP) {
                do {
                    if (top == 0) {
                        this.node = POP;
                        this.top = 0;
                        return BvhWalker.END;
                    }
                    node = stack[--top];
                    mask = stackMask[top] & ~dropped;
                    int base = top * SIZE;
                    for (long a = mask; a != 0; a &= a - 1) {
                        int r = Long.numberOfTrailingZeros(a);
                        mask &= stT[base + r] >= Double.doubleToRawLongBits(tMax[r]) ? ~(1L << r) : -1L;
                    }
                } while (mask == 0);
            }
            if (Bvh.isLeaf(node)) {
                this.node = POP;
                this.top = top;
                active = mask;
                return node;
            }
            int k = Bvh.NODE * node;
            // Every ray of the packet in one loop of independent integer arithmetic without a branch
            // (the compiler turns max, min and conditionals into branches that the processor then
            // mispredicts), which the processor overlaps across rays. Slab distances are compared
            // by their bits as longs, which order doubles ≥ 0 as their values: an entry is at
            // least 0 anyway, so negative ones (sign bit set) are cleared to +0; a far plane below
            // 0 (−0 counted as 0) makes a miss whatever the widening, since the entry is ≥ 0. The
            // lone walk's widened test near ≤ R is read off the sign of R − near, which rounding
            // never flips (and which is + for R = near). No distance is NaN: no direction
            // component is 0 (see start).
            double lnx = b[k + nx], rnx = b[k + nx + 1], lfx = b[k + fx], rfx = b[k + fx + 1];
            double lny = b[k + ny], rny = b[k + ny + 1], lfy = b[k + fy], rfy = b[k + fy + 1];
            double lnz = b[k + nz], rnz = b[k + nz + 1], lfz = b[k + fz], rfz = b[k + fz + 1];
            long goL = 0, goR = 0, leftFirst = 0, rightFirst = 0;
            int base = top * SIZE;
            int end = 64 - Long.numberOfLeadingZeros(mask);
            for (int r = Long.numberOfTrailingZeros(mask); r < end; r++) {
                double x = ox[r], y = oy[r], z = oz[r], i = ix[r], j = iy[r], h = iz[r];
                long t = Double.doubleToRawLongBits(tMax[r]);
                long ln = max(max(entry((lnx - x) * i), entry((lny - y) * j)), entry((lnz - z) * h));
                long rn = max(max(entry((rnx - x) * i), entry((rny - y) * j)), entry((rnz - z) * h));
                long a0 = bits((lfx - x) * i), a1 = bits((lfy - y) * j), a2 = bits((lfz - z) * h);
                long b0 = bits((rfx - x) * i), b1 = bits((rfy - y) * j), b2 = bits((rfz - z) * h);
                long lBehind = exit(a0) | exit(a1) | exit(a2), rBehind = exit(b0) | exit(b1) | exit(b2);
                long lf = min(min(min(t, a0 & Long.MAX_VALUE), a1 & Long.MAX_VALUE), a2 & Long.MAX_VALUE);
                long rf = min(min(min(t, b0 & Long.MAX_VALUE), b1 & Long.MAX_VALUE), b2 & Long.MAX_VALUE);
                double dln = Double.longBitsToDouble(ln), drn = Double.longBitsToDouble(rn);
                double dlf = Double.longBitsToDouble(lf), drf = Double.longBitsToDouble(rf);
                // All ones where the ray enters the child: with both ends ≥ 0, |x| = x in the lone walk's test.
                long hl = ~(lBehind | bits(dlf + BvhWalker.SLAB_ERROR * (dln + dlf) - dln)) >> 63;
                long hr = ~(rBehind | bits(drf + BvhWalker.SLAB_ERROR * (drn + drf) - drn)) >> 63;
                long both = hl & hr, bit = 1L << r;
                long rightNearer = (rn - ln) >> 63;
                goL |= hl & bit;
                goR |= hr & bit;
                leftFirst |= both & ~rightNearer & bit;
                rightFirst |= both & rightNearer & bit;
                // The child put off is the farther one, culled by its entry; a ray entering one
                // child only goes straight down in its lone walk: never culled (Long.MIN_VALUE).
                stT[base + r] = (max(ln, rn) & both) | (Long.MIN_VALUE & ~both);
            }
            goL &= mask;
            goR &= mask;
            leftFirst &= mask;
            rightFirst &= mask;
            boolean rightNear = false;
            if (leftFirst != 0 && rightFirst != 0) {
                long loser;
                if (Long.bitCount(leftFirst) >= Long.bitCount(rightFirst)) {
                    loser = rightFirst;
                } else {
                    loser = leftFirst;
                    rightNear = true;
                }
                dropped |= loser;
                goL &= ~loser;
                goR &= ~loser;
            } else if (rightFirst != 0) {
                rightNear = true;
            }
            int left = children[2 * node], right = children[2 * node + 1];
            if (goL != 0) {
                if (goR != 0) {
                    stack[top] = rightNear ? left : right;
                    stackMask[top++] = rightNear ? goL : goR;
                    node = rightNear ? right : left;
                    mask = rightNear ? goR : goL;
                } else {
                    node = left;
                    mask = goL;
                }
            } else if (goR != 0) {
                node = right;
                mask = goR;
            } else {
                node = POP;
            }
        }
    }

    private static long bits(double d) {
        return Double.doubleToRawLongBits(d);
    }

    /** The bits of max(0, d): a negative d (sign bit set, −0 included) gives +0. */
    private static long entry(double d) {
        long v = Double.doubleToRawLongBits(d);
        return v & ~(v >> 63);
    }

    /** All ones when the bits {@code v} are of a double below 0 or of −0, else 0. */
    private static long exit(long v) {
        return v >> 63;
    }

    /** The larger of two longs ≥ 0 (their difference cannot overflow), without a branch. */
    private static long max(long a, long b) {
        long d = a - b;
        return a - (d & (d >> 63));
    }

    /** The smaller of two longs ≥ 0, without a branch. */
    private static long min(long a, long b) {
        long d = a - b;
        return b + (d & (d >> 63));
    }
}
