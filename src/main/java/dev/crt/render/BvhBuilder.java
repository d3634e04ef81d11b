package dev.crt.render;

import dev.crt.geom.Aabb;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.RecursiveTask;

/**
 * Builds a {@link Bvh} over item bounds with the binned surface area heuristic (16 bins on each
 * axis); subtrees of more than 10,000 items are built in parallel with fork/join.
 */
final class BvhBuilder {
    private static final int BINS = 16;
    static final int MAX_LEAF = 4;
    private static final int PARALLEL_THRESHOLD = 10_000;
    private static final double TRAVERSAL_COST = 1.0;
    private static final double INTERSECTION_COST = 1.5;

    /**
     * Boxes by position in {@link #order}; partitioning moves them with their items, so every pass
     * over a range reads memory in sequence. Centroids are computed from them where needed rather
     * than stored: at a million items the build is bound by memory traffic, not arithmetic.
     */
    private final double[] bounds;
    /** The item order: leaves refer to ranges of it. */
    final int[] order;

    private BvhBuilder(double[] itemBounds, int n) {
        bounds = itemBounds.clone();
        order = new int[n];
        childBox = new double[12 * (n - 1)];
        children = new int[2 * (n - 1)];
        inner = new boolean[n - 1];
        for (int i = 0; i < n; i++) order[i] = i;
    }

    private void swap(int i, int j) {
        int x = order[i];
        order[i] = order[j];
        order[j] = x;
        for (int a = 0; a < 6; a++) {
            double v = bounds[6 * i + a];
            bounds[6 * i + a] = bounds[6 * j + a];
            bounds[6 * j + a] = v;
        }
    }

    /**
     * Inner nodes while building, before compaction: the subtree over items [lo, hi) owns slots
     * [at, at + hi − lo − 1) (a binary tree over m items has at most m − 1 inner nodes), its root
     * at {@code at}, its left subtree from at + 1 and its right one from at + (mid − lo). Slots
     * are in depth-first order with gaps where leaves hold several items; subtrees built in
     * parallel write disjoint slots.
     */
    private final double[] childBox;
    private final int[] children;
    private final boolean[] inner;

    /**
     * Writes {@code b} as item {@code i} of a flat bounds array, widened by an ulp each way:
     * bounds computed with rounding (c ± r) must not clip the solid they hold.
     */
    static void put(Aabb b, double[] flat, int i) {
        flat[6 * i] = Math.nextDown(b.min().x());
        flat[6 * i + 1] = Math.nextDown(b.min().y());
        flat[6 * i + 2] = Math.nextDown(b.min().z());
        flat[6 * i + 3] = Math.nextUp(b.max().x());
        flat[6 * i + 4] = Math.nextUp(b.max().y());
        flat[6 * i + 5] = Math.nextUp(b.max().z());
    }

    /** The hierarchy over {@code n} items whose boxes are {@code bounds} (six doubles each); item order in {@code orderOut}. */
    static Bvh build(double[] bounds, int n, int[] orderOut) {
        // More items than a leaf takes, so that the root is an inner node.
        if (n <= MAX_LEAF || n > (Integer.MAX_VALUE >>> Bvh.LEAF_COUNT_BITS)) throw new IllegalArgumentException("items: " + n);
        BvhBuilder b = new BvhBuilder(bounds, n);
        double[] rootBox = new double[6];
        double[] rootCentroids = new double[6];
        b.measure(0, n, rootBox, 0, rootCentroids, 0);
        int root;
        if (n > PARALLEL_THRESHOLD) {
            // A pool of its own: the common pool leaves one core idle (its parallelism is cores − 1,
            // and the thread that submits only waits).
            ForkJoinPool pool = new ForkJoinPool(Runtime.getRuntime().availableProcessors());
            try {
                root = pool.invoke(b.new Task(0, n, 0, 0, rootBox, 0, rootCentroids, 0));
            } finally {
                pool.shutdown();
            }
        } else {
            root = b.subtree(0, n, 0, 0, new Scratch(), rootBox, 0, rootCentroids, 0);
        }
        System.arraycopy(b.order, 0, orderOut, 0, n);
        if (Bvh.isLeaf(root)) throw new IllegalStateException("a root leaf over " + n + " items");
        return b.compact(rootBox);
    }

