package dev.crt.lang;

import static dev.crt.lang.Scripts.CAMERA;
import static dev.crt.lang.Scripts.error;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Vec3;
import dev.crt.scene.AreaLight;
import dev.crt.scene.Material;
import dev.crt.scene.Rgb;
import dev.crt.scene.Scene;
import dev.crt.scene.SpotLight;
import org.junit.jupiter.api.Test;

/** The second wave's lights and material attributes in scripts: defaults and each diagnostic with its position. */
class LightMaterialAttributesTest {
    private static void at(Diagnostic d, int line, int column, String message) {
        assertThat(d.message()).isEqualTo(message);
        assertThat(d.span().line()).as("line of: " + message).isEqualTo(line);
        assertThat(d.span().column()).as("column of: " + message).isEqualTo(column);
    }

    @Test
    void spotAndAreaLightsTakeTheirAttributesAndDefaults() {
        Scene s = Scripts.scene("Settings { camera -> Camera { position -> vec3(0,0,-5) pointing -> vec3(0,0,0) }\n"
                + "lights -> [SpotLight { origin -> vec3(0,5,0) pointing -> vec3(0,0,0) },\n"
                + "SpotLight { origin -> vec3(0,5,0) pointing -> vec3(0,0,0) angle -> 40 innerangle -> 10 falloff -> 2 },\n"
                + "AreaLight { corner -> vec3(0,5,0) edge1 -> vec3(1,0,0) edge2 -> vec3(0,0,1) color -> rgb(1,0.5,0) }] }\n"
                + "Scene { Sphere { } }\n");
        SpotLight a = (SpotLight) s.settings().lights().get(0);
        assertThat(a.angle()).isEqualTo(30);
        assertThat(a.innerAngle()).isEqualTo(30);
        assertThat(a.color()).isEqualTo(Rgb.WHITE);
        SpotLight b = (SpotLight) s.settings().lights().get(1);
        assertThat(b.angle()).isEqualTo(40);
        assertThat(b.innerAngle()).isEqualTo(10);
        assertThat(b.falloff()).isEqualTo(2);
        AreaLight c = (AreaLight) s.settings().lights().get(2);
        assertThat(c.samples()).isEqualTo(4);
        assertThat(c.edge2()).isEqualTo(new Vec3(0, 0, 1));
        assertThat(c.color()).isEqualTo(new Rgb(1, 0.5, 0));
    }

    @Test
    void materialsTakeFresnelAndAbsorption() {
        Scene s = Scripts.scene(CAMERA + "Scene { Sphere { material -> Material { transparency -> 1 ior -> 1.5 fresnel -> true"
                + " absorption -> rgb(0.1, 0.2, 0.3) } } Sphere { } }\n");
        Material m = ((dev.crt.scene.Sphere) s.entities().get(0)).material();
        assertThat(m.fresnel()).isTrue();
        assertThat(m.absorption()).isEqualTo(new Rgb(0.1, 0.2, 0.3));
        Material d = ((dev.crt.scene.Sphere) s.entities().get(1)).material();
        assertThat(d.fresnel()).isFalse();
        assertThat(d.absorption()).isEqualTo(Rgb.BLACK);
    }

    @Test
    void aMaterialsColorMayBeACheckerTexture() {
        Scene s = Scripts.scene(CAMERA + "Scene { Sphere { material -> Material { color -> Checker { color1 -> rgb(1, 0, 0)"
                + " scale -> 0.5 } } } }\n");
        Material m = ((dev.crt.scene.Sphere) s.entities().get(0)).material();
        assertThat(m.texture()).isEqualTo(new dev.crt.scene.Checker(new Rgb(1, 0, 0), Rgb.BLACK, 0.5));
        at(error("m = Material { color -> 5 }\n"), 1, 16, "attribute 'color' of Material expects an rgb colour or a texture, got number");
        at(error("c = Checker { scale -> 0 }\n"), 1, 15, "scale must be > 0, got 0");
        at(error("c = Checker { color1 -> 3 }\n"), 1, 15, "attribute 'color1' of Checker expects an rgb colour or a texture, got number");
        at(error("c = Noise { color1 -> Checker { } }\n"), 1, 13, "attribute 'color1' of Noise expects an rgb colour, got texture");
    }

    @Test
    void cameraTakesAProjection() {
        Scene s = Scripts.scene("Settings { camera -> Camera { position -> vec3(0,0,-5) pointing -> vec3(0,0,0)"
                + " projection -> \"spherical\" } }\nScene { Sphere { } }\n");
        assertThat(s.settings().camera().projection()).isEqualTo(dev.crt.scene.Projection.SPHERICAL);
        assertThat(Scripts.scene(CAMERA + "Scene { Sphere { } }\n").settings().camera().projection())
                .isEqualTo(dev.crt.scene.Projection.PERSPECTIVE);
        at(error("c = Camera { position -> vec3(0,0,-5) pointing -> vec3(0,0,0) projection -> \"spherial\" }\n"), 1, 63,
                "projection must be one of \"perspective\", \"spherical\", \"cylindrical\", got \"spherial\" (did you mean 'spherical'?)");
    }

    @Test
    void badLightAndMaterialAttributesAreDiagnosedWhereTheyStand() {
        at(error("l = SpotLight { origin -> vec3(0,0,0) pointing -> vec3(0,0,0) }\n"), 1, 39,
                "a SpotLight's pointing must differ from its origin");
        at(error("l = SpotLight { origin -> vec3(0,0,0) pointing -> vec3(0,0,1) angle -> 95 }\n"), 1, 63,
                "angle must be in (0, 90], got 95");
        at(error("l = SpotLight { origin -> vec3(0,0,0) pointing -> vec3(0,0,1) angle -> 20\n  innerangle -> 25 }\n"), 2, 3,
                "innerangle must be in [0, 20], got 25");
        at(error("l = AreaLight { corner -> vec3(0,0,0) edge1 -> vec3(1,0,0) edge2 -> vec3(2,0,0) }\n"), 1, 60,
                "an AreaLight's edge1 and edge2 must span a parallelogram (not zero, not parallel)");
        at(error("l = AreaLight { corner -> vec3(0,0,0) edge1 -> vec3(1,0,0) edge2 -> vec3(0,1,0) samples -> 0 }\n"), 1, 81,
                "samples must be an integer >= 1, got 0");
        at(error("l = AreaLight { corner -> vec3(0,0,0) edge1 -> vec3(1,0,0) edge2 -> vec3(0,1,0) samples -> 1000 }\n"), 1, 81,
                "samples must be at most 256 (that is 65536 shadow rays per shading point), got 1000");
        at(error("l = AreaLight { edge1 -> vec3(1,0,0) edge2 -> vec3(0,1,0) }\n"), 1, 5, "AreaLight needs the attribute 'corner'");
        at(error("m = Material { fresnel -> 1 }\n"), 1, 16, "attribute 'fresnel' of Material expects a boolean, got number");
        at(error("m = Material { absorption -> rgb(0, -1, 0) }\n"), 1, 16, "absorption must not be negative, got rgb(0, -1, 0)");
    }
}
