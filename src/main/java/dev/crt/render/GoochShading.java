package dev.crt.render;

/**
 * Gooch's cool-to-warm shading (docs/rendering.md, "Gooch shading"): per light sample, with
 * t = (1 + N·ω)/2, the colour t·k_warm + (1 − t)·k_cool where k_cool = cool + α·kd·C and
 * k_warm = warm + β·kd·C (α = 0.2, β = 0.6), times the light's colour and its kind's weight, plus
 * the Phong highlight ks·max(0, R·V)^n·Cℓ; the emission is added. Illustration, not lighting: no
 * shadows, no falloff, no ambient term. The outlines are drawn afterwards by {@link Outlines}.
 */
final class GoochShading {
    static final double ALPHA = 0.2, BETA = 0.6;

    private final double[] materials;
    private final Lights lights;
    private final PixelRandom random;
    private final LightSample sample = new LightSample();

    GoochShading(double[] materials, Lights lights, PixelRandom random) {
        this.materials = materials;
        this.lights = lights;
        this.random = random;
    }

    void shade(int m, double cr, double cg, double cb, double ks, double er, double eg, double eb, double px, double py,
            double pz, double nx, double ny, double nz, double vx, double vy, double vz, double[] colour) {
        double[] mat = materials;
        double kd = mat[m + Materials.DIFFUSE], shininess = mat[m + Materials.SHININESS];
        double coolR = mat[m + Materials.COOL] + ALPHA * kd * cr, coolG = mat[m + Materials.COOL + 1] + ALPHA * kd * cg,
                coolB = mat[m + Materials.COOL + 2] + ALPHA * kd * cb;
        double warmR = mat[m + Materials.WARM] + BETA * kd * cr, warmG = mat[m + Materials.WARM + 1] + BETA * kd * cg,
                warmB = mat[m + Materials.WARM + 2] + BETA * kd * cb;
        double r = er, g = eg, b = eb;
        double nv = nx * vx + ny * vy + nz * vz;
        Lights l = lights;
        LightSample ls = sample;
        for (int i = 0; i < l.count; i++) {
            for (int k = 0, samples = l.sampleCount(i); k < samples; k++) {
                l.sample(i, k, px, py, pz, random, ls);
                double weight = ls.weight;
                if (weight == 0) continue;
                double nw = nx * ls.wx + ny * ls.wy + nz * ls.wz;
                double t = (1 + nw) / 2;
                double spec = 0;
                if (ks != 0) {
                    double rv = 2 * nw * nv - (ls.wx * vx + ls.wy * vy + ls.wz * vz);
                    if (rv > 0) spec = ks * Tracer.power(rv, shininess);
                }
                r += weight * l.r[i] * (t * warmR + (1 - t) * coolR + spec);
                g += weight * l.g[i] * (t * warmG + (1 - t) * coolG + spec);
                b += weight * l.b[i] * (t * warmB + (1 - t) * coolB + spec);
            }
        }
        colour[0] = r;
        colour[1] = g;
        colour[2] = b;
    }
}
