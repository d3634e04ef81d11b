package dev.crt.live;

import dev.crt.geom.Aabb;
import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.Box;
import dev.crt.scene.Cone;
import dev.crt.scene.Cylinder;
import dev.crt.scene.Csg;
import dev.crt.scene.Entity;
import dev.crt.scene.Light;
import dev.crt.scene.Material;
import dev.crt.scene.AreaLight;
import dev.crt.scene.Mesh;
import dev.crt.scene.MeshData;
import dev.crt.scene.ParallelLight;
import dev.crt.scene.Plane;
import dev.crt.scene.PointLight;
import dev.crt.scene.SpotLight;
import dev.crt.scene.Primitive;
import dev.crt.scene.Scene;
import dev.crt.scene.Sphere;
import dev.crt.scene.Torus;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

/**
 * Turns a {@link Scene} into {@link GpuScene} data: each top-level entity becomes one block that
 * the fragment shader ray-casts exactly (primitives in their local frames, CSG as a postfix
 * program; meshes as triangles, see {@link GpuScene}), so the live view shows the same solids as the ray tracer. Kinds it does not know are
 * refused with an {@link UnsupportedSceneException}, never drawn wrongly.
 */
public final class SceneConverter {
    private float[] data = new float[4096];
    private int size;
    /** The primitive kinds written, one bit per kind. */
    private int kinds;
    /** The distinct meshes met so far and their {vertex base, index base} in the mesh buffers. */
    private final Map<MeshData, int[]> meshBases = new IdentityHashMap<>();
    private final List<MeshData> meshes = new ArrayList<>();
    /** Each mesh's triangles as sent (in its hierarchy's leaf order when it has one), and the hierarchies' node texels. */
    private final List<int[]> meshTriangles = new ArrayList<>();
    private float[] meshNodes = new float[0];
    private int meshNodeTexels;
    private int meshVertexTexels, meshIndexCount;
    /** Top-level meshes: GpuScene.MESH_INSTANCE_INTS ints and 12 floats each. */
    private int[] meshInstances = new int[0];
    private float[] meshMatrices = new float[0];
    private int meshInstanceCount;
    /** Whether the entity being converted is a CSG tree (its meshes are ray-cast) and its header texel. */
    private boolean inCsg;
    private int entityHeader;

    /** Converts {@code scene}; throws {@link UnsupportedSceneException} for what the live view cannot draw. */
    public static GpuScene convert(Scene scene) {
        return new SceneConverter().run(scene);
    }

    /**
     * Does ahead, on the caller's thread, the slow part of a later {@link #convert} of
     * {@code scene}: the hierarchies of its meshes too large to cast triangle by triangle (about a
     * second for 240,000 triangles on a loaded machine), kept by their content. The studio calls
     * it on its compile thread, so that the Event Dispatch Thread, which converts, finds them built.
     */
    public static void prepare(Scene scene) {
        for (Entity e : scene.entities()) prepare(e);
    }

    private static void prepare(Entity e) {
        if (e instanceof Csg c) {
            prepare(c.left());
            prepare(c.right());
        } else if (e instanceof Mesh m) {
            int triangles = m.data().triangleCount();
            if (triangles > GpuScene.MESH_CAST_LIMIT && triangles <= GpuScene.MESH_BVH_LIMIT) MeshBvh.of(m.data());
        }
    }

