package dev.crt.image;

import java.util.Arrays;
import java.util.Comparator;

/** An indexed image's colours (packed 0xRRGGBB) and the lookup of the one nearest to any colour. */
public final class Palette {
    private final int[] colours;
    /** Entry positions sorted by green, so a search can stop once green alone is farther than the best match. */
    private final int[] byGreen;
    private final int[] greens;

    public Palette(int[] colours) {
        if (colours.length < 1 || colours.length > 256) {
            throw new IllegalArgumentException("a palette holds 1 to 256 colours, got " + colours.length);
        }
        this.colours = colours.clone();
        Integer[] order = new Integer[colours.length];
        for (int i = 0; i < order.length; i++) order[i] = i;
        Arrays.sort(order, Comparator.comparingInt((Integer i) -> green(colours[i])).thenComparingInt(i -> i));
        byGreen = new int[order.length];
        greens = new int[order.length];
        for (int k = 0; k < order.length; k++) {
            byGreen[k] = order[k];
            greens[k] = green(colours[order[k]]);
        }
    }

    public int size() { return colours.length; }

    /** Colour {@code index}, packed 0xRRGGBB. */
    public int colour(int index) { return colours[index]; }

    /** The index of the colour nearest to (r, g, b) in RGB distance; ties go to the lower index. */
    public int nearest(int r, int g, int b) {
        int start = Arrays.binarySearch(greens, g);
        if (start < 0) start = -start - 1;
        int best = -1;
        int bestDistance = Integer.MAX_VALUE;
        for (int lo = start - 1, hi = start; lo >= 0 || hi < byGreen.length; lo--, hi++) {
            boolean searched = false;
            if (hi < byGreen.length) {
                int dg = greens[hi] - g;
                if (dg * dg <= bestDistance) {
                    searched = true;
                    int i = byGreen[hi];
                    int d = distance(colours[i], r, g, b);
                    if (d < bestDistance || (d == bestDistance && i < best)) { best = i; bestDistance = d; }
                }
            }
            if (lo >= 0) {
                int dg = greens[lo] - g;
                if (dg * dg <= bestDistance) {
                    searched = true;
                    int i = byGreen[lo];
                    int d = distance(colours[i], r, g, b);
                    if (d < bestDistance || (d == bestDistance && i < best)) { best = i; bestDistance = d; }
                }
            }
            if (!searched) break;
        }
        return best;
    }

    private static int distance(int c, int r, int g, int b) {
        int dr = red(c) - r;
        int dg = green(c) - g;
        int db = blue(c) - b;
        return dr * dr + dg * dg + db * db;
    }

    static int red(int c) { return (c >> 16) & 0xff; }

    static int green(int c) { return (c >> 8) & 0xff; }

    static int blue(int c) { return c & 0xff; }
}
