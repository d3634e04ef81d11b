package dev.crt.scene;

/**
 * The triangles of a mesh as loaded once and shared by every instance of it: vertex positions
 * (x, y, z per vertex), triangles (three vertex indices each, counter-clockwise seen from outside
 * when the file is consistently wound), and optionally per-vertex normals and texture
 * coordinates (u, v). {@code closed} when every edge is shared by exactly two triangles, which
 * makes the mesh a solid. Arrays are never modified after loading.
 */
public record MeshData(String name, double[] positions, int[] triangles, double[] normals, double[] uvs,
        boolean closed) {
    public int vertexCount() { return positions.length / 3; }

    public int triangleCount() { return triangles.length / 3; }
}
