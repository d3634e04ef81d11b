package dev.crt.render;

import dev.crt.geom.Aabb;
import dev.crt.geom.Transform;
import dev.crt.scene.Csg;
import dev.crt.scene.CsgOperation;
import dev.crt.scene.Entity;
import dev.crt.scene.Primitive;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.ToIntFunction;

/**
 * CSG trees flattened for tracing: each tree is a list of primitive leaves (transforms pushed down,
 * T(A op B) = T(A) op T(B)) under n-ary operation nodes. Chains of one operation are merged into
 * one node ({@code a + b + c} is one union of three; {@code a - b - c} is a minus the union of b
 * and c), so a solid built up in a loop is a shallow tree, not a spine as long as the loop.
 *
 * <p>A ray is intersected exactly: every leaf the line passes through gives the interval where the
 * line is inside it, the interval ends become events sorted by distance, and walking them while
 * updating the inside-state of each node finds where the line enters or leaves the solid. A node
 * keeps a count of its children that are inside, so an event costs the nodes whose state it
 * changes, not the whole tree. Trees of more than {@value #LINEAR_LIMIT} bounded leaves find the
 * leaves a line passes through with a BVH of their own, so a ray pays for the leaves near it.
 *
 * <p>Events closer together than a tiny scale-relative tolerance count as simultaneous and are
 * applied together, so coincident faces resolve by set semantics (a box minus an identical box is
 * empty; two boxes sharing a face unite without an inner wall). When simultaneous events change
 * the result, the surface shown is the one of the leaf that comes last in the tree (in A − B, B's
 * boundary wins on equal distance).
 */
final class CsgSolids {
    static final int UNION = 0;
    static final int INTERSECTION = 1;
    static final int DIFFERENCE = 2;
    /** Relative distance under which boundary events are treated as coincident. */
    static final double TIE = 0x1p-44;
    /**
     * How far behind the origin, in tie tolerances, a leaf's box must end for the leaf to be
     * skipped: such a leaf is entered and left before the ray starts, so it cannot change what the
     * ray meets. Skipping only leaves this far back keeps the grouping of simultaneous events near
     * the origin as if every leaf had been walked, short of 2^24 events in a row each within a
     * tolerance of the next.
     */
    static final double BEHIND = 0x1p24;
    /** Bounded leaves up to which a tree tests every leaf instead of walking a BVH over them. */
    static final int LINEAR_LIMIT = 4;

    private int count;
    private int[] leafStart = new int[4], leafCount = new int[4], nodeStart = new int[4];
    /** Per tree: the leaves every line is tested against (all of them, or the unbounded ones when there is a BVH). */
    private int[] testStart = new int[4], testCount = new int[4];
    /** Per tree: where its BVH's item order starts in {@link #bvhLeaf}. */
    private int[] bvhStart = new int[4];
    private Bvh[] bvh = new Bvh[4];
    private double[] scale = new double[4];
    /** Per tree, its bounds (min x, y, z, max x, y, z) as {@link BvhBuilder#put} writes them when finite, for {@link #mayMeet}; else NaN. */
    private double[] treeBounds = new double[6 * 4];
    /**
     * Per tree: whether it is one operation on two primitives, always tested (no BVH), with a
     * difference's first operand first; such trees are walked by {@link #walkPair}.
     */
    private boolean[] pair = new boolean[4];

    /** Per leaf (global index): its shape, its node (tree-local) and whether it is a difference's first operand. */
    private int[] leafShape = new int[8], leafParent = new int[8];
    private boolean[] leafPositive = new boolean[8];
    private int leafSize;
    /** Per node (global index): operation, number of children, parent (tree-local, −1 at the root), first-operand flag. */
    private int[] nodeOp = new int[8], nodeChildren = new int[8], nodeParent = new int[8];
    private boolean[] nodePositive = new boolean[8];
    private int nodeTotal;
    /** Tree-local leaf indices: the always-tested lists and the BVH item orders. */
    private int[] testLeaf = new int[8], bvhLeaf = new int[8];
    private int testSize, bvhSize;

    int maxLeaves, maxNodes, maxDepth;

