package dev.crt.live;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.fail;

import dev.crt.geom.Aabb;
import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.Background;
import dev.crt.scene.AreaLight;
import dev.crt.scene.Box;
import dev.crt.scene.Cone;
import dev.crt.scene.Cylinder;
import dev.crt.scene.Csg;
import dev.crt.scene.Cylinder;
import dev.crt.scene.CsgOperation;
import dev.crt.scene.Entity;
import dev.crt.scene.GradientBackground;
import dev.crt.scene.Light;
import dev.crt.scene.Material;
import dev.crt.scene.Mesh;
import dev.crt.scene.MeshData;
import dev.crt.scene.PanoramaBackground;
import dev.crt.scene.ParallelLight;
import dev.crt.scene.Picture;
import dev.crt.scene.Plane;
import dev.crt.scene.PointLight;
import dev.crt.scene.Rgb;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import dev.crt.scene.SolidBackground;
import dev.crt.scene.SourceSpan;
import dev.crt.scene.Sphere;
import dev.crt.scene.SpotLight;
import dev.crt.scene.Torus;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;

class SceneConverterTest {
    static final Material M = Material.DEFAULT;
    static final Sphere SPHERE = new Sphere(new Vec3(1, 2, 3), 2, M, Transform.IDENTITY, SourceSpan.NONE);
    static final Box BOX = new Box(new Vec3(-1, -1, -1), new Vec3(1, 1, 1), M, Transform.IDENTITY, SourceSpan.NONE);
    static final Plane PLANE = new Plane(new Vec3(0, 1, 0), new Vec3(0, -1, 0), M, Transform.IDENTITY, SourceSpan.NONE);

    /**
     * Kinds of the scene model the live view does not draw yet (none today; a new kind from
     * another issue goes here until it is drawn): the converter refuses them with one sentence
     * naming the kind, which crt preview prints with exit code 4 and the studio shows in place of
     * the live view. A kind in neither list fails the test below.
     */
    static final Map<Class<?>, Object> NOT_DRAWN_YET = Map.of();

    /** One sample of every concrete kind the scene model has; a new kind must be added here and to the converter. */
    static final Map<Class<?>, Object> SAMPLES = Map.ofEntries(Map.entry(
            Sphere.class, SPHERE),
            Map.entry(Box.class, BOX),
            Map.entry(Plane.class, PLANE),
            Map.entry(Cylinder.class, new Cylinder(Vec3.ZERO, new Vec3(0, 1, 0), 1, true, M, Transform.IDENTITY, SourceSpan.NONE)),
            Map.entry(Cone.class, new Cone(Vec3.ZERO, new Vec3(0, 1, 0), 1, 0, false, M, Transform.IDENTITY, SourceSpan.NONE)),
            Map.entry(Torus.class, new Torus(Vec3.ZERO, new Vec3(0, 1, 0), 1, 0.25, M, Transform.IDENTITY, SourceSpan.NONE)),
            Map.entry(Mesh.class, new Mesh(new MeshData("triangle", new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, new int[] {0, 1, 2},
                    null, null, false), true, M, Transform.IDENTITY, SourceSpan.NONE)),
            Map.entry(Csg.class, new Csg(CsgOperation.DIFFERENCE, BOX, SPHERE, Transform.IDENTITY, SourceSpan.NONE)),
            Map.entry(PointLight.class, new PointLight(new Vec3(0, 5, 0), Rgb.WHITE, 10, 0.1, SourceSpan.NONE)),
            Map.entry(ParallelLight.class, new ParallelLight(new Vec3(1, 1, 1), Vec3.ZERO, Rgb.WHITE, 0, SourceSpan.NONE)),
            Map.entry(SpotLight.class, new SpotLight(new Vec3(0, 5, 0), Vec3.ZERO, 30, 20, Rgb.WHITE, 0, 0.1, SourceSpan.NONE)),
            Map.entry(AreaLight.class, new AreaLight(new Vec3(-1, 5, -1), new Vec3(2, 0, 0), new Vec3(0, 0, 2), 4, Rgb.WHITE, 0, 0,
                    SourceSpan.NONE)),
            Map.entry(SolidBackground.class, new SolidBackground(Rgb.GREY)),
            Map.entry(GradientBackground.class, new GradientBackground(Rgb.WHITE, Rgb.BLACK)),
            Map.entry(PanoramaBackground.class, new PanoramaBackground("p.png", new Picture(1, 1, new float[3]), 0)));

