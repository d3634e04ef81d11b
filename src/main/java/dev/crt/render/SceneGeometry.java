package dev.crt.render;

import dev.crt.geom.Aabb;
import dev.crt.geom.Transform;
import dev.crt.scene.Csg;
import dev.crt.scene.Entity;
import dev.crt.scene.Material;
import dev.crt.scene.Primitive;
import dev.crt.scene.Sphere;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

/**
 * Everything a ray can hit, prepared for tracing. Each top-level entity is one item (a whole CSG
 * tree included): bounded items sit in a BVH (or a plain list when there are at most
 * {@value #LINEAR_LIMIT}), unbounded ones (planes, CSG without finite bounds) in a list every ray tests.
 * An item is a shape index, or −(tree + 1) for a CSG tree.
 */
final class SceneGeometry {
    static final int LINEAR_LIMIT = 4;
    /** {@link #what} of a bounded CSG tree. */
    private static final int CSG = -1;
    /** {@link #what} of an entity outside the hierarchy: unbounded (planes), or with nothing to hit. */
    private static final int OUTSIDE = -2;

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
    /**
     * Per entity of the scene, while preparing: a plain sphere's material index (≥ 0), {@link #CSG},
     * {@link #OUTSIDE}, or −(s + 3) for any other primitive, shape s of {@link #others}.
     */
    private int[] what;
    /** The primitives other than plain spheres, flattened in the first pass (to be copied in the second). */
    private Shapes others = new Shapes().sharingMeshesWith(shapes);

    SceneGeometry(List<Entity> entities) {
        // First pass, in the scene's order: the bounds of every entity, to build the hierarchy.
        // Plain spheres (untransformed, radius > 0: most of a large scene) are measured in chunks
        // on every core, their materials numbered per chunk and then merged in chunk order; the
        // other entities are flattened on this thread in the scene's order.
        int m = entities.size();
        what = new int[m];
        double[] flat = new double[6 * m];
        // The plain spheres' data as the second pass writes it, in the scene's order: read there
        // in the tree's scattered order, one place per sphere instead of the list, the sphere
        // and its centre one after the other.
        double[] sphereData = new double[SphereShape.SIZE * m];
        int chunks = Parallel.chunks(m);
        ChunkMaterials[] found = new ChunkMaterials[chunks];
        Parallel.forChunks(m, chunks, (chunk, from, to) -> found[chunk] = measureSpheres(entities, from, to, flat, sphereData));
        numberMaterials(m, chunks, found);
        List<Integer> outside = new ArrayList<>();
        List<Integer> outsideShape = new ArrayList<>();
        int slow = 0;
        for (ChunkMaterials f : found) slow += f.others;
        // The passes over every entity are methods of their own, as the builder's are: this
        // constructor runs once, and a loop in it had the JIT compile all of it (a third of a
        // second on one core in the middle of a million spheres' build) for nothing.
        int csgTrees = slow > 0 ? measureOthers(entities, flat, outside, outsideShape) : 0;
        // The bounded entities, numbered in the scene's order; their boxes moved together.
        int[] entity = slow > 0 ? bounded(flat) : null;
        int n = entity != null ? entity.length : m;
        int[] order = new int[n];
        if (n > LINEAR_LIMIT) {
            bvh = BvhBuilder.build(flat, n, order);
        } else {
            for (int i = 0; i < n; i++) order[i] = i;
            bvh = null;
        }
        // Second pass: the flat data, laid out in traversal order for locality. Runs of
        // primitives are placed in chunks on every core: plain spheres written from their data,
        // the others copied from the first pass; a CSG tree is flattened on this thread.
        int sphereCount = m - slow;
        shapes.reserve(sphereCount + others.count(), SphereShape.SIZE * sphereCount + others.dataSize());
        owners = new int[Math.max(16, sphereCount + others.count())];
        Aabb[] out = new Aabb[1];
        items = new int[n];
        // The entity at each traversal position, written over its number among the bounded ones.
        if (entity != null) renumber(order, entity);
        placeBounded(entities, sphereData, order, csgTrees, out);
        unbounded = new int[outside.size()];
        for (int i = 0; i < unbounded.length; i++) {
            int index = outside.get(i);
            unbounded[i] = place(entities.get(index), outsideShape.get(i), index, out);
        }
        owner = owners.length == shapes.count() ? owners : Arrays.copyOf(owners, shapes.count());
        owners = null;
        what = null;
        others = null;
    }