    /** Flattens {@code csg} placed by {@code parent}; returns its index and its world bounds in {@code bounds[0]}. */
    int add(Csg csg, Transform parent, Shapes shapes, ToIntFunction<Primitive> materials, Aabb[] bounds) {
        int tree = flatten(csg, parent, shapes, materials, bounds);
        index(tree, shapes);
        return tree;
    }

    /** The world bounds of {@code csg} placed by {@code parent}, its leaves added to {@code shapes}, without preparing it for rays. */
    Aabb bounds(Csg csg, Transform parent, Shapes shapes, ToIntFunction<Primitive> materials) {
        Aabb[] out = new Aabb[1];
        flatten(csg, parent, shapes, materials, out);
        return out[0];
    }

    private int flatten(Csg csg, Transform parent, Shapes shapes, ToIntFunction<Primitive> materials, Aabb[] bounds) {
        int tree = count++;
        if (tree == leafStart.length) {
            int n = tree * 2;
            leafStart = Arrays.copyOf(leafStart, n);
            leafCount = Arrays.copyOf(leafCount, n);
            nodeStart = Arrays.copyOf(nodeStart, n);
            testStart = Arrays.copyOf(testStart, n);
            testCount = Arrays.copyOf(testCount, n);
            bvhStart = Arrays.copyOf(bvhStart, n);
            bvh = Arrays.copyOf(bvh, n);
            scale = Arrays.copyOf(scale, n);
            treeBounds = Arrays.copyOf(treeBounds, 6 * n);
            pair = Arrays.copyOf(pair, n);
        }
        leafStart[tree] = leafSize;
        nodeStart[tree] = nodeTotal;
        Aabb b = node(csg, parent, tree, -1, false, shapes, materials);
        int leaves = leafSize - leafStart[tree];
        leafCount[tree] = leaves;
        maxLeaves = Math.max(maxLeaves, leaves);
        maxNodes = Math.max(maxNodes, nodeTotal - nodeStart[tree]);
        double sc = 0;
        for (int k = leafStart[tree]; k < leafSize; k++) sc = Math.max(sc, shapes.scale[leafShape[k]]);
        scale[tree] = sc;
        bounds[0] = b;
        // The box the scene's BVH gives the tree's leaf (an ulp wider on every side).
        if (!b.isEmpty() && b.isFinite()) BvhBuilder.put(b, treeBounds, tree);
        else Arrays.fill(treeBounds, 6 * tree, 6 * tree + 6, Double.NaN);
        return tree;
    }

    /**
     * Adds a node for {@code c} placed by {@code parent} under tree-local node {@code parentNode},
     * and its operands below it; returns its bounds. Operands that merge into the node (see
     * {@link #merges}) are unfolded with a work stack rather than recursion, since scripts build
     * long chains ({@code u = u + s} in a loop); only nesting of different operations recurses.
     */
    private Aabb node(Csg c, Transform parent, int tree, int parentNode, boolean positive, Shapes shapes,
            ToIntFunction<Primitive> materials) {
        int op = code(c.operation());
        int self = newNode(tree, op, parentNode, positive);
        int counted = nodeStart[tree] + self;
        ArrayDeque<Operand> todo = new ArrayDeque<>();
        todo.push(new Operand(c, parent, true));
        Aabb bounds = null;
        boolean root = true;
        while (!todo.isEmpty()) {
            Operand next = todo.pop();
            Entity e = next.entity();
            Transform placed = next.placed();
            Transform t = e.transform().then(placed);
            boolean first = next.first();
            Aabb b;
            if (e instanceof Csg inner && (root || merges(op, first, code(inner.operation())))) {
                root = false;
                // The right operand is pushed first so that leaves keep the script's left-to-right
                // order. Only a difference's first operand is special, and only its left side can be.
                todo.push(new Operand(inner.right(), t, false));
                todo.push(new Operand(inner.left(), t, first));
                continue;
            }
            nodeChildren[counted]++;
            if (e instanceof Primitive p) {
                b = leaf(p, t, self, op == DIFFERENCE && first, shapes, materials);
            } else {
                b = node((Csg) e, placed, tree, self, op == DIFFERENCE && first, shapes, materials);
            }
            if (op == DIFFERENCE) {
                if (first) {
                    bounds = b;
                } else if (e instanceof Primitive && shapes.kind[leafShape[leafSize - 1]] == Shapes.BOX && bounds != null) {
                    // An axis-aligned box taken away is its own bounds: it trims the first operand's,
                    // which a bowl cut from a ball (sphere − box) shrinks to the bowl.
                    bounds = bounds.less(b, CUT_MARGIN * (1 + maxAbs(bounds) + maxAbs(b)));
                }
            } else {
                bounds = bounds == null ? b : op == UNION ? bounds.union(b) : bounds.intersection(b);
            }
        }
        return bounds;
    }

