package dev.crt.scene;

/**
 * A decoded image as stored in its file: {@code width × height} texels, row 0 at the top,
 * each three floats (r, g, b) in [0, 1], not yet converted to linear light.
 */
public record Picture(int width, int height, float[] rgb) {
    public Picture {
        if (width < 1 || height < 1 || rgb.length != width * height * 3) {
            throw new IllegalArgumentException("bad picture size " + width + "x" + height);
        }
    }

    /** Channel {@code c} of texel (x, y). */
    public float get(int x, int y, int c) { return rgb[(y * width + x) * 3 + c]; }
}
