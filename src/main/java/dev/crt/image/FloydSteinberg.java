package dev.crt.image;

import java.util.Arrays;

/**
 * Maps an image onto a palette with Floyd–Steinberg error diffusion, so smooth gradients show as a
 * fine grain instead of bands. Rows alternate direction (serpentine) to avoid diagonal streaks.
 * Error never flows upwards, so the rows above the first change between two frames get the same
 * indices in both, which keeps still parts of an animation still (and small to store).
 */
public final class FloydSteinberg {
    private FloydSteinberg() {}

    /** Palette indices for {@code rgb} (packed 0xRRGGBB, {@code width × height}, row by row). */
    public static byte[] dither(int[] rgb, int width, int height, Palette palette) {
        byte[] indices = new byte[width * height];
        float[] thisRow = new float[(width + 2) * 3];
        float[] nextRow = new float[(width + 2) * 3];
        for (int y = 0; y < height; y++) {
            boolean leftToRight = (y & 1) == 0;
            int dir = leftToRight ? 1 : -1;
            for (int step = 0; step < width; step++) {
                int x = leftToRight ? step : width - 1 - step;
                int c = rgb[y * width + x];
                int e = (x + 1) * 3;
                int r = clamp(Palette.red(c) + thisRow[e]);
                int g = clamp(Palette.green(c) + thisRow[e + 1]);
                int b = clamp(Palette.blue(c) + thisRow[e + 2]);
                int index = palette.nearest(r, g, b);
                indices[y * width + x] = (byte) index;
                int chosen = palette.colour(index);
                diffuse(thisRow, nextRow, e, dir, 0, r - Palette.red(chosen));
                diffuse(thisRow, nextRow, e, dir, 1, g - Palette.green(chosen));
                diffuse(thisRow, nextRow, e, dir, 2, b - Palette.blue(chosen));
            }
            float[] done = thisRow;
            thisRow = nextRow;
            nextRow = done;
            Arrays.fill(nextRow, 0);
        }
        return indices;
    }

    /** Spreads one channel's error: 7/16 ahead, 3/16 behind below, 5/16 below, 1/16 ahead below. */
    private static void diffuse(float[] thisRow, float[] nextRow, int e, int dir, int channel, int error) {
        int ahead = e + dir * 3 + channel;
        int behind = e - dir * 3 + channel;
        thisRow[ahead] += error * (7f / 16);
        nextRow[behind] += error * (3f / 16);
        nextRow[e + channel] += error * (5f / 16);
        nextRow[ahead] += error * (1f / 16);
    }

    private static int clamp(float v) { return Math.max(0, Math.min(255, Math.round(v))); }
}
