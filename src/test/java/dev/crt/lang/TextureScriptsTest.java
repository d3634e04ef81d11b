package dev.crt.lang;

import static dev.crt.lang.Scripts.CAMERA;
import static dev.crt.lang.Scripts.error;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.scene.Marble;
import dev.crt.scene.Material;
import dev.crt.scene.Noise;
import dev.crt.scene.Rgb;
import dev.crt.scene.Scene;
import dev.crt.scene.Sphere;
import dev.crt.scene.Wood;
import org.junit.jupiter.api.Test;

/** The textures of section 13 in scripts: attributes, defaults and diagnostics with their positions. */
class TextureScriptsTest {
    private static void at(Diagnostic d, int line, int column, String message) {
        assertThat(d.message()).isEqualTo(message);
        assertThat(d.span().line()).as("line of: " + message).isEqualTo(line);
        assertThat(d.span().column()).as("column of: " + message).isEqualTo(column);
    }

    private static Material material(String m) {
        Scene s = Scripts.scene(CAMERA + "Scene { Sphere { material -> " + m + " } }\n");
        return ((Sphere) s.entities().get(0)).material();
    }

    @Test
    void noiseWoodAndMarbleTakeTheirAttributesAndDefaults() {
        assertThat(material("Material { color -> Noise { } }").texture()).isEqualTo(new Noise(Rgb.WHITE, Rgb.BLACK, 1, 0, 4));
        assertThat(material("Material { color -> Wood { color1 -> rgb(1,0,0) scale -> 0.2 turbulence -> 0.5 octaves -> 2 } }")
                .texture()).isEqualTo(new Wood(new Rgb(1, 0, 0), Rgb.BLACK, 0.2, 0.5, 2));
        assertThat(material("Material { color -> Marble { color2 -> rgb(0,0,1) } }").texture())
                .isEqualTo(new Marble(Rgb.WHITE, new Rgb(0, 0, 1), 1, 0, 4));
        at(error("x = Noise { octaves -> 0 }\n"), 1, 13, "octaves must be an integer >= 1, got 0");
        at(error("x = Wood { octaves -> 17 }\n"), 1, 12, "octaves must be an integer from 1 to 16, got 17");
        at(error("x = Marble { turbulence -> -1 }\n"), 1, 14, "turbulence must be >= 0, got -1");
        at(error("x = Marble { scale -> 0 }\n"), 1, 14, "scale must be > 0, got 0");
        at(error("x = Noise { color1 -> 3 }\n"), 1, 13, "attribute 'color1' of Noise expects an rgb colour, got number");
        at(error("x = Wood { ring -> 3 }\n"), 1, 12, "unknown attribute 'ring' for Wood");
    }
}
