package dev.crt.render;

/**
 * One sample of one light as seen from a shading point: the unit direction towards it, the
 * squared distance and distance, the light's falloff, the weight its kind puts on the diffuse and
 * specular terms (a spot's cone, an area sample's cosine and share), and the point a shadow ray
 * aims at. Scratch state, one per tracer, overwritten by every {@link Lights#sample} call.
 */
final class LightSample {
    double wx, wy, wz;
    double d2, dist;
    double falloff;
    /** 1 for point and parallel lights; the factor the light's kind adds otherwise. */
    double weight;
    /** False for a parallel light: no point to aim at, the shadow ray is unbounded. */
    boolean finite;
    double tx, ty, tz;
}
