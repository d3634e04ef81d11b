package dev.crt.render;

/**
 * CRT's local shading model (rendering-model.md): E + Σℓ aℓ(Cℓ⊙C) + Σ over each light's samples
 * of Sℓ·Aℓ·wℓ·(kd·max(0,N·ω)(Cℓ⊙C) + ks·max(0,R·V)^n·Cℓ), where wℓ is the factor of the light's
 * kind (1, a spot's cone, an area sample's cosine and share) and Sℓ the shadow factor of its
 * tracer (with Beer's-law absorption per channel when the scene has absorbing materials). One per
 * render thread; a light sample whose diffuse and specular terms are both zero casts no shadow ray,
 * and none is cast once the pixel's sum is sure to reach 1 ({@link Tracer#saturating}).
 */
final class PhongShading {
    private final Tracer tracer;
    private final double[] materials;
    private final Lights lights;
    private final LightSample sample = new LightSample();

    PhongShading(Tracer tracer, double[] materials, Lights lights) {
        this.tracer = tracer;
        this.materials = materials;
        this.lights = lights;
    }

    /**
     * The local colour of material m, of surface colour C = (cr, cg, cb), specular factor ks and
     * emission E = (er, eg, eb) (the material's, or its textures' at this point), at p with ray-facing
     * shading normal n and view direction v, into {@code colour}; shadow rays leave p along the
     * ray-facing geometric normal g (the same as n except on smooth meshes).
     */
    void shade(int m, double cr, double cg, double cb, double ks, double er, double eg, double eb, double px, double py, double pz, double gx, double gy, double gz,
            double nx, double ny, double nz, double vx, double vy, double vz, double delta, double[] colour) {
        double[] mat = materials;
        double kd = mat[m + Materials.DIFFUSE];
        double shininess = mat[m + Materials.SHININESS];
        double r = er + lights.ambientR * cr;
        double g = eg + lights.ambientG * cg;
        double b = eb + lights.ambientB * cb;
        double nv = nx * vx + ny * vy + nz * vz;
        Lights l = lights;
        LightSample ls = sample;
        Tracer t = tracer;
        boolean saturating = t.saturating;
        lights:
        for (int i = 0; i < l.count; i++) {
            byte kind = l.kind[i];
            for (int k = 0, samples = l.sampleCount(i); k < samples; k++) {
                double wx, wy, wz, d2, falloff, weight;
                if (kind == Lights.POINT) {
                    // The common case in locals (PointLightSource's formulas): no scratch traffic per light.
                    wx = l.x[i] - px;
                    wy = l.y[i] - py;
                    wz = l.z[i] - pz;
                    d2 = wx * wx + wy * wy + wz * wz;
                    double dist = Math.sqrt(d2);
                    wx /= dist;
                    wy /= dist;
                    wz /= dist;
                    falloff = l.falloff[i];
                    weight = 1;
                } else {
                    l.sample(i, k, px, py, pz, t.lightRandom, ls);
                    weight = ls.weight;
                    if (weight == 0) continue;
                    wx = ls.wx;
                    wy = ls.wy;
                    wz = ls.wz;
                    d2 = ls.d2;
                    falloff = ls.falloff;
                }
                double nw = nx * wx + ny * wy + nz * wz;
                double diffuse = nw > 0 ? kd * nw : 0;
                double specular = 0;
                if (ks != 0) {
                    double rv = 2 * nw * nv - (wx * vx + wy * vy + wz * vz);
                    if (rv > 0) specular = ks * Tracer.power(rv, shininess);
                }
                if (diffuse == 0 && specular == 0) continue;
                // The pixel's sum with this colour so far added already reaches 1: the rest cannot lower it.
                if (saturating && t.accR + t.localR * r >= 1 && t.accG + t.localG * g >= 1 && t.accB + t.localB * b >= 1) {
                    break lights;
                }
                double side = nw > 0 ? delta : -delta;
                double s = kind == Lights.POINT
                        ? t.shadowTo(px + side * gx, py + side * gy, pz + side * gz, l.x[i], l.y[i], l.z[i], side, i)
                        : t.shadow(ls, px, py, pz, gx, gy, gz, side, i);
                if (s == 0) continue;
                double att = falloff > 0 ? falloff / d2 : 1;
                double f = s * att * weight;
                double fr = f, fg = f, fb = f;
                if (Features.ABSORPTION && t.absorbing) {
                    fr *= t.shadowR;
                    fg *= t.shadowG;
                    fb *= t.shadowB;
                }
                r += fr * (diffuse * l.r[i] * cr + specular * l.r[i]);
                g += fg * (diffuse * l.g[i] * cg + specular * l.g[i]);
                b += fb * (diffuse * l.b[i] * cb + specular * l.b[i]);
            }
        }
        colour[0] = r;
        colour[1] = g;
        colour[2] = b;
    }
}
