package dev.crt.live;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** crt preview as a separate process: a missing OpenGL is one sentence and exit code 4, and nothing is written. */
class PreviewCommandTest {
    @TempDir
    Path dir;

    private Process crt(List<String> jvmOptions, String... args) throws Exception {
        List<String> command = new java.util.ArrayList<>();
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        command.addAll(jvmOptions);
        command.add("-cp");
        command.add(System.getProperty("java.class.path"));
        command.add("dev.crt.cli.Main");
        command.addAll(List.of(args));
        return new ProcessBuilder(command).redirectOutput(dir.resolve("out.txt").toFile())
                .redirectError(dir.resolve("err.txt").toFile()).start();
    }

    @Test
    void withoutOpenGlItSaysSoInOneSentenceAndExitsWith4() throws Exception {
        Path out = dir.resolve("view.png");
        Process p = crt(List.of("-Dorg.lwjgl.egl.libname=" + dir.resolve("no-such-libEGL.so")),
                "preview", Path.of("scenes/dice.crt").toAbsolutePath().toString(), "-o", out.toString());
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
        String err = Files.readString(dir.resolve("err.txt"), StandardCharsets.UTF_8);
        assertThat(p.exitValue()).as(err).isEqualTo(4);
        assertThat(err).startsWith("crt: OpenGL is not available: the EGL library (libEGL.so.1, Debian package libegl1)"
                + " could not be loaded").doesNotContain("\tat ");
        assertThat(err.strip().lines().count()).isEqualTo(1);
        assertThat(out).doesNotExist();
        assertThat(dir.toFile().list()).containsExactlyInAnyOrder("out.txt", "err.txt");
    }

    @Test
    void writesTheIdPassOfAScene() throws Exception {
        GlAvailability.open().close();
        Path out = dir.resolve("ids.png");
        Process p = crt(List.of(), "preview", Path.of("scenes/dice.crt").toAbsolutePath().toString(), "-o",
                out.toString(), "--pass", "id", "--width", "64", "--height", "48");
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).as(Files.readString(dir.resolve("err.txt"))).isZero();
        java.awt.image.BufferedImage image = javax.imageio.ImageIO.read(out.toFile());
        assertThat(image.getWidth()).isEqualTo(64);
        // Dice sit on a floor plane that fills the bottom: entity 1 (the floor) shows there, in red 1.
        int floor = image.getRGB(32, 47) & 0xFFFFFF;
        assertThat(floor >> 16).isBetween(1, 10);
        assertThat(new File(dir.toFile(), "ids.png")).exists();
    }
}