    private GpuScene run(Scene scene) {
        List<Entity> entities = scene.entities();
        int n = entities.size();
        int[] offsets = new int[n];
        Aabb[] bounds = new Aabb[n];
        // Bounded entities: one-primitive ones from the front, CSG ones from the back, then reversed into place.
        int[] bounded = new int[n];
        float[] boxes = new float[6 * n];
        int nc = 0;
        // Unbounded entities likewise: one-primitive ones (drawn without the CSG walk) first.
        int[] unbounded = new int[n];
        int nb = 0, nu = 0, nuc = 0;
        Aabb all = Aabb.EMPTY;
        for (int i = 0; i < n; i++) {
            Entity e = entities.get(i);
            offsets[i] = size / 4;
            Aabb b = entity(e, i);
            bounds[i] = b;
            if (b.isEmpty()) continue;
            if (e instanceof Mesh) {
                // Rasterised, not ray-cast in a proxy box.
                all = all.union(b);
                continue;
            }
            if (b.isFinite()) {
                int at = e instanceof Primitive ? nb++ : n - 1 - nc++;
                bounded[at] = offsets[i];
                put(boxes, 6 * at, b);
                all = all.union(b);
            } else if (e instanceof Primitive) {
                unbounded[nu++] = offsets[i];
            } else {
                unbounded[n - 1 - nuc++] = offsets[i];
            }
        }
        List<Light> sceneLights = scene.settings().lights();
        if (sceneLights.size() > GpuScene.MAX_LIGHTS) {
            throw new UnsupportedSceneException("the live view shows at most " + GpuScene.MAX_LIGHTS
                    + " lights; this scene has " + sceneLights.size());
        }
        float[] lights = new float[GpuScene.LIGHT_FLOATS * sceneLights.size()];
        for (int i = 0; i < sceneLights.size(); i++) light(sceneLights.get(i), lights, GpuScene.LIGHT_FLOATS * i);
        int[] boundedAll = new int[nb + nc];
        float[] boxesAll = new float[6 * (nb + nc)];
        System.arraycopy(bounded, 0, boundedAll, 0, nb);
        System.arraycopy(boxes, 0, boxesAll, 0, 6 * nb);
        for (int k = 0; k < nc; k++) {
            boundedAll[nb + k] = bounded[n - nc + k];
            System.arraycopy(boxes, 6 * (n - nc + k), boxesAll, 6 * (nb + k), 6);
        }
        int[] unboundedAll = Arrays.copyOf(unbounded, nu + nuc);
        System.arraycopy(unbounded, n - nuc, unboundedAll, nu, nuc);
        return new GpuScene(data, size / 4, offsets, bounds, boundedAll, boxesAll, nb, unboundedAll, nu, tables, seesBackground, lights, sceneLights.size(),
                scene.settings().background(), scene.settings().gamma(), scene.settings().camera(), all, kinds,
                meshes, meshTriangles, Arrays.copyOf(meshNodes, 4 * meshNodeTexels), meshVertexTexels, meshIndexCount,
                Arrays.copyOf(meshInstances, GpuScene.MESH_INSTANCE_INTS * meshInstanceCount),
                Arrays.copyOf(meshMatrices, 12 * meshInstanceCount));
    }

    private static void put(float[] boxes, int at, Aabb b) {
        boxes[at] = (float) b.min().x();
        boxes[at + 1] = (float) b.min().y();
        boxes[at + 2] = (float) b.min().z();
        boxes[at + 3] = (float) b.max().x();
        boxes[at + 4] = (float) b.max().y();
        boxes[at + 5] = (float) b.max().z();
    }

    /**
     * Writes one light's four vec4: (kind, position or direction towards it), (colour, ambient),
     * (falloff, cos angle, cos innerangle, 0) and (axis or normal, 0). A spot light is drawn
     * exactly (its smoothstep cone); an area light as one point at its centre whose strength
     * follows the light's |normal·ω| (no soft shadows: the live view casts one shadow ray).
     */
    private static void light(Light light, float[] out, int at) {
        Vec3 p, axis = Vec3.ZERO;
        int kind;
        double falloff, cosOuter = 0, cosInner = 0;
        if (light instanceof PointLight pl) {
            kind = GpuScene.POINT_LIGHT;
            p = pl.origin();
            falloff = pl.falloff();
        } else if (light instanceof ParallelLight pl) {
            kind = GpuScene.PARALLEL_LIGHT;
            p = pl.towardsLight();
            falloff = 0;
        } else if (light instanceof SpotLight sl) {
            kind = GpuScene.SPOT_LIGHT;
            p = sl.origin();
            falloff = sl.falloff();
            axis = sl.pointing().minus(sl.origin()).normalize();
            cosOuter = Math.cos(Math.toRadians(sl.angle()));
            cosInner = Math.cos(Math.toRadians(sl.innerAngle()));
        } else if (light instanceof AreaLight al) {
            kind = GpuScene.AREA_LIGHT;
            p = al.corner().plus(al.edge1().plus(al.edge2()).times(0.5));
            falloff = al.falloff();
            axis = al.edge1().cross(al.edge2()).normalize();
        } else {
            throw new UnsupportedSceneException("the live view cannot show a " + kindName(light) + " yet");
        }
        out[at] = kind;
        out[at + 1] = (float) p.x();
        out[at + 2] = (float) p.y();
        out[at + 3] = (float) p.z();
        out[at + 4] = (float) light.color().r();
        out[at + 5] = (float) light.color().g();
        out[at + 6] = (float) light.color().b();
        out[at + 7] = (float) light.ambient();
        out[at + 8] = (float) falloff;
        out[at + 9] = (float) cosOuter;
        out[at + 10] = (float) cosInner;
        out[at + 12] = (float) axis.x();
        out[at + 13] = (float) axis.y();
        out[at + 14] = (float) axis.z();
    }

