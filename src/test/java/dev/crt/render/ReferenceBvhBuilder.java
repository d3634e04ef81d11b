package dev.crt.render;

import dev.crt.geom.Aabb;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.RecursiveTask;

/**
 * Builds a {@link Bvh} over item bounds with the binned surface area heuristic (16 bins on each
 * axis, or on the widest axis only for ranges of more than {@value #ONE_AXIS_ABOVE} items);
 * subtrees of more than 10,000 items are built in parallel with fork/join.
 */
final class ReferenceBvhBuilder {
    private static final int BINS = 16;
    static final int MAX_LEAF = 4;
    private static final int PARALLEL_THRESHOLD = 10_000;
    /**
     * Ranges of more items than this are split on one axis (docs/benchmarks.md section 10: warm
     * builds of a million triangles about 8 % faster, renders as fast); smaller ones, every scene's
     * own hierarchy among them, try all three.
     */
    static final int ONE_AXIS_ABOVE = 1 << 16;
    private static final double TRAVERSAL_COST = 1.0;
    private static final double INTERSECTION_COST = 1.5;

    /**
     * Boxes and centroids by position in {@link #order}; partitioning moves them with their items,
     * so every pass over a range reads memory in sequence.
     */
    private final double[] bounds;
    private final double[] centroid;
    /** The item order: leaves refer to ranges of it. */
    final int[] order;

