package dev.crt.image;

/** A rendered image in linear light: {@code width × height} pixels of three floats, row 0 at the top. */
public final class FrameBuffer {
    /** The most pixels an image may have: 2^28, 3 GiB of floats, so every index fits an int. */
    public static final long MAX_PIXELS = 1L << 28;

    private final int width;
    private final int height;
    private final float[] rgb;

    public FrameBuffer(int width, int height) {
        if (width < 1 || height < 1 || (long) width * height > MAX_PIXELS) {
            throw new IllegalArgumentException("bad image size " + width + "x" + height);
        }
        this.width = width;
        this.height = height;
        this.rgb = new float[width * height * 3];
    }

    public int width() { return width; }

    public int height() { return height; }

    public void set(int x, int y, double r, double g, double b) {
        int i = (y * width + x) * 3;
        rgb[i] = (float) r;
        rgb[i + 1] = (float) g;
        rgb[i + 2] = (float) b;
    }

    /** Channel {@code c} (0 red, 1 green, 2 blue) of pixel (x, y). */
    public float get(int x, int y, int c) { return rgb[(y * width + x) * 3 + c]; }

    /** The backing array (r, g, b per pixel, row by row); writers read it directly. */
    public float[] data() { return rgb; }
}
