package dev.crt.lang.value;

import dev.crt.geom.Vec3;

/** A vec3: a point, a direction or a triple of angles. */
public record VectorValue(Vec3 vector) implements Value {
    @Override
    public String typeName() { return "vec3"; }

    @Override
    public String toString() {
        return "vec3(" + NumberValue.format(vector.x()) + ", " + NumberValue.format(vector.y()) + ", "
                + NumberValue.format(vector.z()) + ")";
    }
}
