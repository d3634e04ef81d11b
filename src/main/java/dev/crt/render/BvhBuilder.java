package dev.crt.render;

import dev.crt.geom.Aabb;
import java.util.Arrays;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinTask;
import java.util.concurrent.RecursiveAction;
import java.util.concurrent.RecursiveTask;

/**
 * Builds a {@link Bvh} over item bounds with the binned surface area heuristic (16 bins on each
 * axis, or on the widest axis only for ranges of more than {@value #ONE_AXIS_ABOVE} items);
 * builds of more than {@value #MORTON_ABOVE} items bin every range on its widest axis only and
 * finish their ranges of up to {@value #MORTON_RANGE} by Morton order instead (docs/benchmarks.md
 * sections 18 and 40). Subtrees of more than 10,000 items are built in parallel with fork/join,
 * ranges of more than {@value #PARALLEL_SPLIT_ABOVE} are measured and binned in parts on every
 * thread, and the final renumbering and boxes run in parts too; the tree is the same for any number
 * of threads. The items' bounds are reordered in the caller's array rather than copied, the build
 * records only each node's children, and the boxes are computed at the end into an array of the
 * final size: at most about 134 bytes per item while building, the tree included, where copies
 * and a second layout took 300.
 */
final class BvhBuilder {
    private static final int BINS = 16;
    static final int MAX_LEAF = 4;
    private static final int PARALLEL_THRESHOLD = 10_000;
    /**
     * Ranges of more items than this are split on one axis (docs/benchmarks.md section 10: warm
     * builds of a million triangles about 8 % faster, renders as fast); smaller ones, every scene's
     * own hierarchy among them, try all three, except in builds of more than {@link #MORTON_ABOVE}
     * items, which bin on one axis throughout (section 40: a million spheres' first build in a
     * fresh JVM about a fifth faster, the tree's SAH cost 0.5 % higher).
     */
    static final int ONE_AXIS_ABOVE = 1 << 16;
    /**
     * Builds of more items than this finish their ranges of at most {@link #MORTON_RANGE} items
     * by Morton order instead of binning: one sort per range instead of a binning pass per level
     * and its per-node work. docs/benchmarks.md section 18: a million spheres or triangles build in
     * about half the CPU time; the trees' SAH cost is 10–13 % higher, which the spheres' render
     * did not show and a million-triangle ball's did (about 10 % slower). Smaller builds, every
     * shipped scene's among them, are binned to the leaves and their trees are unchanged.
     */
    static final int MORTON_ABOVE = 1 << 17;
    static final int MORTON_RANGE = 1 << 12;
    /**
     * A build of more than {@link #MORTON_ABOVE} items keeps its build slots as the final node
     * numbers when at most one slot in this many is a gap, rather than renumbering them densely
     * in three more passes over the tree (docs/benchmarks.md section 42).
     */
    static final int GAPS_KEPT = 32;
    /**
     * Ranges of more items than this are measured and binned on every thread at once: the top
     * of the tree, where the subtrees built in parallel have not yet begun.
     */
    static final int PARALLEL_SPLIT_ABOVE = 1 << 17;
    private static final double TRAVERSAL_COST = 1.0;
    private static final double INTERSECTION_COST = 1.5;

    /**
     * The items' boxes (six doubles each), in the order of {@link #order}: partitioning moves them
     * with their items, so every pass over a range reads memory in sequence. Centroids are
     * computed from them where needed, in the same arithmetic as the box's own midpoint.
     */
    private final double[] bounds;
    /** The item order: leaves refer to ranges of it. */
    private final int[] order;
    /**
     * The children of the inner nodes while building, indexed by slot: the subtree over items
     * [lo, hi) owns slots [at, at + hi − lo − 1) (a binary tree over m items has at most m − 1
     * inner nodes), its root at {@code at}, its left subtree from at + 1 and its right one from
     * at + (mid − lo). Slots are in depth-first order, with gaps where leaves hold several items
     * (their children stay 0, which no inner node's are: a child is a leaf, &lt; 0, or a later
     * slot); subtrees built in parallel write disjoint slots. The boxes come afterwards, into an
     * array of the final size (see {@link #finish}).
     */
    private final int[] children;
    /** Whether ranges of at most {@link #MORTON_RANGE} items are split in Morton order (see {@link #MORTON_ABOVE}). */
    private final boolean morton;

