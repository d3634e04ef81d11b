package dev.crt.scene;

import dev.crt.geom.Transform;

/**
 * A solid placed in the scene: a primitive or a CSG combination. Every entity carries the affine
 * transform its modifiers built (object to world) and the place in the script that made it.
 */
public sealed interface Entity permits Primitive, Csg {
    Transform transform();

    SourceSpan span();

    /** A copy with {@code t} applied after the entity's own transform. */
    Entity transformed(Transform t);
}
