package dev.crt.scene;

/**
 * A solid 3D checkerboard: {@code color1} where floor(x/scale) + floor(y/scale) + floor(z/scale)
 * is even, else {@code color2}, in the entity's own coordinates (before its modifiers). Either
 * cell colour may instead be a texture ({@code texture1}, {@code texture2}; null when plain),
 * looked up at the same point.
 */
public record Checker(Rgb color1, Rgb color2, double scale, Texture texture1, Texture texture2) implements Texture {
    /** A checkerboard of two plain colours. */
    public Checker(Rgb color1, Rgb color2, double scale) {
        this(color1, color2, scale, null, null);
    }

    @Override
    public void evaluate(TexturePoint p, double[] out) {
        double k = scale;
        boolean even = ((long) Math.floor(p.x / k) + (long) Math.floor(p.y / k) + (long) Math.floor(p.z / k) & 1) == 0;
        Texture t = even ? texture1 : texture2;
        if (t != null) {
            t.evaluate(p, out);
            return;
        }
        Rgb c = even ? color1 : color2;
        out[0] = c.r();
        out[1] = c.g();
        out[2] = c.b();
    }

    @Override
    public boolean needsUv() {
        return texture1 != null && texture1.needsUv() || texture2 != null && texture2.needsUv();
    }

    @Override
    public Texture prepared(double gamma) {
        if (texture1 == null && texture2 == null) return this;
        return new Checker(color1, color2, scale, texture1 == null ? null : texture1.prepared(gamma),
                texture2 == null ? null : texture2.prepared(gamma));
    }
}
