package dev.crt.live;

import dev.crt.scene.MeshData;
import java.util.Arrays;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * A bounding volume hierarchy over one mesh's triangles, for the shaders that ray-cast meshes too
 * large to test triangle by triangle (shadow rays, meshes inside CSG): the triangles reordered so
 * that each leaf's lie together, and the nodes as pairs of texels.
 *
 * <p>Node {@code i} is texels {@code 2i} = (min x, y, z, first) and {@code 2i + 1} = (max x, y, z,
 * count), in the mesh's own coordinates: a leaf has {@code count} (1 to {@link #LEAF_TRIANGLES})
 * triangles from triangle {@code first}; an inner node has count 0 and its children at nodes
 * {@code first} and {@code first + 1}. Node 0 is the root. Indices are floats, exact up to 2^24.
 */
final class MeshBvh {
    /** Triangles per leaf at most. */
    static final int LEAF_TRIANGLES = 4;
    /** Deepest a tree may be: the shader's traversal stack (a median split halves every range, so depth is about log2 of the leaves). */
    static final int MAX_DEPTH = 32;

    /** The mesh's triangles (three vertex indices each), in leaf order. */
    final int[] triangles;
    /** Eight floats per node, see the class comment. */
    final float[] nodes;

    /**
     * The last hierarchies built, by the mesh's content: every compile reads a mesh file into a new
     * {@link MeshData}, and the hierarchy of the same triangles must not be built again each time.
     */
    private static final Map<Content, MeshBvh> BUILT = Collections.synchronizedMap(new LinkedHashMap<>(8, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<Content, MeshBvh> eldest) {
            return size() > 8;
        }
    });

    /** A mesh's positions and triangles compared by value. */
    private record Content(double[] positions, int[] triangles, int hash) {
        Content(MeshData m) {
            this(m.positions(), m.triangles(), 31 * Arrays.hashCode(m.positions()) + Arrays.hashCode(m.triangles()));
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof Content c && c.hash == hash && Arrays.equals(c.positions, positions)
                    && Arrays.equals(c.triangles, triangles);
        }

        @Override
        public int hashCode() {
            return hash;
        }
    }

    private MeshBvh(int[] triangles, float[] nodes) {
        this.triangles = triangles;
        this.nodes = nodes;
    }

    /** Whether the hierarchy of {@code mesh}'s content is built and kept (no build if not). */
    static boolean isBuilt(MeshData mesh) {
        return BUILT.containsKey(new Content(mesh));
    }

    /** The hierarchy of {@code mesh}, built once for the same positions and triangles (a recompile that keeps the mesh keeps it). */
    static MeshBvh of(MeshData mesh) {
        return BUILT.computeIfAbsent(new Content(mesh), c -> build(mesh));
    }

    private static MeshBvh build(MeshData mesh) {
        int n = mesh.triangleCount();
        double[] p = mesh.positions();
        int[] t = mesh.triangles();
        double[] lo = new double[3 * n], hi = new double[3 * n], centre = new double[3 * n];
        for (int f = 0; f < n; f++) {
            for (int a = 0; a < 3; a++) {
                double v0 = p[3 * t[3 * f] + a], v1 = p[3 * t[3 * f + 1] + a], v2 = p[3 * t[3 * f + 2] + a];
                lo[3 * f + a] = Math.min(v0, Math.min(v1, v2));
                hi[3 * f + a] = Math.max(v0, Math.max(v1, v2));
                centre[3 * f + a] = 0.5 * (lo[3 * f + a] + hi[3 * f + a]);
            }
        }
        int[] order = new int[n];
        for (int f = 0; f < n; f++) order[f] = f;
        Builder b = new Builder(lo, hi, centre, order, Math.max(1, 2 * n));
        b.node(0, 0, n, 1);
        b.count = Math.max(b.count, 1);
        int[] reordered = new int[3 * n];
        for (int i = 0; i < n; i++) System.arraycopy(t, 3 * order[i], reordered, 3 * i, 3);
        return new MeshBvh(reordered, Arrays.copyOf(b.nodes, 8 * b.count));
    }

    private static final class Builder {
        final double[] lo, hi, centre;
        final int[] order;
        float[] nodes;
        int count = 1;

        Builder(double[] lo, double[] hi, double[] centre, int[] order, int capacity) {
            this.lo = lo;
            this.hi = hi;
            this.centre = centre;
            this.order = order;
            this.nodes = new float[8 * capacity];
        }

        /** Fills node {@code i} with triangles [from, to) of the order, splitting at the median of the widest axis of their centres. */
        void node(int i, int from, int to, int depth) {
            double[] box = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
                Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
            double[] spread = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
                Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
            for (int k = from; k < to; k++) {
                int f = order[k];
                for (int a = 0; a < 3; a++) {
                    box[a] = Math.min(box[a], lo[3 * f + a]);
                    box[3 + a] = Math.max(box[3 + a], hi[3 * f + a]);
                    spread[a] = Math.min(spread[a], centre[3 * f + a]);
                    spread[3 + a] = Math.max(spread[3 + a], centre[3 * f + a]);
                }
            }
            for (int a = 0; a < 3; a++) {
                // Rounded outwards to float, so the node holds its triangles as the shader sees them.
                nodes[8 * i + a] = Math.nextDown((float) box[a]);
                nodes[8 * i + 4 + a] = Math.nextUp((float) box[3 + a]);
            }
            if (to - from <= LEAF_TRIANGLES || depth >= MAX_DEPTH) {
                nodes[8 * i + 3] = from;
                nodes[8 * i + 7] = to - from;
                return;
            }
            int axis = 0;
            for (int a = 1; a < 3; a++) {
                if (spread[3 + a] - spread[a] > spread[3 + axis] - spread[axis]) axis = a;
            }
            int mid = (from + to) >>> 1;
            select(from, to, mid, axis);
            int left = count;
            count += 2;
            nodes[8 * i + 3] = left;
            nodes[8 * i + 7] = 0;
            node(left, from, mid, depth + 1);
            node(left + 1, mid, to, depth + 1);
        }

        /** Reorders [from, to) so that position k holds the triangle of its rank by centre on the axis, smaller ones before it, larger after. */
        void select(int from, int to, int k, int axis) {
            int l = from, r = to - 1;
            while (l < r) {
                double pivot = centre[3 * order[(l + r) >>> 1] + axis];
                int i = l, j = r;
                while (i <= j) {
                    while (centre[3 * order[i] + axis] < pivot) i++;
                    while (centre[3 * order[j] + axis] > pivot) j--;
                    if (i <= j) {
                        int swap = order[i];
                        order[i++] = order[j];
                        order[j--] = swap;
                    }
                }
                if (k <= j) r = j;
                else if (k >= i) l = i;
                else return;
            }
        }
    }
}
