package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.image.FrameBuffer;
import dev.crt.scene.AreaLight;
import dev.crt.scene.Finish;
import dev.crt.scene.GradientBackground;
import dev.crt.scene.Material;
import dev.crt.scene.Noise;
import dev.crt.scene.Rgb;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import dev.crt.scene.SourceSpan;
import dev.crt.scene.Texture;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Glossy reflection and refraction (docs/rendering.md): the lobe's mean, and bit-identical renders for any thread count. */
class GlossyTest {
    private static final Rgb HORIZON = rgb(0.9, 0.5, 0.1), SKY = rgb(0.1, 0.3, 0.9);
    private static final Vec3 EYE = v(0, 2, -4);

    static Material glossy(Rgb c, double kr, double kt, double rough, int samples, Texture bump) {
        Finish n = Finish.NONE;
        Finish f = new Finish(null, null, null, null, bump, 0.05, rough, samples, n.model(), n.cool(), n.warm(), n.outline());
        return new Material(c, 1, 0.5, 20, kr, kt, 1.5, Rgb.BLACK, true, false, Rgb.BLACK, null, f);
    }

    /** The mean of the background over the lobe of half-angle ρ·90° about r, turned back above the plane y = 0. */
    private static Rgb lobeMean(Vec3 r, double rough) {
        Vec3 a = Math.abs(r.x()) < 0.9 ? v(0, r.z(), -r.y()).normalize() : v(-r.z(), 0, r.x()).normalize();
        Vec3 b = r.cross(a);
        double cosMax = Math.cos(rough * Math.PI / 2);
        Rgb sum = Rgb.BLACK;
        int n = 100;
        for (int i = 0; i < n; i++) {
            double cos = 1 - (i + 0.5) / n * (1 - cosMax), sin = Math.sqrt(1 - cos * cos);
            for (int k = 0; k < n; k++) {
                double phi = 2 * Math.PI * (k + 0.5) / n;
                Vec3 g = a.times(sin * Math.cos(phi)).plus(b.times(sin * Math.sin(phi))).plus(r.times(cos));
                if (g.y() < 0) g = v(g.x(), -g.y(), g.z());
                sum = sum.plus(Reference.gradient(HORIZON, SKY, g));
            }
        }
        return sum.div(n * n);
    }

    @Test
    void aRoughMirrorShowsTheMeanOfItsLobe() {
        Settings s = Scenes.settings(camera(EYE, v(0, 0, 2), 60), List.of(point(v(0, -100, 0), Rgb.WHITE, 0, 0)),
                new GradientBackground(HORIZON, SKY), 24, 16);
        double rough = 0.4;
        FrameBuffer fb = Renderer.prepare(scene(s, plane(Vec3.Y, Vec3.ZERO, glossy(Rgb.BLACK, 1, 0, rough, 256, null))))
                .render(2, RenderMonitor.NONE);
        double sum = 0;
        int n = 0;
        for (int j = 0; j < s.height(); j++) {
            for (int i = 0; i < s.width(); i++) {
                Vec3 d = Reference.center(s, i, j);
                if (d.y() >= 0) continue;
                Rgb want = lobeMean(Reference.reflect(d, Vec3.Y), rough);
                for (int c = 0; c < 3; c++) {
                    double e = Math.abs(fb.get(i, j, c) - want.get(c));
                    assertThat(e).as("pixel (%d,%d) channel %d", i, j, c).isLessThan(0.04);
                    sum += e;
                    n++;
                }
            }
        }
        assertThat(n).isGreaterThan(300);
        System.out.printf("rough mirror: mean |error| against the lobe's integral %.5f at 256 lobe samples%n", sum / n);
        assertThat(sum / n).isLessThan(0.01);
    }

    /** Glossy glass and metal with a bump map, under an area light, on a noise floor: the same bytes on 1, 2 and 7 threads. */
    @Test
    void glossyTexturedSoftShadowedScenesAreBitIdenticalForAnyThreadCount() {
        AreaLight area = new AreaLight(v(-1, 4, -1), v(1, 0, 0), v(0, 0, 1), 3, Rgb.WHITE, 0, 0.1, SourceSpan.NONE);
        Settings s = Scenes.settings(camera(EYE, v(0, 0.5, 1), 60), List.of(area), new GradientBackground(HORIZON, SKY), 40, 30);
        Material floor = new Material(Rgb.GREY, 1, 0, 30, 0, 0, 1, Rgb.BLACK, true, false, Rgb.BLACK,
                new Noise(Rgb.WHITE, rgb(0.2, 0.3, 0.1), 0.3, 0.5, 3));
        Scene scene = scene(s, plane(Vec3.Y, Vec3.ZERO, floor),
                sphere(v(-0.8, 0.7, 1), 0.7, glossy(rgb(0.9, 0.9, 0.9), 0.2, 0.8, 0.2, 4, new Noise(Rgb.WHITE, Rgb.BLACK, 0.1, 0, 2))),
                new dev.crt.scene.Sphere(v(0.9, 0.6, 1), 0.6, glossy(rgb(0.8, 0.6, 0.2), 0.7, 0, 0.3, 6, null),
                        Transform.IDENTITY, SourceSpan.NONE));
        float[] one = Renderer.prepare(scene).render(1, RenderMonitor.NONE).data();
        assertThat(Renderer.prepare(scene).render(2, RenderMonitor.NONE).data()).isEqualTo(one);
        assertThat(Renderer.prepare(scene).render(7, RenderMonitor.NONE).data()).isEqualTo(one);
    }
}