    /**
     * How far a side of a difference's bounds trimmed by a box taken away ({@link Aabb#less}) is
     * moved back out, relative to the coordinates: far above the rounding of hit points on the
     * box's face, so every hit the solid's walk reports lies inside its bounds.
     */
    static final double CUT_MARGIN = 1e-9;

    private static double maxAbs(Aabb b) {
        double m = 0;
        for (double v : new double[] {b.min().x(), b.min().y(), b.min().z(), b.max().x(), b.max().y(), b.max().z()}) {
            if (Double.isFinite(v)) m = Math.max(m, Math.abs(v));
        }
        return m;
    }

    /** An operand waiting to be added: the entity, what places it, and whether it is a difference's first operand. */
    private record Operand(Entity entity, Transform placed, boolean first) {}

    /**
     * Whether an operand of operation {@code inner} merges into a node of operation {@code op}: a
     * union into a union, an intersection into an intersection, a difference as the first operand
     * of a difference ((a − b) − c = a − b − c), and a union subtracted by a difference
     * (a − (b + c) = a − b − c).
     */
    private static boolean merges(int op, boolean first, int inner) {
        if (op != DIFFERENCE) return inner == op;
        return first ? inner == DIFFERENCE : inner == UNION;
    }

    private Aabb leaf(Primitive p, Transform t, int parentNode, boolean positive, Shapes shapes,
            ToIntFunction<Primitive> materials) {
        int s = shapes.add(p, t, materials.applyAsInt(p));
        int g = leafSize++;
        if (g == leafShape.length) {
            leafShape = Arrays.copyOf(leafShape, 2 * g);
            leafParent = Arrays.copyOf(leafParent, 2 * g);
            leafPositive = Arrays.copyOf(leafPositive, 2 * g);
        }
        leafShape[g] = s;
        leafParent[g] = parentNode;
        leafPositive[g] = positive;
        return shapes.bounds(s);
    }

    private int newNode(int tree, int op, int parentNode, boolean positive) {
        int g = nodeTotal++;
        if (g == nodeOp.length) {
            nodeOp = Arrays.copyOf(nodeOp, 2 * g);
            nodeChildren = Arrays.copyOf(nodeChildren, 2 * g);
            nodeParent = Arrays.copyOf(nodeParent, 2 * g);
            nodePositive = Arrays.copyOf(nodePositive, 2 * g);
        }
        nodeOp[g] = op;
        nodeChildren[g] = 0;
        nodeParent[g] = parentNode;
        nodePositive[g] = positive;
        return g - nodeStart[tree];
    }

    private static int code(CsgOperation operation) {
        return switch (operation) {
            case UNION -> UNION;
            case INTERSECTION -> INTERSECTION;
            case DIFFERENCE -> DIFFERENCE;
        };
    }

