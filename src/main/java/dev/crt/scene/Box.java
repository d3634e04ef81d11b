package dev.crt.scene;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;

/** An axis-aligned box (before the transform) between {@code min} and {@code max}, min ≤ max. */
public record Box(Vec3 min, Vec3 max, Material material, Transform transform, SourceSpan span)
        implements Primitive {
    /** A box from two opposite corners given in any order. */
    public static Box ofCorners(Vec3 a, Vec3 b, Material material, Transform transform, SourceSpan span) {
        return new Box(a.min(b), a.max(b), material, transform, span);
    }

    @Override
    public Box transformed(Transform t) {
        return new Box(min, max, material, transform.then(t), span);
    }
}
