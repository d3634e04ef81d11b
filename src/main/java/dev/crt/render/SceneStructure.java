package dev.crt.render;

/**
 * What {@link Renderer#prepare} built: bounded items in the BVH, unbounded items tested by every
 * ray, primitives in total (CSG leaves included), BVH nodes and depth (0 when the scene is small
 * enough to test every item).
 */
public record SceneStructure(int boundedItems, int unboundedItems, int primitives, int bvhNodes, int bvhDepth) {}
