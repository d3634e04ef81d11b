package dev.crt.lang;

import static dev.crt.lang.Scripts.CAMERA;
import static dev.crt.lang.Scripts.error;
import static dev.crt.lang.Scripts.scene;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.scene.Sampler;
import dev.crt.scene.Settings;
import org.junit.jupiter.api.Test;

/** Settings' {@code sampler} and {@code seed} (language reference, section 13). */
class SamplerSettingsTest {
    private static final String BALL = "Scene { Sphere { } }\n";

    @Test
    void theDefaultsAreTheGridAndSeedZero() {
        Settings s = scene(CAMERA + BALL).settings();
        assertThat(s.sampler()).isEqualTo(Sampler.GRID);
        assertThat(s.seed()).isZero();
        assertThat(s.noise()).isEqualTo(Settings.DEFAULT_NOISE);
    }

    @Test
    void everySamplerIsNamedByItsWordAndTheSeedIsKept() {
        for (Sampler k : Sampler.values()) {
            Settings s = scene(CAMERA + "Settings { sampler -> \"" + k.word() + "\" seed -> 42 }\n" + BALL).settings();
            assertThat(s.sampler()).isEqualTo(k);
            assertThat(s.seed()).isEqualTo(42);
        }
    }

    @Test
    void anUnknownSamplerIsAnErrorAtTheAttributeListingTheChoices() {
        Diagnostic d = error("Settings { sampler -> \"fast\" }\n" + BALL);
        assertThat(d.message()).isEqualTo("sampler must be \"grid\", \"jittered\", \"sobol\" or \"adaptive\", got \"fast\"");
        assertThat(d.span().line()).isEqualTo(1);
        assertThat(d.span().column()).isEqualTo(12);
    }

    @Test
    void aNegativeOrFractionalSeedIsAnError() {
        assertThat(error("Settings { seed -> -1 }\n" + BALL).message()).isEqualTo("seed must be an integer >= 0, got -1");
        assertThat(error("Settings { seed -> 1.5 }\n" + BALL).message()).contains("expects an integer");
    }

    @Test
    void withDepthOfFieldAScriptThatNamesNoSamplerGetsSobolUnlessItNamesOneOrLooksLikeCrt2015() {
        String lens = "Settings { camera -> Camera { position -> vec3(0,0,-5) pointing -> vec3(0,0,0) aperture -> 0.2 } dofsamples -> 8 }\n";
        assertThat(scene(lens + BALL).settings().effectiveSampler()).isEqualTo(Sampler.SOBOL);
        // One lens sample, or no aperture: no depth of field, the grid.
        assertThat(scene(lens + "Settings { dofsamples -> 1 }\n" + BALL).settings().effectiveSampler()).isEqualTo(Sampler.GRID);
        assertThat(scene(CAMERA + "Settings { dofsamples -> 8 }\n" + BALL).settings().effectiveSampler()).isEqualTo(Sampler.GRID);
        // A sampler named in any Settings block, before or after the lens, is kept.
        assertThat(scene("Settings { sampler -> \"grid\" }\n" + lens + BALL).settings().effectiveSampler()).isEqualTo(Sampler.GRID);
        assertThat(scene(lens + "Settings { sampler -> \"jittered\" }\n" + BALL).settings().effectiveSampler()).isEqualTo(Sampler.JITTERED);
        // The look of CRT 2015 samples as that program did, also when chosen after the compile (--shading).
        assertThat(scene(lens + "Settings { shading -> \"original\" }\n" + BALL).settings().effectiveSampler()).isEqualTo(Sampler.GRID);
        Settings s = scene(lens + BALL).settings();
        assertThat(s.withShading(dev.crt.scene.Shading.ORIGINAL).effectiveSampler()).isEqualTo(Sampler.GRID);
        // A sampler chosen in code (the command line's --sampler) counts as named.
        assertThat(s.withSampler(Sampler.GRID, s.noise()).effectiveSampler()).isEqualTo(Sampler.GRID);
        assertThat(s.withNoise(1).effectiveSampler()).isEqualTo(Sampler.SOBOL);
    }
}