    /** Decides how lines find the leaves of {@code tree}: a list, or a BVH over the bounded leaves plus a list of the rest. */
    private void index(int tree, Shapes shapes) {
        int first = leafStart[tree], n = leafCount[tree];
        List<Integer> bounded = new ArrayList<>();
        List<Integer> always = new ArrayList<>();
        for (int k = 0; k < n; k++) {
            Aabb b = shapes.bounds(leafShape[first + k]);
            if (b.isEmpty()) continue;
            (b.isFinite() ? bounded : always).add(k);
        }
        if (bounded.size() <= LINEAR_LIMIT) {
            always.addAll(bounded);
            always.sort(null);
        } else {
            int m = bounded.size();
            double[] flat = new double[6 * m];
            for (int i = 0; i < m; i++) BvhBuilder.put(shapes.bounds(leafShape[first + bounded.get(i)]), flat, i);
            int[] order = new int[m];
            Bvh h = BvhBuilder.build(flat, m, order);
            bvh[tree] = h;
            maxDepth = Math.max(maxDepth, h.depth);
            bvhStart[tree] = bvhSize;
            if (bvhSize + m > bvhLeaf.length) bvhLeaf = Arrays.copyOf(bvhLeaf, Math.max(2 * bvhLeaf.length, bvhSize + m));
            for (int i = 0; i < m; i++) bvhLeaf[bvhSize++] = bounded.get(order[i]);
        }
        testStart[tree] = testSize;
        testCount[tree] = always.size();
        if (testSize + always.size() > testLeaf.length) {
            testLeaf = Arrays.copyOf(testLeaf, Math.max(2 * testLeaf.length, testSize + always.size()));
        }
        for (int k : always) testLeaf[testSize++] = k;
        int g = nodeStart[tree];
        pair[tree] = n == 2 && always.size() == 2 && bvh[tree] == null && nodeChildren[g] == 2
                && leafParent[first] == 0 && leafParent[first + 1] == 0
                && (nodeOp[g] != DIFFERENCE || leafPositive[first] && !leafPositive[first + 1]);
    }

    /** Per-thread working memory for walking the events of one tree. */
    static final class Scratch {
        final boolean[] leafInside;
        /** Per tree-local node: children inside (a difference's first operand not counted), first operand inside. */
        final int[] inside;
        final boolean[] firstInside;
        /** The walk that last reset each node: nodes are reset when first touched, not all before every walk. */
        final int[] stamp;
        int walk;
        final int[] startInside;
        double[] eventT;
        int[] eventLeaf;
        int[] eventFace;
        boolean[] eventEntry;
        /** The events by distance (indices into the event arrays), and room for sorting them. */
        int[] order, merge;
        final BvhWalker walker;
        int starts;
        /**
         * Set by the tracer when some material absorbs: shadow walks then add the optical depth
         * a·s of each stretch inside the solid (a of the surface it leaves by) to depthR, G, B.
         */
        boolean absorbing;
        double depthR, depthG, depthB;

        Scratch(CsgSolids csg) {
            int n = Math.max(1, csg.maxLeaves);
            int m = Math.max(1, csg.maxNodes);
            leafInside = new boolean[n];
            inside = new int[m];
            firstInside = new boolean[m];
            stamp = new int[m];
            startInside = new int[n];
            eventT = new double[2 * n];
            eventLeaf = new int[2 * n];
            eventFace = new int[2 * n];
            eventEntry = new boolean[2 * n];
            order = new int[2 * n];
            merge = new int[2 * n];
            walker = new BvhWalker(2 * csg.maxDepth);
        }

        /**
         * Makes room for {@code events} events: two per leaf suffice for convex leaves, a torus
         * or a mesh may cross more often; the arrays grow once and are kept.
         */
        void room(int events) {
            if (events <= eventT.length) return;
            int n = Math.max(events, 2 * eventT.length);
            eventT = Arrays.copyOf(eventT, n);
            eventLeaf = Arrays.copyOf(eventLeaf, n);
            eventFace = Arrays.copyOf(eventFace, n);
            eventEntry = Arrays.copyOf(eventEntry, n);
            order = new int[n];
            merge = new int[n];
        }

        /** Starts a walk: every node reads as empty (all leaves outside) until touched. */
        void begin() {
            if (++walk == 0) {
                Arrays.fill(stamp, 0);
                walk = 1;
            }
        }
    }

