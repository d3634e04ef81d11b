package dev.crt.lang;

import static dev.crt.lang.Scripts.CAMERA;
import static dev.crt.lang.Scripts.error;
import static dev.crt.lang.Scripts.scene;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.scene.Rgb;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import dev.crt.scene.Shading;
import dev.crt.scene.SolidBackground;
import dev.crt.scene.Sphere;
import org.junit.jupiter.api.Test;

/** Settings' {@code shading}, and what the compiler records for the 2015 model's defaults. */
class ShadingSettingsTest {
    private static final String BALL = "Scene { Sphere { } }\n";

    @Test
    void crtIsTheDefaultAndOriginalIsNamed() {
        assertThat(scene(CAMERA + BALL).settings().shading()).isEqualTo(Shading.CRT);
        Settings s = scene(CAMERA + "Settings { shading -> \"original\" gamma -> 2.2 }\n" + BALL).settings();
        assertThat(s.shading()).isEqualTo(Shading.ORIGINAL);
        assertThat(s.gamma()).isEqualTo(2.2);
        assertThat(s.outputGamma()).as("the 2015 model ignores gamma").isEqualTo(1);
    }

    @Test
    void theOriginalDefaultsApplyWhereNoSettingsBlockGaveTheAttribute() {
        Settings none = scene(CAMERA + "Settings { shading -> \"original\" }\n" + BALL).settings();
        assertThat(none.effectiveRecursionDepth()).isEqualTo(3);
        assertThat(none.effectiveBackground()).isEqualTo(new SolidBackground(Rgb.WHITE));
        Settings given = scene(CAMERA + "Settings { recursiondepth -> 5 background -> Background { color -> rgb(0, 0, 0) } }\n"
                + "Settings { shading -> \"original\" }\n" + BALL).settings();
        assertThat(given.effectiveRecursionDepth()).isEqualTo(5);
        assertThat(given.effectiveBackground()).isEqualTo(new SolidBackground(Rgb.BLACK));
    }

    @Test
    void aMaterialRemembersWhetherItGaveDiffuse() {
        Scene s = scene(CAMERA + "Scene { Sphere { material -> Material { reflectivity -> 0.4 } }\n"
                + "Sphere { material -> Material { reflectivity -> 0.4 diffuse -> 0.9 } } }\n");
        var plain = ((Sphere) s.entities().get(0)).material();
        var given = ((Sphere) s.entities().get(1)).material();
        assertThat(plain.originalDiffuse()).isEqualTo(0.6);
        assertThat(given.originalDiffuse()).isEqualTo(0.9);
        assertThat(plain.diffuse()).as("CRT's model keeps its default").isEqualTo(1);
    }

    @Test
    void anUnknownShadingIsAnError() {
        Diagnostic d = error("Settings { shading -> \"2015\" }\n" + BALL);
        assertThat(d.message()).isEqualTo("shading must be \"crt\" or \"original\", got \"2015\"");
        assertThat(d.span().line()).isEqualTo(1);
    }
}
