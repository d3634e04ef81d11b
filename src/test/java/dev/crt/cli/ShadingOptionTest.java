package dev.crt.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code --shading} on the command line and {@code crt check}'s advice for 2015 scenes. */
class ShadingOptionTest {
    @TempDir
    Path dir;

    /** A 2015-style script: no background (white in the 2015 model), a mirror ball that gives reflectivity only. */
    static final String SCENE_2015 = """
            Settings {
              camera -> Camera { position -> vec3(0, 0, -5) pointing -> vec3(0, 0, 0) }
              lights -> [PointLight { origin -> vec3(-3, 3, -5) ambient -> 0.2 }]
              width -> 32 height -> 24
            }
            Scene { Sphere { material -> Material { color -> rgb(1, 0, 0) reflectivity -> 0.5 } } }
            """;

    private Path script(String text) throws IOException {
        Path p = dir.resolve("old.crt");
        Files.writeString(p, text);
        return p;
    }

    @Test
    void shadingOriginalGivesTheWhiteDefaultBackgroundAndCrtTheBlackOne() throws IOException {
        Path scene = script(SCENE_2015);
        Path crt = dir.resolve("crt.png"), original = dir.resolve("original.png");
        assertThat(CliRun.of("render", scene.toString(), "-o", crt.toString(), "-q").exitCode()).isZero();
        CliRun run = CliRun.of("render", scene.toString(), "-o", original.toString(), "-q", "--shading", "original");
        assertThat(run.exitCode()).as(run.err()).isZero();
        BufferedImage a = ImageIO.read(crt.toFile()), b = ImageIO.read(original.toFile());
        assertThat(a.getRGB(0, 0) & 0xffffff).isEqualTo(0x000000);
        assertThat(b.getRGB(0, 0) & 0xffffff).isEqualTo(0xffffff);
    }

    @Test
    void aBadShadingIsAUsageError() throws IOException {
        CliRun run = CliRun.of("render", script(SCENE_2015).toString(), "--shading", "2015");
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).contains("--shading must be crt or original, not '2015'");
    }

    @Test
    void checkSuggestsTheOriginalShadingForA2015SceneOnly() throws IOException {
        Path scene = script(SCENE_2015);
        CliRun old = CliRun.of("check", scene.toString());
        assertThat(old.exitCode()).isZero();
        assertThat(old.err()).contains("looks like a CRT 2015 scene").contains("--shading original");
        Path modern = dir.resolve("modern.crt");
        Files.writeString(modern, SCENE_2015.replace("reflectivity -> 0.5", "reflectivity -> 0.5 diffuse -> 0.5"));
        assertThat(CliRun.of("check", modern.toString()).err()).doesNotContain("CRT 2015");
        Path chosen = dir.resolve("chosen.crt");
        Files.writeString(chosen, SCENE_2015.replace("width -> 32", "shading -> \"original\" width -> 32"));
        assertThat(CliRun.of("check", chosen.toString()).err()).doesNotContain("CRT 2015");
    }
}
