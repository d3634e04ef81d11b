package dev.crt.scene;

/**
 * A solid noise texture: with q = p/scale and the warp s = turbulence·turb(q) (turb of
 * {@code octaves}), t = clamp(½ + ½·fractal(q + s·(1,1,1)), 0, 1) and the colour
 * color1 + t·(color2 − color1), in the entity's own coordinates.
 */
public record Noise(Rgb color1, Rgb color2, double scale, double turbulence, int octaves) implements Texture {
    @Override
    public void evaluate(TexturePoint p, double[] out) {
        double qx = p.x / scale, qy = p.y / scale, qz = p.z / scale;
        double s = turbulence == 0 ? 0 : turbulence * PerlinNoise.turbulence(qx, qy, qz, octaves);
        double t = 0.5 + 0.5 * PerlinNoise.fractal(qx + s, qy + s, qz + s, octaves);
        PerlinNoise.mix(color1, color2, Math.max(0, Math.min(1, t)), out);
    }
}
