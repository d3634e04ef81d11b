package dev.crt.scene;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;

/**
 * A cone or frustum along the segment from {@code from} to {@code to}, its radius going linearly
 * from {@code radius} at {@code from} to {@code radius2} at {@code to} (before the transform);
 * {@code capped} false leaves an open surface rather than a solid.
 */
public record Cone(Vec3 from, Vec3 to, double radius, double radius2, boolean capped, Material material,
        Transform transform, SourceSpan span) implements Primitive {
    @Override
    public Cone transformed(Transform t) {
        return new Cone(from, to, radius, radius2, capped, material, transform.then(t), span);
    }
}
