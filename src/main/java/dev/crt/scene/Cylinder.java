package dev.crt.scene;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;

/**
 * The points within {@code radius} of the segment from {@code from} to {@code to} whose projection
 * falls on it (before the transform); {@code capped} false leaves an open tube, a surface rather
 * than a solid.
 */
public record Cylinder(Vec3 from, Vec3 to, double radius, boolean capped, Material material, Transform transform,
        SourceSpan span) implements Primitive {
    @Override
    public Cylinder transformed(Transform t) {
        return new Cylinder(from, to, radius, capped, material, transform.then(t), span);
    }
}
