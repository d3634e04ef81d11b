package dev.crt.scene;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;

/**
 * The plane through {@code position} with unit {@code normal}; as a solid (for CSG) it is the
 * half-space on the side opposite the normal.
 */
public record Plane(Vec3 normal, Vec3 position, Material material, Transform transform, SourceSpan span)
        implements Primitive {
    @Override
    public Plane transformed(Transform t) {
        return new Plane(normal, position, material, transform.then(t), span);
    }
}
