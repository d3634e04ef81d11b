package dev.crt.render;

/**
 * The AreaLight kind: sample k of n² lies at Q = Q0 + s·e1 + t·e2 with (s, t) jittered uniformly
 * in cell (k mod n, k div n) of the n×n grid over the parallelogram; each sample is a point light
 * of colour Cℓ/n² with the extra factor |nl·ω| (the parallelogram emits to both sides).
 */
final class AreaLightSource {
    private AreaLightSource() {}

    static void sample(Lights l, int i, int k, double px, double py, double pz, PixelRandom random, LightSample s) {
        int n = l.samples[i];
        double u = (k % n + random.next()) / n, v = (k / n + random.next()) / n;
        double qx = l.x[i] + u * l.e1x[i] + v * l.e2x[i];
        double qy = l.y[i] + u * l.e1y[i] + v * l.e2y[i];
        double qz = l.z[i] + u * l.e1z[i] + v * l.e2z[i];
        double wx = qx - px, wy = qy - py, wz = qz - pz;
        double d2 = wx * wx + wy * wy + wz * wz;
        double dist = Math.sqrt(d2);
        s.d2 = d2;
        s.dist = dist;
        s.falloff = l.falloff[i];
        s.finite = true;
        s.tx = qx;
        s.ty = qy;
        s.tz = qz;
        if (dist == 0) {
            // A point on the light itself: no direction to it, and no light arrives edge-on.
            s.wx = l.ax[i];
            s.wy = l.ay[i];
            s.wz = l.az[i];
            s.weight = 0;
            return;
        }
        s.wx = wx / dist;
        s.wy = wy / dist;
        s.wz = wz / dist;
        s.weight = Math.abs(s.wx * l.ax[i] + s.wy * l.ay[i] + s.wz * l.az[i]) / ((double) n * n);
    }
}