    private BvhBuilder(double[] bounds, int n, int[] order) {
        morton = n > MORTON_ABOVE;
        this.bounds = bounds;
        this.order = order;
        children = new int[2 * (n - 1)];
        for (int i = 0; i < n; i++) order[i] = i;
    }

    private void swap(int i, int j) {
        int x = order[i];
        order[i] = order[j];
        order[j] = x;
        double[] bounds = this.bounds;
        for (int a = 0; a < 6; a++) {
            double v = bounds[6 * i + a];
            bounds[6 * i + a] = bounds[6 * j + a];
            bounds[6 * j + a] = v;
        }
    }

    private double centroid(int i, int axis) {
        return 0.5 * (bounds[6 * i + axis] + bounds[6 * i + 3 + axis]);
    }

    /**
     * Writes {@code b} as item {@code i} of a flat bounds array, widened by an ulp each way:
     * bounds computed with rounding (c ± r) must not clip the solid they hold.
     */
    static void put(Aabb b, double[] flat, int i) {
        put(b.min().x(), b.min().y(), b.min().z(), b.max().x(), b.max().y(), b.max().z(), flat, i);
    }

    /** {@link #put(Aabb, double[], int)} of the box from (x0, y0, z0) to (x1, y1, z1). */
    static void put(double x0, double y0, double z0, double x1, double y1, double z1, double[] flat, int i) {
        flat[6 * i] = Math.nextDown(x0);
        flat[6 * i + 1] = Math.nextDown(y0);
        flat[6 * i + 2] = Math.nextDown(z0);
        flat[6 * i + 3] = Math.nextUp(x1);
        flat[6 * i + 4] = Math.nextUp(y1);
        flat[6 * i + 5] = Math.nextUp(z1);
    }

    /**
     * The hierarchy over {@code n} items whose boxes are {@code bounds} (six doubles each); item
     * order in {@code orderOut}. The boxes are reordered in place: afterwards the box at position
     * k is that of item {@code orderOut[k]}.
     */
    static Bvh build(double[] bounds, int n, int[] orderOut) {
        // More items than a leaf takes, so that the root is an inner node.
        if (n <= MAX_LEAF || n > (Integer.MAX_VALUE >>> Bvh.LEAF_COUNT_BITS)) throw new IllegalArgumentException("items: " + n);
        BvhBuilder b = new BvhBuilder(bounds, n, orderOut);
        int root, depth;
        if (n > PARALLEL_THRESHOLD) {
            // A pool of its own: the common pool leaves one core idle (its parallelism is cores − 1,
            // and the thread that submits only waits).
            ForkJoinPool pool = new ForkJoinPool(Runtime.getRuntime().availableProcessors());
            try {
                Task task = b.new Task(0, n, 0, 1);
                root = pool.invoke(task);
                depth = task.depth;
            } finally {
                pool.shutdown();
            }
        } else {
            Scratch sc = new Scratch();
            root = b.subtree(0, n, 0, sc, 1);
            depth = sc.depth;
        }
        if (Bvh.isLeaf(root)) throw new IllegalStateException("a root leaf over " + n + " items");
        return b.finish(depth);
    }

    /**
     * Renumbers the inner nodes densely, keeping depth-first order (unless a large build's slots
     * leave few gaps: see {@link #GAPS_KEPT}), and computes their boxes from the leaves up into an
     * array of the final size. Each box is the union of the items' boxes
     * below it, as the builder measured it (minimum and maximum are exact, whatever the order);
     * a leaf's items are consecutive in {@link #bounds}, so the leaves are read in one sequential
     * pass.
     */
    private Bvh finish(int depth) {
        int slots = children.length / 2;
        // The renumbering in chunks of slots on every core: each chunk counts its inner nodes,
        // then numbers them from the sum of the counts before it (the same numbers in any chunking).
        int chunks = Parallel.chunks(slots);
        int[] before = new int[chunks + 1];
        int[] children = this.children;
        Parallel.forChunks(slots, chunks, (chunk, from, to) -> {
            int c = 0;
            for (int s = from; s < to; s++) if (children[2 * s] != 0) c++;
            before[chunk + 1] = c;
        });
        for (int c = 0; c < chunks; c++) before[c + 1] += before[c];
        int count = before[chunks];
        int[] links = children;
        // A large build's tree keeps its slots as node numbers where they leave few gaps: where
        // nearly every leaf holds one item (a million spheres' tree has 0.08 % of gaps, a million
        // triangles' 35 %). No child names a gap, and a gap's box stays empty.
        int nodes = morton && slots - count <= slots / GAPS_KEPT ? slots : count;
        if (nodes < slots) {
            int[] index = new int[slots];
            int[] dense = new int[2 * count];
            Parallel.forChunks(slots, chunks, (chunk, from, to) -> {
                int k = before[chunk];
                for (int s = from; s < to; s++) if (children[2 * s] != 0) index[s] = k++;
            });
            Parallel.forChunks(slots, chunks, (chunk, from, to) -> {
                for (int s = from; s < to; s++) {
                    if (children[2 * s] == 0) continue;
                    for (int c = 0; c < 2; c++) {
                        int child = children[2 * s + c];
                        dense[2 * index[s] + c] = Bvh.isLeaf(child) ? child : index[child];
                    }
                }
            });
            links = dense;
        }
        double[] box = new double[Bvh.NODE * nodes];
        boxes(links, box, nodes);
        double[] rootBox = new double[6];
        unionOfChildren(box, 0, rootBox);
        return new Bvh(box, links, rootBox, 2 * count + 1, depth);
    }

