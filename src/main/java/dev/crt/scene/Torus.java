package dev.crt.scene;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;

/**
 * The points within {@code minor} of the ring circle of radius {@code major} about {@code center}
 * in the plane normal to the unit {@code axis} (before the transform); minor &gt; major is a
 * spindle torus.
 */
public record Torus(Vec3 center, Vec3 axis, double major, double minor, Material material, Transform transform,
        SourceSpan span) implements Primitive {
    @Override
    public Torus transformed(Transform t) {
        return new Torus(center, axis, major, minor, material, transform.then(t), span);
    }
}