    static Set<Class<?>> concreteKinds(Class<?> sealed) {
        Set<Class<?>> out = new LinkedHashSet<>();
        if (!sealed.isSealed()) {
            out.add(sealed);
            return out;
        }
        for (Class<?> c : sealed.getPermittedSubclasses()) out.addAll(concreteKinds(c));
        return out;
    }

    static Scene scene(List<Entity> entities, List<Light> lights, Background background) {
        Settings s = Settings.DEFAULT;
        s = new Settings("", "", "", "", lights, s.camera(), background, 1, 1, 5, 1, 64, 48);
        return new Scene("test", s, entities);
    }

    @Test
    void everyKindOfTheSceneModelConverts() {
        List<Class<?>> kinds = new ArrayList<>();
        kinds.addAll(concreteKinds(Entity.class));
        kinds.addAll(concreteKinds(Light.class));
        kinds.addAll(concreteKinds(Background.class));
        assertThat(kinds).hasSizeGreaterThanOrEqualTo(9);
        for (Class<?> kind : kinds) {
            if (NOT_DRAWN_YET.containsKey(kind)) {
                Scene s = scene(List.of((Entity) NOT_DRAWN_YET.get(kind)), List.of(), Background.BLACK);
                assertThatThrownBy(() -> SceneConverter.convert(s)).isInstanceOf(UnsupportedSceneException.class)
                        .hasMessage("the live view cannot draw a " + kind.getSimpleName() + " yet");
                continue;
            }
            Object sample = SAMPLES.get(kind);
            if (sample == null) {
                fail("the scene model has a kind the live view was not taught: " + kind.getName()
                        + "; add it to SceneConverter (and LiveRenderer's shader) and a sample here");
            }
            Scene s = sample instanceof Entity e ? scene(List.of(e), List.of(), Background.BLACK)
                    : sample instanceof Light l ? scene(List.of(SPHERE), List.of(l), Background.BLACK)
                    : scene(List.of(SPHERE), List.of(), (Background) sample);
            GpuScene g = SceneConverter.convert(s);
            assertThat(g.entityCount()).as(kind.getSimpleName()).isEqualTo(1);
        }
    }

    @Test
    void aCsgTreeBecomesAPostfixProgramWithItsPrimitivesInOrder() {
        Csg tree = new Csg(CsgOperation.INTERSECTION,
                new Csg(CsgOperation.DIFFERENCE, BOX, SPHERE, Transform.IDENTITY, SourceSpan.NONE), PLANE,
                Transform.translation(new Vec3(5, 0, 0)), SourceSpan.NONE);
        GpuScene g = SceneConverter.convert(scene(List.of(SPHERE, tree), List.of(), Background.BLACK));
        float[] d = g.texelData();
        int o = 4 * g.entityOffset[1];
        assertThat(d[o]).as("leaves").isEqualTo(3);
        assertThat(d[o + 1]).as("program steps").isEqualTo(5);
        assertThat(d[o + 2]).as("entity index").isEqualTo(1);
        int p = o + 4 * GpuScene.HEADER_TEXELS;
        int[][] expected = {{GpuScene.OP_LEAF, 0}, {GpuScene.OP_LEAF, 1}, {GpuScene.OP_DIFFERENCE, 0},
            {GpuScene.OP_LEAF, 2}, {GpuScene.OP_INTERSECTION, 0}};
        for (int s = 0; s < 5; s++) {
            assertThat(new float[] {d[p + 4 * s], d[p + 4 * s + 1]}).as("step %d", s)
                    .containsExactly(expected[s][0], expected[s][1]);
        }
        int leaves = p + 4 * 5;
        assertThat(d[leaves]).isEqualTo(GpuScene.BOX);
        // The box sits 5 to the right: its world-to-local matrix moves x back by 5.
        assertThat(d[leaves + 4 + 3]).isEqualTo(-5f);
        assertThat(d[leaves + 4 * GpuScene.LEAF_TEXELS]).isEqualTo(GpuScene.SPHERE);
        assertThat(d[leaves + 8 * GpuScene.LEAF_TEXELS]).isEqualTo(GpuScene.PLANE);
        // The box minus a sphere, cut by a half-space: bounded by the box, moved.
        assertThat(g.entityBounds(1)).isEqualTo(new Aabb(new Vec3(4, -1, -1), new Vec3(6, 1, 1)));
        assertThat(g.boundedOffsets).hasSize(2);
        assertThat(g.unboundedOffsets).isEmpty();
    }