    /**
     * Collects and sorts the boundary events of {@code tree} along the line, for the leaves
     * always tested and those whose boxes the line passes through between {@code tMin} and
     * {@code tMax}; returns the number of events. The leaves the line
     * starts in (at t = −∞) are listed in {@code sc.startInside}, {@code sc.starts} of them.
     */
    private int gather(int tree, Ray ray, double tMin, double tMax, Shapes shapes, LineSpan span, Scratch sc) {
        int events = 0;
        sc.starts = 0;
        for (int i = testStart[tree], end = i + testCount[tree]; i < end; i++) {
            events = gatherLeaf(tree, testLeaf[i], ray, shapes, span, sc, events);
        }
        Bvh h = bvh[tree];
        BvhWalker walk = sc.walker;
        if (h == null || !walk.start(h, ray, tMin, tMax)) return events;
        int base = bvhStart[tree];
        for (int leaf = walk.nextAny(tMax); leaf != BvhWalker.END; leaf = walk.nextAny(tMax)) {
            for (int p = Bvh.leafFirst(leaf), end = p + Bvh.leafCount(leaf); p < end; p++) {
                events = gatherLeaf(tree, bvhLeaf[base + p], ray, shapes, span, sc, events);
            }
        }
        return events;
    }

    /** The events of tree-local leaf {@code k}, inserted among the {@code events} already sorted. */
    private int gatherLeaf(int tree, int k, Ray ray, Shapes shapes, LineSpan span, Scratch sc, int events) {
        sc.leafInside[k] = false;
        if (!shapes.span(leafShape[leafStart[tree] + k], ray, span)) return events;
        sc.room(events + 2 * span.count);
        for (int i = 0; i < span.count; i++) {
            if (span.tIn[i] == Double.NEGATIVE_INFINITY) sc.startInside[sc.starts++] = k;
            else events = add(sc, events, span.tIn[i], k, span.faceIn[i], true);
            if (span.tOut[i] != Double.POSITIVE_INFINITY) events = add(sc, events, span.tOut[i], k, span.faceOut[i], false);
        }
        return events;
    }

    private static int add(Scratch sc, int n, double t, int leaf, int face, boolean entry) {
        sc.eventT[n] = t;
        sc.eventLeaf[n] = leaf;
        sc.eventFace[n] = face;
        sc.eventEntry[n] = entry;
        return n + 1;
    }

    /** Runs of events this short are sorted by insertion; longer lists are then merged. */
    private static final int RUN = 16;

    /**
     * The first {@code n} distances {@code t} in increasing order, as indices, in {@code a} or
     * {@code b} (both at least n long), whichever is returned; events at equal distances
     * keep the order they were gathered in, so ties resolve the same way every time. A ray
     * through thousands of operands has thousands of events: runs sorted by insertion and then
     * merged keep that at n log n.
     */
    static int[] sort(double[] t, int n, int[] a, int[] b) {
        for (int i = 0; i < n; i++) a[i] = i;
        for (int lo = 0; lo < n; lo += RUN) {
            int hi = Math.min(n, lo + RUN);
            for (int i = lo + 1; i < hi; i++) {
                int x = a[i];
                double tx = t[x];
                int k = i;
                while (k > lo && t[a[k - 1]] > tx) {
                    a[k] = a[k - 1];
                    k--;
                }
                a[k] = x;
            }
        }
        for (int width = RUN; width < n; width *= 2) {
            for (int lo = 0; lo < n; lo += 2 * width) {
                int mid = Math.min(n, lo + width), hi = Math.min(n, lo + 2 * width);
                int i = lo, j = mid, k = lo;
                while (i < mid && j < hi) b[k++] = t[a[j]] < t[a[i]] ? a[j++] : a[i++];
                while (i < mid) b[k++] = a[i++];
                while (j < hi) b[k++] = a[j++];
            }
            int[] swap = a;
            a = b;
            b = swap;
        }
        return a;
    }

    /** Whether tree-local node {@code v} (already reset for this walk) contains the point the walk is at. */
    private boolean state(int g, int v, Scratch sc) {
        int in = sc.inside[v];
        return switch (nodeOp[g]) {
            case UNION -> in > 0;
            case INTERSECTION -> in == nodeChildren[g];
            default -> sc.firstInside[v] && in == 0;
        };
    }