    /**
     * The first pass over the entities other than plain spheres (marked {@link #OUTSIDE} by
     * {@link #measureSpheres}), in the scene's order: primitives flattened into {@link #others},
     * bounds of the bounded ones into {@code flat}, the unbounded ones listed (with their shape in
     * {@link #others}, or −1 for a CSG tree). Returns the number of bounded CSG trees.
     */
    private int measureOthers(List<Entity> entities, double[] flat, List<Integer> outside, List<Integer> outsideShape) {
        CsgSolids probeCsg = new CsgSolids();
        Materials probeMaterials = new Materials();
        int[] what = this.what;
        int csgTrees = 0;
        for (int index = 0; index < what.length; index++) {
            if (what[index] != OUTSIDE) continue;
            Entity e = entities.get(index);
            int s = -1;
            Aabb b;
            if (e instanceof Primitive p) {
                s = others.add(p, p.transform(), 0);
                b = others.bounds(s);
            } else {
                b = probeCsg.bounds((Csg) e, Transform.IDENTITY, others, q -> probeMaterials.indexOf(q.material()));
            }
            if (b.isEmpty()) continue;
            if (s >= 0) others.material[s] = materials.indexOf(((Primitive) e).material());
            if (b.isFinite()) {
                what[index] = s >= 0 ? -(s + 3) : CSG;
                if (s < 0) csgTrees++;
                BvhBuilder.put(b, flat, index);
            } else {
                outside.add(index);
                outsideShape.add(s);
            }
        }
        return csgTrees;
    }

    /**
     * The entities with bounds (not {@link #OUTSIDE}), by their index in the scene, their boxes
     * moved to the front of {@code flat} in that order; null when every entity has bounds.
     */
    private int[] bounded(double[] flat) {
        int[] what = this.what;
        int m = what.length, n = 0;
        for (int index = 0; index < m; index++) if (what[index] != OUTSIDE) n++;
        if (n == m) return null;
        int[] entity = new int[n];
        for (int index = 0, k = 0; index < m; index++) {
            if (what[index] == OUTSIDE) continue;
            if (k != index) System.arraycopy(flat, 6 * index, flat, 6 * k, 6);
            entity[k++] = index;
        }
        return entity;
    }

    /** Replaces each number among the bounded entities in {@code order} by the entity's index in the scene. */
    private static void renumber(int[] order, int[] entity) {
        for (int i = 0; i < order.length; i++) order[i] = entity[order[i]];
    }

    /**
     * The second pass over the bounded entities, in traversal order: runs of primitives placed
     * by {@link #placeRun}, CSG trees one by one on this thread.
     */
    private void placeBounded(List<Entity> entities, double[] sphereData, int[] byOrder, int csgTrees, Aabb[] out) {
        int n = byOrder.length;
        for (int i = 0; i < n; ) {
            // Without CSG trees the whole order is one run, found without looking at each entity.
            int j = csgTrees == 0 ? n : runEnd(byOrder, i);
            if (j > i) {
                placeRun(sphereData, byOrder, i, j);
                i = j;
            } else {
                int index = byOrder[i];
                items[i++] = place(entities.get(index), -1, index, out);
            }
        }
    }

    /** The end of the run of primitives that starts at traversal position {@code i}: the first CSG tree's position, or the end. */
    private int runEnd(int[] byOrder, int i) {
        int[] what = this.what;
        int j = i;
        while (j < byOrder.length && what[byOrder[j]] != CSG) j++;
        return j;
    }

    /**
     * The distinct Material objects of a chunk's plain spheres, numbered by first appearance,
     * and how many of its entities are left to the one-thread pass.
     */
    private static final class ChunkMaterials {
        /** Scenes often give many objects a few Material objects (a palette): recent answers by identity. */
        private static final int RECENT = 64;
        final List<Material> list = new ArrayList<>();
        private final Map<Material, Integer> index = new IdentityHashMap<>();
        private final Material[] recent = new Material[RECENT];
        private final int[] recentIndex = new int[RECENT];
        int others;

        int indexOf(Material m) {
            int r = System.identityHashCode(m) & (RECENT - 1);
            if (recent[r] == m) return recentIndex[r];
            Integer k = index.get(m);
            if (k == null) {
                k = list.size();
                list.add(m);
                index.put(m, k);
            }
            recent[r] = m;
            recentIndex[r] = k;
            return k;
        }
    }

    /**
     * The bounds of the plain spheres among entities [from, to) into {@code flat} and their data
     * into {@code sphereData} (at their entity index), and their chunk's material numbers into
     * {@link #what}; the other entities are marked {@link #OUTSIDE} for the one-thread pass to
     * look at.
     */
    private ChunkMaterials measureSpheres(List<Entity> entities, int from, int to, double[] flat, double[] sphereData) {
        ChunkMaterials found = new ChunkMaterials();
        int[] what = this.what;
        for (int index = from; index < to; index++) {
            if (entities.get(index) instanceof Sphere sp && sp.transform() == Transform.IDENTITY && sp.radius() > 0
                    && sphereBounds(sp, flat, index)) {
                SphereShape.write(sphereData, SphereShape.SIZE * index, sp.x(), sp.y(), sp.z(), sp.radius());
                what[index] = found.indexOf(sp.material());
            } else {
                what[index] = OUTSIDE;
                found.others++;
            }
        }
        return found;
    }