    /**
     * The boxes of nodes [0, count) of a depth-first tree. The subtree under a node is a run of
     * node numbers, so the tree is cut near its top into subtrees, which are done on every core
     * (each one from its last node back: both children's boxes are known when a node's are
     * written), and then the few nodes above them. Each box is computed alike however the
     * work is cut.
     */
    private void boxes(int[] links, double[] box, int count) {
        // Runs [first, end) of nodes, each a whole subtree; the nodes split to get them, in order.
        int parts = Parallel.threads == 1 || count < Parallel.MIN_CHUNK ? 1 : 8 * Parallel.threads;
        int[] first = new int[parts + 1], end = new int[parts + 1];
        int[] above = new int[parts];
        int runs = 1, split = 0;
        first[0] = 0;
        end[0] = count;
        while (runs < parts) {
            int widest = 0;
            for (int r = 1; r < runs; r++) if (end[r] - first[r] > end[widest] - first[widest]) widest = r;
            int k = first[widest], e = end[widest];
            if (e - k < Parallel.MIN_CHUNK) break;
            // Node k leaves the run: its inner children's subtrees take its place.
            if (split == above.length) above = Arrays.copyOf(above, 2 * split);
            above[split++] = k;
            int l = links[2 * k], r = links[2 * k + 1];
            boolean left = !Bvh.isLeaf(l), right = !Bvh.isLeaf(r);
            if (left && right) {
                first[widest] = l;
                end[widest] = r;
                first[runs] = r;
                end[runs++] = e;
            } else if (left || right) {
                first[widest] = left ? l : r;
            } else {
                first[widest] = e;
            }
        }
        int n = runs;
        Parallel.Chunk run = (chunk, from, to) -> {
            double[] acc = new double[6];
            for (int i = from; i < to; i++) nodeBoxes(links, box, first[i], end[i], acc);
        };
        Parallel.forChunks(n, n, run);
        // The split nodes come before the nodes below them: from the last split back.
        double[] acc = new double[6];
        for (int i = split - 1; i >= 0; i--) nodeBoxes(links, box, above[i], above[i] + 1, acc);
    }

    /**
     * The boxes of nodes [from, to), each after the nodes after it, so that its children's are
     * known. One loop, its body in methods: the JIT compiles a running loop at each loop it finds
     * hot (on-stack replacement), and the two short loops this had inside it cost two more such
     * compiles in every large build (docs/benchmarks.md section 41).
     */
    private void nodeBoxes(int[] links, double[] box, int from, int to, double[] acc) {
        for (int k = to - 1; k >= from; k--) {
            if (links[2 * k] == 0) continue; // a gap (see finish): no inner node has the root as a child
            childBox(links[2 * k], box, acc);
            putChildBox(box, k, 0, acc);
            childBox(links[2 * k + 1], box, acc);
            putChildBox(box, k, 1, acc);
        }
    }

    /** The box of a child (a leaf's items, or an inner node's two children, whose boxes are known) into acc. */
    private void childBox(int child, double[] box, double[] acc) {
        if (Bvh.isLeaf(child)) {
            unionOfItems(Bvh.leafFirst(child), Bvh.leafFirst(child) + Bvh.leafCount(child), acc);
        } else {
            unionOfChildren(box, child, acc);
        }
    }

