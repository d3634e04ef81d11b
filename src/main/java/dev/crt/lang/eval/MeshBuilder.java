package dev.crt.lang.eval;

import dev.crt.scene.MeshData;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;

/**
 * Collects a mesh's positions, texture coordinates, normals and polygons (fanned into triangles)
 * from a file or an inline literal, and finishes it into a {@link MeshData}: one vertex per
 * distinct (position, uv, normal) triple, closedness decided on the positions (each edge shared by
 * exactly two triangles), and area-weighted vertex normals where the source gave none.
 */
final class MeshBuilder {
    /** A mesh that cannot be built, said in a sentence (with the place in the file when there is one). */
    static final class MeshProblem extends Exception {
        MeshProblem(String message) { super(message, null, false, false); }
    }

    private double[] positions = new double[48];
    private int positionCount;
    private double[] uvs = new double[32];
    private int uvCount;
    private double[] normals = new double[48];
    private int normalCount;
    /** Per triangle corner: position, uv and normal index (−1 when absent). */
    private int[] corners = new int[96];
    private int cornerCount;

    int positions() { return positionCount; }

    int uvs() { return uvCount; }

    int normals() { return normalCount; }

    void position(double x, double y, double z, Object where) throws MeshProblem {
        if (!(Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z))) {
            throw new MeshProblem(where + "vertex " + positionCount + " is not a finite point (" + x + ", " + y + ", " + z + ")");
        }
        positions = grow(positions, 3 * positionCount + 3);
        positions[3 * positionCount] = x;
        positions[3 * positionCount + 1] = y;
        positions[3 * positionCount + 2] = z;
        positionCount++;
    }

    void uv(double u, double v, Object where) throws MeshProblem {
        if (!(Double.isFinite(u) && Double.isFinite(v))) throw new MeshProblem(where + "texture coordinate is not finite");
        uvs = grow(uvs, 2 * uvCount + 2);
        uvs[2 * uvCount] = u;
        uvs[2 * uvCount + 1] = v;
        uvCount++;
    }

    void normal(double x, double y, double z, Object where) throws MeshProblem {
        if (!(Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z))) throw new MeshProblem(where + "normal is not finite");
        normals = grow(normals, 3 * normalCount + 3);
        normals[3 * normalCount] = x;
        normals[3 * normalCount + 1] = y;
        normals[3 * normalCount + 2] = z;
        normalCount++;
    }

    /**
     * A polygon of {@code n} corners (position, uv, normal index triples in {@code c}, −1 for an
     * absent uv or normal), fanned from its first corner. Indices are checked against what has been
     * read so far. {@code where} names the place in the file; it becomes text only for a problem.
     */
    void polygon(int[] c, int n, Object where) throws MeshProblem {
        if (n < 3) throw new MeshProblem(where + "a face needs at least 3 vertices, got " + n);
        for (int i = 0; i < n; i++) {
            check(c[3 * i], positionCount, "vertex", where);
            if (c[3 * i + 1] != -1) check(c[3 * i + 1], uvCount, "texture coordinate", where);
            if (c[3 * i + 2] != -1) check(c[3 * i + 2], normalCount, "normal", where);
        }
        for (int i = 1; i + 1 < n; i++) {
            corners = grow(corners, cornerCount + 9);
            corner(c, 0);
            corner(c, i);
            corner(c, i + 1);
        }
    }

    private void corner(int[] c, int k) {
        corners[cornerCount++] = c[3 * k];
        corners[cornerCount++] = c[3 * k + 1];
        corners[cornerCount++] = c[3 * k + 2];
    }

    private static void check(int index, int count, String what, Object where) throws MeshProblem {
        if (index < 0 || index >= count) {
            String plural = what.equals("vertex") ? "vertices" : what + "s";
            throw new MeshProblem(where + what + " " + index + " does not exist (there " + (count == 1 ? "is 1 " + what
                    : "are " + count + " " + plural) + " before it, numbered from 0)");
        }
    }

    private static double[] grow(double[] a, int needed) {
        if (needed <= a.length) return a;
        if (needed > Integer.MAX_VALUE - 16) throw new OutOfMemoryError("mesh too large");
        return Arrays.copyOf(a, Math.max(needed, (int) Math.min(Integer.MAX_VALUE - 16, 2L * a.length)));
    }

    private static int[] grow(int[] a, int needed) {
        if (needed <= a.length) return a;
        return Arrays.copyOf(a, Math.max(needed, (int) Math.min(Integer.MAX_VALUE - 16, 2L * a.length)));
    }

    private record Corner(int position, int uv, int normal) {}

    MeshData finish(String name) throws MeshProblem {
        int triangles = cornerCount / 9;
        if (triangles == 0) throw new MeshProblem("the mesh has no faces");
        boolean closed = closed(triangles);
        // Area-weighted normals per position: the cross product's length is twice the area.
        double[] smooth = new double[3 * positionCount];
        for (int t = 0; t < triangles; t++) {
            int a = corners[9 * t], b = corners[9 * t + 3], c = corners[9 * t + 6];
            double ux = positions[3 * b] - positions[3 * a], uy = positions[3 * b + 1] - positions[3 * a + 1];
            double uz = positions[3 * b + 2] - positions[3 * a + 2];
            double vx = positions[3 * c] - positions[3 * a], vy = positions[3 * c + 1] - positions[3 * a + 1];
            double vz = positions[3 * c + 2] - positions[3 * a + 2];
            double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
            smooth[3 * a] += nx;
            smooth[3 * a + 1] += ny;
            smooth[3 * a + 2] += nz;
            smooth[3 * b] += nx;
            smooth[3 * b + 1] += ny;
            smooth[3 * b + 2] += nz;
            smooth[3 * c] += nx;
            smooth[3 * c + 1] += ny;
            smooth[3 * c + 2] += nz;
        }
        boolean simple = true;
        for (int i = 0; i < cornerCount; i += 3) simple &= corners[i + 1] < 0 && corners[i + 2] < 0;
        if (simple) return finishSimple(name, triangles, smooth, closed);
        boolean anyUv = false;
        for (int i = 0; i < cornerCount; i += 3) anyUv |= corners[i + 1] >= 0;
        // One vertex per distinct corner triple.
        Map<Corner, Integer> vertexOf = new HashMap<>();
        double[] outPositions = new double[3 * Math.max(positionCount, 1)];
        double[] outNormals = new double[3 * Math.max(positionCount, 1)];
        double[] outUvs = anyUv ? new double[2 * Math.max(positionCount, 1)] : null;
        int[] outTriangles = new int[3 * triangles];
        int vertices = 0;
        for (int k = 0; k < 3 * triangles; k++) {
            int p = corners[3 * k], uv = corners[3 * k + 1], n = corners[3 * k + 2];
            Corner key = new Corner(p, uv, n);
            Integer found = vertexOf.get(key);
            if (found != null) {
                outTriangles[k] = found;
                continue;
            }
            int v = vertices++;
            vertexOf.put(key, v);
            outTriangles[k] = v;
            if (3 * v + 3 > outPositions.length) {
                int size = Math.max(3 * v + 3, outPositions.length * 2);
                outPositions = Arrays.copyOf(outPositions, size);
                outNormals = Arrays.copyOf(outNormals, size);
                if (outUvs != null) outUvs = Arrays.copyOf(outUvs, size / 3 * 2);
            }
            System.arraycopy(positions, 3 * p, outPositions, 3 * v, 3);
            double nx, ny, nz;
            if (n >= 0) {
                nx = normals[3 * n];
                ny = normals[3 * n + 1];
                nz = normals[3 * n + 2];
            } else {
                nx = smooth[3 * p];
                ny = smooth[3 * p + 1];
                nz = smooth[3 * p + 2];
            }
            double l = Math.sqrt(nx * nx + ny * ny + nz * nz);
            outNormals[3 * v] = l > 0 ? nx / l : 0;
            outNormals[3 * v + 1] = l > 0 ? ny / l : 0;
            outNormals[3 * v + 2] = l > 0 ? nz / l : 0;
            if (outUvs != null && uv >= 0) {
                outUvs[2 * v] = uvs[2 * uv];
                outUvs[2 * v + 1] = uvs[2 * uv + 1];
            }
        }
        return new MeshData(name, Arrays.copyOf(outPositions, 3 * vertices), outTriangles,
                Arrays.copyOf(outNormals, 3 * vertices), outUvs == null ? null : Arrays.copyOf(outUvs, 2 * vertices), closed);
    }

    /**
     * {@link #finish} for a mesh of positions alone (no uv, no normal given: most large files): a
     * vertex per position, each written once rather than once per corner using it. A position no
     * triangle uses stays at the origin with a zero normal, as in the general case.
     */
    private MeshData finishSimple(String name, int triangles, double[] smooth, boolean closed) {
        int[] outTriangles = new int[3 * triangles];
        boolean[] used = new boolean[positionCount];
        for (int k = 0; k < 3 * triangles; k++) {
            int p = corners[3 * k];
            outTriangles[k] = p;
            used[p] = true;
        }
        double[] outPositions = new double[3 * positionCount];
        double[] outNormals = new double[3 * positionCount];
        for (int p = 0; p < positionCount; p++) {
            if (!used[p]) continue;
            outPositions[3 * p] = positions[3 * p];
            outPositions[3 * p + 1] = positions[3 * p + 1];
            outPositions[3 * p + 2] = positions[3 * p + 2];
            double nx = smooth[3 * p], ny = smooth[3 * p + 1], nz = smooth[3 * p + 2];
            double l = Math.sqrt(nx * nx + ny * ny + nz * nz);
            outNormals[3 * p] = l > 0 ? nx / l : 0;
            outNormals[3 * p + 1] = l > 0 ? ny / l : 0;
            outNormals[3 * p + 2] = l > 0 ? nz / l : 0;
        }
        return new MeshData(name, outPositions, outTriangles, outNormals, null, closed);
    }

    /**
     * Every edge (by positions, either direction) is used by exactly two triangles. The edges are
     * grouped by their lower position (a counting sort), and each position's few higher ends are
     * sorted in place: linear in the triangles, where sorting all 3·triangles edges was the largest
     * part of loading a million-triangle mesh.
     */
    private boolean closed(int triangles) {
        int[] start = new int[positionCount + 2];
        for (int k = 0; k < 3 * triangles; k++) {
            int a = corners[3 * k], b = corners[3 * (k % 3 == 2 ? k - 2 : k + 1)];
            start[Math.min(a, b) + 2]++;
        }
        for (int v = 2; v < start.length; v++) start[v] += start[v - 1];
        int[] higher = new int[3 * triangles];
        for (int k = 0; k < 3 * triangles; k++) {
            int a = corners[3 * k], b = corners[3 * (k % 3 == 2 ? k - 2 : k + 1)];
            higher[start[Math.min(a, b) + 1]++] = Math.max(a, b);
        }
        // start[v] … start[v + 1] now holds the higher ends of the edges whose lower end is v.
        for (int v = 0; v < positionCount; v++) {
            int from = start[v], to = start[v + 1];
            if (((to - from) & 1) != 0) return false;
            Arrays.sort(higher, from, to);
            for (int i = from; i < to; i += 2) {
                if (higher[i] != higher[i + 1] || i + 2 < to && higher[i + 2] == higher[i]) return false;
            }
        }
        return true;
    }
}