    @Test
    void aUnitSphereFrameMapsTheSurfaceToRadiusOne() {
        GpuScene g = SceneConverter.convert(scene(List.of(SPHERE), List.of(), Background.BLACK));
        float[] d = g.texelData();
        int leaf = 4 * (GpuScene.HEADER_TEXELS + 1);
        // World point (3, 2, 3) is on the sphere about (1, 2, 3) of radius 2: local (1, 0, 0).
        double x = d[leaf + 4] * 3 + d[leaf + 5] * 2 + d[leaf + 6] * 3 + d[leaf + 7];
        assertThat(x).isCloseTo(1, org.assertj.core.data.Offset.offset(1e-6));
        assertThat(g.entityBounds(0)).isEqualTo(new Aabb(new Vec3(-1, 0, 1), new Vec3(3, 4, 5)));
    }

    @Test
    void planesAndWhatTheyReachAreUnbounded() {
        Csg cut = new Csg(CsgOperation.DIFFERENCE, PLANE, SPHERE, Transform.IDENTITY, SourceSpan.NONE);
        GpuScene g = SceneConverter.convert(scene(List.of(PLANE, cut, BOX), List.of(), Background.BLACK));
        assertThat(g.unboundedOffsets).hasSize(2);
        assertThat(g.boundedOffsets).hasSize(1);
        assertThat(g.bounds()).isEqualTo(new Aabb(new Vec3(-1, -1, -1), new Vec3(1, 1, 1)));
    }

    @Test
    void unboundedOnesAloneComeFirstAndALonePlaneKeepsItsPlaneInPlaceOfBounds() {
        Csg cut = new Csg(CsgOperation.DIFFERENCE, PLANE, SPHERE, Transform.IDENTITY, SourceSpan.NONE);
        Plane moved = new Plane(new Vec3(0, 1, 0), new Vec3(0, -1, 0), M, Transform.translation(new Vec3(0, 3, 0)),
                SourceSpan.NONE);
        GpuScene g = SceneConverter.convert(scene(List.of(cut, PLANE, BOX, moved), List.of(), Background.BLACK));
        assertThat(g.unboundedOffsets).containsExactly(g.entityOffset[1], g.entityOffset[3], g.entityOffset[0]);
        assertThat(g.unboundedPrimitives).isEqualTo(2);
        float[] d = g.texelData();
        int o = 4 * g.entityOffset[3];
        // y = -1 moved up by 3: the plane y = 2, its normal (0, 1, 0) and offset 2.
        assertThat(new float[] {d[o + 7], d[o + 8], d[o + 9], d[o + 10], d[o + 11]}).containsExactly(2, 0, 1, 0, 2);
        assertThat(d[4 * g.entityOffset[0] + 7]).as("CSG reaching a half-space: unbounded, no plane").isEqualTo(1);
        assertThat(d[4 * g.entityOffset[2] + 7]).as("bounded").isEqualTo(0);
    }

    @Test
    void theTruthTableAgreesWithTheProgramOnEveryMask() {
        // ((box - sphere) ^ plane) + sphere - box: five primitives, 32 entries in two floats.
        Csg tree = new Csg(CsgOperation.DIFFERENCE,
                new Csg(CsgOperation.UNION, new Csg(CsgOperation.INTERSECTION,
                        new Csg(CsgOperation.DIFFERENCE, BOX, SPHERE, Transform.IDENTITY, SourceSpan.NONE), PLANE,
                        Transform.IDENTITY, SourceSpan.NONE), SPHERE, Transform.IDENTITY, SourceSpan.NONE),
                BOX, Transform.IDENTITY, SourceSpan.NONE);
        GpuScene g = SceneConverter.convert(scene(List.of(tree), List.of(), Background.BLACK));
        assertThat(g.tables).isTrue();
        float[] d = g.texelData();
        int p = 4 * (g.entityOffset[0] + GpuScene.HEADER_TEXELS);
        for (int mask = 0; mask < 32; mask++) {
            boolean box0 = (mask & 1) != 0, sphere1 = (mask & 2) != 0, plane2 = (mask & 4) != 0, sphere3 = (mask & 8) != 0,
                    box4 = (mask & 16) != 0;
            boolean expected = ((box0 && !sphere1 && plane2) || sphere3) && !box4;
            int chunk = mask >> 4;
            int bits = (int) d[p + 4 * (chunk >> 1) + 2 + (chunk & 1)];
            assertThat((bits >> (mask & 15) & 1) != 0).as("mask %d", mask).isEqualTo(expected);
        }
    }

