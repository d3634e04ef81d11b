package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Vec3;
import dev.crt.image.FrameBuffer;
import dev.crt.scene.Background;
import dev.crt.scene.Entity;
import dev.crt.scene.GradientBackground;
import dev.crt.scene.Light;
import dev.crt.scene.Material;
import dev.crt.scene.PanoramaBackground;
import dev.crt.scene.Picture;
import dev.crt.scene.Rgb;
import dev.crt.scene.Sampler;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import dev.crt.scene.Shading;
import dev.crt.scene.SolidBackground;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;

/**
 * {@code shading -> "original"} against pixels computed by hand from shared/original-shading.md:
 * each expected value is formed here from the formulas, truncated to 8 bits as the 2015 program
 * wrote them, and must equal the rendered level exactly.
 */
class OriginalShadingTest {
    private static final int W = 40, H = 30;

    /** 2015 settings: every attribute given (as a script that sets them all), shading original. */
    private static Settings original(Vec3 eye, Vec3 at, double fov, List<Light> lights, Background bg, int ss, int depth) {
        return new Settings("t", "", "", "", lights, camera(eye, at, fov), bg, ss, 1, depth, 1, W, H, Sampler.GRID, 0,
                Settings.DEFAULT_NOISE, Shading.ORIGINAL, Settings.ATTRIBUTES);
    }

    private static FrameBuffer render(Settings s, Entity... e) {
        return Renderer.prepare(scene(s, e)).render(2, RenderMonitor.NONE);
    }

    /** The byte the 2015 program wrote for linear value c. */
    private static int level(double c) {
        return c <= 0 ? 0 : (int) Math.min(255, Math.floor(c * 255));
    }

    private static void assertLevels(FrameBuffer fb, int i, int j, Rgb expected) {
        for (int c = 0; c < 3; c++) {
            double e = c == 0 ? expected.r() : c == 1 ? expected.g() : expected.b();
            assertThat(Math.round(fb.get(i, j, c) * 255)).as("pixel (%d, %d) channel %d: %s", i, j, c, expected).isEqualTo(level(e));
        }
    }

    /** A material that sets reflectivity but not diffuse, as 2015 scripts did: kd = 1 − r. */
    private static Material reflective(Rgb c, double r) {
        return new Material(c, 1, 0, 30, r, 0, 1, Rgb.BLACK, false);
    }

    @Test
    void aReflectiveBallUnderAFalloffLightSeenDirectly() {
        Rgb cm = rgb(0.8, 0.4, 0.2), cl = rgb(1, 0.9, 0.8);
        Vec3 c = v(0, 0, 5), light = v(2, 3, 0);
        double r = 0.25, falloff = 20, ambient = 0.1;
        Settings s = original(Vec3.ZERO, c, 40, List.of(point(light, cl, falloff, ambient)), Background.BLACK, 1, 0);
        FrameBuffer fb = render(s, sphere(c, 1, reflective(cm, r)));
        int checked = 0;
        for (int j = 0; j < H; j += 2) {
            for (int i = 0; i < W; i += 2) {
                Vec3 d = Reference.center(s, i, j);
                double t = Reference.sphereHit(Vec3.ZERO, d, c, 1);
                if (!(t > 0)) continue;
                Vec3 p = d.times(t), n = p.minus(c).normalize();
                Vec3 toLight = light.minus(p);
                double dl = toLight.length();
                Vec3 l = toLight.div(dl);
                if (n.dot(l) <= 0.05) continue;
                double isl = falloff / ((dl + t) * (dl + t));
                Rgb expected = cl.times(ambient * (1 - r)).plus(cl.times(n.dot(l) * isl).times(cm.times(1 - r)));
                assertLevels(fb, i, j, expected);
                checked++;
            }
        }
        assertThat(checked).isGreaterThan(20);
    }

    @Test
    void throughAMirrorTheFalloffCountsTheWholePathFromTheCamera() {
        // The camera looks at a black mirror 10 ahead; behind the camera, a ball the mirror shows.
        Rgb cm = rgb(0.9, 0.6, 0.3), cl = rgb(1, 1, 1);
        Vec3 light = v(0, 3, -2);
        double falloff = 50;
        Settings s = original(Vec3.ZERO, v(0, 0, 1), 30, List.of(point(light, cl, falloff, 0)), Background.BLACK, 1, 3);
        Entity mirror = plane(v(0, 0, -1), v(0, 0, 10), reflective(Rgb.BLACK, 1));
        Entity ball = sphere(v(0, 0, -5), 1, reflective(cm, 0));
        FrameBuffer fb = render(s, mirror, ball);
        int checked = 0;
        for (int j = 0; j < H; j++) {
            for (int i = 0; i < W; i++) {
                Vec3 d = Reference.center(s, i, j);
                double tm = 10 / d.z();
                Vec3 m = d.times(tm);
                Vec3 back = Reference.reflect(d, v(0, 0, -1));
                double tb = Reference.sphereHit(m, back, v(0, 0, -5), 1);
                if (!(tb > 0)) continue;
                Vec3 p = m.plus(back.times(tb)), n = p.minus(v(0, 0, -5)).normalize();
                Vec3 toLight = light.minus(p);
                double dl = toLight.length();
                Vec3 l = toLight.div(dl);
                if (n.dot(l) <= 0.05) continue;
                double path = tm + tb;
                Rgb expected = cl.times(n.dot(l) * falloff / ((dl + path) * (dl + path))).times(cm);
                assertLevels(fb, i, j, expected);
                checked++;
            }
        }
        assertThat(checked).isGreaterThan(4);
    }