    /** Flips tree-local leaf {@code k} in or out and carries the change up as far as it changes nodes. */
    private void flip(int tree, int k, Scratch sc) {
        boolean now = sc.leafInside[k] ^= true;
        int g = leafStart[tree] + k;
        int v = leafParent[g];
        boolean first = leafPositive[g];
        int base = nodeStart[tree];
        while (v >= 0) {
            int gv = base + v;
            if (sc.stamp[v] != sc.walk) {
                sc.stamp[v] = sc.walk;
                sc.inside[v] = 0;
                sc.firstInside[v] = false;
            }
            boolean before = state(gv, v, sc);
            if (first) sc.firstInside[v] = now;
            else sc.inside[v] += now ? 1 : -1;
            boolean after = state(gv, v, sc);
            if (after == before) return;
            now = after;
            first = nodePositive[gv];
            v = nodeParent[gv];
        }
    }

    /** Whether the point the walk is at is inside the whole tree. */
    private boolean rootState(int tree, Scratch sc) {
        return sc.stamp[0] == sc.walk && state(nodeStart[tree], 0, sc);
    }

    /**
     * False only when the segment 0 < t < {@code tMax} of the ray misses the bounds of {@code tree}
     * (by the widened slab test of a BVH walk): its solid then has no boundary there, so no hit and
     * a transmittance of 1. True for a tree with empty or unbounded bounds.
     */
    boolean mayMeet(int tree, Ray ray, double tMax) {
        double[] tb = treeBounds;
        return tb[6 * tree] != tb[6 * tree] || ray.enters(tb, 6 * tree, 0, tMax);
    }

    /**
     * The first boundary of the solid {@code tree} with 0 < t < {@code tMax}: writes it into {@code hit}
     * and returns true, or returns false.
     */
    boolean closestHit(int tree, Ray ray, double tMax, Shapes shapes, Materials materials, LineSpan span, Scratch sc,
            Hit hit) {
        return (pair[tree] ? walkPair(tree, ray, tMax, hit, shapes, materials, span, sc)
                : walk(tree, ray, tMax, hit, shapes, materials, span, sc)) != 0;
    }

    /**
     * The product of the transparencies of every boundary of the solid crossed with 0 < t < {@code tMax};
     * 0 as soon as an opaque one is crossed.
     */
    double transmittance(int tree, Ray ray, double tMax, Shapes shapes, Materials materials, LineSpan span, Scratch sc) {
        // The pair walk keeps no stretch lengths: a shadow ray that absorbs (Beer) takes the general walk.
        return pair[tree] && !(Features.ABSORPTION && sc.absorbing) ? walkPair(tree, ray, tMax, null, shapes, materials, span, sc)
                : walk(tree, ray, tMax, null, shapes, materials, span, sc);
    }

