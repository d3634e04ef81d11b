package dev.crt.scene;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;

/** A ball of {@code radius} about {@code center} (before the transform); radius 0 is invisible. */
public record Sphere(Vec3 center, double radius, Material material, Transform transform, SourceSpan span)
        implements Primitive {
    @Override
    public Sphere transformed(Transform t) {
        return new Sphere(center, radius, material, transform.then(t), span);
    }
}
