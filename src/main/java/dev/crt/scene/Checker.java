package dev.crt.scene;

/**
 * A solid 3D checkerboard: {@code color1} where floor(x/scale) + floor(y/scale) + floor(z/scale)
 * is even, else {@code color2}, in the entity's own coordinates (before its modifiers).
 */
public record Checker(Rgb color1, Rgb color2, double scale) implements Texture {
    @Override
    public void evaluate(TexturePoint p, double[] out) {
        double k = scale;
        boolean even = ((long) Math.floor(p.x / k) + (long) Math.floor(p.y / k) + (long) Math.floor(p.z / k) & 1) == 0;
        Rgb c = even ? color1 : color2;
        out[0] = c.r();
        out[1] = c.g();
        out[2] = c.b();
    }
}
