package dev.crt.render;

import dev.crt.geom.Aabb;
import dev.crt.geom.Vec3;
import dev.crt.scene.MeshData;

/**
 * One mesh prepared for rays, shared by all its instances (the lower level of the two-level
 * hierarchy): its triangles reordered into the leaf order of a BVH of their own (or tested one by
 * one when there are few), in the mesh's own coordinates.
 */
final class MeshGeometry {
    /** Triangles up to which a mesh is tested without a hierarchy. */
    static final int LINEAR_LIMIT = 8;

    final double[] positions;
    final double[] normals;
    final double[] uvs;
    /** Three vertex indices per triangle, in BVH leaf order. */
    final int[] triangles;
    final int count;
    final Bvh bvh;
    final boolean closed;
    final Aabb bounds;
    /** {@link #bounds} as (minX, minY, minZ, maxX, maxY, maxZ) and the length of its diagonal. */
    final double[] box;

    MeshGeometry(MeshData data) {
        positions = data.positions();
        normals = data.normals();
        uvs = data.uvs();
        closed = data.closed();
        int[] source = withoutDegenerate(data.triangles(), positions);
        count = source.length / 3;
        double[] flat = new double[6 * count];
        // The triangles' boxes in chunks on every core, each chunk's union kept apart and merged
        // after: minima and maxima are exact, so the result is the same for any number of chunks.
        int chunks = Parallel.chunks(count);
        double[] unions = new double[6 * chunks];
        Parallel.forChunks(count, chunks, (chunk, from, to) -> boxes(source, positions, flat, from, to, unions, chunk));
        double minX = Double.POSITIVE_INFINITY, minY = minX, minZ = minX;
        double maxX = Double.NEGATIVE_INFINITY, maxY = maxX, maxZ = maxX;
        for (int c = 0; c < chunks; c++) {
            minX = Math.min(minX, unions[6 * c]);
            minY = Math.min(minY, unions[6 * c + 1]);
            minZ = Math.min(minZ, unions[6 * c + 2]);
            maxX = Math.max(maxX, unions[6 * c + 3]);
            maxY = Math.max(maxY, unions[6 * c + 4]);
            maxZ = Math.max(maxZ, unions[6 * c + 5]);
        }
        bounds = new Aabb(new Vec3(minX, minY, minZ), new Vec3(maxX, maxY, maxZ));
        double ex = maxX - minX, ey = maxY - minY, ez = maxZ - minZ;
        box = new double[] {minX, minY, minZ, maxX, maxY, maxZ, Math.sqrt(ex * ex + ey * ey + ez * ez)};
        if (count > LINEAR_LIMIT) {
            int[] order = new int[count];
            bvh = BvhBuilder.build(flat, count, order);
            triangles = new int[3 * count];
            int[] out = triangles;
            Parallel.forChunks(count, (chunk, from, to) -> {
                for (int i = from; i < to; i++) {
                    int t = 3 * order[i];
                    out[3 * i] = source[t];
                    out[3 * i + 1] = source[t + 1];
                    out[3 * i + 2] = source[t + 2];
                }
            });
        } else {
            bvh = null;
            triangles = source;
        }
    }

    /**
     * Writes the boxes of triangles [from, to) into {@code flat} and their union (of the exact
     * boxes, before widening) as entry {@code chunk} of {@code unions}.
     */
    private static void boxes(int[] source, double[] positions, double[] flat, int from, int to, double[] unions, int chunk) {
        double minX = Double.POSITIVE_INFINITY, minY = minX, minZ = minX;
        double maxX = Double.NEGATIVE_INFINITY, maxY = maxX, maxZ = maxX;
        for (int t = from; t < to; t++) {
            double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0, x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
            for (int k = 0; k < 3; k++) {
                int v = 3 * source[3 * t + k];
                x0 = Math.min(x0, positions[v]);
                y0 = Math.min(y0, positions[v + 1]);
                z0 = Math.min(z0, positions[v + 2]);
                x1 = Math.max(x1, positions[v]);
                y1 = Math.max(y1, positions[v + 1]);
                z1 = Math.max(z1, positions[v + 2]);
            }
            // Widened by an ulp, as the scene's items are: a box must not clip its triangle.
            BvhBuilder.put(x0, y0, z0, x1, y1, z1, flat, t);
            minX = Math.min(minX, x0);
            minY = Math.min(minY, y0);
            minZ = Math.min(minZ, z0);
            maxX = Math.max(maxX, x1);
            maxY = Math.max(maxY, y1);
            maxZ = Math.max(maxZ, z1);
        }
        unions[6 * chunk] = minX;
        unions[6 * chunk + 1] = minY;
        unions[6 * chunk + 2] = minZ;
        unions[6 * chunk + 3] = maxX;
        unions[6 * chunk + 4] = maxY;
        unions[6 * chunk + 5] = maxZ;
    }

    /**
     * The triangles without those of no area (a repeated vertex, or three vertices on a line to
     * within an angle of 2⁻⁴⁰): they bound nothing, and a line through their edge could otherwise
     * count a crossing there beside the real triangles' one (rounding of the sheared vertices
     * makes such a triangle thin rather than flat).
     */
    static int[] withoutDegenerate(int[] tri, double[] p) {
        // Most meshes have none: they are counted on every core first, and only a mesh with some
        // is copied without them.
        int n3 = tri.length / 3;
        int[] found = new int[Parallel.chunks(n3)];
        Parallel.forChunks(n3, found.length, (chunk, from, to) -> {
            int d = 0;
            for (int t = from; t < to; t++) if (degenerate(tri, p, 3 * t)) d++;
            found[chunk] = d;
        });
        int degenerate = 0;
        for (int d : found) degenerate += d;
        if (degenerate == 0) return tri;
        int[] kept = new int[tri.length];
        int n = 0;
        for (int k = 0; k < tri.length; k += 3) {
            if (degenerate(tri, p, k)) continue;
            System.arraycopy(tri, k, kept, n, 3);
            n += 3;
        }
        return java.util.Arrays.copyOf(kept, n);
    }

    /** Whether the triangle at {@code k} of {@code tri} has no area (see {@link #withoutDegenerate}). */
    private static boolean degenerate(int[] tri, double[] p, int k) {
        int a = 3 * tri[k], b = 3 * tri[k + 1], c = 3 * tri[k + 2];
        double e1x = p[b] - p[a], e1y = p[b + 1] - p[a + 1], e1z = p[b + 2] - p[a + 2];
        double e2x = p[c] - p[a], e2y = p[c + 1] - p[a + 1], e2z = p[c + 2] - p[a + 2];
        double nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
        double area2 = nx * nx + ny * ny + nz * nz;
        double scale2 = (e1x * e1x + e1y * e1y + e1z * e1z) * (e2x * e2x + e2y * e2y + e2z * e2z);
        return !(area2 > 0x1p-80 * scale2);
    }
}