    /**
     * Walks the boundary events of {@code tree} along the ray, applying simultaneous events together.
     * With a {@code hit} it stops at the first boundary in (0, tMax), fills {@code hit} and returns 1
     * (0 when there is none); without, it returns the product of kt over the boundaries crossed.
     * Both walks share this one method on purpose: it is then too large for the JIT to inline into
     * the BVH loops, which keeps those loops small and quick to compile, while CSG runs as its own
     * compiled method.
     */
    double walk(int tree, Ray ray, double tMax, Hit hit, Shapes shapes, Materials materials, LineSpan span,
            Scratch sc) {
        double o = Math.max(Math.abs(ray.ox), Math.max(Math.abs(ray.oy), Math.abs(ray.oz)));
        double tol = TIE * (o + scale[tree]);
        int n = gather(tree, ray, -BEHIND * tol, tMax, shapes, span, sc);
        if (n == 0) return hit == null ? 1 : 0;
        sc.begin();
        for (int i = 0; i < sc.starts; i++) flip(tree, sc.startInside[i], sc);
        boolean known = false, state = false;
        double product = 1;
        // Where the shadow segment last entered the solid (0: it starts inside), for Beer's law.
        double enter = 0;
        int enterShape = -1;
        int[] order = sort(sc.eventT, n, sc.order, sc.merge);
        int i = 0;
        while (i < n) {
            double t0 = sc.eventT[order[i]];
            if (t0 >= tMax) break;
            if (t0 > 0 && !known) {
                state = rootState(tree, sc);
                known = true;
            }
            double limit = t0 + tol + TIE * Math.abs(t0);
            int shown = order[i];
            int j = i;
            for (; j < n && sc.eventT[order[j]] <= limit; j++) {
                int e = order[j];
                flip(tree, sc.eventLeaf[e], sc);
                if (sc.eventLeaf[e] >= sc.eventLeaf[shown]) shown = e;
            }
            if (known) {
                boolean now = rootState(tree, sc);
                if (now != state && sc.eventT[shown] < tMax) {
                    int shape = leafShape[leafStart[tree] + sc.eventLeaf[shown]];
                    if (hit != null) {
                        hit.t = sc.eventT[shown];
                        hit.shape = shape;
                        hit.face = sc.eventFace[shown];
                        hit.flip = sc.eventEntry[shown] != now;
                        return 1;
                    }
                    product *= materials.transparency(shapes.material[shape]);
                    if (product == 0) return 0;
                    if (Features.ABSORPTION && sc.absorbing) {
                        if (now) {
                            enter = sc.eventT[shown];
                            enterShape = shape;
                        } else {
                            absorb(materials, shapes.material[shape], sc.eventT[shown] - enter, sc);
                        }
                    }
                }
                state = now;
            }
            i = j;
        }
        if (Features.ABSORPTION && hit == null && sc.absorbing) {
            if (!known) state = rootState(tree, sc);
            // Still inside where the segment ends: the stretch counts with the material of the
            // surface ahead, or failing one (an unbounded solid) of the one it entered by.
            int ahead = i < n ? leafShape[leafStart[tree] + sc.eventLeaf[order[i]]] : enterShape;
            if (state && ahead >= 0) absorb(materials, shapes.material[ahead], tMax - enter, sc);
        }
        return hit == null ? product : 0;
    }

    /**
     * {@link #walk} for a {@link #pair} tree, with the same events, order, grouping of
     * simultaneous events and choice of the surface shown, so the answer is the same to the bit;
     * but the two inside-states are two booleans instead of the node counters, and a difference or
     * intersection whose first operand the line misses ends before the second is intersected.
     * When a leaf is not one solid interval (a torus, a mesh, an open tube), the general walk answers.
     */
    private double walkPair(int tree, Ray ray, double tMax, Hit hit, Shapes shapes, Materials materials, LineSpan span,
            Scratch sc) {
        int first = leafStart[tree];
        int op = nodeOp[nodeStart[tree]];
        double none = hit == null ? 1 : 0;
        boolean in0 = false, in1 = false;
        int n = 0;
        if (shapes.span(leafShape[first], ray, span)) {
            if (span.count != 1 || span.surface) return walk(tree, ray, tMax, hit, shapes, materials, span, sc);
            if (span.tIn[0] == Double.NEGATIVE_INFINITY) in0 = true;
            else n = add(sc, n, span.tIn[0], 0, span.faceIn[0], true);
            if (span.tOut[0] != Double.POSITIVE_INFINITY) n = add(sc, n, span.tOut[0], 0, span.faceOut[0], false);
        } else if (op != UNION) {
            return none;
        }
        if (shapes.span(leafShape[first + 1], ray, span)) {
            if (span.count != 1 || span.surface) return walk(tree, ray, tMax, hit, shapes, materials, span, sc);
            if (span.tIn[0] == Double.NEGATIVE_INFINITY) in1 = true;
            else n = add(sc, n, span.tIn[0], 1, span.faceIn[0], true);
            if (span.tOut[0] != Double.POSITIVE_INFINITY) n = add(sc, n, span.tOut[0], 1, span.faceOut[0], false);
        } else if (op == INTERSECTION) {
            return none;
        }
        if (n == 0) return none;
        double o = Math.max(Math.abs(ray.ox), Math.max(Math.abs(ray.oy), Math.abs(ray.oz)));
        double tol = TIE * (o + scale[tree]);
        double[] eventT = sc.eventT;
        int[] eventLeaf = sc.eventLeaf;
        if (hit == null && blocks(tree, op, eventT, eventLeaf, n, in0, in1, tMax, tol, shapes, materials)) return 0;
        int[] order = sort(eventT, n, sc.order, sc.merge);
        boolean known = false, state = false;
        double product = 1;
        int i = 0;
        while (i < n) {
            double t0 = eventT[order[i]];
            if (t0 >= tMax) break;
            if (t0 > 0 && !known) {
                state = inside(op, in0, in1);
                known = true;
            }
            double limit = t0 + tol + TIE * Math.abs(t0);
            int shown = order[i];
            int j = i;
            for (; j < n && eventT[order[j]] <= limit; j++) {
                int e = order[j];
                if (eventLeaf[e] == 0) in0 = !in0;
                else in1 = !in1;
                if (eventLeaf[e] >= eventLeaf[shown]) shown = e;
            }
            if (known) {
                boolean now = inside(op, in0, in1);
                if (now != state && eventT[shown] < tMax) {
                    int shape = leafShape[first + eventLeaf[shown]];
                    if (hit != null) {
                        hit.t = eventT[shown];
                        hit.shape = shape;
                        hit.face = sc.eventFace[shown];
                        hit.flip = sc.eventEntry[shown] != now;
                        return 1;
                    }
                    product *= materials.transparency(shapes.material[shape]);
                    if (product == 0) return 0;
                }
                state = now;
            }
            i = j;
        }
        return hit == null ? product : 0;
    }

