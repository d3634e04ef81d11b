package dev.crt.render;

import dev.crt.geom.Aabb;
import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.Box;
import dev.crt.scene.Cone;
import dev.crt.scene.Cylinder;
import dev.crt.scene.Mesh;
import dev.crt.scene.MeshData;
import dev.crt.scene.Plane;
import dev.crt.scene.Primitive;
import dev.crt.scene.Sphere;
import dev.crt.scene.Torus;
import java.util.Arrays;
import java.util.IdentityHashMap;
import java.util.Map;

/**
 * The primitives of a prepared scene as flat arrays, and the one dispatch point from a shape's
 * kind tag to the class that knows that kind ({@link SphereShape}, {@link BoxShape}, …): each
 * operation is one switch over the tags calling that class's static method, so the hot path makes
 * no virtual call and allocates nothing. A kind is one class plus its tag and one line in each
 * switch here; ShapeKindsTest walks every tag and every primitive type so none can be forgotten.
 *
 * <p>A primitive whose transform keeps its shape simple is stored in world space (a sphere under
 * translation, rotation and uniform scale stays a sphere; a box under translation, scale and
 * quarter turns stays an axis-aligned box); only general transforms pay for a matrix per ray.
 */
final class Shapes {
    static final int SPHERE = 0;
    static final int BOX = 1;
    static final int PLANE = 2;
    static final int MAPPED_SPHERE = 3;
    static final int MAPPED_BOX = 4;
    /** A shape with nothing to hit (a sphere of radius 0). */
    static final int EMPTY = 5;
    /** Cylinders, cones and frusta, capped or open. */
    static final int CONE = 6;
    static final int TORUS = 7;
    static final int MESH = 8;
    /** The number of kind tags: tags are 0 … KINDS − 1. */
    static final int KINDS = 9;

    private int count;
    int[] kind = new int[16];
    int[] offset = new int[16];
    int[] material = new int[16];
    /** A length of the order of the primitive's coordinates, for scale-aware ray offsets. */
    double[] scale = new double[16];
    double[] data = new double[64];
    private int dataSize;
    /**
     * Per shape, where the 3×4 world-to-entity matrix of its placement starts in {@link
     * Placements#toEntity}: solid textures are evaluated in the entity's own coordinates, before
     * its modifiers. An untransformed shape's is 0, the identity's, so a million plain spheres
     * hold one matrix, not a million.
     */
    int[] placement = new int[16];
    /** The matrices {@link #placement} points into, shared with the stores made by {@link #sharingMeshesWith}. */
    Placements placements = new Placements();
    /** The meshes the MESH shapes use, each prepared once however many instances share it. */
    MeshGeometry[] meshes = new MeshGeometry[0];
    private Map<MeshData, MeshGeometry> prepared = new IdentityHashMap<>();

    int count() { return count; }

    /** Appends {@code p} placed by {@code toWorld}, returns its index. */
    int add(Primitive p, Transform toWorld, int materialIndex) {
        int s = next();
        material[s] = materialIndex;
        offset[s] = dataSize;
        placement[s] = placements.add(toWorld);
        if (p instanceof Sphere sp) SphereShape.add(this, s, sp, toWorld);
        else if (p instanceof Box b) BoxShape.add(this, s, b, toWorld);
        else if (p instanceof Plane pl) PlaneShape.add(this, s, pl, toWorld);
        else if (p instanceof Cylinder c) ConeShape.add(this, s, c, toWorld);
        else if (p instanceof Cone c) ConeShape.add(this, s, c, toWorld);
        else if (p instanceof Torus t) TorusShape.add(this, s, t, toWorld);
        else if (p instanceof Mesh m) MeshShape.add(this, s, m, toWorld);
        else throw new IllegalArgumentException("no shape class for " + p.getClass().getSimpleName());
        return s;
    }

    /** Appends a copy of shape {@code s} of {@code from}, its material index included; returns its index. */
    int copy(Shapes from, int s) {
        int t = next();
        kind[t] = from.kind[s];
        material[t] = from.material[s];
        scale[t] = from.scale[s];
        placement[t] = placements.of(from, s);
        offset[t] = dataSize;
        int start = from.offset[s], end = s + 1 < from.count ? from.offset[s + 1] : from.dataSize;
        int length = end - start;
        if (dataSize + length > data.length) data = Arrays.copyOf(data, Math.max(data.length * 2, dataSize + length));
        System.arraycopy(from.data, start, data, dataSize, length);
        if (kind[t] == MESH) {
            // The mesh index is the source's: the geometry itself is shared, not prepared again.
            int at = dataSize + Affine.SIZE;
            data[at] = meshIndex(from.meshes[(int) from.data[start + Affine.SIZE]]);
        }
        dataSize += length;
        return t;
    }

