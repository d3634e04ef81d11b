package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Vec3;
import dev.crt.image.FrameBuffer;
import dev.crt.scene.Checker;
import dev.crt.scene.Finish;
import dev.crt.scene.Material;
import dev.crt.scene.Rgb;
import dev.crt.scene.Settings;
import dev.crt.scene.SolidBackground;
import dev.crt.scene.Texture;
import java.util.List;
import java.util.function.Function;
import org.junit.jupiter.api.Test;

/**
 * Textures on every colour channel (docs/rendering.md, "Textures"): emission by colour, specular,
 * reflectivity and transparency by luminance, each pixel against the formula with the channel's
 * value at its hit point, and textured transparency in shadow rays.
 */
class ChannelTexturesTest {
    private static final Vec3 EYE = v(0.3, 5, -4);
    private static final Rgb SKY = rgb(0.2, 0.6, 0.9);
    /** Grey cells, so luminance is the grey level itself: 0.25 and 0.75. */
    private static final Checker GREYS = new Checker(rgb(0.25, 0.25, 0.25), rgb(0.75, 0.75, 0.75), 0.7);

    private static double grey(Vec3 x) {
        long cell = (long) Math.floor(x.x() / 0.7) + (long) Math.floor(x.z() / 0.7) + (long) Math.floor((x.y() - 1e-9) / 0.7);
        return (cell & 1) == 0 ? 0.25 : 0.75;
    }

    private static Material with(Rgb color, double ks, Finish f) {
        return new Material(color, 1, ks, 10, 0, 0, 1.5, Rgb.BLACK, true, false, Rgb.BLACK, null, f);
    }

    private static Finish finish(Texture emission, Texture specular, Texture reflectivity, Texture transparency) {
        Finish n = Finish.NONE;
        return new Finish(emission, specular, reflectivity, transparency, null, 1, 0, n.glossySamples(), n.model(), n.cool(),
                n.warm(), n.outline());
    }

    /** Checks every pixel whose centre ray meets the plane y = 0 away from cell edges against {@code expected}(hit point). */
    private static void check(FrameBuffer fb, Settings s, Function<Vec3, Rgb> expected) {
        int checked = 0;
        for (int j = 0; j < s.height(); j++) {
            for (int i = 0; i < s.width(); i++) {
                Vec3 d = Reference.center(s, i, j);
                if (d.y() >= 0) continue;
                Vec3 x = EYE.plus(d.times(-EYE.y() / d.y()));
                double fx = x.x() / 0.7, fz = x.z() / 0.7;
                if (Math.abs(fx - Math.rint(fx)) < 1e-3 || Math.abs(fz - Math.rint(fz)) < 1e-3) continue;
                Reference.assertPixel(fb, i, j, expected.apply(x));
                checked++;
            }
        }
        assertThat(checked).isGreaterThan(1000);
    }

    private static Settings settings(List<dev.crt.scene.Light> lights) {
        return Scenes.settings(camera(EYE, v(0.3, 0, 1), 60), lights, new SolidBackground(SKY), 64, 48);
    }

    private static FrameBuffer render(Settings s, Material m) {
        return Renderer.prepare(scene(s, plane(Vec3.Y, Vec3.ZERO, m))).render(2, RenderMonitor.NONE);
    }

    @Test
    void emissionTakesTheTexturesColour() {
        Settings s = settings(List.of(point(v(0, -100, 0), Rgb.WHITE, 0, 0)));
        Checker c = new Checker(rgb(0.9, 0.1, 0.3), rgb(0.1, 0.8, 0.2), 0.7);
        check(render(s, with(Rgb.BLACK, 0, finish(c, null, null, null))), s,
                x -> grey(x) == 0.25 ? rgb(0.9, 0.1, 0.3) : rgb(0.1, 0.8, 0.2));
    }

    @Test
    void specularTakesTheTexturesLuminance() {
        Vec3 light = v(0.5, 3, 1);
        Settings s = settings(List.of(point(light, Rgb.WHITE, 0, 0)));
        check(render(s, with(Rgb.BLACK, 0, finish(null, GREYS, null, null))), s,
                x -> Reference.phong(Vec3.Y, light.minus(x).normalize(), EYE.minus(x).normalize(), Rgb.WHITE, Rgb.BLACK, 1,
                        grey(x), 10, 1));
    }

    @Test
    void reflectivityAndTransparencyTakeTheTexturesLuminance() {
        Settings s = settings(List.of(point(v(0, -100, 0), Rgb.WHITE, 0, 0)));
        // A black plane: what shows is kr times the sky it mirrors, or kt times the sky seen through it.
        check(render(s, with(Rgb.BLACK, 0, finish(null, null, GREYS, null))), s, x -> SKY.times(grey(x)));
        check(render(s, with(Rgb.BLACK, 0, finish(null, null, null, GREYS))), s, x -> SKY.times(grey(x)));
    }

    @Test
    void shadowRaysReadTexturedTransparencyWhereTheyCrossTheSurface() {
        // A thin textured slab (a plane y = 1 cut to a box) between a light and a matte floor: each
        // floor point is lit through the cell its shadow ray crosses, twice (top and bottom face).
        Vec3 light = v(0.2, 6, 1.1);
        Settings s = settings(List.of(point(light, Rgb.WHITE, 0, 0)));
        Material glass = new Material(Rgb.BLACK, 1, 0, 10, 0, 1, 1, Rgb.BLACK, true, false, Rgb.BLACK, null,
                finish(null, null, null, GREYS));
        // Thin: both faces fall in the same cells but for a sliver, and the camera never sees it (it is above the eye's frustum).
        dev.crt.scene.Box slab = box(v(-50, 1.3, -50), v(50, 1.31, 50), glass);
        Settings low = Scenes.settings(camera(v(0.3, 1, -4), v(0.3, 0, 1), 60), List.of(point(light, Rgb.WHITE, 0, 0)),
                new SolidBackground(SKY), 64, 48);
        Material floor = matte(rgb(0.8, 0.8, 0.8));
        FrameBuffer fb = Renderer.prepare(scene(low, plane(Vec3.Y, Vec3.ZERO, floor), slab)).render(2, RenderMonitor.NONE);
        int checked = 0;
        for (int j = 0; j < low.height(); j++) {
            for (int i = 0; i < low.width(); i++) {
                Vec3 d = Reference.center(low, i, j);
                if (d.y() >= 0) continue;
                Vec3 eye = v(0.3, 1, -4);
                Vec3 x = eye.plus(d.times(-eye.y() / d.y()));
                Vec3 w = light.minus(x).normalize();
                Vec3 top = x.plus(w.times((1.31 - x.y()) / w.y())), bottom = x.plus(w.times((1.3 - x.y()) / w.y()));
                double kt1 = grey(bottom.plus(v(0, 1e-6, 0))), kt2 = grey(top.minus(v(0, 1e-6, 0)));
                boolean nearEdge = false;
                for (Vec3 p : new Vec3[] {top, bottom}) {
                    double fx = p.x() / 0.7, fz = p.z() / 0.7;
                    nearEdge |= Math.abs(fx - Math.rint(fx)) < 2e-2 || Math.abs(fz - Math.rint(fz)) < 2e-2;
                }
                if (nearEdge) continue;
                Rgb lit = Reference.phong(Vec3.Y, w, eye.minus(x).normalize(), Rgb.WHITE, rgb(0.8, 0.8, 0.8), 1, 0, 30, 1);
                Reference.assertPixel(fb, i, j, lit.times(kt1 * kt2));
                checked++;
            }
        }
        assertThat(checked).isGreaterThan(1000);
    }
}
