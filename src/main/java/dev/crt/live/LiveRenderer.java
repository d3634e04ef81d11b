package dev.crt.live;

import static org.lwjgl.opengl.GL33.*;

import dev.crt.image.IdColors;
import dev.crt.scene.Background;
import dev.crt.scene.GradientBackground;
import dev.crt.scene.PanoramaBackground;
import dev.crt.scene.Picture;
import dev.crt.scene.SolidBackground;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import java.nio.charset.StandardCharsets;
import org.lwjgl.BufferUtils;

/**
 * Draws a {@link GpuScene} into offscreen framebuffers in two passes: geometry (one proxy box per
 * bounded entity and a full-screen triangle per unbounded one, each fragment ray-casting its
 * entity exactly and keeping entity id, distance along the ray and primitive), then shading once
 * per pixel (background, lights, shadow rays, highlights, grid). The same object serves
 * the live view panel, {@code crt preview} and the tests. Every call must come from the thread the
 * {@link GlContext} is current on.
 */
public final class LiveRenderer implements AutoCloseable {
    /** Shadow rays test the scene's entities only when it has at most this many (they cost a loop over all of them). */
    public static final int SHADOW_ENTITY_LIMIT = 256;
    /** Lights that cast shadows: the first ones of the scene. */
    public static final int SHADOW_LIGHTS = 4;

    /** Geometry programs for one-primitive entities and for CSG entities, compiled when first needed. */
    /** Geometry programs by their defines (one-primitive or CSG, the primitive kinds compiled in). */
    private final java.util.Map<String, Integer> geometryPrograms = new java.util.HashMap<>();
    /**
     * Shading and background programs by their variant (background kind, grid, shadows), compiled
     * when first needed: llvmpipe runs every branch for every pixel, so what a frame does not use
     * is left out of its programs rather than skipped at run time.
     */
    private final java.util.Map<String, Integer> shadePrograms = new java.util.HashMap<>();
    private final String common;
    private final int cubeVao, cubeVbo, instanceVbo, csgVao, csgInstanceVbo, fullVao, fullInstanceVbo;
    /** Proxy boxes of CSG entities (csgVao); those of one-primitive entities (cubeVao) are counted by kind. */
    private int csgInstances;
    private final int sceneBuffer, sceneTexture, directoryBuffer, directoryTexture;
    /** The meshes' vertices and triangles: vertex and index buffers of the rasterised draws and texture buffers of the shaders. */
    private final int meshVao, meshVertexBuffer, meshIndexBuffer, meshVertexTexture, meshIndexTexture;
    /** The meshes' hierarchies (MeshBvh nodes), a texture buffer of the shaders. */
    private final int meshNodeBuffer, meshNodeTexture;
    private java.util.List<dev.crt.scene.MeshData> uploadedMeshes = java.util.List.of();
    private int panoramaTexture;
    /** The geometry pass's framebuffer (id, distance, primitive address, depth) and the shaded colour's. */
    private int framebuffer, colourFramebuffer, colourTexture, idTexture, depthTexture, leafTexture, faceTexture, depthBuffer;
    private int width, height;
    private GpuScene scene;
    private float[] uploaded = new float[0];
    private int uploadedTexels;
    private long uploadedFloats;
    private Picture uploadedPanorama;

    /** Compiles the shaders and makes the buffers; the context must be current. */
    public LiveRenderer() {
        common = resource("common.glsl") + resource("scene.glsl");

        cubeVao = glGenVertexArrays();
        glBindVertexArray(cubeVao);
        cubeVbo = glGenBuffers();
        glBindBuffer(GL_ARRAY_BUFFER, cubeVbo);
        glBufferData(GL_ARRAY_BUFFER, cube(), GL_STATIC_DRAW);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, false, 12, 0);
        instanceVbo = glGenBuffers();
        glBindBuffer(GL_ARRAY_BUFFER, instanceVbo);
        instanceAttributes(0);

