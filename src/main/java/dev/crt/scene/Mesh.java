package dev.crt.scene;

import dev.crt.geom.Transform;

/**
 * A triangle mesh placed in the scene; instances of one file share its {@link MeshData}.
 * {@code smooth}: shade with interpolated vertex normals.
 */
public record Mesh(MeshData data, boolean smooth, Material material, Transform transform, SourceSpan span)
        implements Primitive {
    @Override
    public Mesh transformed(Transform t) {
        return new Mesh(data, smooth, material, transform.then(t), span);
    }
}
