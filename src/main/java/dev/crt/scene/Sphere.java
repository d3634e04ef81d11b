package dev.crt.scene;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;

/**
 * A ball of {@code radius} about the centre (x, y, z) (before the transform); radius 0 is
 * invisible. The centre is held as three numbers, not as a {@link Vec3} of its own: a scene of a
 * million spheres holds a million fewer objects, which its compile's collections no longer copy
 * (docs/benchmarks.md section 42).
 */
public record Sphere(double x, double y, double z, double radius, Material material, Transform transform, SourceSpan span)
        implements Primitive {
    public Sphere(Vec3 center, double radius, Material material, Transform transform, SourceSpan span) {
        this(center.x(), center.y(), center.z(), radius, material, transform, span);
    }

    /** The centre, before the transform. */
    public Vec3 center() {
        return new Vec3(x, y, z);
    }

    @Override
    public Sphere transformed(Transform t) {
        return new Sphere(x, y, z, radius, material, transform.then(t), span);
    }
}
