package dev.crt.render;

import dev.crt.geom.Atan;
import dev.crt.scene.Background;
import dev.crt.scene.GradientBackground;
import dev.crt.scene.PanoramaBackground;
import dev.crt.scene.Picture;
import dev.crt.scene.SolidBackground;

/**
 * The colour of rays that hit nothing: a solid colour, a horizon-to-sky gradient by elevation, or an
 * equirectangular panorama sampled bilinearly (wrapping in u, clamped in v) from a linear-light copy
 * of its texels made once. A panorama of 8-bit texels (every decoded JPEG or PNG) is kept as one
 * int per texel and a table of the 256 linear values, a quarter of the floats' memory (72 MB
 * instead of 216 MB for 6000 × 3000) and the same values to the bit; its angles come from
 * {@link Atan}, not the library's native asin and atan2. The 2015 model maps gradients and panoramas its own way (linearly in
 * the direction's height, see {@link #BackgroundShader(Background, double, boolean)}).
 */
final class BackgroundShader {
    private static final int SOLID = 0, GRADIENT = 1, PANORAMA = 2, GRADIENT_2015 = 3, PANORAMA_2015 = 4;

    private final int kind;
    private final double r0, g0, b0, r1, g1, b1;
    /** The texels as floats, r, g, b per texel, when the picture holds floats; else null. */
    private final float[] texels;
    /** The texels as 0xRRGGBB of 8-bit codes, the picture's own, when it holds codes; else null. */
    private final int[] packed;
    /**
     * The value of each 8-bit code, linear or as stored (see the constructor): floats, held as
     * doubles so that a lookup's twelve reads need no conversion (the same values; 10 ns of a
     * lookup's 78).
     */
    private final double[] level = new double[256];
    private final int texWidth, texHeight;
    private final double angle;
    /** The panorama's x + 0.5 = atan2(d.x, d.z)·uScale + uOffset (mod width), y = vOffset − elevation·vScale. */
    private final double uScale, uOffset, vScale, vOffset;

    BackgroundShader(Background background, double gamma) {
        this(background, gamma, false);
    }

    /**
     * A background shader; {@code original} gives the 2015 program's mappings: the gradient
     * horizon·(1 − |D.y|) + sky·|D.y|, and the panorama at u = ((angle + atan2(−D.x, D.z) + π)
     * mod 2π)/2π, v = D.y/2 + 1/2, image position ((1 − u)·width, (1 − v)·height), bilinear and
     * wrapping both ways, texels as stored (no gamma).
     */
    BackgroundShader(Background background, double gamma, boolean original) {
        double[] c = new double[6];
        float[] tex = null;
        int[] codes = null;
        int w = 0, h = 0;
        double ang = 0;
        if (background instanceof SolidBackground s) {
            kind = SOLID;
            c[0] = s.color().r();
            c[1] = s.color().g();
            c[2] = s.color().b();
        } else if (background instanceof GradientBackground g) {
            kind = original ? GRADIENT_2015 : GRADIENT;
            c[0] = g.horizon().r();
            c[1] = g.horizon().g();
            c[2] = g.horizon().b();
            c[3] = g.sky().r();
            c[4] = g.sky().g();
            c[5] = g.sky().b();
        } else {
            PanoramaBackground p = (PanoramaBackground) background;
            kind = original ? PANORAMA_2015 : PANORAMA;
            Picture pic = p.image();
            w = pic.width();
            h = pic.height();
            boolean linearise = gamma != 1 && !original;
            for (int k = 0; k < 256; k++) level[k] = linearise ? (float) srgbToLinear(k / 255f) : k / 255f;
            codes = pic.codes();
            if (codes == null) {
                tex = pic.floats().clone();
                if (linearise) {
                    for (int i = 0; i < tex.length; i++) tex[i] = (float) srgbToLinear(tex[i]);
                }
            }
            ang = p.angle();
        }
        r0 = c[0];
        g0 = c[1];
        b0 = c[2];
        r1 = c[3];
        g1 = c[4];
        b1 = c[5];
        texels = tex;
        packed = codes;
        texWidth = w;
        texHeight = h;
        angle = ang;
        uScale = w / (2 * Math.PI);
        double turn = 0.5 + ang / (2 * Math.PI);
        uOffset = (turn - Math.floor(turn)) * w;
        vScale = h / Math.PI;
        vOffset = 0.5 * h - 0.5;
    }

    /** Whether this shader reads the same packed texels as {@code other} (not copies of them). */
    boolean sharesTexels(BackgroundShader other) {
        return packed != null && packed == other.packed;
    }

    /** The sRGB transfer function inverted: stored value in [0, 1] to linear light. */
    static double srgbToLinear(double v) {
        return v <= 0.04045 ? v / 12.92 : Math.pow((v + 0.055) / 1.055, 2.4);
    }

    /** Whether every colour this background gives is non-negative (a panorama's 8-bit texels always are). */
    boolean nonNegative() {
        if (!(r0 >= 0 && g0 >= 0 && b0 >= 0 && r1 >= 0 && g1 >= 0 && b1 >= 0)) return false;
        if (texels != null) {
            for (float v : texels) {
                if (!(v >= 0)) return false;
            }
        }
        return true;
    }