    @Test
    void inShadowOnlyTheAmbientTermRemainsWithoutTheMaterialColour() {
        Rgb cl = rgb(1, 0.8, 0.6);
        double ambient = 0.3, r = 0.2;
        Settings s = original(v(0, 4, -6), v(0, 0, 0), 40, List.of(point(v(0, 6, 0), cl, 0, ambient)), Background.BLACK, 1, 0);
        // The ball hides the light from the floor right under it; the floor's colour must not show in its shadow.
        FrameBuffer fb = render(s, plane(v(0, 1, 0), v(0, 0, 0), reflective(rgb(0.2, 0.9, 0.4), r)), sphere(v(0, 2, 0), 1, M));
        Vec3 d = v(0, 0, 0).minus(v(0, 4, -6)).normalize();
        int[] px = pixelOf(s, d);
        assertLevels(fb, px[0], px[1], cl.times(ambient * (1 - r)));
    }

    private static final Material M = reflective(rgb(0.5, 0.5, 0.5), 0);

    /** The pixel whose centre ray is nearest to direction d. */
    private static int[] pixelOf(Settings s, Vec3 d) {
        int[] best = {0, 0};
        double bestDot = -2;
        for (int j = 0; j < H; j++) {
            for (int i = 0; i < W; i++) {
                double dot = Reference.center(s, i, j).dot(d);
                if (dot > bestDot) {
                    bestDot = dot;
                    best = new int[] {i, j};
                }
            }
        }
        return best;
    }

    @Test
    void aPlaneSeenFromBehindIsNotThereAndANegativeDiffuseClampsToZero() {
        Rgb bg = rgb(0.2, 0.4, 0.6);
        // The plane's normal points away from the camera: the 2015 program never hit it.
        Settings s = original(Vec3.ZERO, v(0, 0, 1), 40, List.of(point(v(0, 0, -3), Rgb.WHITE, 0, 0)), new SolidBackground(bg), 1, 0);
        FrameBuffer fb = render(s, plane(v(0, 0, 1), v(0, 0, 5), M));
        assertLevels(fb, W / 2, H / 2, bg);
        // CRT's model sees it.
        FrameBuffer crt = render(s.withShading(Shading.CRT), plane(v(0, 0, 1), v(0, 0, 5), M));
        assertThat(crt.get(W / 2, H / 2, 0)).isNotEqualTo((float) 0.2);
        // Facing the camera but lit from behind: N·L < 0 is not clamped, and the sum truncates to 0.
        Settings behind = original(Vec3.ZERO, v(0, 0, 1), 40, List.of(point(v(0, 0, 8), Rgb.WHITE, 0, 0)), new SolidBackground(bg), 1, 0);
        FrameBuffer dark = render(behind, plane(v(0, 0, -1), v(0, 0, 5), M));
        assertLevels(dark, W / 2, H / 2, Rgb.BLACK);
    }

    @Test
    void theGradientIsSymmetricBelowTheHorizonAndLevelsAreTruncated() {
        Rgb horizon = rgb(0.9, 0.5, 0.1), sky = rgb(0.1, 0.3, 1.0);
        Settings s = original(Vec3.ZERO, v(0, -1, 2), 60, List.of(), new GradientBackground(horizon, sky), 1, 0);
        FrameBuffer fb = render(s);
        for (int j = 0; j < H; j += 3) {
            for (int i = 0; i < W; i += 3) {
                Vec3 d = Reference.center(s, i, j);
                double e = Math.abs(d.y());
                assertLevels(fb, i, j, horizon.times(1 - e).plus(sky.times(e)));
            }
        }
        // 0.5 is 127.5 levels: the 2015 program wrote 127 where CRT rounds to 128.
        Settings half = original(Vec3.ZERO, v(0, 0, 1), 60, List.of(), new SolidBackground(rgb(0.5, 0.5, 0.5)), 1, 0);
        assertThat(Math.round(render(half).get(3, 3, 0) * 255)).isEqualTo(127);
        assertThat(Math.round(render(half.withShading(Shading.CRT)).get(3, 3, 0) * 255)).isEqualTo(128);
    }