    /** Writes entity {@code e}'s block; returns its world bounds. */
    private Aabb entity(Entity e, int index) {
        int header = size;
        entityHeader = header / 4;
        inCsg = e instanceof Csg;
        reserve(4 * GpuScene.HEADER_TEXELS);
        size += 4 * GpuScene.HEADER_TEXELS;
        steps = 0;
        leafCount = 0;
        program(e);
        if (leafCount > GpuScene.MAX_LEAVES) {
            throw new UnsupportedSceneException("the live view draws CSG of at most " + GpuScene.MAX_LEAVES
                    + " primitives; the entity at " + e.span() + " has " + leafCount);
        }
        reserve(4 * steps);
        int programAt = size;
        for (int s = 0; s < steps; s++) {
            data[size++] = program[2 * s];
            data[size++] = program[2 * s + 1];
            data[size++] = 0;
            data[size++] = 0;
        }
        if (leafCount <= GpuScene.TABLE_LEAVES) truthTable(programAt);
        else tables = false;
        Aabb b = leaves(e, Transform.IDENTITY);
        double scale = b.isFinite() && !b.isEmpty()
                ? Math.max(maxAbs(b.min()), maxAbs(b.max())) : 1;
        data[header] = leafCount;
        data[header + 1] = steps;
        data[header + 2] = index;
        data[header + 3] = (float) scale;
        boolean finite = b.isFinite() && !b.isEmpty();
        data[header + 4] = finite ? (float) b.min().x() : -1e30f;
        data[header + 5] = finite ? (float) b.min().y() : -1e30f;
        data[header + 6] = finite ? (float) b.min().z() : -1e30f;
        data[header + 7] = finite ? 0 : 1;
        data[header + 8] = finite ? (float) b.max().x() : 1e30f;
        data[header + 9] = finite ? (float) b.max().y() : 1e30f;
        data[header + 10] = finite ? (float) b.max().z() : 1e30f;
        data[header + 11] = 0;
        if (e instanceof Plane) {
            // A plane alone: its (normal, offset) in place of the bounds, so a shadow ray's bounds test is its crossing.
            System.arraycopy(data, programAt + 4 * steps + 4, data, header + 8, 4);
            data[header + 7] = 2;
        }
        return b;
    }

    /** The postfix program of the entity being converted: (opcode, leaf) pairs. */
    private int[] program = new int[64];
    private int steps;
    private int leafCount;

    private void program(Entity e) {
        if (e instanceof Primitive) {
            step(GpuScene.OP_LEAF, leafCount++);
        } else if (e instanceof Csg c) {
            program(c.left());
            program(c.right());
            step(switch (c.operation()) {
                case UNION -> GpuScene.OP_UNION;
                case INTERSECTION -> GpuScene.OP_INTERSECTION;
                case DIFFERENCE -> GpuScene.OP_DIFFERENCE;
            }, 0);
        } else {
            throw new UnsupportedSceneException("the live view cannot draw a " + kindName(e) + " yet");
        }
    }

    /** Whether a material so far reflects or lets light through (the shading then looks the background up in those directions). */
    private boolean seesBackground;

    /** Whether every entity so far has its truth table written (at most {@link GpuScene#TABLE_LEAVES} primitives). */
    private boolean tables = true;

