package dev.crt.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.crt.geom.Atan;
import dev.crt.scene.PanoramaBackground;
import dev.crt.scene.Picture;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The panorama's compact store (an int per 8-bit texel) and its own atan2 give the colours
 * of the plain formula: bilinear over float texels, angles from the library.
 */
class PanoramaStoreTest {
    @Test
    void atanAgreesWithTheLibraryWellWithinATexel() {
        SplittableRandom r = new SplittableRandom(7);
        double[] special = {0.0, -0.0, 1, -1, 1e-300, -1e-300, 3, -3};
        for (double y : special) {
            for (double x : special) assertThat(Atan.atan2(y, x)).as("atan2(%s, %s)", y, x).isCloseTo(Math.atan2(y, x), within(4e-11));
        }
        for (int i = 0; i < 200_000; i++) {
            double x = r.nextDouble(-1, 1) * Math.pow(10, r.nextInt(-6, 7)), y = r.nextDouble(-1, 1) * Math.pow(10, r.nextInt(-6, 7));
            if (i % 5 == 0) y = i % 10 == 0 ? x : -x;
            assertThat(Atan.atan2(y, x)).isCloseTo(Math.atan2(y, x), within(4e-11));
            // Either side of tan(π/8), where the reduction changes: the polynomial's far end.
            double t = Math.tan(Math.PI / 8) * (1 + r.nextDouble(-1e-9, 1e-9));
            assertThat(Atan.atan2(t * x, x)).isCloseTo(Math.atan2(t * x, x), within(4e-11));
            // The panorama's elevation: asin(s) as atan2(s, √(1 − s²)), also where s nears ±1.
            double s = i % 3 == 0 ? Math.copySign(1 - r.nextDouble() * 1e-6, x) : r.nextDouble(-1, 1);
            assertThat(Atan.atan2(s, Math.sqrt((1 - s) * (1 + s)))).isCloseTo(Math.asin(s), within(4e-11));
        }
        assertThat(Atan.atan2(1, 0)).isEqualTo(Math.PI / 2);
        assertThat(Atan.atan2(-2, 0)).isEqualTo(-Math.PI / 2);
    }

    @Test
    void eightBitAndFloatTexelsShadeAsThePlainFormula() {
        SplittableRandom r = new SplittableRandom(11);
        int w = 37, h = 19;
        float[] codes = new float[w * h * 3], any = new float[w * h * 3];
        for (int i = 0; i < codes.length; i++) {
            codes[i] = r.nextInt(256) / 255f;
            any[i] = r.nextFloat();
        }
        for (float[] rgb : new float[][] {codes, any}) {
            Picture pic = new Picture(w, h, rgb);
            for (double gamma : new double[] {1, 2.2}) {
                BackgroundShader shader = new BackgroundShader(new PanoramaBackground("p", pic, 0.7), gamma);
                double[] got = new double[3], want = new double[3];
                for (int i = 0; i < 20_000; i++) {
                    double dx = r.nextDouble(-1, 1), dy = r.nextDouble(-1, 1), dz = r.nextDouble(-1, 1);
                    shader.shade(dx, dy, dz, got);
                    reference(pic, 0.7, gamma, dx, dy, dz, want);
                    for (int c = 0; c < 3; c++) assertThat(got[c]).isCloseTo(want[c], within(1e-9));
                }
            }
        }
    }

    @Test
    void onlyExactEightBitValuesGetACode() {
        for (int k = 0; k < 256; k++) {
            float v = k / 255f;
            assertThat(BackgroundShader.code(v)).isEqualTo(k);
            assertThat(BackgroundShader.code(Math.nextUp(v))).isEqualTo(-1);
            if (k > 0) assertThat(BackgroundShader.code(Math.nextDown(v))).isEqualTo(-1);
        }
        assertThat(BackgroundShader.code(-0f)).isEqualTo(0);
        for (float v : new float[] {-1f / 255, -0.4f, Float.NaN, 256f / 255, Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY, 1e30f}) {
            assertThat(BackgroundShader.code(v)).as("%s", v).isEqualTo(-1);
        }
    }

    @Test
    void aPictureIsPackedOnceAndAnotherGetsItsOwnTexels() {
        SplittableRandom r = new SplittableRandom(5);
        int w = 16, h = 8;
        float[] a = new float[w * h * 3], b = new float[w * h * 3];
        for (int i = 0; i < a.length; i++) {
            a[i] = r.nextInt(256) / 255f;
            b[i] = r.nextInt(256) / 255f;
        }
        Picture first = new Picture(w, h, a), second = new Picture(w, h, b);
        BackgroundShader one = new BackgroundShader(new PanoramaBackground("a", first, 0), 2.2);
        BackgroundShader again = new BackgroundShader(new PanoramaBackground("a", first, 0), 1);
        assertThat(again.sharesTexels(one)).isTrue();
        BackgroundShader other = new BackgroundShader(new PanoramaBackground("b", second, 0), 2.2);
        assertThat(other.sharesTexels(one)).isFalse();
        double[] got = new double[3], want = new double[3];
        for (int i = 0; i < 2_000; i++) {
            double dx = r.nextDouble(-1, 1), dy = r.nextDouble(-1, 1), dz = r.nextDouble(-1, 1);
            other.shade(dx, dy, dz, got);
            reference(second, 0, 2.2, dx, dy, dz, want);
            for (int c = 0; c < 3; c++) assertThat(got[c]).isCloseTo(want[c], within(1e-9));
            again.shade(dx, dy, dz, got);
            reference(first, 0, 1, dx, dy, dz, want);
            for (int c = 0; c < 3; c++) assertThat(got[c]).isCloseTo(want[c], within(1e-9));
        }
    }

    /** The panorama of rendering-model.md, written out plainly. */
    private static void reference(Picture p, double angle, double gamma, double dx, double dy, double dz, double[] out) {
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double u = 0.5 + (Math.atan2(dx, dz) + angle) / (2 * Math.PI);
        u -= Math.floor(u);
        double v = 0.5 - Math.asin(dy / len) / Math.PI;
        double x = u * p.width() - 0.5, y = v * p.height() - 0.5;
        int fx = (int) Math.floor(x), fy = (int) Math.floor(y);
        double ax = x - fx, ay = y - fy;
        int x0 = Math.floorMod(fx, p.width()), x1 = (x0 + 1) % p.width();
        int y0 = Math.max(0, Math.min(p.height() - 1, fy)), y1 = Math.max(0, Math.min(p.height() - 1, fy + 1));
        for (int c = 0; c < 3; c++) {
            double top = (1 - ax) * lin(p.get(x0, y0, c), gamma) + ax * lin(p.get(x1, y0, c), gamma);
            double bottom = (1 - ax) * lin(p.get(x0, y1, c), gamma) + ax * lin(p.get(x1, y1, c), gamma);
            out[c] = (1 - ay) * top + ay * bottom;
        }
    }

    private static double lin(float v, double gamma) {
        return gamma == 1 ? v : (float) BackgroundShader.srgbToLinear(v);
    }
}
