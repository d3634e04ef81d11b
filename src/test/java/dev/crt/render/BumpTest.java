package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Vec3;
import dev.crt.image.FrameBuffer;
import dev.crt.scene.Background;
import dev.crt.scene.Finish;
import dev.crt.scene.Marble;
import dev.crt.scene.Material;
import dev.crt.scene.Rgb;
import dev.crt.scene.Settings;
import dev.crt.scene.Texture;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Bump mapping (docs/rendering.md): the height's gradient along the tangent frame tilts the shading normal. */
class BumpTest {
    private static final Vec3 EYE = v(0.3, 5, -4), LIGHT = v(-2, 4, 1);
    private static final Rgb C = rgb(0.8, 0.7, 0.6);
    /** t = ½ + ½·sin(2πx/4): luminance t from black to white, a height of bumpscale·t. */
    private static final Texture WAVES = new Marble(Rgb.BLACK, Rgb.WHITE, 4, 0, 1);

    private static Material bumped(double bumpScale) {
        Finish n = Finish.NONE;
        Finish f = new Finish(null, null, null, null, WAVES, bumpScale, 0, n.glossySamples(), n.model(), n.cool(), n.warm(),
                n.outline());
        return new Material(C, 1, 0, 30, 0, 0, 1, Rgb.BLACK, true, false, Rgb.BLACK, null, f);
    }

    private static Settings settings() {
        return Scenes.settings(camera(EYE, v(0.3, 0, 1), 60), List.of(point(LIGHT, Rgb.WHITE, 0, 0)), Background.BLACK, 64, 48);
    }

    @Test
    void aPlaneShadesAlongTheTiltedNormal() {
        double k = 0.6;
        Settings s = settings();
        FrameBuffer fb = Renderer.prepare(scene(s, plane(Vec3.Y, Vec3.ZERO, bumped(k)))).render(2, RenderMonitor.NONE);
        int checked = 0;
        for (int j = 0; j < s.height(); j++) {
            for (int i = 0; i < s.width(); i++) {
                Vec3 d = Reference.center(s, i, j);
                if (d.y() >= 0) continue;
                Vec3 x = EYE.plus(d.times(-EYE.y() / d.y()));
                // h = k(½ + ½ sin(2πx/4)): ∂h/∂x = k·(π/4)·cos(2πx/4); N' = normalize(−∂h/∂x, 1, 0).
                double hx = k * Math.PI / 4 * Math.cos(2 * Math.PI * x.x() / 4);
                Vec3 n = v(-hx, 1, 0).normalize();
                Vec3 w = LIGHT.minus(x).normalize();
                Reference.assertPixel(fb, i, j, Reference.phong(n, w, EYE.minus(x).normalize(), Rgb.WHITE, C, 1, 0, 30, 1));
                checked++;
            }
        }
        assertThat(checked).isGreaterThan(1500);
    }

    @Test
    void bumpScaleZeroIsTheFlatSurfaceAndStrongBumpsStayFinite() {
        Settings s = settings();
        FrameBuffer flat = Renderer.prepare(scene(s, sphere(v(0, 1, 0), 1, matte(C)), plane(Vec3.Y, Vec3.ZERO, matte(C))))
                .render(2, RenderMonitor.NONE);
        FrameBuffer zero = Renderer.prepare(scene(s, sphere(v(0, 1, 0), 1, bumped(0)), plane(Vec3.Y, Vec3.ZERO, bumped(0))))
                .render(2, RenderMonitor.NONE);
        int differ = 0;
        for (int k = 0; k < flat.data().length; k++) if (flat.data()[k] != zero.data()[k]) differ++;
        assertThat(differ).as("values differing from the flat render").isZero();
        FrameBuffer strong = Renderer.prepare(scene(s, sphere(v(0, 1, 0), 1, bumped(1e6)), plane(Vec3.Y, Vec3.ZERO, bumped(-1e6))))
                .render(2, RenderMonitor.NONE);
        Reference.assertNoNaN(strong);
    }
}