    /**
     * Writes the entity's CSG program as a truth table over its primitives: entry m tells whether a
     * point inside exactly the primitives of bit mask m is inside the entity. Sixteen entries per
     * float (exact as an integer), in the z and w of the program's texels from {@code at}: the
     * shader reads one texel to tell inside from outside instead of running the program.
     */
    private void truthTable(int at) {
        int entries = 1 << leafCount;
        for (int chunk = 0; chunk * 16 < entries; chunk++) {
            int bits = 0;
            for (int k = 0; k < 16 && chunk * 16 + k < entries; k++) {
                if (inside(chunk * 16 + k)) bits |= 1 << k;
            }
            data[at + 4 * (chunk >> 1) + 2 + (chunk & 1)] = bits;
        }
    }

    /** The program run on the set of primitives of bit mask {@code mask}, as the shader's program walk runs it. */
    private boolean inside(int mask) {
        long stack = 0;
        for (int s = 0; s < steps; s++) {
            int op = program[2 * s];
            if (op == GpuScene.OP_LEAF) {
                stack = stack << 1 | (mask >> program[2 * s + 1] & 1);
            } else {
                long b = stack & 1, a = stack >> 1 & 1;
                stack >>= 2;
                long r = op == GpuScene.OP_UNION ? a | b : op == GpuScene.OP_INTERSECTION ? a & b : a & (b ^ 1);
                stack = stack << 1 | r;
            }
        }
        return (stack & 1) != 0;
    }

    private void step(int opcode, int leaf) {
        if (2 * steps + 2 > program.length) program = Arrays.copyOf(program, 2 * program.length);
        program[2 * steps] = opcode;
        program[2 * steps + 1] = leaf;
        steps++;
    }

    /** Writes the primitives of {@code e} (in program order) placed by {@code outer}; returns the bounds of the solid. */
    private Aabb leaves(Entity e, Transform outer) {
        Transform t = e.transform().then(outer);
        if (e instanceof Sphere s) return sphere(s, t);
        if (e instanceof Box b) return box(b, t);
        if (e instanceof Plane p) return plane(p, t);
        if (e instanceof Cylinder c) return cone(c.from(), c.to(), c.radius(), c.radius(), c.capped(), c.material(), t);
        if (e instanceof Cone c) return cone(c.from(), c.to(), c.radius(), c.radius2(), c.capped(), c.material(), t);
        if (e instanceof Torus tr) return torus(tr, t);
        if (e instanceof Mesh m) return mesh(m, t);
        if (e instanceof Csg c) {
            Aabb left = leaves(c.left(), t);
            Aabb right = leaves(c.right(), t);
            return switch (c.operation()) {
                case UNION -> left.union(right);
                case INTERSECTION -> left.intersection(right);
                case DIFFERENCE -> left;
            };
        }
        throw new UnsupportedSceneException("the live view cannot draw a " + kindName(e) + " yet");
    }

    private Aabb sphere(Sphere s, Transform t) {
        if (!(s.radius() > 0)) return empty(s.material());
        double r = s.radius();
        Transform unit = Transform.scaling(new Vec3(r, r, r)).then(Transform.translation(s.center())).then(t);
        leafHeader(GpuScene.SPHERE);
        matrix(unit.inverseMatrix());
        zeros(2);
        material(s.material());
        // The ellipsoid M·(unit ball) + t reaches |row i of M| along world axis i.
        double[] m = unit.matrix();
        double[] lo = new double[3], hi = new double[3];
        for (int i = 0; i < 3; i++) {
            double e = Math.sqrt(m[4 * i] * m[4 * i] + m[4 * i + 1] * m[4 * i + 1] + m[4 * i + 2] * m[4 * i + 2]);
            lo[i] = m[4 * i + 3] - e;
            hi[i] = m[4 * i + 3] + e;
        }
        return new Aabb(new Vec3(lo[0], lo[1], lo[2]), new Vec3(hi[0], hi[1], hi[2]));
    }

    private Aabb empty(Material m) {
        leafHeader(GpuScene.EMPTY);
        zeros(5);
        material(m);
        return Aabb.EMPTY;
    }