    @Test
    void csgOfMoreThanTablePrimitivesHasNoTable() {
        Entity e = SPHERE;
        for (int i = 0; i < GpuScene.TABLE_LEAVES; i++) e = new Csg(CsgOperation.UNION, e, BOX, Transform.IDENTITY, SourceSpan.NONE);
        assertThat(SceneConverter.convert(scene(List.of(e), List.of(), Background.BLACK)).tables).isFalse();
    }

    private static MeshData tetrahedron(int copies) {
        double[] p = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
        int[] one = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
        int[] t = new int[one.length * copies];
        for (int i = 0; i < copies; i++) System.arraycopy(one, 0, t, one.length * i, one.length);
        return new MeshData("tetrahedron", p, t, null, null, true);
    }

    @Test
    void meshesAreSentOnceAndTopLevelOnesListedForRasterising() {
        MeshData data = tetrahedron(1);
        Mesh a = new Mesh(data, false, M, Transform.IDENTITY, SourceSpan.NONE);
        Mesh b = new Mesh(data, false, M, Transform.translation(new Vec3(5, 0, 0)), SourceSpan.NONE);
        Csg cut = new Csg(CsgOperation.DIFFERENCE, b, SPHERE, Transform.IDENTITY, SourceSpan.NONE);
        GpuScene g = SceneConverter.convert(scene(List.of(SPHERE, a, cut, a), List.of(), Background.BLACK));
        // One copy of the data for the three instances; the two top-level ones drawn as triangles.
        assertThat(g.meshes).containsExactly(data);
        assertThat(g.meshVertexTexels).isEqualTo(4);
        assertThat(g.meshIndexCount).isEqualTo(12);
        assertThat(g.meshInstances).hasSize(2 * GpuScene.MESH_INSTANCE_INTS);
        assertThat(g.meshInstances[0]).isEqualTo(g.entityOffset[1]);
        assertThat(g.meshInstances[GpuScene.MESH_INSTANCE_INTS]).isEqualTo(g.entityOffset[3]);
        assertThat(g.meshInstances[4]).as("triangles").isEqualTo(4);
        // The sphere and the CSG tree are ray-cast in proxy boxes; the meshes are not.
        assertThat(g.boundedOffsets).containsExactly(g.entityOffset[0], g.entityOffset[2]);
        assertThat(g.entityBounds(2)).isEqualTo(new Aabb(new Vec3(5, 0, 0), new Vec3(6, 1, 1)));
        assertThat(g.texelData()[4 * g.meshInstances[1]]).isEqualTo(GpuScene.MESH);
    }

    @Test
    void preparingASceneBuildsTheHierarchiesOfItsLargeMeshesAheadAndNoOthers() {
        SourceSpan at = new SourceSpan("m.crt", 4, 9, 0, 1);
        // Contents no other test uses, so that nothing has built them before.
        MeshData inCsg = MeshBvhTest.sphere(13, 17), alone = MeshBvhTest.sphere(11, 19), small = tetrahedron(2);
        Mesh a = new Mesh(inCsg, false, M, Transform.IDENTITY, at), b = new Mesh(alone, false, M, Transform.IDENTITY, at);
        Mesh c = new Mesh(small, false, M, Transform.IDENTITY, at);
        Scene s = scene(List.of(new Csg(CsgOperation.DIFFERENCE, SPHERE, new Csg(CsgOperation.UNION, SPHERE, a, Transform.IDENTITY, at),
                Transform.IDENTITY, at), b, c), List.of(), Background.BLACK);
        assertThat(MeshBvh.isBuilt(inCsg) || MeshBvh.isBuilt(alone)).isFalse();
        SceneConverter.prepare(s);
        assertThat(MeshBvh.isBuilt(inCsg)).as("a mesh deep in CSG").isTrue();
        assertThat(MeshBvh.isBuilt(alone)).as("a mesh on its own").isTrue();
        assertThat(MeshBvh.isBuilt(small)).as("a mesh cast triangle by triangle").isFalse();
        assertThat(SceneConverter.convert(s).meshNodes).isNotEmpty();
    }

