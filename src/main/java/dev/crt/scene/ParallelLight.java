package dev.crt.scene;

import dev.crt.geom.Vec3;

/** A light from infinitely far away, travelling in the direction from {@code from} to {@code pointing}. */
public record ParallelLight(Vec3 from, Vec3 pointing, Rgb color, double ambient, SourceSpan span)
        implements Light {
    /** The unit direction towards the light, the same at every point. */
    public Vec3 towardsLight() { return from.minus(pointing).normalize(); }
}