    /** The doubles of {@link #data} in use. */
    int dataSize() { return dataSize; }

    /** Makes room for {@code shapes} shapes and {@code doubles} doubles of data in all, so that adding that many copies nothing. */
    void reserve(int shapes, int doubles) {
        if (shapes > kind.length) {
            kind = Arrays.copyOf(kind, shapes);
            offset = Arrays.copyOf(offset, shapes);
            material = Arrays.copyOf(material, shapes);
            scale = Arrays.copyOf(scale, shapes);
            placement = Arrays.copyOf(placement, shapes);
        }
        if (doubles > data.length) data = Arrays.copyOf(data, doubles);
    }

    /**
     * Appends {@code n} shapes and {@code doubles} doubles of data for the caller to write (each
     * shape's kind, material, scale, matrix, offset and data), from several threads at once if it
     * likes; the shapes are numbered from the former {@link #count}, the data from the former
     * {@link #dataSize}.
     */
    void claim(int n, int doubles) {
        reserve(count + n, dataSize + doubles);
        count += n;
        dataSize += doubles;
    }

    /**
     * Writes a copy of shape {@code s} of {@code source}, a store sharing this one's placements,
     * as shape {@code t}, claimed, with its data from {@code at}; returns where its data ends. A
     * MESH shape keeps the source's mesh index until {@link #reindexMeshes}.
     */
    int copyAt(Shapes source, int s, int t, int at) {
        kind[t] = source.kind[s];
        material[t] = source.material[s];
        scale[t] = source.scale[s];
        placement[t] = source.placement[s];
        offset[t] = at;
        int start = source.offset[s], end = s + 1 < source.count ? source.offset[s + 1] : source.dataSize;
        System.arraycopy(source.data, start, data, at, end - start);
        return at + end - start;
    }

    /** Renumbers the meshes of the MESH shapes among [from, to), copied from {@code source} by {@link #copyAt}, as this store's. */
    void reindexMeshes(Shapes source, int from, int to) {
        for (int t = from; t < to; t++) {
            if (kind[t] != MESH) continue;
            // The geometry itself is shared, not prepared again.
            int at = offset[t] + Affine.SIZE;
            data[at] = meshIndex(source.meshes[(int) data[at]]);
        }
    }

    private int next() {
        int s = count++;
        if (s == kind.length) {
            int n = s * 2;
            kind = Arrays.copyOf(kind, n);
            offset = Arrays.copyOf(offset, n);
            material = Arrays.copyOf(material, n);
            scale = Arrays.copyOf(scale, n);
            placement = Arrays.copyOf(placement, n);
        }
        return s;
    }

    /**
     * Makes this store prepare meshes into {@code other}'s table and keep its placements' matrices
     * in {@code other}'s, so that both share them; returns this.
     */
    Shapes sharingMeshesWith(Shapes other) {
        prepared = other.prepared;
        placements = other.placements;
        return this;
    }

    /** The world-to-entity matrices of the shapes' placements, 12 doubles each, the identity's first. */
    static final class Placements {
        /** The matrices, row-major; {@link Shapes#placement} gives where each shape's starts. */
        double[] toEntity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
        private int size = 12;

        /** Where the inverse matrix of {@code toWorld} starts, added unless it is the identity. */
        int add(Transform toWorld) {
            if (toWorld == Transform.IDENTITY) return 0;
            int at = room();
            toWorld.copyInverse(toEntity, at);
            return at;
        }

        /** Where the matrix of shape {@code s} of {@code from} starts here, added unless the stores share their placements. */
        int of(Shapes from, int s) {
            int at = from.placement[s];
            if (from.placements == this || at == 0) return at;
            int to = room();
            System.arraycopy(from.placements.toEntity, at, toEntity, to, 12);
            return to;
        }

        private int room() {
            if (size + 12 > toEntity.length) toEntity = Arrays.copyOf(toEntity, 2 * toEntity.length);
            size += 12;
            return size - 12;
        }
    }

    /** The prepared geometry of {@code data}, made on first use. */
    MeshGeometry mesh(MeshData data) {
        return prepared.computeIfAbsent(data, MeshGeometry::new);
    }

    /** The index of {@code g} in {@link #meshes}, adding it when it is new here. */
    int meshIndex(MeshGeometry g) {
        for (int i = 0; i < meshes.length; i++) if (meshes[i] == g) return i;
        meshes = Arrays.copyOf(meshes, meshes.length + 1);
        meshes[meshes.length - 1] = g;
        return meshes.length - 1;
    }

