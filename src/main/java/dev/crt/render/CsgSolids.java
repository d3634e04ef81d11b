package dev.crt.render;

import dev.crt.geom.Aabb;
import dev.crt.geom.Transform;
import dev.crt.scene.Csg;
import dev.crt.scene.Entity;
import dev.crt.scene.Primitive;
import java.util.Arrays;
import java.util.function.ToIntFunction;

/**
 * CSG trees flattened for tracing: each tree is a list of primitive leaves (transforms pushed down,
 * T(A op B) = T(A) op T(B)) and a postfix program over their inside-states.
 *
 * <p>A ray is intersected exactly: every leaf gives the interval where the line is inside it, the
 * interval ends become events sorted by distance, and walking them while re-evaluating the program
 * finds where the line enters or leaves the resulting solid. Events closer together than a tiny
 * scale-relative tolerance count as simultaneous and are applied together, so coincident faces
 * resolve by set semantics (a box minus an identical box is empty; two boxes sharing a face unite
 * without an inner wall). When simultaneous events change the result, the surface shown is the one
 * of the leaf that comes last in the tree (in A − B, B's boundary wins on equal distance).
 */
final class CsgSolids {
    static final int UNION = -1;
    static final int INTERSECTION = -2;
    static final int DIFFERENCE = -3;
    /** Relative distance under which boundary events are treated as coincident. */
    static final double TIE = 0x1p-44;

    private int count;
    int[] leafStart = new int[4], leafCount = new int[4], progStart = new int[4], progLength = new int[4];
    double[] scale = new double[4];
    int[] leafShape = new int[8];
    int[] program = new int[16];
    private int leafSize, programSize;
    int maxLeaves;

    /** Flattens {@code csg} placed by {@code parent}; returns its index and its world bounds in {@code bounds[0]}. */
    int add(Csg csg, Transform parent, Shapes shapes, ToIntFunction<Primitive> materials, Aabb[] bounds) {
        int tree = count++;
        if (tree == leafStart.length) {
            int n = tree * 2;
            leafStart = Arrays.copyOf(leafStart, n);
            leafCount = Arrays.copyOf(leafCount, n);
            progStart = Arrays.copyOf(progStart, n);
            progLength = Arrays.copyOf(progLength, n);
            scale = Arrays.copyOf(scale, n);
        }
        leafStart[tree] = leafSize;
        progStart[tree] = programSize;
        Aabb b = flatten(csg, parent, tree, shapes, materials);
        leafCount[tree] = leafSize - leafStart[tree];
        progLength[tree] = programSize - progStart[tree];
        maxLeaves = Math.max(maxLeaves, leafCount[tree]);
        double sc = 0;
        for (int k = leafStart[tree]; k < leafSize; k++) sc = Math.max(sc, shapes.scale[leafShape[k]]);
        scale[tree] = sc;
        bounds[0] = b;
        return tree;
    }

    private Aabb flatten(Entity e, Transform parent, int tree, Shapes shapes, ToIntFunction<Primitive> materials) {
        Transform t = e.transform().then(parent);
        if (e instanceof Primitive p) {
            int s = shapes.add(p, t, materials.applyAsInt(p));
            int local = leafSize - leafStart[tree];
            if (leafSize == leafShape.length) leafShape = Arrays.copyOf(leafShape, leafSize * 2);
            leafShape[leafSize++] = s;
            emit(local);
            return shapes.bounds(s);
        }
        Csg c = (Csg) e;
        Aabb a = flatten(c.left(), t, tree, shapes, materials);
        Aabb b = flatten(c.right(), t, tree, shapes, materials);
        switch (c.operation()) {
            case UNION -> {
                emit(UNION);
                return a.union(b);
            }
            case INTERSECTION -> {
                emit(INTERSECTION);
                return a.intersection(b);
            }
            default -> {
                emit(DIFFERENCE);
                return a;
            }
        }
    }

    private void emit(int code) {
        if (programSize == program.length) program = Arrays.copyOf(program, programSize * 2);
        program[programSize++] = code;
    }

    /** Per-thread working memory for walking the events of one tree. */
    static final class Scratch {
        final boolean[] inside;
        final boolean[] stack;
        final double[] eventT;
        final int[] eventLeaf;
        final int[] eventFace;
        final boolean[] eventEntry;

        Scratch(int maxLeaves) {
            int n = Math.max(1, maxLeaves);
            inside = new boolean[n];
            stack = new boolean[n + 1];
            eventT = new double[2 * n];
            eventLeaf = new int[2 * n];
            eventFace = new int[2 * n];
            eventEntry = new boolean[2 * n];
        }
    }

