package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Vec3;
import dev.crt.image.FrameBuffer;
import dev.crt.scene.Background;
import dev.crt.scene.Checker;
import dev.crt.scene.ImageTexture;
import dev.crt.scene.Material;
import dev.crt.scene.MipMap;
import dev.crt.scene.Picture;
import dev.crt.scene.Rgb;
import dev.crt.scene.Settings;
import dev.crt.scene.Texture;
import dev.crt.scene.TextureMapping;
import dev.crt.scene.TexturePoint;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** Image textures: texel lookups, the mip level chosen from the ray cone, poles and seams, and a plane to the horizon. */
class ImageTextureTest {
    private static final Vec3 ONE = v(1, 1, 1);

    private static Picture random(int w, int h, long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        float[] rgb = new float[w * h * 3];
        for (int i = 0; i < rgb.length; i++) rgb[i] = (float) r.nextDouble();
        return new Picture(w, h, rgb);
    }

    /** A checkerboard picture of {@code cells} × {@code cells} cells, each {@code texels} texels wide. */
    private static Picture checker(int cells, int texels) {
        int n = cells * texels;
        float[] rgb = new float[n * n * 3];
        for (int y = 0; y < n; y++) {
            for (int x = 0; x < n; x++) {
                float v = ((x / texels + y / texels) & 1) == 0 ? 1f : 0f;
                for (int c = 0; c < 3; c++) rgb[(y * n + x) * 3 + c] = v;
            }
        }
        return new Picture(n, n, rgb);
    }

    private static Material textured(Texture t) {
        return new Material(Rgb.GREY, 1, 0, 30, 0, 0, 1, Rgb.BLACK, true, false, Rgb.BLACK, t);
    }

    @Test
    void aTexelCentredLookupReturnsTheTexelAtEveryLevel() {
        Picture p = random(12, 7, 1);
        MipMap mip = new MipMap(p, 1);
        double[] out = new double[3];
        for (int y = 0; y < 7; y++) {
            for (int x = 0; x < 12; x++) {
                mip.sample((x + 0.5) / 12, (y + 0.5) / 7, 0, out);
                for (int c = 0; c < 3; c++) assertThat(out[c]).isEqualTo(p.get(x, y, c), org.assertj.core.data.Offset.offset(1e-6));
                // Whole turns away: textures tile.
                mip.sample((x + 0.5) / 12 - 3, (y + 0.5) / 7 + 5, 0, out);
                for (int c = 0; c < 3; c++) assertThat(out[c]).isEqualTo(p.get(x, y, c), org.assertj.core.data.Offset.offset(1e-6));
            }
        }
        // Level 1 of a 12 × 7 picture is 6 × 3, each texel the mean of the 2 × 2 under it.
        assertThat(mip.width(1)).isEqualTo(6);
        assertThat(mip.height(1)).isEqualTo(3);
        mip.sample(2.5 / 6, 1.5 / 3, 1, out);
        double mean = (p.get(4, 2, 0) + p.get(5, 2, 0) + p.get(4, 3, 0) + p.get(5, 3, 0)) / 4.0;
        assertThat(out[0]).isCloseTo(mean, org.assertj.core.data.Offset.offset(1e-6));
        assertThat(mip.level(1.0 / 12, 0)).isEqualTo(0);
        assertThat(mip.level(2.0 / 12, 0)).isEqualTo(1);
    }

    /**
     * A plane facing the camera at distance 10, the camera's field of view making each pixel one
     * unit wide there, and a picture of {@code n × n} texels spread over the 32 × 32 units seen:
     * each pixel centre falls on a texel centre of level log2(n/32).
     */
    private static FrameBuffer facing(Picture p) {
        double fov = Math.toDegrees(2 * Math.atan(16.0 / 10));
        Settings s = Scenes.settings(camera(v(0, 0, 0), v(0, 0, 1), fov), List.of(point(v(0, 0, 100), Rgb.WHITE, 0, 1)),
                Background.BLACK, 32, 32);
        ImageTexture t = new ImageTexture("random", p, TextureMapping.PLANAR, v(32, 32, 32), Vec3.ZERO, v(-16, 16, 0));
        return Renderer.prepare(scene(s, plane(v(0, 0, -1), v(0, 0, 10), textured(t)))).render(2, RenderMonitor.NONE);
    }

    /** A picture of 8-bit codes (as files load) makes the very mip chain of the floats it stands for, with and without gamma. */
    @Test
    void codesMakeTheMipChainOfTheirFloats() {
        SplittableRandom r = new SplittableRandom(23);
        int[] codes = new int[13 * 9];
        for (int i = 0; i < codes.length; i++) codes[i] = r.nextInt(1 << 24);
        Picture coded = Picture.ofCodes(13, 9, codes), floats = new Picture(13, 9, coded.floats());
        for (double gamma : new double[] {1, 2.2}) {
            MipMap a = new MipMap(coded, gamma), b = new MipMap(floats, gamma);
            assertThat(a.levels()).isEqualTo(b.levels());
            double[] got = new double[3], want = new double[3];
            for (int i = 0; i < 5_000; i++) {
                double s = r.nextDouble(-2, 2), t = r.nextDouble(-2, 2), lod = r.nextDouble(-1, a.levels());
                a.sample(s, t, lod, got);
                b.sample(s, t, lod, want);
                assertThat(got).containsExactly(want);
            }
        }
    }