    /** Writes acc as the box of child c (0 or 1) of node k. */
    private static void putChildBox(double[] box, int k, int c, double[] acc) {
        int o = Bvh.NODE * k + c;
        box[o] = acc[0];
        box[o + 2] = acc[1];
        box[o + 4] = acc[2];
        box[o + Bvh.MAX] = acc[3];
        box[o + Bvh.MAX + 2] = acc[4];
        box[o + Bvh.MAX + 4] = acc[5];
    }

    private void unionOfItems(int from, int to, double[] acc) {
        double[] bounds = this.bounds;
        double minX = Double.POSITIVE_INFINITY, minY = Double.POSITIVE_INFINITY, minZ = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY, maxY = Double.NEGATIVE_INFINITY, maxZ = Double.NEGATIVE_INFINITY;
        for (int i = from; i < to; i++) {
            int k = 6 * i;
            double v;
            if ((v = bounds[k]) < minX) minX = v;
            if ((v = bounds[k + 1]) < minY) minY = v;
            if ((v = bounds[k + 2]) < minZ) minZ = v;
            if ((v = bounds[k + 3]) > maxX) maxX = v;
            if ((v = bounds[k + 4]) > maxY) maxY = v;
            if ((v = bounds[k + 5]) > maxZ) maxZ = v;
        }
        acc[0] = minX;
        acc[1] = minY;
        acc[2] = minZ;
        acc[3] = maxX;
        acc[4] = maxY;
        acc[5] = maxZ;
    }

    /** The union of the two children's boxes of node {@code k}, into acc (min x, y, z, max x, y, z). */
    private static void unionOfChildren(double[] box, int k, double[] acc) {
        int o = Bvh.NODE * k;
        for (int a = 0; a < 3; a++) {
            double l = box[o + 2 * a], r = box[o + 2 * a + 1];
            acc[a] = r < l ? r : l;
            l = box[o + Bvh.MAX + 2 * a];
            r = box[o + Bvh.MAX + 2 * a + 1];
            acc[3 + a] = r > l ? r : l;
        }
    }

    private final class Task extends RecursiveTask<Integer> {
        private static final long serialVersionUID = 1L;
        private final int lo, hi, at, level;
        /** The levels of the subtree's deepest leaf, counted from the tree's root; set by {@link #compute}. */
        int depth;

        Task(int lo, int hi, int at, int level) {
            this.lo = lo;
            this.hi = hi;
            this.at = at;
            this.level = level;
        }

        @Override
        protected Integer compute() {
            Scratch sc = new Scratch();
            if (morton && hi - lo <= MORTON_RANGE) {
                int root = mortonSubtree(lo, hi, at, sc, level);
                depth = sc.depth;
                return root;
            }
            int mid = split(lo, hi, sc);
            if (mid < 0) {
                depth = level;
                return Bvh.leaf(lo, hi - lo);
            }
            int leftAt = at + 1, rightAt = at + (mid - lo);
            Task left = new Task(lo, mid, leftAt, level + 1);
            Task right = new Task(mid, hi, rightAt, level + 1);
            if (mid - lo > PARALLEL_THRESHOLD) left.fork();
            int r, l;
            if (hi - mid > PARALLEL_THRESHOLD) {
                r = right.compute();
                sc.depth = right.depth;
            } else {
                r = subtree(mid, hi, rightAt, sc, level + 1);
            }
            if (mid - lo > PARALLEL_THRESHOLD) {
                l = left.join();
                sc.depth = Math.max(sc.depth, left.depth);
            } else {
                l = subtree(lo, mid, leftAt, sc, level + 1);
            }
            children[2 * at] = l;
            children[2 * at + 1] = r;
            depth = sc.depth;
            return at;
        }
    }

    /**
     * Builds the subtree over [lo, hi), whose root is at {@code level}, from slot {@code at};
     * returns its root (a slot or a leaf) and raises {@code sc.depth} to the level of its deepest
     * leaf.
     */
    private int subtree(int lo, int hi, int at, Scratch sc, int level) {
        if (morton && hi - lo <= MORTON_RANGE) return mortonSubtree(lo, hi, at, sc, level);
        int mid = split(lo, hi, sc);
        if (mid < 0) {
            if (level > sc.depth) sc.depth = level;
            return Bvh.leaf(lo, hi - lo);
        }
        int l = subtree(lo, mid, at + 1, sc, level + 1);
        int r = subtree(mid, hi, at + (mid - lo), sc, level + 1);
        children[2 * at] = l;
        children[2 * at + 1] = r;
        return at;
    }

