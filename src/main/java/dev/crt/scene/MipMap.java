package dev.crt.scene;

/**
 * A picture's mip chain in linear light: level 0 the texels themselves, each next level half as
 * wide and high (at least 1), each texel the mean of the 2×2 texels under it. Lookups wrap in
 * both directions (textures tile); (s, t) = (0, 0) is the top-left corner of the picture and
 * (1, 1) its bottom-right, so texel (i, j) has its centre at ((i + ½)/w, (j + ½)/h).
 */
public final class MipMap {
    private final float[][] texels;
    private final int[] widths, heights;

    /** The chain of {@code picture}, its stored values decoded from sRGB to linear light when {@code gamma} is not 1. */
    public MipMap(Picture picture, double gamma) {
        int w = picture.width(), h = picture.height();
        int levels = 1;
        for (int a = w, b = h; a > 1 || b > 1; a = Math.max(1, a >> 1), b = Math.max(1, b >> 1)) levels++;
        texels = new float[levels][];
        widths = new int[levels];
        heights = new int[levels];
        float[] base;
        int[] codes = picture.codes();
        if (codes != null) {
            // Each code's value once, as the loop below would convert it.
            float[] value = new float[256];
            for (int k = 0; k < 256; k++) value[k] = gamma != 1 ? (float) srgbToLinear(k / 255f) : k / 255f;
            base = new float[codes.length * 3];
            for (int i = 0; i < codes.length; i++) {
                int p = codes[i];
                base[3 * i] = value[p >> 16 & 0xFF];
                base[3 * i + 1] = value[p >> 8 & 0xFF];
                base[3 * i + 2] = value[p & 0xFF];
            }
        } else {
            base = picture.floats().clone();
            if (gamma != 1) {
                for (int i = 0; i < base.length; i++) base[i] = (float) srgbToLinear(base[i]);
            }
        }
        texels[0] = base;
        widths[0] = w;
        heights[0] = h;
        for (int k = 1; k < levels; k++) {
            int pw = widths[k - 1], ph = heights[k - 1];
            int nw = Math.max(1, pw >> 1), nh = Math.max(1, ph >> 1);
            float[] src = texels[k - 1], dst = new float[nw * nh * 3];
            for (int y = 0; y < nh; y++) {
                int y0 = Math.min(2 * y, ph - 1), y1 = Math.min(2 * y + 1, ph - 1);
                for (int x = 0; x < nw; x++) {
                    int x0 = Math.min(2 * x, pw - 1), x1 = Math.min(2 * x + 1, pw - 1);
                    for (int c = 0; c < 3; c++) {
                        dst[(y * nw + x) * 3 + c] = 0.25f * (src[(y0 * pw + x0) * 3 + c] + src[(y0 * pw + x1) * 3 + c]
                                + src[(y1 * pw + x0) * 3 + c] + src[(y1 * pw + x1) * 3 + c]);
                    }
                }
            }
            texels[k] = dst;
            widths[k] = nw;
            heights[k] = nh;
        }
    }

    public int levels() { return texels.length; }

    public int width(int level) { return widths[level]; }

    public int height(int level) { return heights[level]; }

    /**
     * The level of detail of a footprint {@code ws} wide in s and {@code wt} in t: log2 of the
     * larger of the two in level-0 texels, so a footprint of one texel is level 0.
     */
    public double level(double ws, double wt) {
        double texelsAcross = Math.max(ws * widths[0], wt * heights[0]);
        return texelsAcross > 0 ? Math.log(texelsAcross) * (1 / Math.log(2)) : Double.NEGATIVE_INFINITY;
    }

    /** Trilinear lookup at (s, t) and level of detail {@code lod} into out[0..2]: bilinear within the two nearest levels, blended. */
    public void sample(double s, double t, double lod, double[] out) {
        if (!(s == s) || Double.isInfinite(s)) s = 0;
        if (!(t == t) || Double.isInfinite(t)) t = 0;
        int last = texels.length - 1;
        if (!(lod > 0)) {
            bilinear(0, s, t, out, 1, false);
        } else if (lod >= last) {
            bilinear(last, s, t, out, 1, false);
        } else {
            int k = (int) lod;
            double f = lod - k;
            bilinear(k, s, t, out, 1 - f, false);
            if (f > 0) bilinear(k + 1, s, t, out, f, true);
        }
    }

    private void bilinear(int level, double s, double t, double[] out, double weight, boolean add) {
        int w = widths[level], h = heights[level];
        float[] tex = texels[level];
        double x = s * w - 0.5, y = t * h - 0.5;
        double fx0 = Math.floor(x), fy0 = Math.floor(y);
        double fx = x - fx0, fy = y - fy0;
        int x0 = (int) Math.floorMod((long) fx0, (long) w), y0 = (int) Math.floorMod((long) fy0, (long) h);
        int x1 = x0 + 1 == w ? 0 : x0 + 1, y1 = y0 + 1 == h ? 0 : y0 + 1;
        double w00 = (1 - fx) * (1 - fy), w10 = fx * (1 - fy), w01 = (1 - fx) * fy, w11 = fx * fy;
        int a = (y0 * w + x0) * 3, b = (y0 * w + x1) * 3, c = (y1 * w + x0) * 3, d = (y1 * w + x1) * 3;
        for (int k = 0; k < 3; k++) {
            double v = weight * (w00 * tex[a + k] + w10 * tex[b + k] + w01 * tex[c + k] + w11 * tex[d + k]);
            out[k] = add ? out[k] + v : v;
        }
    }

    /** The sRGB transfer function inverted (IEC 61966-2-1). */
    static double srgbToLinear(double c) {
        return c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4);
    }
}