    /** Writes the background seen along direction d (any length) into {@code out[0..2]}. */
    void shade(double dx, double dy, double dz, double[] out) {
        switch (kind) {
            case SOLID -> {
                out[0] = r0;
                out[1] = g0;
                out[2] = b0;
            }
            case GRADIENT -> {
                double s = dy / Math.sqrt(dx * dx + dy * dy + dz * dz);
                double e = Math.asin(Math.max(-1, Math.min(1, s))) / (Math.PI / 2);
                e = Math.max(0, Math.min(1, e));
                out[0] = (1 - e) * r0 + e * r1;
                out[1] = (1 - e) * g0 + e * g1;
                out[2] = (1 - e) * b0 + e * b1;
            }
            case PANORAMA -> panorama(dx, dy, dz, out);
            case GRADIENT_2015 -> {
                double e = Math.abs(dy / Math.sqrt(dx * dx + dy * dy + dz * dz));
                out[0] = (1 - e) * r0 + e * r1;
                out[1] = (1 - e) * g0 + e * g1;
                out[2] = (1 - e) * b0 + e * b1;
            }
            default -> panorama2015(dx, dy, dz, out);
        }
    }

    private void panorama2015(double dx, double dy, double dz, double[] out) {
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double a = (angle + Atan.atan2(-dx / len, dz / len) + Math.PI) % (2 * Math.PI);
        if (a < 0) a += 2 * Math.PI;
        double u = a / (2 * Math.PI), v = dy / len / 2 + 0.5;
        double x = (1 - u) * texWidth, y = (1 - v) * texHeight;
        double fx = Math.floor(x), fy = Math.floor(y);
        double ax = x - fx, ay = y - fy;
        int x0 = Math.floorMod((int) fx, texWidth), x1 = (x0 + 1) % texWidth;
        int y0 = Math.floorMod((int) fy, texHeight), y1 = (y0 + 1) % texHeight;
        bilinear(x0, x1, y0, y1, ax, ay, out);
    }

    /**
     * u = frac(0.5 + (atan2(d.x, d.z) + angle)/2π), v = 0.5 − asin(d.y)/π (rounded otherwise than
     * written: x and y within 1e-12 of a texel of it); texel (x, y) covers
     * [x, x+1)/width × [y, y+1)/height, so its centre sits at ((x + 0.5)/width, (y + 0.5)/height).
     */
    private void panorama(double dx, double dy, double dz, double[] out) {
        // x + 0.5 = u·width as one product and sum (the turn's offset folded into uOffset) wrapped
        // into [0, width) by a comparison, y likewise: no division, no floor before the texels'.
        double t = Atan.atan2(dx, dz) * uScale + uOffset;
        if (t >= texWidth) t -= texWidth;
        else if (t < 0) t += texWidth;
        // asin(d.y/|d|) is the elevation atan2(d.y, √(d.x² + d.z²)): one square root, no clamp.
        double y = vOffset - Atan.atan2(dy, Math.sqrt(dx * dx + dz * dz)) * vScale;
        double x = t - 0.5;
        double fx = Math.floor(x), fy = Math.floor(y);
        double ax = x - fx, ay = y - fy;
        // t is in [0, width], so fx in [−1, width − 1]: the wrap without an integer division.
        int x0 = (int) fx, x1 = x0 + 1;
        if (x0 < 0) x0 += texWidth;
        if (x1 == texWidth) x1 = 0;
        int y0 = clamp((int) fy, texHeight), y1 = clamp((int) fy + 1, texHeight);
        bilinear(x0, x1, y0, y1, ax, ay, out);
    }

    /** Mixes texels (x0, y0), (x1, y0), (x0, y1), (x1, y1) by weights ax across and ay down. */
    private void bilinear(int x0, int x1, int y0, int y1, double ax, double ay, double[] out) {
        int i00 = y0 * texWidth + x0, i01 = y0 * texWidth + x1, i10 = y1 * texWidth + x0, i11 = y1 * texWidth + x1;
        int[] p = packed;
        if (p != null) {
            double[] lv = level;
            int p00 = p[i00], p01 = p[i01], p10 = p[i10], p11 = p[i11];
            for (int c = 0, shift = 16; c < 3; c++, shift -= 8) {
                double top = (1 - ax) * lv[p00 >> shift & 0xFF] + ax * lv[p01 >> shift & 0xFF];
                double bottom = (1 - ax) * lv[p10 >> shift & 0xFF] + ax * lv[p11 >> shift & 0xFF];
                out[c] = (1 - ay) * top + ay * bottom;
            }
            return;
        }
        float[] t = texels;
        for (int c = 0; c < 3; c++) {
            double top = (1 - ax) * t[i00 * 3 + c] + ax * t[i01 * 3 + c];
            double bottom = (1 - ax) * t[i10 * 3 + c] + ax * t[i11 * 3 + c];
            out[c] = (1 - ay) * top + ay * bottom;
        }
    }

    private static int clamp(int y, int h) {
        return y < 0 ? 0 : Math.min(y, h - 1);
    }
}
