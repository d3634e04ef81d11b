package dev.crt.scene;

/**
 * Solid marble: veins across the entity's x axis. With q = p/scale and s = turbulence·turb(q),
 * t = ½ + ½·sin(2π(qx + s)), the colour color1 + t·(color2 − color1), one band per {@code scale}.
 */
public record Marble(Rgb color1, Rgb color2, double scale, double turbulence, int octaves) implements Texture {
    @Override
    public void evaluate(TexturePoint p, double[] out) {
        double qx = p.x / scale, qy = p.y / scale, qz = p.z / scale;
        double s = turbulence == 0 ? 0 : turbulence * PerlinNoise.turbulence(qx, qy, qz, octaves);
        double t = 0.5 + 0.5 * Math.sin(2 * Math.PI * (qx + s));
        PerlinNoise.mix(color1, color2, t, out);
    }
}