    /** Renumbers the inner nodes densely, keeping depth-first order. */
    private Bvh compact(double[] rootBox) {
        int slots = inner.length;
        int[] index = new int[slots];
        int count = 0;
        for (int s = 0; s < slots; s++) if (inner[s]) index[s] = count++;
        double[] box = new double[Bvh.NODE * count];
        int[] links = new int[2 * count];
        int[] level = new int[count];
        level[0] = 1;
        int depth = 0;
        for (int s = 0; s < slots; s++) {
            if (!inner[s]) continue;
            int k = index[s];
            Bvh.putChild(box, k, 0, childBox, 12 * s);
            Bvh.putChild(box, k, 1, childBox, 12 * s + 6);
            for (int c = 0; c < 2; c++) {
                int child = children[2 * s + c];
                if (Bvh.isLeaf(child)) {
                    depth = Math.max(depth, level[k] + 1);
                } else {
                    child = index[child];
                    // Depth-first order: a parent comes before its children.
                    level[child] = level[k] + 1;
                }
                links[2 * k + c] = child;
            }
        }
        return new Bvh(box, links, rootBox, 2 * count + 1, depth);
    }

    private final class Task extends RecursiveTask<Integer> {
        private static final long serialVersionUID = 1L;
        private final int lo, hi, at, depth;
        private final double[] box;
        private final int boxAt;
        /** The range's centroid bounds, copied: the parent's scratch moves on while this task waits. */
        private final double[] centroids;

        Task(int lo, int hi, int at, int depth, double[] box, int boxAt, double[] centroids, int centroidsAt) {
            this.lo = lo;
            this.hi = hi;
            this.at = at;
            this.depth = depth;
            this.box = box;
            this.boxAt = boxAt;
            this.centroids = java.util.Arrays.copyOfRange(centroids, centroidsAt, centroidsAt + 6);
        }

        @Override
        protected Integer compute() {
            Scratch sc = new Scratch();
            int mid = split(lo, hi, sc, box, boxAt, centroids, 0, at, depth);
            if (mid < 0) return Bvh.leaf(lo, hi - lo);
            inner[at] = true;
            double[] c = sc.centroids;
            int cAt = 12 * depth, leftAt = at + 1, rightAt = at + (mid - lo);
            Task left = new Task(lo, mid, leftAt, depth + 1, childBox, 12 * at, c, cAt);
            if (mid - lo > PARALLEL_THRESHOLD) left.fork();
            children[2 * at + 1] = hi - mid > PARALLEL_THRESHOLD
                    ? new Task(mid, hi, rightAt, depth + 1, childBox, 12 * at + 6, c, cAt + 6).compute()
                    : subtree(mid, hi, rightAt, depth + 1, sc, childBox, 12 * at + 6, c, cAt + 6);
            children[2 * at] = mid - lo > PARALLEL_THRESHOLD ? left.join()
                    : subtree(lo, mid, leftAt, depth + 1, sc, childBox, 12 * at, c, cAt);
            return at;
        }
    }

    /**
     * Builds the subtree over [lo, hi) from slot {@code at}, at {@code depth} below the root; its
     * box is at {@code boxAt} in {@code box} and the bounds of its centroids at {@code cAt} in
     * {@code centroids} (both written by the parent's split). Returns its root (a slot or a leaf).
     */
    private int subtree(int lo, int hi, int at, int depth, Scratch sc, double[] box, int boxAt, double[] centroids, int cAt) {
        int mid = split(lo, hi, sc, box, boxAt, centroids, cAt, at, depth);
        if (mid < 0) return Bvh.leaf(lo, hi - lo);
        inner[at] = true;
        // Read after the split: it may have grown the array.
        double[] c = sc.centroids;
        children[2 * at] = subtree(lo, mid, at + 1, depth + 1, sc, childBox, 12 * at, c, 12 * depth);
        children[2 * at + 1] = subtree(mid, hi, at + (mid - lo), depth + 1, sc, childBox, 12 * at + 6, c, 12 * depth + 6);
        return at;
    }

    /**
     * Per-thread working space of {@link #split}. The bins are kept empty between splits and only
     * the bins a split used are emptied again, so a small range does not pay for all of them.
     */
    private static final class Scratch {
        final int[] binCount = new int[3 * BINS];
        final double[] binBox = new double[3 * 6 * BINS];
        /** Per axis, a bit per bin that holds at least one item. */
        final int[] used = new int[3];
        final double[] rightArea = new double[BINS];
        final int[] rightCount = new int[BINS];
        final double[] acc = new double[6];
        final double[] scale = new double[3];
        /**
         * Per depth d, at 12·d, the centroid bounds (min x, y, z, max x, y, z) of the two halves
         * of the last range split at that depth: a split hands them to its halves, which are
         * built before anything at that depth is split again.
         */
        double[] centroids = new double[12 * 32];

