package dev.crt.render;

/** The PointLight kind: ω = normalize(Q − X), d = |Q − X|. */
final class PointLightSource {
    private PointLightSource() {}

    static void sample(Lights l, int i, double px, double py, double pz, LightSample s) {
        double qx = l.x[i], qy = l.y[i], qz = l.z[i];
        double wx = qx - px, wy = qy - py, wz = qz - pz;
        double d2 = wx * wx + wy * wy + wz * wz;
        double dist = Math.sqrt(d2);
        s.wx = wx / dist;
        s.wy = wy / dist;
        s.wz = wz / dist;
        s.d2 = d2;
        s.dist = dist;
        s.falloff = l.falloff[i];
        s.weight = 1;
        s.finite = true;
        s.tx = qx;
        s.ty = qy;
        s.tz = qz;
    }
}
