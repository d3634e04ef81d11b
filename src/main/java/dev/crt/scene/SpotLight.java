package dev.crt.scene;

import dev.crt.geom.Vec3;

/**
 * A point light at {@code origin} lighting a cone about the direction towards {@code pointing}:
 * full strength within {@code innerAngle} of the axis, none beyond {@code angle}, a smoothstep
 * between (half-angles in degrees).
 */
public record SpotLight(Vec3 origin, Vec3 pointing, double angle, double innerAngle, Rgb color, double falloff,
        double ambient, SourceSpan span) implements Light {}
