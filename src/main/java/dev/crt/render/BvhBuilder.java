package dev.crt.render;

import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.RecursiveTask;

/**
 * Builds a {@link Bvh} over item bounds with the binned surface area heuristic (16 bins on each
 * axis); subtrees of more than 10,000 items are built in parallel with fork/join.
 */
final class BvhBuilder {
    private static final int BINS = 16;
    private static final int MAX_LEAF = 4;
    private static final int PARALLEL_THRESHOLD = 10_000;
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

    private BvhBuilder(double[] itemBounds, int n) {
        bounds = itemBounds.clone();
        centroid = new double[3 * n];
        order = new int[n];
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

    /** The hierarchy over {@code n} items whose boxes are {@code bounds} (six doubles each); item order in {@code orderOut}. */
    static Bvh build(double[] bounds, int n, int[] orderOut) {
        BvhBuilder b = new BvhBuilder(bounds, n);
        Node root;
        if (n > PARALLEL_THRESHOLD) {
            // A pool of its own: the common pool leaves one core idle (its parallelism is cores − 1,
            // and the thread that submits only waits).
            ForkJoinPool pool = new ForkJoinPool(Runtime.getRuntime().availableProcessors());
            try {
                root = pool.invoke(b.new Task(0, n));
            } finally {
                pool.shutdown();
            }
        } else {
            root = b.subtree(0, n, new Scratch());
        }
        System.arraycopy(b.order, 0, orderOut, 0, n);
        int nodes = root.size;
        double[] box = new double[6 * nodes];
        int[] link = new int[nodes];
        int[] count = new int[nodes];
        int[] depth = new int[1];
        flatten(root, 0, 1, box, link, count, depth);
        return new Bvh(box, link, count, nodes, depth[0]);
    }

    private static int flatten(Node node, int at, int level, double[] box, int[] link, int[] count, int[] depth) {
        System.arraycopy(node.box, 0, box, 6 * at, 6);
        depth[0] = Math.max(depth[0], level);
        if (node.left == null) {
            link[at] = node.first;
            count[at] = node.count;
            return at + 1;
        }
        int right = flatten(node.left, at + 1, level + 1, box, link, count, depth);
        link[at] = right;
        count[at] = 0;
        return flatten(node.right, right, level + 1, box, link, count, depth);
    }

    private static final class Node {
        /** Filled in by {@link #split}. */
        final double[] box = new double[6];
        Node left, right;
        int first, count;
        int size = 1;
    }

    private final class Task extends RecursiveTask<Node> {
        private static final long serialVersionUID = 1L;
        private final int lo, hi;

        Task(int lo, int hi) {
            this.lo = lo;
            this.hi = hi;
        }

        @Override
        protected Node compute() {
            Node node = new Node();
            Scratch sc = new Scratch();
            int mid = split(node, lo, hi, sc);
            if (mid < 0) return node;
            Task left = new Task(lo, mid);
            Task right = new Task(mid, hi);
            if (mid - lo > PARALLEL_THRESHOLD) left.fork();
            node.right = hi - mid > PARALLEL_THRESHOLD ? right.compute() : subtree(mid, hi, sc);
            node.left = mid - lo > PARALLEL_THRESHOLD ? left.join() : subtree(lo, mid, sc);
            node.size = 1 + node.left.size + node.right.size;
            return node;
        }
    }

    private Node subtree(int lo, int hi, Scratch sc) {
        Node node = new Node();
        int mid = split(node, lo, hi, sc);
        if (mid < 0) return node;
        node.left = subtree(lo, mid, sc);
        node.right = subtree(mid, hi, sc);
        node.size = 1 + node.left.size + node.right.size;
        return node;
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

        Scratch() {
            for (int b = 0; b < 3 * BINS; b++) resetBox(binBox, b);
        }
    }

    /** Partitions [lo, hi) by the best SAH split and returns its middle, or makes {@code node} a leaf and returns −1. */
    private int split(Node node, int lo, int hi, Scratch sc) {
        int n = hi - lo;
        // One pass for the node's box and the bounds of the centroids.
        double[] box = node.box;
        double[] cmin = sc.cmin, cmax = sc.cmax;
        for (int a = 0; a < 3; a++) {
            box[a] = Double.POSITIVE_INFINITY;
            box[3 + a] = Double.NEGATIVE_INFINITY;
            cmin[a] = Double.POSITIVE_INFINITY;
            cmax[a] = Double.NEGATIVE_INFINITY;
        }
        for (int i = lo; i < hi; i++) {
            for (int a = 0; a < 3; a++) {
                box[a] = Math.min(box[a], bounds[6 * i + a]);
                box[3 + a] = Math.max(box[3 + a], bounds[6 * i + 3 + a]);
                cmin[a] = Math.min(cmin[a], centroid[3 * i + a]);
                cmax[a] = Math.max(cmax[a], centroid[3 * i + a]);
            }
        }
        if (n <= 1) return leaf(node, lo, hi);
        double bestCost = Double.POSITIVE_INFINITY;
        int bestAxis = -1, bestBin = -1;
        int[] binCount = sc.binCount;
        double[] binBox = sc.binBox;
        int[] used = sc.used;
        double[] scale = sc.scale;
        for (int axis = 0; axis < 3; axis++) {
            double extent = cmax[axis] - cmin[axis];
            scale[axis] = extent > 0 ? BINS / extent : 0;
        }
        for (int axis = 0; axis < 3; axis++) {
            // An axis on which all centroids coincide offers no split.
            if (scale[axis] == 0) continue;
            double min = cmin[axis], k = scale[axis];
            int base = axis * BINS, mask = 0;
            for (int i = lo; i < hi; i++) {
                int bin = bin(centroid[3 * i + axis], min, k);
                mask |= 1 << bin;
                binCount[base + bin]++;
                grow(binBox, base + bin, bounds, i);
            }
            used[axis] = mask;
        }
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
        double parentArea = area(node.box);
        if (bestAxis < 0) {
            // All centroids coincide: split the range in the middle if it is too big for a leaf.
            return n <= MAX_LEAF ? leaf(node, lo, hi) : lo + n / 2;
        }
        double splitCost = TRAVERSAL_COST + INTERSECTION_COST * bestCost / parentArea;
        if (n <= MAX_LEAF && (splitCost >= INTERSECTION_COST * n || !(parentArea > 0))) return leaf(node, lo, hi);
        double k = scale[bestAxis];
        int i = lo, j = hi - 1;
        while (i <= j) {
            if (bin(centroid[3 * i + bestAxis], cmin[bestAxis], k) <= bestBin) {
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

    private int leaf(Node node, int lo, int hi) {
        node.first = lo;
        node.count = hi - lo;
        return -1;
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
        for (int a = 0; a < 3; a++) {
            boxes[6 * b + a] = Math.min(boxes[6 * b + a], items[6 * item + a]);
            boxes[6 * b + 3 + a] = Math.max(boxes[6 * b + 3 + a], items[6 * item + 3 + a]);
        }
    }

    private static void include(double[] acc, double[] boxes, int b) {
        for (int a = 0; a < 3; a++) {
            acc[a] = Math.min(acc[a], boxes[6 * b + a]);
            acc[3 + a] = Math.max(acc[3 + a], boxes[6 * b + 3 + a]);
        }
    }

    private static double area(double[] b) {
        double x = b[3] - b[0], y = b[4] - b[1], z = b[5] - b[2];
        if (!(x >= 0 && y >= 0 && z >= 0)) return 0;
        return x * y + y * z + z * x;
    }
}