    @Test
    void oneTexelPerPixelOnAFacingPlaneIsLevelZeroAndTwoIsLevelOne() {
        Picture p = random(32, 32, 2);
        FrameBuffer fb = facing(p);
        for (int j = 0; j < 32; j++) {
            for (int i = 0; i < 32; i++) Reference.assertPixel(fb, i, j, new Rgb(p.get(i, j, 0), p.get(i, j, 1), p.get(i, j, 2)));
        }
        Picture q = random(64, 64, 3);
        fb = facing(q);
        for (int j = 0; j < 32; j++) {
            for (int i = 0; i < 32; i++) {
                double[] mean = new double[3];
                for (int c = 0; c < 3; c++) {
                    mean[c] = (q.get(2 * i, 2 * j, c) + q.get(2 * i + 1, 2 * j, c) + q.get(2 * i, 2 * j + 1, c)
                            + q.get(2 * i + 1, 2 * j + 1, c)) / 4;
                }
                Reference.assertPixel(fb, i, j, new Rgb(mean[0], mean[1], mean[2]));
            }
        }
    }

    @Test
    void polesAndSeamsGiveNoNaN() {
        Picture p = random(16, 8, 4);
        double[] out = new double[3];
        TexturePoint at = new TexturePoint();
        for (TextureMapping m : TextureMapping.values()) {
            Texture t = new ImageTexture("random", p, m, ONE, v(10, 20, 30), v(0.1, 0, 0));
            for (double[] q : new double[][] {{0, 1, 0}, {0, -1, 0}, {0, 0, 0}, {0, 0.5, -1}, {-0.0, 0.3, -1}, {1e-300, 1, 0}}) {
                for (double w : new double[] {0, 0.01, 1e300}) {
                    at.at(q[0], q[1], q[2], q[0], q[1], q[2]);
                    at.width = w;
                    at.widthU = w;
                    at.widthV = w;
                    t.evaluate(at, out);
                    for (double c : out) assertThat(Double.isFinite(c)).as(m + " at " + java.util.Arrays.toString(q)).isTrue();
                }
            }
        }
        // A sphere seen from above its pole and across its seam, in every mapping.
        Settings s = Scenes.settings(camera(v(0.001, 3, -2.5), v(0, 0, 0), 50), List.of(point(v(0, 5, -5), Rgb.WHITE, 0, 0.3)),
                Background.BLACK, 48, 48);
        for (TextureMapping m : TextureMapping.values()) {
            Texture t = new ImageTexture("random", p, m, ONE, Vec3.ZERO, Vec3.ZERO);
            Reference.assertNoNaN(Renderer.prepare(scene(s, sphere(Vec3.ZERO, 1, textured(t)))).render(2, RenderMonitor.NONE));
        }
    }

    /** The mean |difference| of the three channels over rows {@code from} to {@code to} − 1. */
    private static double error(FrameBuffer a, FrameBuffer b, int from, int to) {
        double sum = 0;
        int n = 0;
        for (int j = from; j < to; j++) {
            for (int i = 0; i < a.width(); i++) {
                for (int c = 0; c < 3; c++) sum += Math.abs(a.get(i, j, c) - b.get(i, j, c));
                n += 3;
            }
        }
        return sum / n;
    }

    /**
     * A checkerboard to the horizon: one sample per pixel with the mip chain against 256 samples per
     * pixel (which look up level ≤ 0 and average), and the same board as the point-sampled Checker at
     * one sample per pixel, which shimmers into moiré far away.
     */
    @Test
    void aCheckerPlaneToTheHorizonConvergesToSupersampling() {
        Settings s = Scenes.settings(camera(v(0, 1, 0), v(0, 0.75, 10), 60), List.of(point(v(0, -100, 0), Rgb.WHITE, 0, 1)),
                Background.BLACK, 96, 64);
        // 8 × 8 cells of 8 texels over 2 × 2 units: cells 0.25 wide, as Checker { scale -> 0.25 }.
        ImageTexture image = new ImageTexture("checker", checker(8, 8), TextureMapping.BOX, v(2, 2, 2), Vec3.ZERO, Vec3.ZERO);
        Material mipped = textured(image);
        FrameBuffer one = Renderer.prepare(scene(s, plane(Vec3.Y, Vec3.ZERO, mipped))).render(2, RenderMonitor.NONE);
        FrameBuffer reference = Renderer.prepare(scene(s.withSampling(16, 1), plane(Vec3.Y, Vec3.ZERO, mipped)))
                .render(2, RenderMonitor.NONE);
        FrameBuffer point = Renderer.prepare(scene(s, plane(Vec3.Y, Vec3.ZERO,
                textured(new Checker(Rgb.BLACK, Rgb.WHITE, 0.25))))).render(2, RenderMonitor.NONE);
        // Rows 33 on: the plane (the horizon is at row 32 for this camera); rows 33 to 40, the far part.
        double mipError = error(one, reference, 33, 64), pointError = error(point, reference, 33, 64);
        double farMip = error(one, reference, 33, 40), farPoint = error(point, reference, 33, 40);
        System.out.printf("horizon checker, mean |error| against 256 spp: mipmapped 1 spp %.4f (far rows %.4f),"
                + " point-sampled 1 spp %.4f (far rows %.4f)%n", mipError, farMip, pointError, farPoint);
        assertThat(mipError).isLessThan(0.07);
        assertThat(mipError).isLessThan(pointError / 3);
        assertThat(farMip).isLessThan(farPoint / 3);
    }
}
