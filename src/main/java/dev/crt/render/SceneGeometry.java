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
    private int[] owners = new int[16];

    SceneGeometry(List<Entity> entities) {
        // First pass, in the scene's order: every primitive flattened with its material (kept, to
        // be copied in the second pass), and the bounds of every entity, to build the hierarchy.
        Shapes firstShapes = new Shapes().sharingMeshesWith(shapes);
        CsgSolids probeCsg = new CsgSolids();
        Materials probeMaterials = new Materials();
        List<Entity> bounded = new ArrayList<>();
        List<Entity> infinite = new ArrayList<>();
        // Per bounded and per unbounded entity, its index in the scene's list.
        int[] boundedIndex = new int[16];
        List<Integer> infiniteIndex = new ArrayList<>();
        int index = -1;
        // Per bounded or unbounded entity, its index in firstShapes, or −1 for a CSG tree.
        int[] boundedShape = new int[16];
        List<Integer> infiniteShape = new ArrayList<>();
        double[] flat = new double[6 * 16];
        Aabb[] out = new Aabb[1];
        for (Entity e : entities) {
            index++;
            Aabb b;
            int s = -1;
            if (e instanceof Primitive p) {
                s = firstShapes.add(p, p.transform(), 0);
                b = firstShapes.bounds(s);
            } else {
                b = probeCsg.bounds((Csg) e, Transform.IDENTITY, firstShapes, q -> probeMaterials.indexOf(q.material()));
            }
            if (b.isEmpty()) continue;
            if (s >= 0) firstShapes.material[s] = materials.indexOf(((Primitive) e).material());
            if (b.isFinite()) {
                int i = bounded.size();
                bounded.add(e);
                if (i == boundedShape.length) {
                    boundedShape = Arrays.copyOf(boundedShape, 2 * i);
                    boundedIndex = Arrays.copyOf(boundedIndex, 2 * i);
                    flat = Arrays.copyOf(flat, 12 * i);
                }
                boundedShape[i] = s;
                boundedIndex[i] = index;
                BvhBuilder.put(b, flat, i);
            } else {
                infinite.add(e);
                infiniteShape.add(s);
                infiniteIndex.add(index);
            }
        }
        int n = bounded.size();
        int[] order = new int[n];
        if (n > LINEAR_LIMIT) {
            bvh = BvhBuilder.build(flat, n, order);
        } else {
            for (int i = 0; i < n; i++) order[i] = i;
            bvh = null;
        }
        // Second pass: the flat data, laid out in traversal order for locality. A primitive is
        // copied from the first pass rather than flattened again, which would visit the scene's
        // objects in a scattered order.
        items = new int[n];
        for (int i = 0; i < n; i++) {
            int k = order[i];
            items[i] = place(bounded.get(k), boundedShape[k], boundedIndex[k], firstShapes, out);
        }
        unbounded = new int[infinite.size()];
        for (int i = 0; i < unbounded.length; i++) {
            unbounded[i] = place(infinite.get(i), infiniteShape.get(i), infiniteIndex.get(i), firstShapes, out);
        }
        owner = Arrays.copyOf(owners, shapes.count());
        owners = null;
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
