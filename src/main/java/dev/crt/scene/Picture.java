package dev.crt.scene;

import java.util.Objects;

/**
 * A decoded image as stored in its file: {@code width × height} texels, row 0 at the top, each
 * r, g, b in [0, 1], not yet converted to linear light. A picture of 8-bit samples (what JPEG,
 * PNG, GIF and BMP files decode to) holds them as their codes, one int 0xRRGGBB per texel, code k
 * standing for k/255f: a third of the floats' memory (72 MB instead of 216 MB for 6000 × 3000),
 * and what the renderer's panorama reads as it is. Any other picture holds three floats per texel.
 * A picture's arrays are shared, never written into.
 */
public final class Picture {
    private final int width, height;
    /** r, g, b per texel when the picture is not one of codes; else null. */
    private final float[] rgb;
    /** 0xRRGGBB per texel when the picture is one of codes; else null. */
    private final int[] codes;

    /** A picture of any stored values: r, g, b per texel. */
    public Picture(int width, int height, float[] rgb) {
        this(width, height, Objects.requireNonNull(rgb), null);
    }

    private Picture(int width, int height, float[] rgb, int[] codes) {
        long texels = (long) width * height;
        if (width < 1 || height < 1 || (rgb != null ? rgb.length != 3 * texels : codes.length != texels)) {
            throw new IllegalArgumentException("bad picture size " + width + "x" + height);
        }
        this.width = width;
        this.height = height;
        this.rgb = rgb;
        this.codes = codes;
    }

    /** A picture of 8-bit samples: 0xRRGGBB per texel (its top byte is not read), code k standing for k/255f. */
    public static Picture ofCodes(int width, int height, int[] codes) {
        return new Picture(width, height, null, Objects.requireNonNull(codes));
    }

    public int width() { return width; }

    public int height() { return height; }

    /** The texels as 0xRRGGBB 8-bit codes, when the picture holds them; else null. */
    public int[] codes() { return codes; }

    /**
     * The texels as floats, r, g, b per texel: the picture's own array, or for a picture of codes
     * a new one each call (k/255f for code k), so callers that can read {@link #codes} should.
     */
    public float[] floats() {
        if (rgb != null) return rgb;
        float[] out = new float[codes.length * 3];
        for (int i = 0; i < codes.length; i++) {
            int p = codes[i];
            out[3 * i] = CODE_VALUE[p >> 16 & 0xFF];
            out[3 * i + 1] = CODE_VALUE[p >> 8 & 0xFF];
            out[3 * i + 2] = CODE_VALUE[p & 0xFF];
        }
        return out;
    }

    /** Channel {@code c} of texel (x, y). */
    public float get(int x, int y, int c) {
        int i = y * width + x;
        return codes != null ? CODE_VALUE[codes[i] >> (16 - 8 * c) & 0xFF] : rgb[i * 3 + c];
    }

    /** The value k/255f of each 8-bit code k. */
    private static final float[] CODE_VALUE = new float[256];

    static {
        for (int k = 0; k < 256; k++) CODE_VALUE[k] = k / 255f;
    }

    /** Equal when of one size with the very same texel arrays: scenes compare without reading their texels. */
    @Override
    public boolean equals(Object o) {
        return o instanceof Picture p && p.width == width && p.height == height && p.rgb == rgb && p.codes == codes;
    }

    @Override
    public int hashCode() {
        return Objects.hash(width, height, System.identityHashCode(rgb), System.identityHashCode(codes));
    }

    @Override
    public String toString() {
        return "Picture[" + width + "x" + height + (codes != null ? ", 8-bit codes]" : ", floats]");
    }
}
