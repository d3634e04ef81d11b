package dev.crt.live;

import dev.crt.geom.Aabb;
import dev.crt.scene.Background;
import dev.crt.scene.Camera;

/**
 * A scene flattened for the GPU by {@link SceneConverter}: one float array of vec4 texels holding
 * every top-level entity (a header, its CSG program and its primitives), the instance lists that
 * draw them, the lights as uniform arrays, and what the background and camera need.
 *
 * <p>Layout of an entity at texel {@code o}: {@code o} = (leaves, program length, entity index,
 * scale), {@code o+1} = (bounds min, 0; or 1 when unbounded, 2 for a plane alone), {@code o+2} =
 * (bounds max, 0; the plane's world normal and offset for a plane alone), then one texel per
 * program step (opcode, leaf, and two floats of the truth table, see {@link #TABLE_LEAVES}) in
 * postfix order, then {@link #LEAF_TEXELS} texels per primitive: (kind, parameters), three rows of the world-to-local matrix (a plane keeps its
 * world normal and offset in the first), local box min and max (a cone: its length, then 0),
 * (colour, diffuse), (specular, shininess, transparency, reflectivity), (emission, 0).
 * Parameters: a cone's (r0, r1, capped), a torus's (major, minor, 0), zeros otherwise.
 *
 * <p>A mesh leaf: (MESH, smooth with vertex normals, vertex base, index base), the three matrix
 * rows, (triangles, closed, vertices, 0), (node base + 1 of its hierarchy in {@link #meshNodes}, or
 * 0 for a mesh of at most {@link #MESH_CAST_LIMIT} triangles, 0, 0, 0), the material. Its vertices (and then its
 * normals) are texels of the mesh vertex buffer from the vertex base, its triangles three indices
 * each in the index buffer from the index base: the buffers hold {@link #meshes} one after the
 * other. A top-level mesh is rasterised (one draw per {@link #meshInstances} entry, its triangle
 * numbers kept per pixel for shading); a mesh inside CSG, and any mesh in shadow rays, is ray-cast
 * in the shader: triangle by triangle up to {@link #MESH_CAST_LIMIT} triangles, through its
 * hierarchy above that, up to {@link #MESH_BVH_LIMIT} (larger ones cast no shadows and are refused in CSG).
 */
public final class GpuScene {
    public static final int HEADER_TEXELS = 3;
    public static final int LEAF_TEXELS = 9;
    /** Primitive kinds as the shader reads them. */
    public static final int SPHERE = 0, BOX = 1, PLANE = 2, EMPTY = 3, CONE = 4, TORUS = 5, MESH = 6;
    /** Triangles up to which a mesh is ray-cast triangle by triangle in the shader (inside CSG, and for shadow rays); larger ones through a hierarchy. */
    public static final int MESH_CAST_LIMIT = 256;
    /**
     * Triangles up to which a larger mesh gets a hierarchy ({@link MeshBvh}; its first build takes
     * about a second at 240,000 triangles, on the thread that sets the scene): meshes beyond it are
     * rasterised only, cast no shadows and are refused inside CSG.
     */
    public static final int MESH_BVH_LIMIT = 100_000;
    /**
     * Entities of up to this many primitives also carry their CSG program as a truth table (2^n
     * entries, sixteen to a float in the z and w of the program texels, which a program of 2n − 1
     * steps has room for).
     */
    public static final int TABLE_LEAVES = 8;
    /** Program opcodes as the shader reads them. */
    public static final int OP_LEAF = 0, OP_UNION = 1, OP_INTERSECTION = 2, OP_DIFFERENCE = 3;
    /** The shader's limits: primitives per top-level entity (a 32-bit inside mask) and lights. */
    public static final int MAX_LEAVES = 32, MAX_LIGHTS = 16;
    /** Light kinds as the shader reads them. */
    public static final int POINT_LIGHT = 0, PARALLEL_LIGHT = 1, SPOT_LIGHT = 2, AREA_LIGHT = 3;
    /** Floats per light: four vec4. */
    public static final int LIGHT_FLOATS = 16;

