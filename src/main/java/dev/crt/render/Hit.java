package dev.crt.render;

/**
 * The nearest surface found so far along a ray: its parameter, the primitive and face it lies on,
 * and whether the primitive's outward normal must be flipped to point out of the visible solid
 * (surfaces of B exposed by A − B). Per-thread scratch.
 */
final class Hit {
    double t;
    int shape;
    int face;
    boolean flip;
}
