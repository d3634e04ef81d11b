package dev.crt.render;

/** The ParallelLight kind: the same direction towards the light everywhere, no distance, no falloff. */
final class ParallelLightSource {
    private ParallelLightSource() {}

    static void sample(Lights l, int i, LightSample s) {
        s.wx = l.x[i];
        s.wy = l.y[i];
        s.wz = l.z[i];
        s.d2 = Double.POSITIVE_INFINITY;
        s.dist = Double.POSITIVE_INFINITY;
        s.falloff = 0;
        s.weight = 1;
        s.finite = false;
    }
}
