package dev.crt.scene;

/**
 * Solid wood: rings about the entity's y axis. With q = p/scale and s = turbulence·turb(q),
 * t = ½ − ½·cos(2π(√(qx² + qz²) + s)), the colour color1 + t·(color2 − color1): color1 between
 * the rings, color2 on them, one ring per {@code scale}.
 */
public record Wood(Rgb color1, Rgb color2, double scale, double turbulence, int octaves) implements Texture {
    @Override
    public void evaluate(TexturePoint p, double[] out) {
        double qx = p.x / scale, qy = p.y / scale, qz = p.z / scale;
        double s = turbulence == 0 ? 0 : turbulence * PerlinNoise.turbulence(qx, qy, qz, octaves);
        double t = 0.5 - 0.5 * Math.cos(2 * Math.PI * (Math.sqrt(qx * qx + qz * qz) + s));
        PerlinNoise.mix(color1, color2, t, out);
    }
}