    /**
     * Numbers the chunks' materials in chunk order, so in the order of their first appearance in
     * the scene whatever the chunking, and renumbers the spheres' material numbers accordingly.
     */
    private void numberMaterials(int m, int chunks, ChunkMaterials[] found) {
        int[][] global = new int[chunks][];
        boolean same = true;
        for (int c = 0; c < chunks; c++) {
            List<Material> list = found[c].list;
            global[c] = new int[list.size()];
            for (int k = 0; k < list.size(); k++) {
                global[c][k] = materials.indexOf(list.get(k));
                same &= global[c][k] == k;
            }
        }
        if (same) return;
        int[] what = this.what;
        Parallel.forChunks(m, chunks, (chunk, from, to) -> {
            int[] g = global[chunk];
            for (int index = from; index < to; index++) if (what[index] >= 0) what[index] = g[what[index]];
        });
    }

    /**
     * Writes the bounds of an untransformed sphere as item {@code i} of a flat bounds array, with
     * the arithmetic of {@link SphereShape#bounds} and {@link BvhBuilder#put}; returns false,
     * writing nothing, when they are not finite.
     */
    private static boolean sphereBounds(Sphere sp, double[] flat, int i) {
        double x = sp.x(), y = sp.y(), z = sp.z(), r = sp.radius();
        double x0 = x - r, y0 = y - r, z0 = z - r, x1 = x + r, y1 = y + r, z1 = z + r;
        if (!(Double.isFinite(x0) && Double.isFinite(y0) && Double.isFinite(z0)
                && Double.isFinite(x1) && Double.isFinite(y1) && Double.isFinite(z1))) return false;
        BvhBuilder.put(x0, y0, z0, x1, y1, z1, flat, i);
        return true;
    }

    /**
     * Places the primitives of traversal positions [i, j) (entities {@code byOrder[i]} …) as
     * shapes, items and owners, in chunks on every core: each chunk measures its data, then
     * writes it from where the chunks before it end (the same layout in any chunking). Plain
     * spheres are copied from their data in {@code sphereData}, the others from the first pass.
     * When the first pass flattened nothing into {@link #others}, every primitive is a plain
     * sphere of {@link SphereShape#SIZE} numbers, and the chunks' starts are known without the
     * measuring pass.
     */
    private void placeRun(double[] sphereData, int[] byOrder, int i, int j) {
        int n = j - i, first = shapes.count();
        int chunks = Parallel.chunks(n);
        long[] before = new long[chunks + 1];
        if (others.count() == 0) {
            for (int c = 0; c <= chunks; c++) before[c] = (long) SphereShape.SIZE * Parallel.start(n, chunks, c);
        } else {
            runLengths(byOrder, i, n, chunks, before);
        }
        int[] what = this.what;
        int base = shapes.dataSize();
        if (base + before[chunks] > Integer.MAX_VALUE - 16) throw new OutOfMemoryError("scene data too large");
        shapes.claim(n, (int) before[chunks]);
        if (first + n > owners.length) owners = Arrays.copyOf(owners, Math.max(first + n, 2 * owners.length));
        int[] owners = this.owners;
        Parallel.forChunks(n, chunks, (chunk, a, b) -> {
            int at = base + (int) before[chunk];
            for (int k = i + a; k < i + b; k++) {
                int index = byOrder[k], w = what[index], t = first + k - i;
                if (w >= 0) {
                    SphereShape.place(shapes, t, at, sphereData, SphereShape.SIZE * index, w);
                    at += SphereShape.SIZE;
                } else {
                    at = shapes.copyAt(others, -w - 3, t, at);
                }
                items[k] = t;
                owners[t] = index;
            }
        });
        if (others.meshes.length > 0) shapes.reindexMeshes(others, first, first + n);
    }

    /** Where each chunk of the run's n positions from {@code i} starts in the shapes' data, relative to the run's start, into {@code before}. */
    private void runLengths(int[] byOrder, int i, int n, int chunks, long[] before) {
        int[] what = this.what, offsetFrom = others.offset;
        int last = others.count() - 1, lastEnd = others.dataSize();
        Parallel.forChunks(n, chunks, (chunk, a, b) -> {
            long length = 0;
            for (int k = i + a; k < i + b; k++) {
                int w = what[byOrder[k]];
                if (w >= 0) {
                    length += SphereShape.SIZE;
                } else {
                    int s = -w - 3;
                    length += (s < last ? offsetFrom[s + 1] : lastEnd) - offsetFrom[s];
                }
            }
            before[chunk + 1] = length;
        });
        for (int c = 0; c < chunks; c++) before[c + 1] += before[c];
    }

    /** Flattens entity number {@code index} of the scene; the shapes it adds are recorded as its own. */
    private int place(Entity e, int first, int index, Aabb[] out) {
        int from = shapes.count();
        int item = first >= 0 ? shapes.copy(others, first)
                : -(csg.add((Csg) e, Transform.IDENTITY, shapes, q -> materials.indexOf(q.material()), out) + 1);
        int to = shapes.count();
        if (to > owners.length) owners = Arrays.copyOf(owners, Math.max(to, 2 * owners.length));
        Arrays.fill(owners, from, to, index);
        return item;
    }
}
