package dev.crt.render;

import dev.crt.geom.Aabb;
import dev.crt.geom.Transform;
import dev.crt.scene.Csg;
import dev.crt.scene.Entity;
import dev.crt.scene.Primitive;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Everything a ray can hit, prepared for tracing. Each top-level entity is one item (a whole CSG
 * tree included): bounded items sit in a BVH (or a plain list when there are at most
 * {@value #LINEAR_LIMIT}), unbounded ones (planes, CSG without finite bounds) in a list every ray tests.
 * An item is a shape index, or −(tree + 1) for a CSG tree.
 */
final class SceneGeometry {
    static final int LINEAR_LIMIT = 4;

    final Shapes shapes = new Shapes();
    final CsgSolids csg = new CsgSolids();
    final Materials materials = new Materials();
    /** Bounded items, in BVH leaf order. */
    final int[] items;
    final int[] unbounded;
    /** Null when the bounded items are few enough to test them all. */
    final Bvh bvh;
    /**
     * Per shape, the index in the scene's entity list of the top-level entity it belongs to (a
     * CSG tree's leaves all name the tree), so a hit can be traced back to the script. Read only
     * by picking and passes, never on the render path.
     */
    final int[] owner;
    private int[] owners;

    SceneGeometry(List<Entity> entities) {
        // First pass, in the scene's order: every primitive flattened with its material (kept, to
        // be copied in the second pass), and the bounds of every entity, to build the hierarchy.
        // The stores are sized for one shape per entity up front: growing arrays of a million
        // shapes by doubling copied them about twice over.
        int m = entities.size();
        Shapes firstShapes = new Shapes().sharingMeshesWith(shapes);
        firstShapes.reserve(m, 5 * m);
        CsgSolids probeCsg = new CsgSolids();
        Materials probeMaterials = new Materials();
        // Per bounded entity, its index in the scene's list, and in firstShapes (−1 for a CSG tree).
        int[] boundedIndex = new int[m];
        int[] boundedShape = new int[m];
        List<Integer> infiniteIndex = new ArrayList<>();
        List<Integer> infiniteShape = new ArrayList<>();
        int n = 0;
        double[] flat = new double[6 * m];
        for (int index = 0; index < m; index++) {
            Entity e = entities.get(index);
            int s = -1;
            if (e instanceof Primitive p) {
                s = firstShapes.add(p, p.transform(), 0);
                if (firstShapes.kind[s] == Shapes.SPHERE) {
                    // Never empty (radius > 0); its material is numbered as any visible primitive's.
                    firstShapes.material[s] = materials.indexOf(p.material());
                    // A sphere's bounds written straight in, as BvhBuilder.put writes Aabb's.
                    if (!sphereBounds(firstShapes.data, firstShapes.offset[s], flat, n)) {
                        infiniteIndex.add(index);
                        infiniteShape.add(s);
                        continue;
                    }
                    boundedShape[n] = s;
                    boundedIndex[n++] = index;
                    continue;
                }
            }
            Aabb b = s >= 0 ? firstShapes.bounds(s)
                    : probeCsg.bounds((Csg) e, Transform.IDENTITY, firstShapes, q -> probeMaterials.indexOf(q.material()));
            if (b.isEmpty()) continue;
            if (s >= 0) firstShapes.material[s] = materials.indexOf(((Primitive) e).material());
            if (b.isFinite()) {
                boundedShape[n] = s;
                boundedIndex[n] = index;
                BvhBuilder.put(b, flat, n++);
            } else {
                infiniteIndex.add(index);
                infiniteShape.add(s);
            }
        }
        int[] order = new int[n];
        if (n > LINEAR_LIMIT) {
            bvh = BvhBuilder.build(flat, n, order);
        } else {
            for (int i = 0; i < n; i++) order[i] = i;
            bvh = null;
        }
        flat = null;
        // Second pass: the flat data, laid out in traversal order for locality. A primitive is
        // copied from the first pass rather than flattened again, which would visit the scene's
        // objects in a scattered order; runs of primitives are copied array by array.
        shapes.reserve(firstShapes.count(), firstShapes.dataSize());
        owners = new int[Math.max(16, firstShapes.count())];
        Aabb[] out = new Aabb[1];
        items = new int[n];
        int[] src = new int[n];
        for (int i = 0; i < n; ) {
            int j = i;
            while (j < n && boundedShape[order[j]] >= 0) {
                src[j] = boundedShape[order[j]];
                j++;
            }
            if (j > i) {
                int from = shapes.count();
                shapes.copyAll(firstShapes, src, i, j);
                if (shapes.count() > owners.length) owners = Arrays.copyOf(owners, Math.max(shapes.count(), 2 * owners.length));
                for (int k = i; k < j; k++) {
                    items[k] = from + k - i;
                    owners[from + k - i] = boundedIndex[order[k]];
                }
                i = j;
            } else {
                int k = order[i];
                items[i++] = place(entities.get(boundedIndex[k]), -1, boundedIndex[k], firstShapes, out);
            }
        }
        unbounded = new int[infiniteIndex.size()];
        for (int i = 0; i < unbounded.length; i++) {
            int index = infiniteIndex.get(i);
            unbounded[i] = place(entities.get(index), infiniteShape.get(i), index, firstShapes, out);
        }
        owner = Arrays.copyOf(owners, shapes.count());
        owners = null;
    }

    /**
     * Writes the bounds of the SPHERE at {@code o} of {@code data} as item {@code i} of a flat
     * bounds array, with the arithmetic of {@link SphereShape#bounds} and {@link BvhBuilder#put};
     * returns false, writing nothing, when they are not finite.
     */
    private static boolean sphereBounds(double[] data, int o, double[] flat, int i) {
        double x = data[o], y = data[o + 1], z = data[o + 2], r = data[o + 3];
        double x0 = x - r, y0 = y - r, z0 = z - r, x1 = x + r, y1 = y + r, z1 = z + r;
        if (!(Double.isFinite(x0) && Double.isFinite(y0) && Double.isFinite(z0)
                && Double.isFinite(x1) && Double.isFinite(y1) && Double.isFinite(z1))) return false;
        BvhBuilder.put(x0, y0, z0, x1, y1, z1, flat, i);
        return true;
    }

    /** Flattens entity number {@code index} of the scene; the shapes it adds are recorded as its own. */
    private int place(Entity e, int first, int index, Shapes firstShapes, Aabb[] out) {
        int from = shapes.count();
        int item = first >= 0 ? shapes.copy(firstShapes, first)
                : -(csg.add((Csg) e, Transform.IDENTITY, shapes, q -> materials.indexOf(q.material()), out) + 1);
        int to = shapes.count();
        if (to > owners.length) owners = Arrays.copyOf(owners, Math.max(to, 2 * owners.length));
        Arrays.fill(owners, from, to, index);
        return item;
    }
}