    /**
     * A cylinder (r0 = r1), cone or frustum, as the ray tracer places it: a frame whose z runs
     * along the axis from {@code from} (0) to {@code to} (1) and whose x, y are scene units across.
     */
    private Aabb cone(Vec3 from, Vec3 to, double r0, double r1, boolean capped, Material m, Transform t) {
        Vec3 w = to.minus(from);
        double length = w.length();
        if (!(length > 0) || !(r0 > 0 || r1 > 0)) return empty(m);
        Vec3[] axes = Transform.axes(w.div(length));
        Transform local = Transform.frame(axes[0], axes[1], w, from).then(t);
        kinds |= 1 << GpuScene.CONE;
        texel(GpuScene.CONE, r0, r1, capped ? 1 : 0);
        matrix(local.inverseMatrix());
        texel(length, 0, 0, 0);
        zeros(1);
        material(m);
        double rm = Math.max(r0, r1);
        return new Aabb(new Vec3(-rm, -rm, 0), new Vec3(rm, rm, 1)).transformed(local);
    }

    /** A torus in the ray tracer's frame: centred at the origin, axis z, scene units. */
    private Aabb torus(Torus tr, Transform t) {
        double length = tr.axis().length();
        if (!(length > 0) || !(tr.major() > 0) || !(tr.minor() > 0)) return empty(tr.material());
        Vec3[] axes = Transform.axes(tr.axis().div(length));
        Transform local = Transform.frame(axes[0], axes[1], axes[2], tr.center()).then(t);
        kinds |= 1 << GpuScene.TORUS;
        texel(GpuScene.TORUS, tr.major(), tr.minor(), 0);
        matrix(local.inverseMatrix());
        zeros(2);
        material(tr.material());
        double e = tr.major() + tr.minor(), h = tr.minor();
        return new Aabb(new Vec3(-e, -e, -h), new Vec3(e, e, h)).transformed(local);
    }

    /**
     * A mesh: its data placed once in the mesh buffers (shared by every instance of it), the leaf
     * pointing there; a top-level one is also listed for rasterising.
     */
    private Aabb mesh(Mesh m, Transform t) {
        MeshData data = m.data();
        int triangles = data.triangleCount();
        if (triangles == 0) return empty(m.material());
        if (inCsg && !data.closed()) {
            throw new UnsupportedSceneException("the live view draws only closed meshes inside CSG; the mesh "
                    + data.name() + " at " + m.span() + " is open");
        }
        if (inCsg && triangles > GpuScene.MESH_BVH_LIMIT) {
            throw new UnsupportedSceneException("the live view draws meshes of at most " + GpuScene.MESH_BVH_LIMIT
                    + " triangles inside CSG; the mesh " + data.name() + " at " + m.span() + " has " + triangles);
        }
        boolean normals = m.smooth() && data.normals() != null;
        int[] base = meshBases.get(data);
        if (base == null) {
            int[] order = data.triangles();
            int nodes = 0;
            if (triangles > GpuScene.MESH_CAST_LIMIT && triangles <= GpuScene.MESH_BVH_LIMIT) {
                // Too many to cast triangle by triangle: a hierarchy, its triangles in its leaves' order.
                MeshBvh bvh = MeshBvh.of(data);
                order = bvh.triangles;
                nodes = meshNodeTexels + 1;
                if (meshNodes.length < 4 * meshNodeTexels + bvh.nodes.length) {
                    meshNodes = Arrays.copyOf(meshNodes, Math.max(2 * meshNodes.length, 4 * meshNodeTexels + bvh.nodes.length));
                }
                System.arraycopy(bvh.nodes, 0, meshNodes, 4 * meshNodeTexels, bvh.nodes.length);
                meshNodeTexels += bvh.nodes.length / 4;
            }
            base = new int[] {meshVertexTexels, meshIndexCount, nodes};
            meshBases.put(data, base);
            meshes.add(data);
            meshTriangles.add(order);
            meshVertexTexels += data.vertexCount() * (data.normals() != null ? 2 : 1);
            meshIndexCount += data.triangles().length;
            // The leaf holds the bases as floats: exact up to 2^24.
            if (meshVertexTexels > 1 << 24 || meshIndexCount > 1 << 24 || meshNodeTexels > 1 << 24) {
                throw new UnsupportedSceneException("the live view draws meshes of at most " + (1 << 24)
                        + " vertices and indices in all; this scene has more");
            }
        }
        kinds |= 1 << GpuScene.MESH;
        int leaf = size / 4;
        texel(GpuScene.MESH, normals ? 1 : 0, base[0], base[1]);
        matrix(t.inverseMatrix());
        texel(triangles, data.closed() ? 1 : 0, data.vertexCount(), 0);
        texel(base[2], 0, 0, 0);
        material(m.material());
        if (!inCsg) {
            int n = meshInstanceCount++;
            int k = GpuScene.MESH_INSTANCE_INTS;
            if (meshInstances.length < k * meshInstanceCount) {
                meshInstances = Arrays.copyOf(meshInstances, 2 * k * meshInstanceCount);
                meshMatrices = Arrays.copyOf(meshMatrices, 2 * 12 * meshInstanceCount);
            }
            meshInstances[k * n] = entityHeader;
            meshInstances[k * n + 1] = leaf;
            meshInstances[k * n + 2] = base[0];
            meshInstances[k * n + 3] = base[1];
            meshInstances[k * n + 4] = triangles;
            double[] w = t.matrix();
            for (int i = 0; i < 12; i++) meshMatrices[12 * n + i] = (float) w[i];
        }
        double[] p = data.positions();
        double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0, x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
        for (int i = 0; i < p.length; i += 3) {
            x0 = Math.min(x0, p[i]);
            y0 = Math.min(y0, p[i + 1]);
            z0 = Math.min(z0, p[i + 2]);
            x1 = Math.max(x1, p[i]);
            y1 = Math.max(y1, p[i + 1]);
            z1 = Math.max(z1, p[i + 2]);
        }
        return new Aabb(new Vec3(x0, y0, z0), new Vec3(x1, y1, z1)).transformed(t);
    }