        csgVao = glGenVertexArrays();
        glBindVertexArray(csgVao);
        glBindBuffer(GL_ARRAY_BUFFER, cubeVbo);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, false, 12, 0);
        csgInstanceVbo = glGenBuffers();
        glBindBuffer(GL_ARRAY_BUFFER, csgInstanceVbo);
        instanceAttributes(0);

        fullVao = glGenVertexArrays();
        glBindVertexArray(fullVao);
        fullInstanceVbo = glGenBuffers();
        glBindBuffer(GL_ARRAY_BUFFER, fullInstanceVbo);
        instanceAttributes(0);
        glBindVertexArray(0);

        sceneBuffer = glGenBuffers();
        sceneTexture = glGenTextures();
        directoryBuffer = glGenBuffers();
        directoryTexture = glGenTextures();
        panoramaTexture = glGenTextures();

        meshVao = glGenVertexArrays();
        glBindVertexArray(meshVao);
        meshVertexBuffer = glGenBuffers();
        glBindBuffer(GL_ARRAY_BUFFER, meshVertexBuffer);
        glBufferData(GL_ARRAY_BUFFER, 16, GL_STATIC_DRAW);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 4, GL_FLOAT, false, 16, 0);
        meshIndexBuffer = glGenBuffers();
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, meshIndexBuffer);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, 4, GL_STATIC_DRAW);
        glBindVertexArray(0);
        meshVertexTexture = glGenTextures();
        glBindTexture(GL_TEXTURE_BUFFER, meshVertexTexture);
        glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, meshVertexBuffer);
        meshIndexTexture = glGenTextures();
        glBindTexture(GL_TEXTURE_BUFFER, meshIndexTexture);
        glTexBuffer(GL_TEXTURE_BUFFER, GL_R32I, meshIndexBuffer);
        meshNodeBuffer = glGenBuffers();
        glBindBuffer(GL_TEXTURE_BUFFER, meshNodeBuffer);
        glBufferData(GL_TEXTURE_BUFFER, 16, GL_STATIC_DRAW);
        meshNodeTexture = glGenTextures();
        glBindTexture(GL_TEXTURE_BUFFER, meshNodeTexture);
        glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, meshNodeBuffer);
        check("creating the renderer");
    }

    /**
     * The shaders' defines: the background kind, the cone, torus and mesh code only where the scene
     * has them, CSG by truth tables where every entity has one, the background seen in mirrors and
     * glass only where there are some, gamma only when it is not 1.
     */
    private String header(int backgroundKind) {
        return "#version 330 core\n#define BACKGROUND_KIND " + backgroundKind + "\n"
                + ((scene.kinds & 1 << GpuScene.CONE) != 0 ? "#define HAS_CONE\n" : "")
                + ((scene.kinds & 1 << GpuScene.TORUS) != 0 ? "#define HAS_TORUS\n" : "")
                + (scene.tables ? "#define CSG_TABLE\n" : "")
                + (scene.seesBackground ? "#define SEES_BACKGROUND\n" : "")
                + (scene.gamma == 1 ? "#define LINEAR_OUTPUT\n" : "")
                + ((scene.kinds & 1 << GpuScene.MESH) != 0
                        ? "#define HAS_MESH\n#define MESH_CAST_LIMIT " + GpuScene.MESH_CAST_LIMIT + "\n" : "")
                + (scene.meshNodes.length > 0 ? "#define HAS_MESH_BVH\n#define MESH_BVH_DEPTH " + MeshBvh.MAX_DEPTH + "\n" : "");
    }

    /** The geometry program for one-primitive entities of {@code kind} ({@code primitives}) or for CSG entities. */
    private int geometryProgram(boolean primitives, int kind) {
        String defines = header(0) + (primitives ? "#define PRIMITIVES\n#define ONE_KIND " + kind + "\n" : "");
        return geometryPrograms.computeIfAbsent(defines,
                d -> program(d + resource("entity.vert"), d + common + resource("entity.frag")));
    }

    private int meshProgram() {
        String defines = header(0);
        return geometryPrograms.computeIfAbsent("mesh\n" + defines,
                d -> program(resource("mesh.vert"), defines + common + resource("mesh.frag")));
    }

    private int shadeProgram(int kind, boolean background, boolean grid, boolean shadows) {
        String defines = header(kind) + (background ? "#define BACKGROUND\n" : "") + (grid ? "#define GRID\n" : "")
                + (shadows ? "#define SHADOWS\n" : "");
        return shadePrograms.computeIfAbsent(defines,
                d -> program(resource("fullscreen.vert"), d + common + resource("shade.frag")));
    }

    private int backgroundKind() {
        Background bg = scene.background;
        if (bg instanceof SolidBackground) return 0;
        if (bg instanceof GradientBackground) return 1;
        if (bg instanceof PanoramaBackground) return 2;
        throw new UnsupportedSceneException("the live view cannot show a " + bg.getClass().getSimpleName() + " yet");
    }

    /** Per instance, from byte {@code from} of the bound buffer: box min (3 floats), box max (3 floats), header offset (1 int); 28 bytes. */
    private static void instanceAttributes(long from) {
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 3, GL_FLOAT, false, 28, from);
        glVertexAttribDivisor(1, 1);
        glEnableVertexAttribArray(2);
        glVertexAttribPointer(2, 3, GL_FLOAT, false, 28, from + 12);
        glVertexAttribDivisor(2, 1);
        glEnableVertexAttribArray(3);
        glVertexAttribIPointer(3, 1, GL_INT, 28, from + 24);
        glVertexAttribDivisor(3, 1);
    }

    /** The twelve triangles of the unit cube, wound counter-clockwise seen from outside. */
    private static FloatBuffer cube() {
        int[][] faces = {
            {0, 2, 6, 4}, {1, 5, 7, 3}, // x = 0, x = 1
            {0, 4, 5, 1}, {2, 3, 7, 6}, // y = 0, y = 1
            {0, 1, 3, 2}, {4, 6, 7, 5}, // z = 0, z = 1
        };
        FloatBuffer b = BufferUtils.createFloatBuffer(36 * 3);
        for (int[] f : faces) {
            for (int k : new int[] {f[0], f[1], f[2], f[0], f[2], f[3]}) {
                b.put(k & 1).put((k >> 1) & 1).put((k >> 2) & 1);
            }
        }
        return b.flip();
    }

    /**
     * Makes {@code next} the scene drawn. Only the texels that differ from what the GPU holds are
     * sent (one range from the first difference to the last), and nothing when the scene's data
     * are unchanged; a panorama is re-sent only when it is another picture.
     */
    public void setScene(GpuScene next) {
        float[] data = next.data;
        int floats = next.texels * 4;
        if (floats > uploadedFloats) {
            long capacity = Math.max(1024, Math.max(floats, uploadedFloats * 2));
            glBindBuffer(GL_TEXTURE_BUFFER, sceneBuffer);
            glBufferData(GL_TEXTURE_BUFFER, capacity * 4, GL_DYNAMIC_DRAW);
            uploadedFloats = capacity;
            uploadedTexels = 0;
            glBindTexture(GL_TEXTURE_BUFFER, sceneTexture);
            glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, sceneBuffer);
        }
        int limit = uploadedTexels == next.texels ? floats : Math.min(floats, uploadedTexels * 4);
        int first = 0;
        while (first < limit && Float.floatToRawIntBits(data[first]) == Float.floatToRawIntBits(uploaded[first])) first++;
        int last = floats;
        if (limit == floats) {
            while (last > first && Float.floatToRawIntBits(data[last - 1]) == Float.floatToRawIntBits(uploaded[last - 1])) last--;
        }
        if (last > first) {
            glBindBuffer(GL_TEXTURE_BUFFER, sceneBuffer);
            FloatBuffer range = BufferUtils.createFloatBuffer(last - first);
            range.put(data, first, last - first).flip();
            glBufferSubData(GL_TEXTURE_BUFFER, 4L * first, range);
        }
        lastUploadFloats = Math.max(0, last - first);
        uploaded = java.util.Arrays.copyOf(data, floats);
        uploadedTexels = next.texels;

        IntBuffer directory = BufferUtils.createIntBuffer(Math.max(1, next.entityOffset.length));
        directory.put(next.entityOffset).flip();
        glBindBuffer(GL_TEXTURE_BUFFER, directoryBuffer);
        glBufferData(GL_TEXTURE_BUFFER, directory, GL_DYNAMIC_DRAW);
        glBindTexture(GL_TEXTURE_BUFFER, directoryTexture);
        glTexBuffer(GL_TEXTURE_BUFFER, GL_R32I, directoryBuffer);

        glBindBuffer(GL_ARRAY_BUFFER, instanceVbo);
        glBufferData(GL_ARRAY_BUFFER, instancesByKind(next, next.boundedBoxes, next.boundedOffsets, next.boundedPrimitives,
                boundedKindStart), GL_DYNAMIC_DRAW);
        glBindBuffer(GL_ARRAY_BUFFER, csgInstanceVbo);
        glBufferData(GL_ARRAY_BUFFER, instances(next.boundedBoxes, next.boundedOffsets, next.boundedPrimitives,
                next.boundedOffsets.length), GL_DYNAMIC_DRAW);
        csgInstances = next.boundedOffsets.length - next.boundedPrimitives;
        glBindBuffer(GL_ARRAY_BUFFER, fullInstanceVbo);
        float[] noBoxes = new float[6 * next.unboundedOffsets.length];
        int nu = next.unboundedOffsets.length, nup = next.unboundedPrimitives;
        ByteBuffer unbounded = BufferUtils.createByteBuffer(Math.max(28, 28 * nu));
        unbounded.put(instancesByKind(next, noBoxes, next.unboundedOffsets, nup, unboundedKindStart).limit(28 * nup));
        unbounded.put(instances(noBoxes, next.unboundedOffsets, nup, nu).limit(28 * (nu - nup)));
        glBufferData(GL_ARRAY_BUFFER, unbounded.position(0).limit(unbounded.capacity()), GL_DYNAMIC_DRAW);

        if (!sameMeshes(next.meshes, uploadedMeshes)) {
            uploadMeshes(next);
            uploadedMeshes = next.meshes;
        }

        if (next.background instanceof PanoramaBackground p && p.image() != uploadedPanorama) {
            uploadPanorama(p.image(), next.gamma);
            uploadedPanorama = p.image();
        }
        scene = next;
        check("uploading the scene");
    }

    private long lastUploadFloats;

    private static boolean sameMeshes(java.util.List<dev.crt.scene.MeshData> a, java.util.List<dev.crt.scene.MeshData> b) {
        if (a.size() != b.size()) return false;
        for (int i = 0; i < a.size(); i++) if (a.get(i) != b.get(i)) return false;
        return true;
    }

    /** Sends every mesh of {@code next} in the layout the converter gave: vertex texels (positions, then normals), indices. */
    private void uploadMeshes(GpuScene next) {
        FloatBuffer vertices = BufferUtils.createFloatBuffer(4 * Math.max(1, next.meshVertexTexels));
        IntBuffer indices = BufferUtils.createIntBuffer(Math.max(1, next.meshIndexCount));
        for (int i = 0; i < next.meshes.size(); i++) {
            dev.crt.scene.MeshData m = next.meshes.get(i);
            putTexels(vertices, m.positions());
            if (m.normals() != null) putTexels(vertices, m.normals());
            indices.put(next.meshTriangles.get(i));
        }
        vertices.position(0).limit(vertices.capacity());
        indices.position(0).limit(indices.capacity());
        glBindBuffer(GL_ARRAY_BUFFER, meshVertexBuffer);
        glBufferData(GL_ARRAY_BUFFER, vertices, GL_STATIC_DRAW);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        glBindVertexArray(meshVao);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, meshIndexBuffer);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, indices, GL_STATIC_DRAW);
        glBindVertexArray(0);
        FloatBuffer nodes = BufferUtils.createFloatBuffer(Math.max(4, next.meshNodes.length));
        nodes.put(next.meshNodes).position(0);
        glBindBuffer(GL_TEXTURE_BUFFER, meshNodeBuffer);
        glBufferData(GL_TEXTURE_BUFFER, nodes, GL_STATIC_DRAW);
        lastUploadFloats += 4L * next.meshVertexTexels + next.meshIndexCount + next.meshNodes.length;
    }

    private static void putTexels(FloatBuffer out, double[] xyz) {
        for (int i = 0; i < xyz.length; i += 3) out.put((float) xyz[i]).put((float) xyz[i + 1]).put((float) xyz[i + 2]).put(0f);
    }

    /** How many floats the last {@link #setScene} sent to the GPU (for tests and benchmarks). */
    public long lastUploadFloats() { return lastUploadFloats; }

    /**
     * Where each primitive kind's instances start among the one-primitive entities, bounded and
     * unbounded (entry {@code KINDS} is the end): each kind is drawn by a program with only
     * its own intersection code, since llvmpipe runs every kind's code for every pixel otherwise.
     */
    private final int[] boundedKindStart = new int[KINDS + 1], unboundedKindStart = new int[KINDS + 1];
    private static final int KINDS = GpuScene.MESH + 1;

    /** Instance records of the one-primitive entities [0, count) ordered by kind, the kinds' starts into {@code start}. */
    private static ByteBuffer instancesByKind(GpuScene g, float[] boxes, int[] offsets, int count, int[] start) {
        java.util.Arrays.fill(start, 0);
        int[] kind = new int[count];
        for (int i = 0; i < count; i++) {
            kind[i] = (int) g.data[4 * (offsets[i] + GpuScene.HEADER_TEXELS + 1)];
            start[kind[i] + 1]++;
        }
        for (int k = 0; k < KINDS; k++) start[k + 1] += start[k];
        int[] next = java.util.Arrays.copyOf(start, KINDS);
        ByteBuffer b = BufferUtils.createByteBuffer(Math.max(28, 28 * count));
        for (int i = 0; i < count; i++) {
            b.position(28 * next[kind[i]]++);
            for (int k = 0; k < 6; k++) b.putFloat(boxes[6 * i + k]);
            b.putInt(offsets[i]);
        }
        return b.position(0).limit(Math.max(28, 28 * count));
    }

    /** Instance records (box min, box max, header offset) of entries [from, to). */
    private static ByteBuffer instances(float[] boxes, int[] offsets, int from, int to) {
        int n = to - from;
        ByteBuffer b = BufferUtils.createByteBuffer(Math.max(28, 28 * n));
        for (int i = from; i < to; i++) {
            for (int k = 0; k < 6; k++) b.putFloat(boxes[6 * i + k]);
            b.putInt(offsets[i]);
        }
        return b.position(0).limit(Math.max(28, 28 * n));
    }

    private void uploadPanorama(Picture pic, double gamma) {
        FloatBuffer texels = BufferUtils.createFloatBuffer(pic.width() * pic.height() * 3);
        int[] codes = pic.codes();
        if (codes != null) {
            float[] value = new float[256];
            for (int k = 0; k < 256; k++) value[k] = gamma != 1 ? (float) srgbToLinear(k / 255f) : k / 255f;
            for (int p : codes) texels.put(value[p >> 16 & 0xFF]).put(value[p >> 8 & 0xFF]).put(value[p & 0xFF]);
        } else {
            for (float v : pic.floats()) texels.put(gamma != 1 ? (float) srgbToLinear(v) : v);
        }
        texels.flip();
        glBindTexture(GL_TEXTURE_2D, panoramaTexture);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, pic.width(), pic.height(), 0, GL_RGB, GL_FLOAT, texels);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }

    private static double srgbToLinear(double v) {
        return v <= 0.04045 ? v / 12.92 : Math.pow((v + 0.055) / 1.055, 2.4);
    }

    /** What a frame shows besides the scene. */
    public record Overlay(int selected, int hovered, boolean grid, double gridSpacing, int gridAxis) {
        public static final Overlay NONE = new Overlay(-1, -1, false, 1, 1);
    }

    /** Sizes the offscreen framebuffers (ids R32I, distances R32F, primitive addresses R32I; colour RGBA8) to {@code w × h}. */
    public void resize(int w, int h) {
        if (w == width && h == height && framebuffer != 0) return;
        deleteFramebuffers();
        width = w;
        height = h;
        framebuffer = glGenFramebuffers();
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        idTexture = attachment(GL_R32I, GL_RED_INTEGER, GL_INT, GL_COLOR_ATTACHMENT0);
        depthTexture = attachment(GL_R32F, GL_RED, GL_FLOAT, GL_COLOR_ATTACHMENT1);
        leafTexture = attachment(GL_R32I, GL_RED_INTEGER, GL_INT, GL_COLOR_ATTACHMENT2);
        faceTexture = attachment(GL_R32I, GL_RED_INTEGER, GL_INT, GL_COLOR_ATTACHMENT3);
        depthBuffer = glGenRenderbuffers();
        glBindRenderbuffer(GL_RENDERBUFFER, depthBuffer);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH32F_STENCIL8, w, h);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depthBuffer);
        glDrawBuffers(new int[] {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3});
        complete();
        colourFramebuffer = glGenFramebuffers();
        glBindFramebuffer(GL_FRAMEBUFFER, colourFramebuffer);
        colourTexture = attachment(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, GL_COLOR_ATTACHMENT0);
        // The same stencil: the shading pass reads which pixels the geometry pass hit.
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depthBuffer);
        glDrawBuffers(new int[] {GL_COLOR_ATTACHMENT0});
        complete();
    }

    private static void complete() {
        int status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        if (status != GL_FRAMEBUFFER_COMPLETE) {
            throw new IllegalStateException("the offscreen framebuffer is incomplete (0x" + Integer.toHexString(status) + ")");
        }
    }

    private void deleteFramebuffers() {
        if (framebuffer == 0) return;
        glDeleteFramebuffers(new int[] {framebuffer, colourFramebuffer});
        glDeleteTextures(new int[] {colourTexture, idTexture, depthTexture, leafTexture, faceTexture});
        glDeleteRenderbuffers(depthBuffer);
        framebuffer = 0;
    }

    private int attachment(int internal, int format, int type, int slot) {
        int t = glGenTextures();
        glBindTexture(GL_TEXTURE_2D, t);
        glTexImage2D(GL_TEXTURE_2D, 0, internal, width, height, 0, format, type, (ByteBuffer) null);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glFramebufferTexture2D(GL_FRAMEBUFFER, slot, GL_TEXTURE_2D, t, 0);
        return t;
    }

    /**
     * Clears the framebuffers before drawing one or more viewports: colour to the grey between
     * viewports, ids to background, distances to +∞. Whole-buffer clears, never scissored: llvmpipe
     * clears whole buffers cheaply and scissored ones pixel by pixel.
     */
    public void clear() {
        glDisable(GL_SCISSOR_TEST);
        glBindFramebuffer(GL_FRAMEBUFFER, colourFramebuffer);
        glClearBufferfv(GL_COLOR, 0, new float[] {0.2f, 0.2f, 0.2f, 1});
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        glClearBufferiv(GL_COLOR, 0, new int[] {0, 0, 0, 0});
        glClearBufferfv(GL_COLOR, 1, new float[] {Float.POSITIVE_INFINITY, 0, 0, 0});
        glClearBufferiv(GL_COLOR, 2, new int[] {0, 0, 0, 0});
        glStencilMask(0xFF);
        glClearBufferfi(GL_DEPTH_STENCIL, 0, 1, 0);
    }

    /**
     * Draws the scene through {@code view} into the viewport ({@code x}, {@code y} from the top
     * left, {@code w × h} pixels): the geometry pass (ids, distances) and the shading pass (colour).
     * Call {@link #clear} first, once for all the viewports of a frame.
     */
    public void draw(ViewCamera view, int x, int y, int w, int h, Overlay overlay) {
        if (scene == null) throw new IllegalStateException("no scene: call setScene first");
        int glY = height - y - h;
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        glViewport(x, glY, w, h);
        glEnable(GL_SCISSOR_TEST);
        glScissor(x, glY, w, h);

        // Geometry: every entity's proxy, ray-cast per fragment; the depth test keeps the nearest hit
        // and marks the pixel in the stencil buffer, so shading runs only where something was hit.
        glEnable(GL_STENCIL_TEST);
        glStencilMask(0xFF);
        glStencilFunc(GL_ALWAYS, 1, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glEnable(GL_DEPTH_CLAMP);
        int p;
        if (scene.boundedOffsets.length > 0) {
            // Back faces only: they cover every pixel whose ray meets the box, the camera inside it included.
            glEnable(GL_CULL_FACE);
            glCullFace(GL_FRONT);
            glFrontFace(frontFace(view));
            glBindVertexArray(cubeVao);
            glBindBuffer(GL_ARRAY_BUFFER, instanceVbo);
            drawByKind(boundedKindStart, 36, view, x, glY, w, h, overlay, false);
            if (csgInstances > 0) {
                useGeometryProgram(geometryProgram(false, -1), view, x, glY, w, h, overlay, false);
                glBindVertexArray(csgVao);
                glDrawArraysInstanced(GL_TRIANGLES, 0, 36, csgInstances);
            }
            glDisable(GL_CULL_FACE);
        }
        int unboundedPrimitives = scene.unboundedPrimitives, unboundedCsg = scene.unboundedOffsets.length - unboundedPrimitives;
        glBindVertexArray(fullVao);
        glBindBuffer(GL_ARRAY_BUFFER, fullInstanceVbo);
        drawByKind(unboundedKindStart, 3, view, x, glY, w, h, overlay, true);
        if (unboundedCsg > 0) {
            // The CSG ones follow in the same instance buffer (no base instance in GL 3.3: the attributes start there).
            useGeometryProgram(geometryProgram(false, -1), view, x, glY, w, h, overlay, true);
            instanceAttributes(28L * unboundedPrimitives);
            glDrawArraysInstanced(GL_TRIANGLES, 0, 3, unboundedCsg);
        }
        int meshes = scene.meshInstances.length / GpuScene.MESH_INSTANCE_INTS;
        if (meshes > 0) {
            p = meshProgram();
            useGeometryProgram(p, view, x, glY, w, h, overlay, false);
            int rows = glGetUniformLocation(p, "meshRows"), entity = glGetUniformLocation(p, "entityIndex");
            int leaf = glGetUniformLocation(p, "meshLeaf");
            glBindVertexArray(meshVao);
            float[] m = new float[12];
            for (int i = 0; i < meshes; i++) {
                int at = GpuScene.MESH_INSTANCE_INTS * i;
                System.arraycopy(scene.meshMatrices, 12 * i, m, 0, 12);
                glUniform4fv(rows, m);
                glUniform1i(entity, (int) scene.data[4 * scene.meshInstances[at] + 2]);
                glUniform1i(leaf, scene.meshInstances[at + 1]);
                glDrawElementsBaseVertex(GL_TRIANGLES, 3 * scene.meshInstances[at + 4], GL_UNSIGNED_INT,
                        4L * scene.meshInstances[at + 3], scene.meshInstances[at + 2]);
            }
        }
        glDisable(GL_DEPTH_CLAMP);
        glDisable(GL_DEPTH_TEST);

        // Shading: once per pixel, from what the geometry pass kept; the background where it found nothing.
        glBindFramebuffer(GL_FRAMEBUFFER, colourFramebuffer);
        glStencilMask(0);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        glBindVertexArray(fullVao);
        int kind = backgroundKind();
        p = shadeProgram(kind, true, overlay.grid(), false);
        glUseProgram(p);
        cameraUniforms(p, view, x, glY, w, h, overlay);
        glStencilFunc(GL_EQUAL, 0, 0xFF);
        glDrawArrays(GL_TRIANGLES, 0, 3);

        p = shadeProgram(kind, false, false, scene.entityOffset.length <= SHADOW_ENTITY_LIMIT);
        glUseProgram(p);
        glStencilFunc(GL_EQUAL, 1, 0xFF);
        cameraUniforms(p, view, x, glY, w, h, overlay);
        sceneTexture(p);
        bind(p, "ids", 3, GL_TEXTURE_2D, idTexture);
        bind(p, "depths", 4, GL_TEXTURE_2D, depthTexture);
        bind(p, "leaves", 5, GL_TEXTURE_2D, leafTexture);
        bind(p, "faces", 6, GL_TEXTURE_2D, faceTexture);
        bind(p, "directory", 2, GL_TEXTURE_BUFFER, directoryTexture);
        glActiveTexture(GL_TEXTURE0);
        glUniform1i(glGetUniformLocation(p, "entityCount"), scene.entityOffset.length);
        glUniform1i(glGetUniformLocation(p, "shadowLights"), SHADOW_LIGHTS);
        glUniform1i(glGetUniformLocation(p, "lightCount"), scene.lightCount);
        int n = scene.lightCount;
        if (n > 0) {
            float[] a = new float[4 * n], b = new float[4 * n], c = new float[4 * n], d = new float[4 * n];
            int stride = GpuScene.LIGHT_FLOATS;
            for (int i = 0; i < n; i++) {
                System.arraycopy(scene.lights, stride * i, a, 4 * i, 4);
                System.arraycopy(scene.lights, stride * i + 4, b, 4 * i, 4);
                System.arraycopy(scene.lights, stride * i + 8, c, 4 * i, 4);
                System.arraycopy(scene.lights, stride * i + 12, d, 4 * i, 4);
            }
            glUniform4fv(glGetUniformLocation(p, "lightA"), a);
            glUniform4fv(glGetUniformLocation(p, "lightB"), b);
            glUniform4fv(glGetUniformLocation(p, "lightC"), c);
            glUniform4fv(glGetUniformLocation(p, "lightD"), d);
        }
        glUniform1i(glGetUniformLocation(p, "selected"), overlay.selected() + 1);
        glUniform1i(glGetUniformLocation(p, "hovered"), overlay.hovered() + 1);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
        glDisable(GL_STENCIL_TEST);
        glStencilMask(0xFF);
        glDisable(GL_SCISSOR_TEST);
        check("drawing");
    }

    /**
     * One instanced draw of {@code vertices} per primitive kind with instances, each with its
     * kind's program, from the vertex array and instance buffer bound; instances of kind k are
     * [kindStart[k], kindStart[k + 1]).
     */
    private void drawByKind(int[] kindStart, int vertices, ViewCamera view, int x, int y, int w, int h, Overlay overlay,
            boolean fullScreen) {
        for (int k = 0; k < KINDS; k++) {
            int from = kindStart[k], count = kindStart[k + 1] - from;
            if (count == 0) continue;
            useGeometryProgram(geometryProgram(true, k), view, x, y, w, h, overlay, fullScreen);
            instanceAttributes(28L * from);
            glDrawArraysInstanced(GL_TRIANGLES, 0, vertices, count);
        }
    }

    private void useGeometryProgram(int p, ViewCamera view, int x, int y, int w, int h, Overlay overlay, boolean fullScreen) {
        glUseProgram(p);
        cameraUniforms(p, view, x, y, w, h, overlay);
        sceneTexture(p);
        glUniform1f(glGetUniformLocation(p, "depthScale"), (float) depthScale(view));
        glUniformMatrix4fv(glGetUniformLocation(p, "viewProjection"), false, view.projection((double) w / h));
        glUniform1i(glGetUniformLocation(p, "fullScreen"), fullScreen ? 1 : 0);
    }

    private void sceneTexture(int p) {
        bind(p, "scene", 1, GL_TEXTURE_BUFFER, sceneTexture);
        if ((scene.kinds & 1 << GpuScene.MESH) != 0) {
            bind(p, "meshVertices", 7, GL_TEXTURE_BUFFER, meshVertexTexture);
            bind(p, "meshIndices", 8, GL_TEXTURE_BUFFER, meshIndexTexture);
            if (scene.meshNodes.length > 0) bind(p, "meshNodes", 9, GL_TEXTURE_BUFFER, meshNodeTexture);
        }
    }

    private static void bind(int p, String name, int unit, int target, int texture) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(target, texture);
        glUniform1i(glGetUniformLocation(p, name), unit);
        glActiveTexture(GL_TEXTURE0);
    }

    /**
     * The scene's frame is left-handed (r, u, f), so the projection mirrors windings: the cube's
     * outside faces, wound counter-clockwise in a right-handed sense, appear clockwise on screen.
     */
    private static int frontFace(ViewCamera view) {
        double handed = view.right().cross(view.up()).dot(view.forward());
        return handed > 0 ? GL_CW : GL_CCW;
    }

    /** Scene depth t is stored as t/(t + s): monotonic, so the depth test orders hits along each ray. */
    private double depthScale(ViewCamera view) {
        dev.crt.geom.Aabb b = scene.bounds;
        if (b.isEmpty()) return 1;
        double far = b.max().minus(b.min()).length() + b.center().minus(view.position()).length();
        return Math.max(1e-6, far / 8);
    }

    private void cameraUniforms(int p, ViewCamera v, int x, int y, int w, int h, Overlay overlay) {
        glUniform2f(glGetUniformLocation(p, "viewportOrigin"), x, y);
        glUniform2f(glGetUniformLocation(p, "viewportSize"), w, h);
        glUniform1i(glGetUniformLocation(p, "orthographic"), v.orthographic() ? 1 : 0);
        vec3(p, "cameraPosition", v.position());
        vec3(p, "cameraForward", v.forward());
        vec3(p, "cameraRight", v.right());
        vec3(p, "cameraUp", v.up());
        glUniform1f(glGetUniformLocation(p, "halfHeight"), (float) v.scale());
        glUniform1f(glGetUniformLocation(p, "gamma"), (float) scene.gamma);
        glUniform1f(glGetUniformLocation(p, "gridSpacing"), (float) overlay.gridSpacing());
        glUniform1i(glGetUniformLocation(p, "gridAxis"), overlay.gridAxis());
        Background bg = scene.background;
        if (bg instanceof SolidBackground s) {
            glUniform3f(glGetUniformLocation(p, "background0"), (float) s.color().r(), (float) s.color().g(),
                    (float) s.color().b());
        } else if (bg instanceof GradientBackground g) {
            glUniform3f(glGetUniformLocation(p, "background0"), (float) g.horizon().r(), (float) g.horizon().g(),
                    (float) g.horizon().b());
            glUniform3f(glGetUniformLocation(p, "background1"), (float) g.sky().r(), (float) g.sky().g(),
                    (float) g.sky().b());
        } else if (bg instanceof PanoramaBackground pano) {
            glUniform1f(glGetUniformLocation(p, "panoramaAngle"), (float) pano.angle());
            glActiveTexture(GL_TEXTURE0);
            glBindTexture(GL_TEXTURE_2D, panoramaTexture);
            glUniform1i(glGetUniformLocation(p, "panorama"), 0);
        }
    }

    private static void vec3(int p, String name, dev.crt.geom.Vec3 v) {
        glUniform3f(glGetUniformLocation(p, name), (float) v.x(), (float) v.y(), (float) v.z());
    }

    /** The colour image as packed 0xFFRRGGBB ints, rows top to bottom. */
    public int[] readColour() {
        int[] out = new int[width * height];
        readColour(width, height, out);
        return out;
    }

    /**
     * The top-left {@code w × h} pixels of the colour image into {@code out} as 0xFFRRGGBB ints
     * (the alpha drawn is 1), rows top to bottom: read as BGRA words, which are those ints on
     * a little-endian machine's memory order, so no pixel is converted in Java.
     */
    public void readColour(int w, int h, int[] out) {
        IntBuffer b = BufferUtils.createIntBuffer(w * h);
        glBindFramebuffer(GL_FRAMEBUFFER, colourFramebuffer);
        glReadBuffer(GL_COLOR_ATTACHMENT0);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glReadPixels(0, height - h, w, h, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, b);
        for (int row = 0; row < h; row++) {
            b.position((h - 1 - row) * w);
            b.get(out, row * w, w);
        }
    }

    /** The entity index seen at each pixel (−1 for background), rows top to bottom. */
    public int[] readIds() {
        IntBuffer b = BufferUtils.createIntBuffer(width * height);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        glReadBuffer(GL_COLOR_ATTACHMENT0);
        glReadPixels(0, 0, width, height, GL_RED_INTEGER, GL_INT, b);
        int[] out = new int[width * height];
        for (int row = 0; row < height; row++) {
            int src = (height - 1 - row) * width;
            for (int i = 0; i < width; i++) out[row * width + i] = IdColors.entityIndex(b.get(src + i));
        }
        return out;
    }

    /** The entity index at pixel (x, y) from the top left, −1 for background: picking. */
    public int idAt(int x, int y) {
        IntBuffer b = BufferUtils.createIntBuffer(1);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        glReadBuffer(GL_COLOR_ATTACHMENT0);
        glReadPixels(x, height - 1 - y, 1, 1, GL_RED_INTEGER, GL_INT, b);
        return IdColors.entityIndex(b.get(0));
    }

    /** Distance along the unit ray at each pixel (+∞ for background), rows top to bottom. */
    public float[] readDepth() {
        FloatBuffer b = BufferUtils.createFloatBuffer(width * height);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        glReadBuffer(GL_COLOR_ATTACHMENT1);
        glReadPixels(0, 0, width, height, GL_RED, GL_FLOAT, b);
        float[] out = new float[width * height];
        for (int row = 0; row < height; row++) {
            b.position((height - 1 - row) * width);
            b.get(out, row * width, width);
        }
        return out;
    }

    public int width() { return width; }

    public int height() { return height; }

    @Override
    public void close() {
        deleteFramebuffers();
        glDeleteTextures(new int[] {sceneTexture, directoryTexture, panoramaTexture, meshVertexTexture, meshIndexTexture,
            meshNodeTexture});
        glDeleteBuffers(new int[] {sceneBuffer, directoryBuffer, cubeVbo, instanceVbo, csgInstanceVbo, fullInstanceVbo,
            meshVertexBuffer, meshIndexBuffer, meshNodeBuffer});
        glDeleteVertexArrays(new int[] {cubeVao, csgVao, fullVao, meshVao});
        for (int p : geometryPrograms.values()) glDeleteProgram(p);
        for (int p : shadePrograms.values()) glDeleteProgram(p);
    }

    private static void check(String what) {
        int e = glGetError();
        if (e != GL_NO_ERROR) throw new IllegalStateException("OpenGL error 0x" + Integer.toHexString(e) + " while " + what);
    }

    private static String resource(String name) {
        try (InputStream in = LiveRenderer.class.getResourceAsStream(name)) {
            if (in == null) throw new IllegalStateException("missing shader resource " + name);
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static int program(String vertex, String fragment) {
        int vs = shader(GL_VERTEX_SHADER, vertex), fs = shader(GL_FRAGMENT_SHADER, fragment);
        int p = glCreateProgram();
        glAttachShader(p, vs);
        glAttachShader(p, fs);
        glLinkProgram(p);
        if (glGetProgrami(p, GL_LINK_STATUS) != GL_TRUE) {
            throw new IllegalStateException("shader link failed: " + glGetProgramInfoLog(p));
        }
        glDeleteShader(vs);
        glDeleteShader(fs);
        return p;
    }

    private static int shader(int type, String source) {
        int s = glCreateShader(type);
        glShaderSource(s, source);
        glCompileShader(s);
        if (glGetShaderi(s, GL_COMPILE_STATUS) != GL_TRUE) {
            throw new IllegalStateException("shader compile failed: " + glGetShaderInfoLog(s));
        }
        return s;
    }
}
