package dev.crt.render;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.Cone;
import dev.crt.scene.Cylinder;
import dev.crt.scene.Material;
import dev.crt.scene.Mesh;
import dev.crt.scene.SourceSpan;
import dev.crt.scene.Torus;
import dev.crt.scene.Primitive;
import java.util.List;

/** Samples of the primitive types added after spheres, boxes and planes, for the tests that walk every kind. */
final class ShapeSamples {
    private ShapeSamples() {}

    static List<Primitive> secondWave(Material m) {
        return List.of(
                new Cylinder(new Vec3(0, -1, 0.2), new Vec3(0.3, 1, 0), 0.6, true, m, Transform.IDENTITY, SourceSpan.NONE),
                new Cylinder(new Vec3(0, -1, 0.2), new Vec3(0.3, 1, 0), 0.6, false, m, Transform.IDENTITY, SourceSpan.NONE),
                new Cone(new Vec3(0.1, -1, 0), new Vec3(0, 1, 0.3), 1, 0.2, true, m, Transform.IDENTITY, SourceSpan.NONE),
                new Cone(new Vec3(0.1, -1, 0), new Vec3(0, 1, 0.3), 0.9, 0, false, m, Transform.IDENTITY, SourceSpan.NONE),
                new Torus(new Vec3(0.1, 0.2, 0), new Vec3(0.2, 1, -0.3).normalize(), 1, 0.3, m, Transform.IDENTITY, SourceSpan.NONE),
                new Torus(new Vec3(0, 0, 0), new Vec3(0, 0, 1), 0.5, 0.8, m, Transform.IDENTITY, SourceSpan.NONE),
                new Mesh(Meshes.torus(1, 0.4, 16, 8), true, m, Transform.translation(new Vec3(0.1, 0, 0)), SourceSpan.NONE),
                new Mesh(Meshes.grid(3), false, m, Transform.translation(new Vec3(-1.4, -1.6, 0.2)), SourceSpan.NONE));
    }
}