    /**
     * Builds the subtree over [lo, hi) as {@link #subtree} does, splitting by the items' Morton
     * codes (their centroids on a grid of 1024 cubes along the range's longest side): each
     * range is split where the highest bit in which its first and last codes differ changes, a
     * range of equal codes in the middle, and ranges of up to {@value #MAX_LEAF} items become a
     * leaf by the same cost rule as binned ones.
     */
    private int mortonSubtree(int lo, int hi, int at, Scratch sc, int level) {
        int n = hi - lo;
        if (sc.keys == null) {
            sc.keys = new long[MORTON_RANGE];
            sc.sorted = new long[MORTON_RANGE];
            sc.digits = new int[1 << MORTON_DIGIT];
            sc.orderCopy = new int[MORTON_RANGE];
            sc.boundsCopy = new double[6 * MORTON_RANGE];
        }
        measure(lo, hi, sc);
        double[] cmin = sc.cmin, cmax = sc.cmax;
        double extent = Math.max(cmax[0] - cmin[0], Math.max(cmax[1] - cmin[1], cmax[2] - cmin[2]));
        double k = extent > 0 ? 1024 / extent : 0;
        mortonKeys(lo, hi, cmin, k, sc.keys);
        reorder(lo, n, sortByCode(sc, n), sc);
        return mortonSplit(lo, hi, lo, at, sc, level);
    }

    /**
     * The sort keys of [lo, hi): each item's Morton code (its centroid on the grid of cubes of
     * side 1 / k from cmin) above its position in the range. {@link #mortonSubtree}'s passes are
     * small methods of their own, which the JIT compiles quickly, where it compiled the one large
     * method again at each of its loops while it ran (docs/benchmarks.md section 41).
     */
    private void mortonKeys(int lo, int hi, double[] cmin, double k, long[] keys) {
        double mx = cmin[0], my = cmin[1], mz = cmin[2];
        for (int i = lo; i < hi; i++) {
            int x = grid(centroid(i, 0), mx, k), y = grid(centroid(i, 1), my, k), z = grid(centroid(i, 2), mz, k);
            keys[i - lo] = (long) (spread(x) << 2 | spread(y) << 1 | spread(z)) << 32 | (i - lo);
        }
    }

    /** Puts the n items from {@code lo} in the order of the sorted keys (positions in their low 32 bits). */
    private void reorder(int lo, int n, long[] keys, Scratch sc) {
        int[] order = this.order, orderCopy = sc.orderCopy;
        double[] bounds = this.bounds, boundsCopy = sc.boundsCopy;
        for (int j = 0; j < n; j++) {
            int from = lo + (int) keys[j];
            orderCopy[j] = order[from];
            System.arraycopy(bounds, 6 * from, boundsCopy, 6 * j, 6);
        }
        System.arraycopy(orderCopy, 0, order, lo, n);
        System.arraycopy(boundsCopy, 0, bounds, 6 * lo, 6 * n);
    }

    /** Bits of the Morton code sorted by each pass of {@link #sortByCode}: three passes over the 30. */
    static final int MORTON_DIGIT = 10;

    /** Sorts the first n of {@code sc.keys} by {@link #sortByCode(long[], long[], int[], int)}, leaving them in {@code sc.keys}; returns it. */
    private static long[] sortByCode(Scratch sc, int n) {
        long[] sorted = sortByCode(sc.keys, sc.sorted, sc.digits, n);
        if (sorted != sc.keys) {
            sc.sorted = sc.keys;
            sc.keys = sorted;
        }
        return sorted;
    }

    /**
     * Sorts the first n of {@code keys} (a 30-bit Morton code above a range position in the low
     * 32 bits, each position once, in increasing order) by code, ties in position order: the order
     * a sort of the keys as numbers gives, by three stable passes of ten bits (least significant
     * first) through {@code spare} instead of comparisons. Returns the array that holds the result
     * (one of the two); {@code digits} has 2^10 counts.
     */
    static long[] sortByCode(long[] keys, long[] spare, int[] digits, int n) {
        long[] from = keys, to = spare;
        for (int shift = 32; shift < 62; shift += MORTON_DIGIT) {
            radixPass(from, to, digits, n, shift);
            long[] t = from;
            from = to;
            to = t;
        }
        return from;
    }