        Scratch() {
            for (int b = 0; b < 3 * BINS; b++) resetBox(binBox, b);
        }
    }

    /**
     * The box of items [lo, hi) into {@code box} at {@code at} and the bounds of their centroids
     * into {@code centroids} at {@code cAt}: for the root, and for halves of a split in the middle.
     * Comparisons rather than Math.min and Math.max, which also order −0 and NaN: item bounds are
     * finite, and −0 and +0 act alike in a slab test and an area.
     */
    private void measure(int lo, int hi, double[] box, int at, double[] centroids, int cAt) {
        double minX = Double.POSITIVE_INFINITY, minY = Double.POSITIVE_INFINITY, minZ = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY, maxY = Double.NEGATIVE_INFINITY, maxZ = Double.NEGATIVE_INFINITY;
        double cminX = Double.POSITIVE_INFINITY, cminY = Double.POSITIVE_INFINITY, cminZ = Double.POSITIVE_INFINITY;
        double cmaxX = Double.NEGATIVE_INFINITY, cmaxY = Double.NEGATIVE_INFINITY, cmaxZ = Double.NEGATIVE_INFINITY;
        double[] bounds = this.bounds;
        for (int i = lo; i < hi; i++) {
            int k = 6 * i;
            double v;
            if ((v = bounds[k]) < minX) minX = v;
            if ((v = bounds[k + 1]) < minY) minY = v;
            if ((v = bounds[k + 2]) < minZ) minZ = v;
            if ((v = bounds[k + 3]) > maxX) maxX = v;
            if ((v = bounds[k + 4]) > maxY) maxY = v;
            if ((v = bounds[k + 5]) > maxZ) maxZ = v;
            if ((v = 0.5 * (bounds[k] + bounds[k + 3])) < cminX) cminX = v;
            if (v > cmaxX) cmaxX = v;
            if ((v = 0.5 * (bounds[k + 1] + bounds[k + 4])) < cminY) cminY = v;
            if (v > cmaxY) cmaxY = v;
            if ((v = 0.5 * (bounds[k + 2] + bounds[k + 5])) < cminZ) cminZ = v;
            if (v > cmaxZ) cmaxZ = v;
        }
        box[at] = minX;
        box[at + 1] = minY;
        box[at + 2] = minZ;
        box[at + 3] = maxX;
        box[at + 4] = maxY;
        box[at + 5] = maxZ;
        centroids[cAt] = cminX;
        centroids[cAt + 1] = cminY;
        centroids[cAt + 2] = cminZ;
        centroids[cAt + 3] = cmaxX;
        centroids[cAt + 4] = cmaxY;
        centroids[cAt + 5] = cmaxZ;
    }