    @Test
    void thePanoramaIsMappedLinearlyInHeightAndWrapsBothWays() {
        int w = 8, h = 4;
        float[] rgb = new float[w * h * 3];
        for (int k = 0; k < w * h; k++) {
            rgb[3 * k] = (k % w) / 8f;
            rgb[3 * k + 1] = (k / w) / 4f;
            rgb[3 * k + 2] = ((k * 37) % 11) / 11f;
        }
        Picture pic = new Picture(w, h, rgb);
        double angle = 0.7;
        BackgroundShader shader = new BackgroundShader(new PanoramaBackground("p", pic, angle), 2.2, true);
        double[] out = new double[3];
        for (Vec3 d : new Vec3[] {v(0.3, 0.2, 0.9), v(-0.9, -0.4, -0.1), v(0.01, 0.99, -0.05), v(0.5, -0.999, 0.2), v(-1e-9, 0, -1)}) {
            Vec3 u = d.normalize();
            double a = (angle + Math.atan2(-u.x(), u.z()) + Math.PI) % (2 * Math.PI);
            if (a < 0) a += 2 * Math.PI;
            double x = (1 - a / (2 * Math.PI)) * w, y = (1 - (u.y() / 2 + 0.5)) * h;
            int x0 = (int) Math.floor(x), y0 = (int) Math.floor(y);
            double fx = x - x0, fy = y - y0;
            shader.shade(d.x(), d.y(), d.z(), out);
            for (int c = 0; c < 3; c++) {
                double expected = (1 - fy) * ((1 - fx) * pic.get(Math.floorMod(x0, w), Math.floorMod(y0, h), c)
                        + fx * pic.get(Math.floorMod(x0 + 1, w), Math.floorMod(y0, h), c))
                        + fy * ((1 - fx) * pic.get(Math.floorMod(x0, w), Math.floorMod(y0 + 1, h), c)
                        + fx * pic.get(Math.floorMod(x0 + 1, w), Math.floorMod(y0 + 1, h), c));
                assertThat(out[c]).as("%s channel %d", d, c).isCloseTo(expected, org.assertj.core.api.Assertions.within(1e-6));
            }
        }
    }

    @Test
    void supersamplesSitAtTheCellsTopLeftCorners() {
        // Camera along +z, fov 90, square picture: pixel column i + sx looks at x = 2(i + sx)/W − 1 on z = 1.
        // A thin glowing box fills x ≥ edge at z = 1, with its edge at column 10.6 of a 20-pixel-wide picture.
        int w = 20;
        double edge = 2 * 10.6 / w - 1;
        Settings s = new Settings("t", "", "", "", List.of(), camera(Vec3.ZERO, v(0, 0, 1), 90), Background.BLACK, 2, 1, 0, 1,
                w, w, Sampler.GRID, 0, Settings.DEFAULT_NOISE, Shading.ORIGINAL, Settings.ATTRIBUTES);
        Material glow = new Material(Rgb.BLACK, 0, 0, 1, 0, 0, 1, Rgb.WHITE, true);
        Entity box = box(v(edge, -10, 1), v(10, 10, 1.001), glow);
        FrameBuffer fb = render(s, box);
        // Samples at columns 10.0 and 10.5 both miss; 11.0 and 11.5 both hit.
        assertThat(fb.get(10, 5, 0)).isEqualTo(0f);
        assertThat(Math.round(fb.get(11, 5, 0) * 255)).isEqualTo(255);
        // CRT's centred samples (10.25, 10.75) put half of column 10 on the box.
        FrameBuffer crt = render(s.withShading(Shading.CRT), box);
        assertThat(crt.get(10, 5, 0)).isEqualTo(0.5f);
    }

    @Test
    void theDefaultsOfTheOriginalModelApplyOnlyWhereTheScriptGaveNothing() {
        Settings none = new Settings("t", "", "", "", List.of(), camera(Vec3.ZERO, v(0, 0, 1), 40), Background.BLACK, 1, 1, 5, 2.2,
                W, H, Sampler.GRID, 0, Settings.DEFAULT_NOISE, Shading.ORIGINAL, Set.of());
        assertThat(none.effectiveRecursionDepth()).isEqualTo(3);
        assertThat(none.effectiveBackground()).isEqualTo(new SolidBackground(Rgb.WHITE));
        assertThat(none.outputGamma()).isEqualTo(1);
        assertThat(render(none).get(4, 4, 1)).isEqualTo(1f);
        Settings given = none.withShading(Shading.CRT);
        assertThat(given.effectiveRecursionDepth()).isEqualTo(5);
        assertThat(given.outputGamma()).isEqualTo(2.2);
        assertThat(given.effectiveBackground()).isEqualTo(Background.BLACK);
    }
}