    /** One stable pass of {@link #sortByCode}: the first n keys from {@code from} into {@code to} by their ten bits at {@code shift}. */
    private static void radixPass(long[] from, long[] to, int[] digits, int n, int shift) {
        int mask = (1 << MORTON_DIGIT) - 1;
        Arrays.fill(digits, 0);
        for (int i = 0; i < n; i++) digits[(int) (from[i] >>> shift) & mask]++;
        for (int d = 0, sum = 0; d <= mask; d++) {
            int c = digits[d];
            digits[d] = sum;
            sum += c;
        }
        for (int i = 0; i < n; i++) {
            long key = from[i];
            to[digits[(int) (key >>> shift) & mask]++] = key;
        }
    }

    /** The subtree over [a, b) of the range sorted by {@link #mortonSubtree} from {@code lo}. */
    private int mortonSplit(int a, int b, int lo, int at, Scratch sc, int level) {
        int n = b - a;
        long[] code = sc.keys;
        long first = code[a - lo] >>> 32, last = code[b - 1 - lo] >>> 32;
        int mid;
        if (first == last) {
            mid = a + n / 2;
        } else {
            // The codes share every bit above the highest one in which they differ: those with
            // it set come last.
            long bit = Long.highestOneBit(first ^ last) << 32;
            int i = a + 1, j = b - 1;
            while (i < j) {
                int m = (i + j) >>> 1;
                if ((code[m - lo] & bit) != 0) j = m; else i = m + 1;
            }
            mid = i;
        }
        boolean leaf = n == 1;
        if (!leaf && n <= MAX_LEAF) {
            double[] box = sc.box, left = sc.left, right = sc.right;
            unionOfItems(a, mid, left);
            unionOfItems(mid, b, right);
            // The range's box is the union of its halves' (minima and maxima are exact).
            for (int c = 0; c < 3; c++) {
                box[c] = right[c] < left[c] ? right[c] : left[c];
                box[3 + c] = right[3 + c] > left[3 + c] ? right[3 + c] : left[3 + c];
            }
            double parentArea = area(box);
            double splitCost = TRAVERSAL_COST
                    + INTERSECTION_COST * (area(left) * (mid - a) + area(right) * (b - mid)) / parentArea;
            leaf = splitCost >= INTERSECTION_COST * n || !(parentArea > 0);
        }
        if (leaf) {
            if (level > sc.depth) sc.depth = level;
            return Bvh.leaf(a, n);
        }
        int l = mortonSplit(a, mid, lo, at + 1, sc, level + 1);
        int r = mortonSplit(mid, b, lo, at + (mid - a), sc, level + 1);
        children[2 * at] = l;
        children[2 * at + 1] = r;
        return at;
    }

    private static int grid(double c, double min, double k) {
        int g = (int) ((c - min) * k);
        return g < 0 ? 0 : Math.min(g, 1023);
    }

    /** The ten low bits of {@code v} spread to every third bit. */
    private static int spread(int v) {
        v = (v | v << 16) & 0x030000FF;
        v = (v | v << 8) & 0x0300F00F;
        v = (v | v << 4) & 0x030C30C3;
        return (v | v << 2) & 0x09249249;
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
        /** The box of the range being split, and of its halves in {@link #mortonSplit}. */
        final double[] box = new double[6], left = new double[6], right = new double[6];
        /** The result of {@link #sweep}. */
        double bestCost;
        int bestAxis, bestBin;
        /** The deepest leaf's level seen by this thread's {@link #subtree} calls. */
        int depth;
        /** Sort keys, then Morton codes, of {@link #mortonSubtree}'s range, and its reordering space; made when first needed. */
        long[] keys;
        /** The other array of {@link #sortByCode}'s passes, and its digit counts. */
        long[] sorted;
        int[] digits;
        int[] orderCopy;
        double[] boundsCopy;

        Scratch() {
            for (int b = 0; b < 3 * BINS; b++) resetBox(binBox, b);
        }
    }