    @Test
    void openMeshesAreRefusedInCsgWithTheirPlaceAndLargeOnesGetAHierarchy() {
        SourceSpan at = new SourceSpan("m.crt", 4, 9, 0, 1);
        MeshData many = MeshBvhTest.sphere(12, 12);
        Mesh big = new Mesh(many, false, M, Transform.IDENTITY, at);
        Scene s = scene(List.of(new Csg(CsgOperation.UNION, big, SPHERE, Transform.IDENTITY, at), SPHERE, big), List.of(),
                Background.BLACK);
        GpuScene g = SceneConverter.convert(s);
        // Sent once, its triangles in the hierarchy's order; both leaves point at its nodes.
        assertThat(g.meshes).hasSize(1);
        assertThat(g.meshTriangles.get(0)).isEqualTo(MeshBvh.of(many).triangles);
        assertThat(g.meshNodes).isEqualTo(MeshBvh.of(many).nodes);
        float[] d = g.texelData();
        int csgLeaf = 4 * (g.entityOffset[0] + GpuScene.HEADER_TEXELS + 3);
        assertThat(d[csgLeaf]).isEqualTo(GpuScene.MESH);
        assertThat(d[csgLeaf + 4 * 5]).as("node base + 1").isEqualTo(1);
        assertThat(d[4 * g.meshInstances[1] + 4 * 5]).as("the top-level instance too").isEqualTo(1);
        // Beyond the hierarchy's limit: refused inside CSG with its place, drawn alone without one.
        Mesh huge = new Mesh(tetrahedron(GpuScene.MESH_BVH_LIMIT / 4 + 1), false, M, Transform.IDENTITY, at);
        Scene h = scene(List.of(new Csg(CsgOperation.UNION, huge, SPHERE, Transform.IDENTITY, at)), List.of(), Background.BLACK);
        assertThatThrownBy(() -> SceneConverter.convert(h)).isInstanceOf(UnsupportedSceneException.class)
                .hasMessage("the live view draws meshes of at most 100000 triangles inside CSG; the mesh tetrahedron at m.crt:4:9"
                        + " has 100004");
        assertThat(SceneConverter.convert(scene(List.of(huge), List.of(), Background.BLACK)).meshNodes).isEmpty();
        // A small mesh has none.
        GpuScene small = SceneConverter.convert(scene(List.of(new Mesh(tetrahedron(1), false, M, Transform.IDENTITY, at)),
                List.of(), Background.BLACK));
        assertThat(small.meshNodes).isEmpty();
        assertThat(small.texelData()[4 * small.meshInstances[1] + 4 * 5]).isEqualTo(0);
        MeshData open = new MeshData("sheet", new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, new int[] {0, 1, 2}, null, null, false);
        Scene o = scene(List.of(new Csg(CsgOperation.UNION, new Mesh(open, false, M, Transform.IDENTITY, at), SPHERE,
                Transform.IDENTITY, at)), List.of(), Background.BLACK);
        assertThatThrownBy(() -> SceneConverter.convert(o)).isInstanceOf(UnsupportedSceneException.class)
                .hasMessage("the live view draws only closed meshes inside CSG; the mesh sheet at m.crt:4:9 is open");
    }

    @Test
    void tooLargeACsgTreeIsRefusedWithItsPlace() {
        Entity e = SPHERE;
        for (int i = 0; i < GpuScene.MAX_LEAVES; i++) {
            e = new Csg(CsgOperation.UNION, e, SPHERE, Transform.IDENTITY, new SourceSpan("big.crt", 7, 3, 0, 1));
        }
        Scene s = scene(List.of(e), List.of(), Background.BLACK);
        assertThatThrownBy(() -> SceneConverter.convert(s)).isInstanceOf(UnsupportedSceneException.class)
                .hasMessage("the live view draws CSG of at most 32 primitives; the entity at big.crt:7:3 has 33");
    }
}
