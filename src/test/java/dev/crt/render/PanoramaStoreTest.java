package dev.crt.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import dev.crt.geom.Atan;
import dev.crt.scene.PanoramaBackground;
import dev.crt.scene.Picture;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The panorama's compact store (a picture's 8-bit codes, an int per texel, read as they are) and
 * its own atan2 give the colours of the plain formula: bilinear over float texels, angles from
 * the library.
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
        float[] any = new float[w * h * 3];
        for (int i = 0; i < any.length; i++) any[i] = r.nextFloat();
        for (Picture pic : new Picture[] {randomCodes(r, w, h), new Picture(w, h, any)}) {
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

    /**
     * A picture of codes (as files of 8-bit samples load) and a picture of the very floats they
     * stand for shade to the same bits, in both mappings and with or without gamma: the codes are
     * read as they are, the floats through the float path.
     */
    @Test
    void codesAndTheirFloatsShadeToTheSameBits() {
        SplittableRandom r = new SplittableRandom(13);
        int w = 41, h = 23;
        Picture codes = randomCodes(r, w, h), floats = new Picture(w, h, codes.floats());
        assertThat(floats.codes()).isNull();
        for (boolean original : new boolean[] {false, true}) {
            for (double gamma : new double[] {1, 2.2}) {
                BackgroundShader a = new BackgroundShader(new PanoramaBackground("c", codes, 0.3), gamma, original);
                BackgroundShader b = new BackgroundShader(new PanoramaBackground("f", floats, 0.3), gamma, original);
                assertThat(a.nonNegative()).isTrue();
                assertThat(b.nonNegative()).isTrue();
                double[] got = new double[3], want = new double[3];
                for (int i = 0; i < 20_000; i++) {
                    double dx = r.nextDouble(-1, 1), dy = r.nextDouble(-1, 1), dz = r.nextDouble(-1, 1);
                    a.shade(dx, dy, dz, got);
                    b.shade(dx, dy, dz, want);
                    assertThat(got).as("original %s, gamma %s", original, gamma).containsExactly(want);
                }
            }
        }
    }

    @Test
    void aPictureOfCodesStandsForTheirFloats() {
        int[] all = new int[256];
        for (int k = 0; k < 256; k++) all[k] = k << 16 | (255 - k) << 8 | k * 7 % 256;
        Picture pic = Picture.ofCodes(16, 16, all);
        float[] f = pic.floats();
        assertThat(f).hasSize(3 * 256);
        assertThat(pic.floats()).isNotSameAs(f).containsExactly(f);
        for (int k = 0; k < 256; k++) {
            int x = k % 16, y = k / 16;
            float[] want = {k / 255f, (255 - k) / 255f, k * 7 % 256 / 255f};
            for (int c = 0; c < 3; c++) {
                assertThat(pic.get(x, y, c)).isEqualTo(want[c]);
                assertThat(f[3 * k + c]).isEqualTo(want[c]);
            }
        }
        // The top byte is not read (getRGB's alpha, had a decoder left it).
        assertThat(Picture.ofCodes(1, 1, new int[] {0xFF102030}).get(0, 0, 0)).isEqualTo(0x10 / 255f);
        assertThatThrownBy(() -> Picture.ofCodes(4, 4, new int[15])).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new Picture(4, 4, new float[47])).isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void shadersOfOnePictureShareItsCodes() {
        SplittableRandom r = new SplittableRandom(5);
        int w = 16, h = 8;
        Picture first = randomCodes(r, w, h), second = randomCodes(r, w, h);
        BackgroundShader one = new BackgroundShader(new PanoramaBackground("a", first, 0), 2.2);
        BackgroundShader again = new BackgroundShader(new PanoramaBackground("a", first, 0), 1);
        BackgroundShader old = new BackgroundShader(new PanoramaBackground("a", first, 0), 2.2, true);
        assertThat(again.sharesTexels(one)).isTrue();
        assertThat(old.sharesTexels(one)).isTrue();
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

    private static Picture randomCodes(SplittableRandom r, int w, int h) {
        int[] codes = new int[w * h];
        for (int i = 0; i < codes.length; i++) codes[i] = r.nextInt(1 << 24);
        return Picture.ofCodes(w, h, codes);
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
