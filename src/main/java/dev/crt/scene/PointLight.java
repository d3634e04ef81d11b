package dev.crt.scene;

import dev.crt.geom.Vec3;

/** A light at a point; {@code falloff} 0 means no attenuation with distance, else falloff/d². */
public record PointLight(Vec3 origin, Rgb color, double falloff, double ambient, SourceSpan span)
        implements Light {}