    /** Collects and sorts the boundary events of {@code tree} along the ray; sets the inside-states at t = −∞. */
    private int gather(int tree, Ray ray, Shapes shapes, LineSpan span, Scratch sc) {
        int first = leafStart[tree], n = leafCount[tree];
        int events = 0;
        for (int k = 0; k < n; k++) {
            boolean hit = shapes.span(leafShape[first + k], ray, span);
            sc.inside[k] = hit && span.tIn == Double.NEGATIVE_INFINITY;
            if (!hit) continue;
            if (span.tIn != Double.NEGATIVE_INFINITY) events = insert(sc, events, span.tIn, k, span.faceIn, true);
            if (span.tOut != Double.POSITIVE_INFINITY) events = insert(sc, events, span.tOut, k, span.faceOut, false);
        }
        return events;
    }

    /** Insertion into the sorted event list; equal distances keep leaf order, so ties are deterministic. */
    private static int insert(Scratch sc, int n, double t, int leaf, int face, boolean entry) {
        int i = n;
        while (i > 0 && sc.eventT[i - 1] > t) {
            sc.eventT[i] = sc.eventT[i - 1];
            sc.eventLeaf[i] = sc.eventLeaf[i - 1];
            sc.eventFace[i] = sc.eventFace[i - 1];
            sc.eventEntry[i] = sc.eventEntry[i - 1];
            i--;
        }
        sc.eventT[i] = t;
        sc.eventLeaf[i] = leaf;
        sc.eventFace[i] = face;
        sc.eventEntry[i] = entry;
        return n + 1;
    }

    private boolean evaluate(int tree, Scratch sc) {
        int p = progStart[tree], end = p + progLength[tree];
        boolean[] st = sc.stack;
        int top = 0;
        for (; p < end; p++) {
            int code = program[p];
            if (code >= 0) {
                st[top++] = sc.inside[code];
            } else {
                boolean b = st[--top], a = st[top - 1];
                st[top - 1] = code == UNION ? a | b : code == INTERSECTION ? a & b : a & !b;
            }
        }
        return st[0];
    }

    /**
     * The first boundary of the solid {@code tree} with 0 < t < {@code tMax}: writes it into {@code hit}
     * and returns true, or returns false.
     */
    boolean closestHit(int tree, Ray ray, double tMax, Shapes shapes, Materials materials, LineSpan span, Scratch sc,
            Hit hit) {
        return walk(tree, ray, tMax, hit, shapes, materials, span, sc) != 0;
    }

    /**
     * The product of the transparencies of every boundary of the solid crossed with 0 < t < {@code tMax};
     * 0 as soon as an opaque one is crossed.
     */
    double transmittance(int tree, Ray ray, double tMax, Shapes shapes, Materials materials, LineSpan span, Scratch sc) {
        return walk(tree, ray, tMax, null, shapes, materials, span, sc);
    }

    /**
     * Walks the boundary events of {@code tree} along the ray, applying simultaneous events together.
     * With a {@code hit} it stops at the first boundary in (0, tMax), fills {@code hit} and returns 1
     * (0 when there is none); without, it returns the product of kt over the boundaries crossed.
     * Both walks share this one method on purpose: it is then too large for the JIT to inline into
     * the BVH loops, which keeps those loops small and quick to compile, while CSG runs as its own
     * compiled method.
     */
    private double walk(int tree, Ray ray, double tMax, Hit hit, Shapes shapes, Materials materials, LineSpan span,
            Scratch sc) {
        int n = gather(tree, ray, shapes, span, sc);
        if (n == 0) return hit == null ? 1 : 0;
        double o = Math.max(Math.abs(ray.ox), Math.max(Math.abs(ray.oy), Math.abs(ray.oz)));
        double tol = TIE * (o + scale[tree]);
        boolean known = false, state = false;
        double product = 1;
        int i = 0;
        while (i < n) {
            double t0 = sc.eventT[i];
            if (t0 >= tMax) break;
            if (t0 > 0 && !known) {
                state = evaluate(tree, sc);
                known = true;
            }
            double limit = t0 + tol + TIE * Math.abs(t0);
            int shown = i;
            int j = i;
            for (; j < n && sc.eventT[j] <= limit; j++) {
                sc.inside[sc.eventLeaf[j]] ^= true;
                if (sc.eventLeaf[j] >= sc.eventLeaf[shown]) shown = j;
            }
            if (known) {
                boolean now = evaluate(tree, sc);
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
                }
                state = now;
            }
            i = j;
        }
        return hit == null ? product : 0;
    }
}