    /** Both matrices of {@code t} as an {@link Affine} placement. */
    void pushMatrices(Transform t) {
        double[] inv = t.inverseMatrix();
        double[] m = t.matrix();
        for (double v : inv) push(v);
        for (double v : m) push(v);
    }

    void push(double... values) {
        if (dataSize + values.length > data.length) {
            data = Arrays.copyOf(data, Math.max(data.length * 2, dataSize + values.length));
        }
        System.arraycopy(values, 0, data, dataSize, values.length);
        dataSize += values.length;
    }

    static double maxAbs(Vec3 v) {
        return maxAbs(v.x(), v.y(), v.z());
    }

    static double maxAbs(double x, double y, double z) {
        return Math.max(Math.abs(x), Math.max(Math.abs(y), Math.abs(z)));
    }

    /** Whether shape {@code s} is a plane (one-sided in the 2015 shading model). */
    boolean isPlane(int s) { return kind[s] == PLANE; }

    private IllegalStateException unknown(int s) {
        return new IllegalStateException("shape kind " + kind[s] + " has no entry in this switch");
    }

    /** World bounds of shape {@code s}; infinite for planes, empty for invisible shapes. */
    Aabb bounds(int s) {
        int o = offset[s];
        double[] a = data;
        return switch (kind[s]) {
            case SPHERE -> SphereShape.bounds(a, o);
            case BOX -> BoxShape.bounds(a, o);
            case PLANE -> PlaneShape.bounds();
            case MAPPED_SPHERE -> SphereShape.mappedBounds(a, o);
            case MAPPED_BOX -> BoxShape.mappedBounds(a, o);
            case CONE -> ConeShape.bounds(a, o);
            case TORUS -> TorusShape.bounds(a, o);
            case MESH -> MeshShape.bounds(a, o, meshes[(int) a[o + Affine.SIZE]]);
            case EMPTY -> Aabb.EMPTY;
            default -> throw unknown(s);
        };
    }

    /**
     * Every crossing of the line of {@code ray} with the solid {@code s}: on success writes the
     * parameter intervals inside the solid (±∞ where it never leaves) and the faces crossed into
     * {@code out}, and returns true; returns false when the line misses it.
     */
    boolean span(int s, Ray ray, LineSpan out) {
        int o = offset[s];
        double[] a = data;
        switch (kind[s]) {
            case SPHERE:
                return SphereShape.span(a, o, ray, out);
            case BOX:
                return BoxShape.span(a, o, ray, out);
            case PLANE:
                return PlaneShape.span(a, o, ray, out);
            case MAPPED_SPHERE:
                return SphereShape.mappedSpan(a, o, ray, out);
            case MAPPED_BOX:
                return BoxShape.mappedSpan(a, o, ray, out);
            case EMPTY:
                return false;
            // The second wave's kinds, behind their switch (Features): with it off they are never reached.
            case CONE:
                if (Features.SHAPES) return ConeShape.span(a, o, ray, out);
                break;
            case TORUS:
                if (Features.SHAPES) return TorusShape.span(a, o, ray, out, out.roots);
                break;
            case MESH:
                if (Features.SHAPES) return MeshShape.span(a, o, ray, out, meshes[(int) a[o + Affine.SIZE]]);
                break;
            default:
                break;
        }
        throw unknown(s);
    }

    /**
     * The nearest crossing of shape {@code s} with 0 &lt; t &lt; tMax into {@code hit} (t, shape, face;
     * flip false), for a shape standing alone (CSG gathers crossings with {@link #span}). Meshes and
     * tori stop at the nearest hit instead of gathering the whole line; the other kinds read the
     * first crossing of their span, which is as cheap. {@code scratch} is the thread's span.
     */
    boolean firstHit(int s, Ray ray, double tMax, LineSpan scratch, Hit hit) {
        int o = offset[s];
        double[] a = data;
        if (Features.SHAPES) {
            switch (kind[s]) {
                case MESH:
                    return MeshShape.firstHit(a, o, ray, tMax, scratch, meshes[(int) a[o + Affine.SIZE]], s, hit);
                case TORUS: {
                    double t = TorusShape.firstHit(a, o, ray, tMax, scratch.roots);
                    if (t != t) return false;
                    hit.t = t;
                    hit.shape = s;
                    hit.face = 0;
                    hit.flip = false;
                    return true;
                }
                case SPHERE, BOX, PLANE, MAPPED_SPHERE, MAPPED_BOX, CONE, EMPTY:
                    break;
                default:
                    throw unknown(s);
            }
        }
        if (!span(s, ray, scratch)) return false;
        return firstOf(scratch, s, tMax, hit);
    }