    private Aabb box(Box b, Transform t) {
        leafHeader(GpuScene.BOX);
        matrix(t.inverseMatrix());
        texel(b.min().x(), b.min().y(), b.min().z(), 0);
        texel(b.max().x(), b.max().y(), b.max().z(), 0);
        material(b.material());
        return new Aabb(b.min(), b.max()).transformed(t);
    }

    private Aabb plane(Plane p, Transform t) {
        Vec3 n = t.applyToNormal(p.normal()).normalize();
        Vec3 q = t.applyToPoint(p.position());
        leafHeader(GpuScene.PLANE);
        texel(n.x(), n.y(), n.z(), n.dot(q));
        zeros(4);
        material(p.material());
        return Aabb.INFINITE;
    }

    private void leafHeader(int kind) {
        texel(kind, 0, 0, 0);
    }

    private void matrix(double[] m) {
        for (int row = 0; row < 3; row++) texel(m[4 * row], m[4 * row + 1], m[4 * row + 2], m[4 * row + 3]);
    }

    private void material(Material m) {
        if (m.reflectivity() > 0 || m.transparency() > 0) seesBackground = true;
        texel(m.color().r(), m.color().g(), m.color().b(), m.diffuse());
        texel(m.specular(), m.shininess(), m.transparency(), m.reflectivity());
        texel(m.emission().r(), m.emission().g(), m.emission().b(), 0);
    }

    private void zeros(int texels) {
        for (int i = 0; i < texels; i++) texel(0, 0, 0, 0);
    }

    private void texel(double a, double b, double c, double d) {
        reserve(4);
        data[size++] = (float) a;
        data[size++] = (float) b;
        data[size++] = (float) c;
        data[size++] = (float) d;
    }

    private void reserve(int floats) {
        if (size + floats > data.length) data = Arrays.copyOf(data, Math.max(2 * data.length, size + floats));
    }

    private static double maxAbs(Vec3 v) {
        return Math.max(Math.abs(v.x()), Math.max(Math.abs(v.y()), Math.abs(v.z())));
    }

    private static String kindName(Object o) {
        return o.getClass().getSimpleName();
    }
}
