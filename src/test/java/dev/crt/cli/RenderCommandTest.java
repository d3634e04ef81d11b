package dev.crt.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class RenderCommandTest {
    @TempDir
    Path dir;

    static final String SCENE = """
            Settings {
              title -> "Test ball" author -> "CRT tests"
              camera -> Camera { position -> vec3(0, 0, -5) pointing -> vec3(0, 0, 0) }
              lights -> [PointLight { origin -> vec3(-3, 3, -5) }]
              background -> Background { color -> rgb(0, 0, 1) }
              width -> 40 height -> 30
            }
            Scene { Sphere { material -> Material { color -> rgb(1, 0, 0) } } }
            """;

    private Path script(String text) throws IOException {
        Path p = dir.resolve("scene.crt");
        Files.writeString(p, text);
        return p;
    }

    private List<Path> files() throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.filter(p -> !p.getFileName().toString().endsWith(".crt")).toList();
        }
    }

    @Test
    void rendersAPngOfTheScriptsSizeWithItsMetadata() throws IOException {
        Path out = dir.resolve("ball.png");
        CliRun run = CliRun.of("render", script(SCENE).toString(), "-o", out.toString(), "--quiet");
        assertThat(run.exitCode()).as(run.err()).isZero();
        BufferedImage img = ImageIO.read(out.toFile());
        assertThat(img.getWidth()).isEqualTo(40);
        assertThat(img.getHeight()).isEqualTo(30);
        assertThat(img.getRGB(0, 0) & 0xffffff).isEqualTo(0x0000ff);
        assertThat((img.getRGB(20, 15) >> 16) & 0xff).isGreaterThan(0);
        assertThat(Files.readString(out, java.nio.charset.StandardCharsets.ISO_8859_1)).contains("Test ball");
        assertThat(files()).containsExactly(out);
    }

    @Test
    void commandLineValuesOverrideTheSettings() throws IOException {
        Path out = dir.resolve("small.ppm");
        CliRun run = CliRun.of("render", script(SCENE).toString(), "-o", out.toString(), "--width", "16",
                "--height", "8", "--supersampling", "2", "--threads", "1", "--quiet");
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(new String(Files.readAllBytes(out), 0, 9, java.nio.charset.StandardCharsets.US_ASCII))
                .isEqualTo("P6\n16 8\n2");
    }

    @Test
    void statsListRaysAndPhases() throws IOException {
        Path out = dir.resolve("ball.pfm");
        CliRun run = CliRun.of("render", script(SCENE).toString(), "-o", out.toString(), "--stats", "--quiet");
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(run.out()).contains("primary", "shadow", "reflected", "refracted", "Mrays/s",
                "compile", "bvh build", "render", "write");
        assertThat(run.out()).containsPattern("primary\\s+1,200\\n");
    }

    @Test
    void aScriptErrorWritesNothingAndExitsOne() throws IOException {
        Path out = dir.resolve("bad.png");
        CliRun run = CliRun.of("render", script("Scene { Sphere { radius -> \"big\" } }").toString(),
                "-o", out.toString());
        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.err()).contains("scene.crt:1:");
        assertThat(files()).isEmpty();
    }

    @Test
    void anUnknownImageTypeIsAUsageErrorBeforeAnyWork() throws IOException {
        CliRun run = CliRun.of("render", script(SCENE).toString(), "-o", dir.resolve("x.jpg").toString());
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).contains("unsupported image type '.jpg'");
        assertThat(files()).isEmpty();
    }

    @Test
    void missingOutputFoldersAreCreatedAsAnimateDoes() throws IOException {
        Path out = dir.resolve("no/such/x.png");
        CliRun run = CliRun.of("render", script(SCENE).toString(), "-o", out.toString());
        assertThat(run.exitCode()).isEqualTo(0);
        assertThat(out).isRegularFile();
    }

    @Test
    void anImageTooLargeToHoldIsRefusedBeforeRendering() throws IOException {
        CliRun run = CliRun.of("render", script(SCENE).toString(), "-o", dir.resolve("huge.png").toString(),
                "--width", "100000", "--height", "100000");
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).contains("100000×100000 pixels is too large");
        assertThat(files()).isEmpty();
    }

    @Test
    void badOptionValuesAreUsageErrors() throws IOException {
        String s = script(SCENE).toString();
        assertThat(CliRun.of("render", s, "--width", "0").exitCode()).isEqualTo(2);
        assertThat(CliRun.of("render", s, "--threads", "-1").exitCode()).isEqualTo(2);
        assertThat(CliRun.of("render", s, "--supersampling", "many").exitCode()).isEqualTo(2);
        assertThat(CliRun.of("render").exitCode()).isEqualTo(2);
    }

    /** Ctrl-C (or any polite termination) mid-render: the process ends and leaves no file behind. */
    @Test
    void aCancelledRenderLeavesNoFile() throws Exception {
        Path big = script(SCENE.replace("width -> 40 height -> 30", "width -> 4000 height -> 3000 supersampling -> 4"));
        Path out = dir.resolve("big.png");
        Process p = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), Main.class.getName(),
                "render", big.toString(), "-o", out.toString())
                .redirectErrorStream(true).redirectOutput(dir.resolve("log.txt").toFile()).start();
        Thread.sleep(2500);
        assertThat(p.isAlive()).as("still rendering when cancelled").isTrue();
        long t0 = System.nanoTime();
        p.destroy();
        assertThat(p.waitFor(10, TimeUnit.SECONDS)).isTrue();
        assertThat((System.nanoTime() - t0) / 1e9).isLessThan(5);
        Files.delete(dir.resolve("log.txt"));
        assertThat(files()).isEmpty();
    }
}