    private ReferenceBvhBuilder(double[] itemBounds, int n) {
        bounds = itemBounds.clone();
        centroid = new double[3 * n];
        order = new int[n];
        childBox = new double[12 * (n - 1)];
        children = new int[2 * (n - 1)];
        inner = new boolean[n - 1];
        for (int i = 0; i < n; i++) {
            order[i] = i;
            for (int a = 0; a < 3; a++) centroid[3 * i + a] = 0.5 * (bounds[6 * i + a] + bounds[6 * i + 3 + a]);
        }
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
        for (int a = 0; a < 3; a++) {
            double v = centroid[3 * i + a];
            centroid[3 * i + a] = centroid[3 * j + a];
            centroid[3 * j + a] = v;
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
        ReferenceBvhBuilder b = new ReferenceBvhBuilder(bounds, n);
        double[] rootBox = new double[6];
        int root;
        if (n > PARALLEL_THRESHOLD) {
            // A pool of its own: the common pool leaves one core idle (its parallelism is cores − 1,
            // and the thread that submits only waits).
            ForkJoinPool pool = new ForkJoinPool(Runtime.getRuntime().availableProcessors());
            try {
                root = pool.invoke(b.new Task(0, n, 0, rootBox, 0));
            } finally {
                pool.shutdown();
            }
        } else {
            root = b.subtree(0, n, 0, new Scratch(), rootBox, 0);
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
        private final int lo, hi, at;
        private final double[] boxOut;
        private final int boxAt;

        Task(int lo, int hi, int at, double[] boxOut, int boxAt) {
            this.lo = lo;
            this.hi = hi;
            this.at = at;
            this.boxOut = boxOut;
            this.boxAt = boxAt;
        }

        @Override
        protected Integer compute() {
            Scratch sc = new Scratch();
            int mid = split(lo, hi, sc, boxOut, boxAt);
            if (mid < 0) return Bvh.leaf(lo, hi - lo);
            inner[at] = true;
            int leftAt = at + 1, rightAt = at + (mid - lo);
            Task left = new Task(lo, mid, leftAt, childBox, 12 * at);
            Task right = new Task(mid, hi, rightAt, childBox, 12 * at + 6);
            if (mid - lo > PARALLEL_THRESHOLD) left.fork();
            children[2 * at + 1] = hi - mid > PARALLEL_THRESHOLD ? right.compute()
                    : subtree(mid, hi, rightAt, sc, childBox, 12 * at + 6);
            children[2 * at] = mid - lo > PARALLEL_THRESHOLD ? left.join()
                    : subtree(lo, mid, leftAt, sc, childBox, 12 * at);
            return at;
        }
    }

    /** Builds the subtree over [lo, hi) from slot {@code at}, its box into {@code boxOut}; returns its root (a slot or a leaf). */
    private int subtree(int lo, int hi, int at, Scratch sc, double[] boxOut, int boxAt) {
        int mid = split(lo, hi, sc, boxOut, boxAt);
        if (mid < 0) return Bvh.leaf(lo, hi - lo);
        inner[at] = true;
        children[2 * at] = subtree(lo, mid, at + 1, sc, childBox, 12 * at);
        children[2 * at + 1] = subtree(mid, hi, at + (mid - lo), sc, childBox, 12 * at + 6);
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
        final double[] cmin = new double[3], cmax = new double[3], scale = new double[3];
        /** The result of {@link #sweep}. */
        double bestCost;
        int bestAxis, bestBin;

        Scratch() {
            for (int b = 0; b < 3 * BINS; b++) resetBox(binBox, b);
        }
    }

    /**
     * Writes the box of [lo, hi) into {@code box} at {@code at}, then partitions the range by the
     * best SAH split and returns its middle, or returns −1 when the range is a leaf. Each pass
     * over the items is a method of its own: small methods are compiled early and quickly, where
     * one large one ran interpreted through the first levels of a million-item build while the
     * compiler worked on it for seconds.
     */
    private int split(int lo, int hi, Scratch sc, double[] box, int at) {
        int n = hi - lo;
        measure(lo, hi, sc, box, at);
        if (n <= 1) return -1;
        double[] cmin = sc.cmin, cmax = sc.cmax, scale = sc.scale;
        for (int axis = 0; axis < 3; axis++) {
            double extent = cmax[axis] - cmin[axis];
            scale[axis] = extent > 0 ? BINS / extent : 0;
        }
        if (n > ONE_AXIS_ABOVE) {
            // Binned on the axis of the centroids' largest extent only: a third of the binning work
            // where a range is large enough for the three axes' best splits to differ little.
            int widest = cmax[0] - cmin[0] >= cmax[1] - cmin[1] ? 0 : 1;
            if (cmax[2] - cmin[2] > cmax[widest] - cmin[widest]) widest = 2;
            for (int axis = 0; axis < 3; axis++) if (axis != widest) scale[axis] = 0;
            sc.used[0] = sc.used[1] = sc.used[2] = 0;
            sc.used[widest] = binAxis(lo, hi, sc, widest);
        } else {
            binAll(lo, hi, sc);
        }
        sweep(sc);
        int bestAxis = sc.bestAxis;
        double parentArea = area(box[at], box[at + 1], box[at + 2], box[at + 3], box[at + 4], box[at + 5]);
        if (bestAxis < 0) {
            // All centroids coincide: split the range in the middle if it is too big for a leaf.
            return n <= MAX_LEAF ? -1 : lo + n / 2;
        }
        double splitCost = TRAVERSAL_COST + INTERSECTION_COST * sc.bestCost / parentArea;
        if (n <= MAX_LEAF && (splitCost >= INTERSECTION_COST * n || !(parentArea > 0))) return -1;
        return partition(lo, hi, bestAxis, cmin[bestAxis], scale[bestAxis], sc.bestBin);
    }

    /** One pass for the box of [lo, hi) (into box at {@code at}) and the bounds of its centroids (into sc). */
    private void measure(int lo, int hi, Scratch sc, double[] box, int at) {
        double minX = Double.POSITIVE_INFINITY, minY = Double.POSITIVE_INFINITY, minZ = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY, maxY = Double.NEGATIVE_INFINITY, maxZ = Double.NEGATIVE_INFINITY;
        double cminX = Double.POSITIVE_INFINITY, cminY = Double.POSITIVE_INFINITY, cminZ = Double.POSITIVE_INFINITY;
        double cmaxX = Double.NEGATIVE_INFINITY, cmaxY = Double.NEGATIVE_INFINITY, cmaxZ = Double.NEGATIVE_INFINITY;
        // Comparisons rather than Math.min and Math.max, which also order −0 and NaN: item bounds
        // are finite, and these loops run over every item at every level of the tree.
        double[] bounds = this.bounds, centroid = this.centroid;
        for (int i = lo; i < hi; i++) {
            int k = 6 * i;
            double v;
            if ((v = bounds[k]) < minX) minX = v;
            if ((v = bounds[k + 1]) < minY) minY = v;
            if ((v = bounds[k + 2]) < minZ) minZ = v;
            if ((v = bounds[k + 3]) > maxX) maxX = v;
            if ((v = bounds[k + 4]) > maxY) maxY = v;
            if ((v = bounds[k + 5]) > maxZ) maxZ = v;
            int c = 3 * i;
            if ((v = centroid[c]) < cminX) cminX = v;
            if (v > cmaxX) cmaxX = v;
            if ((v = centroid[c + 1]) < cminY) cminY = v;
            if (v > cmaxY) cmaxY = v;
            if ((v = centroid[c + 2]) < cminZ) cminZ = v;
            if (v > cmaxZ) cmaxZ = v;
        }
        double[] cmin = sc.cmin, cmax = sc.cmax;
        cmin[0] = cminX;
        cmin[1] = cminY;
        cmin[2] = cminZ;
        cmax[0] = cmaxX;
        cmax[1] = cmaxY;
        cmax[2] = cmaxZ;
        box[at] = minX;
        box[at + 1] = minY;
        box[at + 2] = minZ;
        box[at + 3] = maxX;
        box[at + 4] = maxY;
        box[at + 5] = maxZ;
    }

    /** Bins every item of [lo, hi) on all three axes at once (those of non-zero scale), so the item data is read once. */
    private void binAll(int lo, int hi, Scratch sc) {
        int[] binCount = sc.binCount;
        double[] binBox = sc.binBox, centroid = this.centroid, bounds = this.bounds;
        double kx = sc.scale[0], ky = sc.scale[1], kz = sc.scale[2];
        double mx = sc.cmin[0], my = sc.cmin[1], mz = sc.cmin[2];
        int maskX = 0, maskY = 0, maskZ = 0;
        for (int i = lo; i < hi; i++) {
            int c = 3 * i;
            if (kx != 0) {
                int bin = bin(centroid[c], mx, kx);
                maskX |= 1 << bin;
                binCount[bin]++;
                grow(binBox, bin, bounds, i);
            }
            if (ky != 0) {
                int bin = bin(centroid[c + 1], my, ky);
                maskY |= 1 << bin;
                binCount[BINS + bin]++;
                grow(binBox, BINS + bin, bounds, i);
            }
            if (kz != 0) {
                int bin = bin(centroid[c + 2], mz, kz);
                maskZ |= 1 << bin;
                binCount[2 * BINS + bin]++;
                grow(binBox, 2 * BINS + bin, bounds, i);
            }
        }
        sc.used[0] = maskX;
        sc.used[1] = maskY;
        sc.used[2] = maskZ;
    }

    /** Bins every item of [lo, hi) on {@code axis} alone; returns the mask of the bins used. */
    private int binAxis(int lo, int hi, Scratch sc, int axis) {
        int[] binCount = sc.binCount;
        double[] binBox = sc.binBox, centroid = this.centroid, bounds = this.bounds;
        double k = sc.scale[axis], min = sc.cmin[axis];
        int base = axis * BINS, mask = 0;
        for (int i = lo; i < hi; i++) {
            int bin = bin(centroid[3 * i + axis], min, k);
            mask |= 1 << bin;
            binCount[base + bin]++;
            grow(binBox, base + bin, bounds, i);
        }
        return mask;
    }

    /**
     * The SAH sweeps over the bins {@link #binAll} or {@link #binAxis} filled: the best axis, bin
     * and cost into sc (axis −1 when no axis has two bins in use); empties the bins again.
     */
    private static void sweep(Scratch sc) {
        double bestCost = Double.POSITIVE_INFINITY;
        int bestAxis = -1, bestBin = -1;
        int[] binCount = sc.binCount, used = sc.used;
        double[] binBox = sc.binBox, scale = sc.scale;
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
            for (int m = mask; m != 0; m &= m - 1) {
                int b = base + Integer.numberOfTrailingZeros(m);
                binCount[b] = 0;
                resetBox(binBox, b);
            }
        }
        sc.bestCost = bestCost;
        sc.bestAxis = bestAxis;
        sc.bestBin = bestBin;
    }

    /** Moves the items of [lo, hi) whose centroid falls in a bin up to {@code last} on {@code axis} first; returns where the rest start. */
    private int partition(int lo, int hi, int axis, double min, double k, int last) {
        double[] centroid = this.centroid;
        int i = lo, j = hi - 1;
        while (i <= j) {
            if (bin(centroid[3 * i + axis], min, k) <= last) {
                i++;
            } else {
                swap(i, j);
                j--;
            }
        }
        return i;
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

    private static void grow(double[] boxes, int b, double[] items, int item) {
        int o = 6 * b, k = 6 * item;
        boxes[o] = Math.min(boxes[o], items[k]);
        boxes[o + 1] = Math.min(boxes[o + 1], items[k + 1]);
        boxes[o + 2] = Math.min(boxes[o + 2], items[k + 2]);
        boxes[o + 3] = Math.max(boxes[o + 3], items[k + 3]);
        boxes[o + 4] = Math.max(boxes[o + 4], items[k + 4]);
        boxes[o + 5] = Math.max(boxes[o + 5], items[k + 5]);
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
