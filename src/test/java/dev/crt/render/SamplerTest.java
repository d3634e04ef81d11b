package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.image.FrameBuffer;
import dev.crt.scene.ApertureShape;
import dev.crt.scene.Camera;
import dev.crt.scene.GradientBackground;
import dev.crt.scene.Rgb;
import dev.crt.scene.Sampler;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import dev.crt.scene.SourceSpan;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The pixel samplers: the budget each spends, thread independence, and their error against a
 * converged reference on a scene with defocus and hard edges (a lit ball in front of a
 * checkered row of boxes, seen through a wide lens).
 */
class SamplerTest {
    private static final int W = 40, H = 30;

    private static Scene scene(Sampler sampler, int supersampling, int dof, double noise, long seed) {
        Camera cam = new Camera(v(0, 1, -6), v(0, 0.5, 0), 45, 0, 300, 6, ApertureShape.HEXAGON, SourceSpan.NONE);
        Settings s = new Settings("samplers", "", "", "", List.of(point(v(-3, 5, -4), Rgb.WHITE, 0, 0.1)), cam,
                new GradientBackground(rgb(0.9, 0.9, 1), rgb(0.1, 0.2, 0.6)), supersampling, dof, 2, 1, W, H,
                sampler, seed, noise);
        var entities = new java.util.ArrayList<dev.crt.scene.Entity>();
        entities.add(sphere(v(0.3, 0.6, 0), 1, matte(rgb(0.9, 0.3, 0.2))));
        for (int k = 0; k < 6; k++) {
            double x = -3 + k;
            entities.add(box(v(x, 0, 3), v(x + 0.5, 2.5, 3.5), matte(k % 2 == 0 ? Rgb.WHITE : rgb(0.05, 0.05, 0.05))));
        }
        entities.add(plane(v(0, 1, 0), v(0, -0.4, 0), matte(rgb(0.5, 0.5, 0.5))));
        return new Scene("samplers", s, entities);
    }

    private static FrameBuffer render(Scene scene, int threads) {
        return Renderer.prepare(scene).render(threads, RenderMonitor.NONE);
    }

    /** Root mean square difference in 8-bit levels (linear values clamped to [0, 1], gamma 1). */
    static double rmse(FrameBuffer a, FrameBuffer b) {
        float[] x = a.data(), y = b.data();
        double sum = 0;
        for (int k = 0; k < x.length; k++) {
            double d = 255 * (Math.min(1, Math.max(0, x[k])) - Math.min(1, Math.max(0, y[k])));
            sum += d * d;
        }
        return Math.sqrt(sum / x.length);
    }

    private static FrameBuffer reference;

    private static synchronized FrameBuffer reference() {
        if (reference == null) reference = render(scene(Sampler.SOBOL, 8, 64, 0, 99), 0);
        return reference;
    }

    @Test
    void everySamplerIsTheSameForAnyThreadCount() {
        for (Sampler s : Sampler.values()) {
            Scene scene = scene(s, 2, 4, 0.5, 3);
            float[] one = render(scene, 1).data();
            assertThat(render(scene, 2).data()).as(s.word()).isEqualTo(one);
            assertThat(render(scene, 7).data()).as(s.word()).isEqualTo(one);
        }
    }

    @Test
    void everySamplerSpendsTheBudgetAndTheAdaptiveOneAtMostThat() {
        long budget = (long) W * H * 3 * 3 * 5;
        for (Sampler s : Sampler.values()) {
            Renderer r = Renderer.prepare(scene(s, 3, 5, 0.5, 0));
            r.render(2, RenderMonitor.NONE);
            long primary = r.stats().primaryRays();
            if (s == Sampler.ADAPTIVE) {
                // Flat sky and floor stop at the minimum; defocused edges take more.
                assertThat(primary).isLessThan(budget).isGreaterThanOrEqualTo((long) W * H * PixelSampler.PILOT);
            } else {
                assertThat(primary).as(s.word()).isEqualTo(budget);
            }
        }
    }

    @Test
    void theSceneSeedChangesTheRandomSamplersAndZeroKeepsTheGridOfWaveOne() {
        assertThat(render(scene(Sampler.JITTERED, 2, 4, 0.5, 1), 2).data())
                .isNotEqualTo(render(scene(Sampler.JITTERED, 2, 4, 0.5, 2), 2).data());
        assertThat(render(scene(Sampler.SOBOL, 2, 4, 0.5, 1), 2).data())
                .isNotEqualTo(render(scene(Sampler.SOBOL, 2, 4, 0.5, 2), 2).data());
        // The three-argument Settings is wave 1's: grid, seed 0.
        Scene wave1 = scene(Sampler.GRID, 2, 4, 0.5, 0);
        Settings s = wave1.settings();
        Settings old = new Settings(s.title(), s.author(), s.date(), s.notes(), s.lights(), s.camera(), s.background(),
                2, 4, s.recursionDepth(), s.gamma(), W, H);
        assertThat(render(wave1.withSettings(old), 2).data()).isEqualTo(render(wave1, 2).data());
    }

    @Test
    void sobolBeatsTheGridAndEverySamplerConvergesAsTheBudgetGrows() {
        FrameBuffer ref = reference();
        double[] at16 = new double[3], at256 = new double[3];
        Sampler[] kinds = {Sampler.GRID, Sampler.JITTERED, Sampler.SOBOL};
        for (int k = 0; k < kinds.length; k++) {
            at16[k] = rmse(render(scene(kinds[k], 2, 4, 0, 0), 0), ref);
            at256[k] = rmse(render(scene(kinds[k], 4, 16, 0, 0), 0), ref);
            // Error falls about as 1/sqrt(samples) or faster: 16 times the samples, a quarter of the error or less, with room.
            assertThat(at256[k]).as(kinds[k].word()).isLessThan(0.45 * at16[k]);
        }
        System.out.printf("RMSE in levels, 16 spp / 256 spp: grid %.2f / %.2f, jittered %.2f / %.2f, sobol %.2f / %.2f%n",
                at16[0], at256[0], at16[1], at256[1], at16[2], at256[2]);
        assertThat(at16[2]).isLessThan(0.85 * at16[0]);
        assertThat(at256[2]).isLessThan(0.85 * at256[0]);
    }

    @Test
    void theAdaptiveSamplerMeetsItsNoiseTargetWithFewerRays() {
        FrameBuffer ref = reference();
        Renderer full = Renderer.prepare(scene(Sampler.SOBOL, 4, 8, 0, 0));
        double fullError = rmse(full.render(0, RenderMonitor.NONE), ref);
        Renderer adaptive = Renderer.prepare(scene(Sampler.ADAPTIVE, 4, 8, 0.5, 0));
        double adaptiveError = rmse(adaptive.render(0, RenderMonitor.NONE), ref);
        double saved = 1 - (double) adaptive.stats().primaryRays() / full.stats().primaryRays();
        System.out.printf("128 spp: sobol RMSE %.2f levels; adaptive (noise 0.5) RMSE %.2f with %.0f%% fewer rays%n",
                fullError, adaptiveError, 100 * saved);
        // Where every pixel of a neighbourhood agrees, the pilot is the answer; elsewhere the full budget is spent.
        assertThat(saved).isGreaterThan(0.2);
        assertThat(adaptiveError).isLessThan(1.25 * fullError);
    }
}