    final float[] data;
    final int texels;
    /** Texel offset of each top-level entity's header, by entity index. */
    final int[] entityOffset;
    /** World bounds of each top-level entity (infinite for those reaching a plane's half-space, empty when nothing shows). */
    final Aabb[] entityBounds;
    /** Bounded entities: their header offsets and boxes (min xyz, max xyz) for the proxy cubes. */
    final int[] boundedOffsets;
    final float[] boundedBoxes;
    /** How many of the bounded entities, listed first, are a single primitive (drawn without the CSG walk). */
    final int boundedPrimitives;
    /** Entities with infinite bounds, drawn by a full-screen pass. */
    final int[] unboundedOffsets;
    /** How many of the unbounded entities, listed first, are a single primitive. */
    final int unboundedPrimitives;
    /** Whether every entity has its CSG truth table (none has more than {@link #TABLE_LEAVES} primitives). */
    final boolean tables;
    /** Whether some material reflects or is transparent (its shading looks the background up). */
    final boolean seesBackground;
    /**
     * Per light four vec4: (kind, position or direction towards the light), (colour, ambient),
     * (falloff, cos angle, cos innerangle, 0), (spot axis or area normal, 0).
     */
    final float[] lights;
    final int lightCount;
    final Background background;
    final double gamma;
    final Camera camera;
    final Aabb bounds;
    /**
     * The primitive kinds present, one bit per kind: the shaders compile the cone and torus code
     * only for scenes that have them (llvmpipe pays for every branch on every pixel).
     */
    final int kinds;
    /** The distinct meshes, in the order their vertices and indices lie in the mesh buffers. */
    final java.util.List<dev.crt.scene.MeshData> meshes;
    /** Each of {@link #meshes}' triangles as the index buffer holds them: in its hierarchy's leaf order when it has one. */
    final java.util.List<int[]> meshTriangles;
    /** The node texels of the meshes' hierarchies ({@link MeshBvh}), one after the other. */
    final float[] meshNodes;
    /** Texels of vertex data (positions, then normals when smooth) and indices of all {@link #meshes}. */
    final int meshVertexTexels, meshIndexCount;
    /** Top-level meshes: per instance (entity header offset, leaf address, vertex base, index base, triangles). */
    final int[] meshInstances;
    /** Per mesh instance its mesh-to-world matrix, three rows of four. */
    final float[] meshMatrices;

    GpuScene(float[] data, int texels, int[] entityOffset, Aabb[] entityBounds, int[] boundedOffsets,
            float[] boundedBoxes, int boundedPrimitives, int[] unboundedOffsets, int unboundedPrimitives, boolean tables,
            boolean seesBackground, float[] lights, int lightCount, Background background,
            double gamma, Camera camera, Aabb bounds, int kinds, java.util.List<dev.crt.scene.MeshData> meshes,
            java.util.List<int[]> meshTriangles, float[] meshNodes, int meshVertexTexels, int meshIndexCount, int[] meshInstances, float[] meshMatrices) {
        this.data = data;
        this.texels = texels;
        this.entityOffset = entityOffset;
        this.entityBounds = entityBounds;
        this.boundedOffsets = boundedOffsets;
        this.boundedBoxes = boundedBoxes;
        this.boundedPrimitives = boundedPrimitives;
        this.unboundedOffsets = unboundedOffsets;
        this.unboundedPrimitives = unboundedPrimitives;
        this.tables = tables;
        this.seesBackground = seesBackground;
        this.lights = lights;
        this.lightCount = lightCount;
        this.background = background;
        this.gamma = gamma;
        this.camera = camera;
        this.bounds = bounds;
        this.kinds = kinds;
        this.meshes = java.util.List.copyOf(meshes);
        this.meshTriangles = java.util.List.copyOf(meshTriangles);
        this.meshNodes = meshNodes;
        this.meshVertexTexels = meshVertexTexels;
        this.meshIndexCount = meshIndexCount;
        this.meshInstances = meshInstances;
        this.meshMatrices = meshMatrices;
    }

    /** Floats per mesh instance in {@link #meshInstances}. */
    static final int MESH_INSTANCE_INTS = 5;

    /** Number of top-level entities. */
    public int entityCount() { return entityOffset.length; }

    /** World bounds of top-level entity {@code i}. */
    public Aabb entityBounds(int i) { return entityBounds[i]; }

    /** The union of the finite bounds of every entity (empty when there is none). */
    public Aabb bounds() { return bounds; }

    /** The scene's own camera. */
    public Camera camera() { return camera; }

    /** The texels as floats, four per texel (a copy). */
    public float[] texelData() { return java.util.Arrays.copyOf(data, texels * 4); }
}
