package dev.crt.scene;

import dev.crt.geom.Vec3;

/**
 * A light-emitting parallelogram {@code corner + s·edge1 + t·edge2}, s, t ∈ [0, 1], shining to
 * both sides, sampled at {@code samples}² stratified points per shading point (soft shadows).
 */
public record AreaLight(Vec3 corner, Vec3 edge1, Vec3 edge2, int samples, Rgb color, double falloff, double ambient,
        SourceSpan span) implements Light {}
