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
import dev.crt.geom.Vec3;
import dev.crt.scene.ImageTexture;
import dev.crt.scene.TextureMapping;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

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
        dev.crt.scene.Checker nested = (dev.crt.scene.Checker) material("Material { color -> Checker { color1 -> Marble { } color2 -> rgb(0, 0, 1) } }").texture();
        assertThat(nested.texture1()).isEqualTo(new Marble(Rgb.WHITE, Rgb.BLACK, 1, 0, 4));
        assertThat(nested.texture2()).isNull();
        assertThat(nested.color2()).isEqualTo(new Rgb(0, 0, 1));
        at(error("x = Noise { octaves -> 0 }\n"), 1, 13, "octaves must be an integer >= 1, got 0");
        at(error("x = Wood { octaves -> 17 }\n"), 1, 12, "octaves must be an integer from 1 to 16, got 17");
        at(error("x = Marble { turbulence -> -1 }\n"), 1, 14, "turbulence must be >= 0, got -1");
        at(error("x = Marble { scale -> 0 }\n"), 1, 14, "scale must be > 0, got 0");
        at(error("x = Noise { color1 -> 3 }\n"), 1, 13, "attribute 'color1' of Noise expects an rgb colour, got number");
        at(error("x = Wood { ring -> 3 }\n"), 1, 12, "unknown attribute 'ring' for Wood");
    }

    private static CompileResult compileIn(Path dir, String text) {
        return CrtCompiler.compile(new Source("scene.crt", text, dir.resolve("scene.crt")),
                new CompileOptions(0, List.of(Path.of("assets")), CompileOptions.DEFAULT_LOOP_BUDGET, CompileOptions.DEFAULT_TIME_BUDGET));
    }

    @Test
    void imageTexturesFindPngAndJpegFilesAndTakeTheirMappingAndTransform(@TempDir Path dir) throws Exception {
        BufferedImage small = new BufferedImage(4, 2, BufferedImage.TYPE_INT_RGB);
        small.setRGB(1, 0, 0xFF0000);
        assertThat(ImageIO.write(small, "jpeg", dir.resolve("label.jpg").toFile())).isTrue();
        CompileResult r = compileIn(dir, CAMERA + "Scene { Sphere { material -> Material { color -> ImageTexture { file -> \"label.jpg\""
                + " mapping -> \"spherical\" scale -> 2 rotate -> vec3(0, 90, 0) offset -> vec3(1, 0, 0) } } }\n"
                + "Sphere { material -> Material { emission -> ImageTexture { file -> \"/tiles.png\" } specular -> Noise { } } } }\n");
        assertThat(r.hasErrors()).as("%s", r.diagnostics()).isFalse();
        ImageTexture a = (ImageTexture) ((Sphere) r.scene().entities().get(0)).material().texture();
        assertThat(a.mapping()).isEqualTo(TextureMapping.SPHERICAL);
        assertThat(a.scale()).isEqualTo(new Vec3(2, 2, 2));
        assertThat(a.rotate()).isEqualTo(new Vec3(0, 90, 0));
        assertThat(a.picture().width()).isEqualTo(4);
        assertThat(Path.of(a.path())).isEqualTo(dir.resolve("label.jpg"));
        Material b = ((Sphere) r.scene().entities().get(1)).material();
        ImageTexture tiles = (ImageTexture) b.finish().emission();
        assertThat(tiles.mapping()).isEqualTo(TextureMapping.UV);
        assertThat(tiles.picture().width()).isEqualTo(256);
        assertThat(b.finish().specular()).isEqualTo(new Noise(Rgb.WHITE, Rgb.BLACK, 1, 0, 4));
    }

    @Test
    void badImageTexturesAndChannelsAreDiagnosedWhereTheyStand(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("notes.png"), "not a picture");
        List<Diagnostic> e = compileIn(dir, "x = ImageTexture { file -> \"missing.png\" }\n").diagnostics();
        assertThat(e.get(0).message()).startsWith("image file 'missing.png' not found; looked for ");
        assertThat(e.get(0).span().column()).isEqualTo(20);
        e = compileIn(dir, "x = ImageTexture { file -> \"notes.png\" }\n").diagnostics();
        assertThat(e.get(0).message()).startsWith("cannot use image 'notes.png': ").contains("not an image CRT can decode");
        String script = "x = ImageTexture { file -> \"" + Path.of("assets/tiles.png").toAbsolutePath() + "\" mapping -> \"planer\" }\n";
        at(error(script), 1, script.indexOf("mapping") + 1,
                "mapping must be one of \"uv\", \"planar\", \"spherical\", \"cylindrical\", \"box\", got \"planer\" (did you mean 'planar'?)");
        at(error("m = Material { specular -> \"shiny\" }\n"), 1, 16, "attribute 'specular' of Material expects a number or a texture, got string");
        at(error("m = Material { bump -> 2 }\n"), 1, 16, "attribute 'bump' of Material expects a texture, got number");
        at(error("m = Material { emission -> 2 }\n"), 1, 16, "attribute 'emission' of Material expects an rgb colour or a texture, got number");
        at(error("m = Material { roughness -> 2 }\n"), 1, 16, "roughness must be in [0, 1], got 2");
        at(error("m = Material { model -> \"goch\" }\n"), 1, 16, "model must be one of \"phong\", \"gooch\", got \"goch\" (did you mean 'gooch'?)");
    }
}