    /** The first crossing of {@code span} with 0 &lt; t &lt; tMax into {@code hit}. */
    private static boolean firstOf(LineSpan span, int s, double tMax, Hit hit) {
        for (int i = 0; i < span.count; i++) {
            double t;
            int face;
            if (span.tIn[i] > 0) {
                t = span.tIn[i];
                face = span.faceIn[i];
            } else if (span.tOut[i] > 0) {
                t = span.tOut[i];
                face = span.faceOut[i];
            } else {
                continue;
            }
            if (!(t < tMax)) return false;
            hit.t = t;
            hit.shape = s;
            hit.face = face;
            hit.flip = false;
            return true;
        }
        return false;
    }

    /**
     * Whether shape {@code s} (standing alone) crosses the ray anywhere with 0 &lt; t &lt; tMax: the
     * shadow test of an opaque shape, which stops at the first crossing found.
     */
    boolean anyHit(int s, Ray ray, double tMax, LineSpan scratch) {
        int o = offset[s];
        double[] a = data;
        if (Features.SHAPES) {
            switch (kind[s]) {
                case MESH:
                    return MeshShape.anyHit(a, o, ray, tMax, scratch, meshes[(int) a[o + Affine.SIZE]]);
                case TORUS:
                    return TorusShape.anyHit(a, o, ray, tMax, scratch.roots);
                case SPHERE, BOX, PLANE, MAPPED_SPHERE, MAPPED_BOX, CONE, EMPTY:
                    break;
                default:
                    throw unknown(s);
            }
        }
        if (!span(s, ray, scratch)) return false;
        for (int i = 0; i < scratch.count; i++) {
            double in = scratch.tIn[i], out = scratch.tOut[i];
            if (in > 0 && in < tMax || out > 0 && out < tMax) return true;
        }
        return false;
    }

    /**
     * The surface point of shape {@code s} at parameter {@code t} of {@code ray} on {@code face},
     * snapped back onto the exact surface (so its error scales with its own coordinates, not with the
     * ray's length), and the primitive's outward unit normal there.
     */
    void surface(int s, int face, double t, Ray ray, SurfacePoint out) {
        int o = offset[s];
        double[] a = data;
        double px = ray.ox + t * ray.dx, py = ray.oy + t * ray.dy, pz = ray.oz + t * ray.dz;
        out.shaded = false;
        switch (kind[s]) {
            case SPHERE -> SphereShape.surface(a, o, px, py, pz, out);
            case BOX -> BoxShape.surface(a, o, face, px, py, pz, out);
            case PLANE -> PlaneShape.surface(a, o, px, py, pz, out);
            case MAPPED_SPHERE -> SphereShape.mappedSurface(a, o, px, py, pz, out);
            case MAPPED_BOX -> BoxShape.mappedSurface(a, o, face, px, py, pz, out);
            // The second wave's kinds, behind their switch (Features): with it off they are never reached.
            case CONE -> {
                if (!Features.SHAPES) throw unknown(s);
                ConeShape.surface(a, o, face, px, py, pz, out);
            }
            case TORUS -> {
                if (!Features.SHAPES) throw unknown(s);
                TorusShape.surface(a, o, px, py, pz, out);
            }
            case MESH -> {
                if (!Features.SHAPES) throw unknown(s);
                MeshShape.surface(a, o, face, px, py, pz, out, meshes[(int) a[o + Affine.SIZE]]);
            }
            default -> throw unknown(s);
        }
    }

    /**
     * The surface coordinates (u, v) and tangents dp/du, dp/dv of the point {@link #surface} wrote
     * into {@code out} for the same shape and face. Kept apart from {@link #surface} so that only
     * what uses them (textures, bump maps) pays for them.
     */
    void frame(int s, int face, SurfacePoint out) {
        int o = offset[s];
        double[] a = data;
        switch (kind[s]) {
            case SPHERE -> SphereShape.frame(a, o, out);
            case BOX -> BoxShape.frame(a, o, face, out);
            case PLANE -> PlaneShape.frame(a, o, out);
            case MAPPED_SPHERE -> SphereShape.mappedFrame(a, o, out);
            case MAPPED_BOX -> BoxShape.mappedFrame(a, o, face, out);
            case CONE -> ConeShape.frame(a, o, face, out);
            case TORUS -> TorusShape.frame(a, o, out);
            case MESH -> MeshShape.frame(a, o, face, out, meshes[(int) a[o + Affine.SIZE]]);
            default -> throw unknown(s);
        }
    }
}