    /**
     * Splits items [lo, hi), whose box is at {@code boxAt} in {@code box} and centroid bounds at
     * {@code cAt} in {@code centroids}, by the best SAH split: partitions the range, writes the
     * halves' boxes to slot {@code slot} of {@link #childBox} and their centroid bounds to depth
     * {@code depth} of the scratch's centroids, and returns the middle; returns −1 when the range
     * is a leaf. The halves' boxes are the unions of their bins, and their centroid bounds are
     * gathered by the partition, so no range is read twice for them.
     */
    private int split(int lo, int hi, Scratch sc, double[] box, int boxAt, double[] centroids, int cAt, int slot, int depth) {
        int n = hi - lo;
        double minX = box[boxAt], minY = box[boxAt + 1], minZ = box[boxAt + 2];
        double maxX = box[boxAt + 3], maxY = box[boxAt + 4], maxZ = box[boxAt + 5];
        double[] bounds = this.bounds;
        if (n <= 1) return -1;
        double bestCost = Double.POSITIVE_INFINITY;
        int bestAxis = -1, bestBin = -1;
        int[] binCount = sc.binCount;
        double[] binBox = sc.binBox;
        int[] used = sc.used;
        double[] scale = sc.scale;
        for (int axis = 0; axis < 3; axis++) {
            double extent = centroids[cAt + 3 + axis] - centroids[cAt + axis];
            scale[axis] = extent > 0 ? BINS / extent : 0;
        }
        // One pass bins every item on all three axes at once, so the item data is read once.
        double kx = scale[0], ky = scale[1], kz = scale[2];
        double mx = centroids[cAt], my = centroids[cAt + 1], mz = centroids[cAt + 2];
        int maskX = 0, maskY = 0, maskZ = 0;
        for (int i = lo; i < hi; i++) {
            int c = 6 * i;
            if (kx != 0) {
                int bin = bin(0.5 * (bounds[c] + bounds[c + 3]), mx, kx);
                maskX |= 1 << bin;
                binCount[bin]++;
                grow(binBox, bin, bounds, i);
            }
            if (ky != 0) {
                int bin = bin(0.5 * (bounds[c + 1] + bounds[c + 4]), my, ky);
                maskY |= 1 << bin;
                binCount[BINS + bin]++;
                grow(binBox, BINS + bin, bounds, i);
            }
            if (kz != 0) {
                int bin = bin(0.5 * (bounds[c + 2] + bounds[c + 5]), mz, kz);
                maskZ |= 1 << bin;
                binCount[2 * BINS + bin]++;
                grow(binBox, 2 * BINS + bin, bounds, i);
            }
        }
        used[0] = maskX;
        used[1] = maskY;
        used[2] = maskZ;
        // The sweeps visit only the bins in use: an empty bin changes neither a running box nor a
        // count, so every cost is the one a sweep over all bins computes, and ties resolve alike
        // (the first candidate of equal cost is kept).
        double[] rightArea = sc.rightArea;
        int[] rightCount = sc.rightCount;
        double[] acc = sc.acc;
        for (int axis = 0; axis < 3; axis++) {
            if (scale[axis] == 0) continue;
            int base = axis * BINS, mask = used[axis];
            resetAcc(acc);
            int accCount = 0;
            for (int m = mask; m != 0; ) {
                int b = 31 - Integer.numberOfLeadingZeros(m);
                m &= ~(1 << b);
                include(acc, binBox, base + b);
                accCount += binCount[base + b];
                rightArea[b] = area(acc);
                rightCount[b] = accCount;
            }
            resetAcc(acc);
            accCount = 0;
            for (int m = mask; ; ) {
                int b = Integer.numberOfTrailingZeros(m);
                m &= m - 1;
                if (m == 0) break;
                include(acc, binBox, base + b);
                accCount += binCount[base + b];
                int next = Integer.numberOfTrailingZeros(m);
                double cost = area(acc) * accCount + rightArea[next] * rightCount[next];
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = axis;
                    bestBin = b;
                }
            }
        }
        double parentArea = area(minX, minY, minZ, maxX, maxY, maxZ);
        if (sc.centroids.length < 12 * (depth + 1)) sc.centroids = java.util.Arrays.copyOf(sc.centroids, 24 * (depth + 1));
        double[] halves = sc.centroids;
        int halvesAt = 12 * depth;
        if (bestAxis < 0) {
            // All centroids coincide: split the range in the middle if it is too big for a leaf.
            emptyBins(sc);
            if (n <= MAX_LEAF) return -1;
            int mid = lo + n / 2;
            measure(lo, mid, childBox, 12 * slot, halves, halvesAt);
            measure(mid, hi, childBox, 12 * slot + 6, halves, halvesAt + 6);
            return mid;
        }
        double splitCost = TRAVERSAL_COST + INTERSECTION_COST * bestCost / parentArea;
        if (n <= MAX_LEAF && (splitCost >= INTERSECTION_COST * n || !(parentArea > 0))) {
            emptyBins(sc);
            return -1;
        }
        // The halves' boxes: the unions of the chosen axis's bins on either side of the split.
        int base = bestAxis * BINS;
        resetAcc(acc);
        for (int m = sc.used[bestAxis] & (2 << bestBin) - 1; m != 0; m &= m - 1) include(acc, binBox, base + Integer.numberOfTrailingZeros(m));
        System.arraycopy(acc, 0, childBox, 12 * slot, 6);
        resetAcc(acc);
        for (int m = sc.used[bestAxis] & -(2 << bestBin); m != 0; m &= m - 1) include(acc, binBox, base + Integer.numberOfTrailingZeros(m));
        System.arraycopy(acc, 0, childBox, 12 * slot + 6, 6);
        emptyBins(sc);
        // The partition gathers the centroid bounds of each half as it places the items.
        double lminX = Double.POSITIVE_INFINITY, lminY = Double.POSITIVE_INFINITY, lminZ = Double.POSITIVE_INFINITY;
        double lmaxX = Double.NEGATIVE_INFINITY, lmaxY = Double.NEGATIVE_INFINITY, lmaxZ = Double.NEGATIVE_INFINITY;
        double rminX = Double.POSITIVE_INFINITY, rminY = Double.POSITIVE_INFINITY, rminZ = Double.POSITIVE_INFINITY;
        double rmaxX = Double.NEGATIVE_INFINITY, rmaxY = Double.NEGATIVE_INFINITY, rmaxZ = Double.NEGATIVE_INFINITY;
        double k = scale[bestAxis], min = centroids[cAt + bestAxis];
        int i = lo, j = hi - 1;
        while (i <= j) {
            int c = 6 * i;
            double x = 0.5 * (bounds[c] + bounds[c + 3]), y = 0.5 * (bounds[c + 1] + bounds[c + 4]), z = 0.5 * (bounds[c + 2] + bounds[c + 5]);
            if (bin(bestAxis == 0 ? x : bestAxis == 1 ? y : z, min, k) <= bestBin) {
                if (x < lminX) lminX = x;
                if (x > lmaxX) lmaxX = x;
                if (y < lminY) lminY = y;
                if (y > lmaxY) lmaxY = y;
                if (z < lminZ) lminZ = z;
                if (z > lmaxZ) lmaxZ = z;
                i++;
            } else {
                if (x < rminX) rminX = x;
                if (x > rmaxX) rmaxX = x;
                if (y < rminY) rminY = y;
                if (y > rmaxY) rmaxY = y;
                if (z < rminZ) rminZ = z;
                if (z > rmaxZ) rmaxZ = z;
                swap(i, j);
                j--;
            }
        }
        halves[halvesAt] = lminX;
        halves[halvesAt + 1] = lminY;
        halves[halvesAt + 2] = lminZ;
        halves[halvesAt + 3] = lmaxX;
        halves[halvesAt + 4] = lmaxY;
        halves[halvesAt + 5] = lmaxZ;
        halves[halvesAt + 6] = rminX;
        halves[halvesAt + 7] = rminY;
        halves[halvesAt + 8] = rminZ;
        halves[halvesAt + 9] = rmaxX;
        halves[halvesAt + 10] = rmaxY;
        halves[halvesAt + 11] = rmaxZ;
        return i;
    }

    /** Empties the bins the last split used, so the next split finds them empty. */
    private static void emptyBins(Scratch sc) {
        for (int axis = 0; axis < 3; axis++) {
            for (int m = sc.used[axis]; m != 0; m &= m - 1) {
                int b = axis * BINS + Integer.numberOfTrailingZeros(m);
                sc.binCount[b] = 0;
                resetBox(sc.binBox, b);
            }
        }
    }

    private static int bin(double c, double min, double k) {
        int b = (int) ((c - min) * k);
        return b < 0 ? 0 : Math.min(b, BINS - 1);
    }

    private static void resetAcc(double[] acc) {
        for (int a = 0; a < 3; a++) {
            acc[a] = Double.POSITIVE_INFINITY;
            acc[3 + a] = Double.NEGATIVE_INFINITY;
        }
    }

    private static void resetBox(double[] boxes, int b) {
        for (int a = 0; a < 3; a++) {
            boxes[6 * b + a] = Double.POSITIVE_INFINITY;
            boxes[6 * b + 3 + a] = Double.NEGATIVE_INFINITY;
        }
    }

    /**
     * Comparisons rather than Math.min and Math.max (which also order −0 and NaN, at a longer
     * instruction sequence): item bounds are finite, a bin's box only feeds areas, which −0 and
     * +0 leave alike, and this runs for every item on three axes at every level of the tree.
     */
    private static void grow(double[] boxes, int b, double[] items, int item) {
        int o = 6 * b, k = 6 * item;
        double v;
        if ((v = items[k]) < boxes[o]) boxes[o] = v;
        if ((v = items[k + 1]) < boxes[o + 1]) boxes[o + 1] = v;
        if ((v = items[k + 2]) < boxes[o + 2]) boxes[o + 2] = v;
        if ((v = items[k + 3]) > boxes[o + 3]) boxes[o + 3] = v;
        if ((v = items[k + 4]) > boxes[o + 4]) boxes[o + 4] = v;
        if ((v = items[k + 5]) > boxes[o + 5]) boxes[o + 5] = v;
    }

    private static void include(double[] acc, double[] boxes, int b) {
        for (int a = 0; a < 3; a++) {
            acc[a] = Math.min(acc[a], boxes[6 * b + a]);
            acc[3 + a] = Math.max(acc[3 + a], boxes[6 * b + 3 + a]);
        }
    }

    private static double area(double[] b) {
        return area(b[0], b[1], b[2], b[3], b[4], b[5]);
    }

    private static double area(double minX, double minY, double minZ, double maxX, double maxY, double maxZ) {
        double x = maxX - minX, y = maxY - minY, z = maxZ - minZ;
        if (!(x >= 0 && y >= 0 && z >= 0)) return 0;
        return x * y + y * z + z * x;
    }
}
