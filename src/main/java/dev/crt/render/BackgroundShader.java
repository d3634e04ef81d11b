package dev.crt.render;

import dev.crt.scene.Background;
import dev.crt.scene.GradientBackground;
import dev.crt.scene.PanoramaBackground;
import dev.crt.scene.Picture;
import dev.crt.scene.SolidBackground;

/**
 * The colour of rays that hit nothing: a solid colour, a horizon-to-sky gradient by elevation, or an
 * equirectangular panorama sampled bilinearly (wrapping in u, clamped in v) from a linear-light copy
 * of its texels made once. The 2015 model maps gradients and panoramas its own way (linearly in
 * the direction's height, see {@link #BackgroundShader(Background, double, boolean)}).
 */
final class BackgroundShader {
    private static final int SOLID = 0, GRADIENT = 1, PANORAMA = 2, GRADIENT_2015 = 3, PANORAMA_2015 = 4;

    private final int kind;
    private final double r0, g0, b0, r1, g1, b1;
    private final float[] texels;
    private final int texWidth, texHeight;
    private final double angle;

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
            tex = pic.rgb().clone();
            if (gamma != 1 && !original) {
                for (int i = 0; i < tex.length; i++) tex[i] = (float) srgbToLinear(tex[i]);
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
        texWidth = w;
        texHeight = h;
        angle = ang;
    }

    /** The sRGB transfer function inverted: stored value in [0, 1] to linear light. */
    static double srgbToLinear(double v) {
        return v <= 0.04045 ? v / 12.92 : Math.pow((v + 0.055) / 1.055, 2.4);
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
        double a = (angle + Math.atan2(-dx / len, dz / len) + Math.PI) % (2 * Math.PI);
        if (a < 0) a += 2 * Math.PI;
        double u = a / (2 * Math.PI), v = dy / len / 2 + 0.5;
        double x = (1 - u) * texWidth, y = (1 - v) * texHeight;
        double fx = Math.floor(x), fy = Math.floor(y);
        double ax = x - fx, ay = y - fy;
        int x0 = Math.floorMod((int) fx, texWidth), x1 = (x0 + 1) % texWidth;
        int y0 = Math.floorMod((int) fy, texHeight), y1 = (y0 + 1) % texHeight;
        for (int c = 0; c < 3; c++) {
            double top = (1 - ax) * texels[(y0 * texWidth + x0) * 3 + c] + ax * texels[(y0 * texWidth + x1) * 3 + c];
            double bottom = (1 - ax) * texels[(y1 * texWidth + x0) * 3 + c] + ax * texels[(y1 * texWidth + x1) * 3 + c];
            out[c] = (1 - ay) * top + ay * bottom;
        }
    }

    /**
     * u = frac(0.5 + (atan2(d.x, d.z) + angle)/2π), v = 0.5 − asin(d.y)/π; texel (x, y) covers
     * [x, x+1)/width × [y, y+1)/height, so its centre sits at ((x + 0.5)/width, (y + 0.5)/height).
     */
    private void panorama(double dx, double dy, double dz, double[] out) {
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double u = 0.5 + (Math.atan2(dx, dz) + angle) / (2 * Math.PI);
        u -= Math.floor(u);
        double v = 0.5 - Math.asin(Math.max(-1, Math.min(1, dy / len))) / Math.PI;
        double x = u * texWidth - 0.5, y = v * texHeight - 0.5;
        double fx = Math.floor(x), fy = Math.floor(y);
        double ax = x - fx, ay = y - fy;
        int x0 = Math.floorMod((int) fx, texWidth), x1 = (x0 + 1) % texWidth;
        int y0 = clamp((int) fy, texHeight), y1 = clamp((int) fy + 1, texHeight);
        for (int c = 0; c < 3; c++) {
            double top = (1 - ax) * texels[(y0 * texWidth + x0) * 3 + c] + ax * texels[(y0 * texWidth + x1) * 3 + c];
            double bottom = (1 - ax) * texels[(y1 * texWidth + x0) * 3 + c] + ax * texels[(y1 * texWidth + x1) * 3 + c];
            out[c] = (1 - ay) * top + ay * bottom;
        }
    }

    private static int clamp(int y, int h) {
        return y < 0 ? 0 : Math.min(y, h - 1);
    }
}
