package dev.crt.render;

import dev.crt.scene.Entity;

/**
 * What the primary ray through a pixel's centre meets first: the top-level entity (its index in
 * the scene's entity list, and the entity itself with the SourceSpan that wrote it) and the
 * distance from the camera along the ray.
 */
public record Pick(int entityIndex, Entity entity, double distance) {}
