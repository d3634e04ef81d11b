package dev.crt.scene;

import dev.crt.geom.Transform;

/** {@code left op right}, as a solid; surfaces keep the materials of the primitives they belong to. */
public record Csg(CsgOperation operation, Entity left, Entity right, Transform transform, SourceSpan span)
        implements Entity {
    @Override
    public Csg transformed(Transform t) {
        return new Csg(operation, left, right, transform.then(t), span);
    }
}