    /**
     * Measures the box of [lo, hi) (into sc), then partitions the range by the
     * best SAH split and returns its middle, or returns −1 when the range is a leaf. Each pass
     * over the items is a method of its own: small methods are compiled early and quickly, where
     * one large one ran interpreted through the first levels of a million-item build while the
     * compiler worked on it for seconds.
     */
    private int split(int lo, int hi, Scratch sc) {
        int n = hi - lo;
        boolean wide = n > PARALLEL_SPLIT_ABOVE && Parallel.threads > 1 && ForkJoinTask.inForkJoinPool();
        if (wide) measureInParts(lo, hi, sc); else measure(lo, hi, sc);
        if (n <= 1) return -1;
        double[] cmin = sc.cmin, cmax = sc.cmax, scale = sc.scale;
        for (int axis = 0; axis < 3; axis++) {
            double extent = cmax[axis] - cmin[axis];
            scale[axis] = extent > 0 ? BINS / extent : 0;
        }
        if (n > ONE_AXIS_ABOVE || morton) {
            // Binned on the axis of the centroids' largest extent only: a third of the binning work
            // where a range is large enough for the three axes' best splits to differ little.
            int widest = cmax[0] - cmin[0] >= cmax[1] - cmin[1] ? 0 : 1;
            if (cmax[2] - cmin[2] > cmax[widest] - cmin[widest]) widest = 2;
            for (int axis = 0; axis < 3; axis++) if (axis != widest) scale[axis] = 0;
            sc.used[0] = sc.used[1] = sc.used[2] = 0;
            sc.used[widest] = wide ? binAxisInParts(lo, hi, sc, widest) : binAxis(lo, hi, sc, widest);
        } else {
            binAll(lo, hi, sc);
        }
        sweep(sc);
        int bestAxis = sc.bestAxis;
        double parentArea = area(sc.box);
        if (bestAxis < 0) {
            // All centroids coincide: split the range in the middle if it is too big for a leaf.
            return n <= MAX_LEAF ? -1 : lo + n / 2;
        }
        double splitCost = TRAVERSAL_COST + INTERSECTION_COST * sc.bestCost / parentArea;
        if (n <= MAX_LEAF && (splitCost >= INTERSECTION_COST * n || !(parentArea > 0))) return -1;
        return partition(lo, hi, bestAxis, cmin[bestAxis], scale[bestAxis], sc.bestBin);
    }

    /** Runs {@code work.apply(k)} for the parts k = 0 … c − 1 of a range as tasks of the build's pool, and waits for them. */
    private static void inParts(int c, java.util.function.IntFunction<Runnable> work) {
        RecursiveAction[] tasks = new RecursiveAction[c];
        for (int k = 0; k < c; k++) {
            Runnable r = work.apply(k);
            tasks[k] = new RecursiveAction() {
                private static final long serialVersionUID = 1L;

                @Override
                protected void compute() { r.run(); }
            };
        }
        ForkJoinTask.invokeAll(tasks);
    }

    /**
     * {@link #measure} of a range of more than {@value #PARALLEL_SPLIT_ABOVE} items on every
     * thread of the build's pool (the top of the tree, where no other subtree runs beside it):
     * each part measured apart, then their minima and maxima taken, which are exact, so the
     * result is that of one pass.
     */
    private void measureInParts(int lo, int hi, Scratch sc) {
        int c = Parallel.threads;
        Scratch[] parts = new Scratch[c];
        for (int k = 0; k < c; k++) parts[k] = new Scratch();
        inParts(c, k -> () -> measure(Parallel.start(hi - lo, c, k) + lo, Parallel.start(hi - lo, c, k + 1) + lo, parts[k]));
        measure(lo, lo, sc);
        for (Scratch p : parts) {
            for (int a = 0; a < 3; a++) {
                if (p.box[a] < sc.box[a]) sc.box[a] = p.box[a];
                if (p.box[3 + a] > sc.box[3 + a]) sc.box[3 + a] = p.box[3 + a];
                if (p.cmin[a] < sc.cmin[a]) sc.cmin[a] = p.cmin[a];
                if (p.cmax[a] > sc.cmax[a]) sc.cmax[a] = p.cmax[a];
            }
        }
    }

    /**
     * {@link #binAxis} of a large range on every thread of the build's pool, as {@link
     * #measureInParts}: each part bins into bins of its own, which are then added up (counts)
     * and united (boxes, exact), so the bins are those of one pass.
     */
    private int binAxisInParts(int lo, int hi, Scratch sc, int axis) {
        int c = Parallel.threads;
        Scratch[] parts = new Scratch[c];
        int[] masks = new int[c];
        for (int k = 0; k < c; k++) {
            parts[k] = new Scratch();
            System.arraycopy(sc.scale, 0, parts[k].scale, 0, 3);
            System.arraycopy(sc.cmin, 0, parts[k].cmin, 0, 3);
        }
        inParts(c, k -> () -> masks[k] = binAxis(Parallel.start(hi - lo, c, k) + lo, Parallel.start(hi - lo, c, k + 1) + lo, parts[k], axis));
        int base = axis * BINS, mask = 0;
        for (int k = 0; k < c; k++) {
            mask |= masks[k];
            for (int m = masks[k]; m != 0; m &= m - 1) {
                int b = base + Integer.numberOfTrailingZeros(m);
                sc.binCount[b] += parts[k].binCount[b];
                grow(sc.binBox, b, parts[k].binBox, b);
            }
        }
        return mask;
    }

