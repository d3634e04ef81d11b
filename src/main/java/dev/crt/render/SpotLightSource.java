package dev.crt.render;

/**
 * The SpotLight kind: a point light times s = smoothstep(cos(angle), cos(innerangle), ω'·a), with
 * a the unit axis and ω' = −ω the direction from the light to the point; a hard edge when the
 * two angles are equal.
 */
final class SpotLightSource {
    private SpotLightSource() {}

    static void sample(Lights l, int i, double px, double py, double pz, LightSample s) {
        PointLightSource.sample(l, i, px, py, pz, s);
        s.weight = cone(l.cosOuter[i], l.cosInner[i], -(s.wx * l.ax[i] + s.wy * l.ay[i] + s.wz * l.az[i]));
    }

    /** smoothstep(cosOuter, cosInner, x): 1 at or inside the inner cone, 0 at or outside the outer one. */
    static double cone(double cosOuter, double cosInner, double x) {
        if (x >= cosInner) return 1;
        if (x <= cosOuter) return 0;
        double t = (x - cosOuter) / (cosInner - cosOuter);
        return t * t * (3 - 2 * t);
    }
}
