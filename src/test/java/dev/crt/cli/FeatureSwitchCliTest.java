package dev.crt.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * crt run with a feature switched off (-Dcrt.without, read once per JVM, hence a JVM of its own):
 * a scene that uses the feature is one sentence and the usage exit code, and no picture is written;
 * a plain scene renders.
 */
class FeatureSwitchCliTest {
    @TempDir
    Path dir;

    private static final String CAMERA = "camera -> Camera { position -> vec3(0, 1, -5) pointing -> vec3(0, 0, 0) }";

    @Test
    void aSceneUsingASwitchedOffFeatureIsRefusedAndAPlainOneRenders() throws Exception {
        Path textured = Files.writeString(dir.resolve("textured.crt"), "Settings { width -> 8 height -> 8 " + CAMERA + " }\n"
                + "Scene { Sphere { material -> Material { color -> Checker { } } } }\n");
        Path plain = Files.writeString(dir.resolve("plain.crt"), "Settings { width -> 8 height -> 8 " + CAMERA + " }\n"
                + "Scene { Sphere { } }\n");
        Path refused = dir.resolve("refused.png"), rendered = dir.resolve("plain.png"), pass = dir.resolve("depth.pfm");
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Dcrt.without=textures,glossy", "-cp", System.getProperty("java.class.path"), "dev.crt.cli.Main"));
        Run r = run(command, "render", textured.toString(), "-q", "-o", refused.toString());
        assertThat(r.exit).isEqualTo(ExitCode.USAGE);
        assertThat(r.err).startsWith("crt: error: the scene uses textures (image, checker, noise, marble, wood; with their ray cones),"
                + " which this run leaves out (-Dcrt.without=textures,glossy)\n");
        assertThat(refused).doesNotExist();
        Run p = run(command, "render", textured.toString(), "--pass", "depth", "-q", "-o", pass.toString());
        assertThat(p.exit).isEqualTo(ExitCode.USAGE);
        assertThat(p.err).contains("the scene uses textures").doesNotContain("internal error");
        assertThat(pass).doesNotExist();
        Run ok = run(command, "render", plain.toString(), "-q", "-o", rendered.toString());
        assertThat(ok.exit).as(ok.err).isEqualTo(ExitCode.OK);
        assertThat(rendered).isNotEmptyFile();
    }

    private record Run(int exit, String err) {}

    private Run run(List<String> command, String... args) throws Exception {
        List<String> c = new ArrayList<>(command);
        c.addAll(List.of(args));
        Path err = dir.resolve("err.txt");
        Process p = new ProcessBuilder(c).redirectError(err.toFile()).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
        return new Run(p.exitValue(), Files.readString(err));
    }
}