    /**
     * For {@link #walkPair}'s shadow rays, without sorting: whether one of the {@code n} events
     * (unsorted) lies in (0, tMax) alone, farther from every other event than the walk's grouping
     * reaches either way, on an opaque leaf, where the solid's inside changes (the other leaf's
     * state there, counted from {@code in0}/{@code in1} at −∞ over its earlier events, decides it).
     * The walk then returns 0 at that event if not at an earlier one, so 0 is its answer; when
     * this finds no such event the walk answers. A shadow ray blocked by a bowl cut from a ball
     * takes this way (drops.crt: seven in eight of the pair walks of its shadow rays).
     */
    private boolean blocks(int tree, int op, double[] eventT, int[] eventLeaf, int n, boolean in0, boolean in1, double tMax,
            double tol, Shapes shapes, Materials materials) {
        for (int e = 0; e < n; e++) {
            double t = eventT[e];
            if (!(t > 0 && t < tMax)) continue;
            int leaf = eventLeaf[e];
            // The other leaf's state just before t, and whether any event is close enough to t to
            // share its group (the walk's grouping: t′ ≤ t0 + tol + TIE·|t0| from a group's first t0).
            boolean other = leaf == 0 ? in1 : in0, alone = true;
            double limit = t + tol + TIE * Math.abs(t);
            for (int f = 0; f < n; f++) {
                if (f == e) continue;
                double u = eventT[f];
                if (!(u > limit || t > u + tol + TIE * Math.abs(u))) {
                    alone = false;
                    break;
                }
                if (eventLeaf[f] != leaf && u < t) other = !other;
            }
            if (!alone) continue;
            // Whether this flip shows: the solid's inside, by the same rule as the walk's, differs
            // with this leaf in and out while the other stays as it is.
            boolean changes = leaf == 0 ? inside(op, true, other) != inside(op, false, other)
                    : inside(op, other, true) != inside(op, other, false);
            if (changes && materials.transparency(shapes.material[leafShape[leafStart[tree] + leaf]]) == 0) return true;
        }
        return false;
    }

    private static boolean inside(int op, boolean a, boolean b) {
        return switch (op) {
            case UNION -> a | b;
            case INTERSECTION -> a & b;
            default -> a & !b;
        };
    }

    private static void absorb(Materials materials, int material, double length, Scratch sc) {
        int m = material * Materials.STRIDE;
        double[] d = materials.data;
        sc.depthR += d[m + Materials.AR] * length;
        sc.depthG += d[m + Materials.AG] * length;
        sc.depthB += d[m + Materials.AB] * length;
    }
}