    /** One pass for the box of [lo, hi) and the bounds of its centroids (into sc). */
    private void measure(int lo, int hi, Scratch sc) {
        double minX = Double.POSITIVE_INFINITY, minY = Double.POSITIVE_INFINITY, minZ = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY, maxY = Double.NEGATIVE_INFINITY, maxZ = Double.NEGATIVE_INFINITY;
        double cminX = Double.POSITIVE_INFINITY, cminY = Double.POSITIVE_INFINITY, cminZ = Double.POSITIVE_INFINITY;
        double cmaxX = Double.NEGATIVE_INFINITY, cmaxY = Double.NEGATIVE_INFINITY, cmaxZ = Double.NEGATIVE_INFINITY;
        // Comparisons rather than Math.min and Math.max, which also order −0 and NaN: item bounds
        // are finite, and these loops run over every item at every level of the tree.
        double[] bounds = this.bounds;
        for (int i = lo; i < hi; i++) {
            int k = 6 * i;
            double x0 = bounds[k], y0 = bounds[k + 1], z0 = bounds[k + 2];
            double x1 = bounds[k + 3], y1 = bounds[k + 4], z1 = bounds[k + 5];
            if (x0 < minX) minX = x0;
            if (y0 < minY) minY = y0;
            if (z0 < minZ) minZ = z0;
            if (x1 > maxX) maxX = x1;
            if (y1 > maxY) maxY = y1;
            if (z1 > maxZ) maxZ = z1;
            double v;
            if ((v = 0.5 * (x0 + x1)) < cminX) cminX = v;
            if (v > cmaxX) cmaxX = v;
            if ((v = 0.5 * (y0 + y1)) < cminY) cminY = v;
            if (v > cmaxY) cmaxY = v;
            if ((v = 0.5 * (z0 + z1)) < cminZ) cminZ = v;
            if (v > cmaxZ) cmaxZ = v;
        }
        double[] cmin = sc.cmin, cmax = sc.cmax;
        cmin[0] = cminX;
        cmin[1] = cminY;
        cmin[2] = cminZ;
        cmax[0] = cmaxX;
        cmax[1] = cmaxY;
        cmax[2] = cmaxZ;
        double[] box = sc.box;
        box[0] = minX;
        box[1] = minY;
        box[2] = minZ;
        box[3] = maxX;
        box[4] = maxY;
        box[5] = maxZ;
    }

    /** Bins every item of [lo, hi) on all three axes at once (those of non-zero scale), so the item data is read once. */
    private void binAll(int lo, int hi, Scratch sc) {
        int[] binCount = sc.binCount;
        double[] binBox = sc.binBox, bounds = this.bounds;
        double kx = sc.scale[0], ky = sc.scale[1], kz = sc.scale[2];
        double mx = sc.cmin[0], my = sc.cmin[1], mz = sc.cmin[2];
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
        sc.used[0] = maskX;
        sc.used[1] = maskY;
        sc.used[2] = maskZ;
    }

    /** Bins every item of [lo, hi) on {@code axis} alone; returns the mask of the bins used. */
    private int binAxis(int lo, int hi, Scratch sc, int axis) {
        int[] binCount = sc.binCount;
        double[] binBox = sc.binBox, bounds = this.bounds;
        double k = sc.scale[axis], min = sc.cmin[axis];
        int base = axis * BINS, mask = 0;
        for (int i = lo; i < hi; i++) {
            int bin = bin(0.5 * (bounds[6 * i + axis] + bounds[6 * i + 3 + axis]), min, k);
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
        int i = lo, j = hi - 1;
        while (i <= j) {
            if (bin(centroid(i, axis), min, k) <= last) {
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

    /**
     * Widens bin {@code b} by item {@code item}. Comparisons rather than Math.min and Math.max (as
     * in {@link #measure}): after its first few items a bin's box rarely grows, so the branches
     * are well predicted, and item bounds are finite.
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
