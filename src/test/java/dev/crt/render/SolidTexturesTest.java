package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.image.FrameBuffer;
import dev.crt.scene.Background;
import dev.crt.scene.Marble;
import dev.crt.scene.Material;
import dev.crt.scene.Noise;
import dev.crt.scene.PerlinNoise;
import dev.crt.scene.Plane;
import dev.crt.scene.Rgb;
import dev.crt.scene.Settings;
import dev.crt.scene.SourceSpan;
import dev.crt.scene.Texture;
import dev.crt.scene.Wood;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** Perlin's improved noise and the Noise, Wood and Marble textures against their formulas (docs/rendering.md). */
class SolidTexturesTest {
    private static final Rgb C1 = rgb(0.9, 0.8, 0.1), C2 = rgb(0.1, 0.2, 0.7);

    @Test
    void noiseIsZeroOnTheLatticeBoundedAndContinuous() {
        SplittableRandom r = new SplittableRandom(7);
        double min = 0, max = 0;
        for (int k = 0; k < 20000; k++) {
            int x = r.nextInt(-300, 300), y = r.nextInt(-300, 300), z = r.nextInt(-300, 300);
            assertThat(PerlinNoise.noise(x, y, z)).isEqualTo(0);
            double px = r.nextDouble(-50, 50), py = r.nextDouble(-50, 50), pz = r.nextDouble(-50, 50);
            double n = PerlinNoise.noise(px, py, pz);
            min = Math.min(min, n);
            max = Math.max(max, n);
            // Gradients have length ≤ √2 and the fade is C², so the noise is Lipschitz: small moves, small changes.
            double m = PerlinNoise.noise(px + 1e-6, py - 1e-6, pz + 1e-6);
            assertThat(Math.abs(m - n)).isLessThan(1e-5);
        }
        assertThat(min).isBetween(-1.05, -0.5);
        assertThat(max).isBetween(0.5, 1.05);
    }

    @Test
    void fractalAndTurbulenceAreTheirSums() {
        double x = 1.37, y = -2.2, z = 0.41;
        double f = 0, t = 0;
        for (int i = 0; i < 5; i++) {
            double s = Math.pow(2, i);
            f += PerlinNoise.noise(x * s, y * s, z * s) / s;
            t += Math.abs(PerlinNoise.noise(x * s, y * s, z * s)) / s;
        }
        assertThat(PerlinNoise.fractal(x, y, z, 5)).isCloseTo(f, org.assertj.core.data.Offset.offset(1e-15));
        assertThat(PerlinNoise.turbulence(x, y, z, 5)).isCloseTo(t, org.assertj.core.data.Offset.offset(1e-15));
    }

    private static double clamp(double t) { return Math.max(0, Math.min(1, t)); }

    /** The documented t of each texture at entity point q (before scale), computed from the noise alone. */
    private static double expected(Texture tex, Vec3 p) {
        if (tex instanceof Noise n) {
            Vec3 q = p.div(n.scale());
            double s = n.turbulence() * PerlinNoise.turbulence(q.x(), q.y(), q.z(), n.octaves());
            return clamp(0.5 + 0.5 * PerlinNoise.fractal(q.x() + s, q.y() + s, q.z() + s, n.octaves()));
        }
        if (tex instanceof Wood w) {
            Vec3 q = p.div(w.scale());
            double s = w.turbulence() * PerlinNoise.turbulence(q.x(), q.y(), q.z(), w.octaves());
            return 0.5 - 0.5 * Math.cos(2 * Math.PI * (Math.hypot(q.x(), q.z()) + s));
        }
        Marble m = (Marble) tex;
        Vec3 q = p.div(m.scale());
        double s = m.turbulence() * PerlinNoise.turbulence(q.x(), q.y(), q.z(), m.octaves());
        return 0.5 + 0.5 * Math.sin(2 * Math.PI * (q.x() + s));
    }

    /**
     * A plane y = 0.25 moved up by 0.5 (entity coordinates are before the modifier), lit by ambient
     * light only: every pixel shows color1 + t·(color2 − color1) of its entity point.
     */
    private static void rendersItsFormula(Texture tex) {
        Vec3 eye = v(0.3, 4, -3);
        Settings s = Scenes.settings(camera(eye, v(0.3, 0, 1), 60), List.of(point(v(0, -100, 0), Rgb.WHITE, 0, 1)),
                Background.BLACK, 64, 48);
        Material m = new Material(Rgb.GREY, 1, 0, 30, 0, 0, 1, Rgb.BLACK, true, false, Rgb.BLACK, tex);
        Vec3 shift = v(0, 0.5, 0);
        Plane plane = new Plane(Vec3.Y, v(0, 0.25, 0), m, Transform.translation(shift), SourceSpan.NONE);
        FrameBuffer fb = Renderer.prepare(scene(s, plane)).render(2, RenderMonitor.NONE);
        int checked = 0;
        for (int j = 0; j < s.height(); j++) {
            for (int i = 0; i < s.width(); i++) {
                Vec3 d = Reference.center(s, i, j);
                if (d.y() >= -0.05) continue;
                Vec3 x = eye.plus(d.times((0.75 - eye.y()) / d.y()));
                double t = expected(tex, x.minus(shift));
                Reference.assertPixel(fb, i, j, C1.plus(C2.minus(C1).times(t)));
                checked++;
            }
        }
        assertThat(checked).isGreaterThan(1500);
    }

    @Test
    void noiseWoodAndMarbleRenderTheirFormulas() {
        rendersItsFormula(new Noise(C1, C2, 0.6, 0, 4));
        rendersItsFormula(new Noise(C1, C2, 0.6, 0.8, 3));
        rendersItsFormula(new Wood(C1, C2, 0.3, 0.4, 4));
        rendersItsFormula(new Marble(C1, C2, 0.5, 2, 5));
    }
}
