package dev.crt.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** {@code crt studio} on the command line: help, and a plain sentence where there is no display. */
class StudioCommandTest {
    @Test
    void helpDescribesTheCommandAndExitsZero() {
        CliRun run = CliRun.of("studio", "--help");
        assertThat(run.exitCode()).isZero();
        assertThat(run.out()).contains("Usage: crt studio", "[SCENE...]", "F5 renders", "XDG_CONFIG_HOME");
        CliRun help = CliRun.of("help", "studio");
        assertThat(help.exitCode()).isZero();
        assertThat(help.out()).isEqualTo(run.out());
        assertThat(CliRun.of("--help").out()).contains("studio");
    }

    @Test
    void withoutADisplayItSaysSoInOneSentenceAndExitsTwo() throws IOException, InterruptedException {
        // A separate JVM with DISPLAY removed, as a user over ssh without X forwarding runs it.
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        ProcessBuilder pb = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"), Main.class.getName(),
                "studio", "scenes/dice.crt");
        pb.environment().remove("DISPLAY");
        pb.environment().remove("WAYLAND_DISPLAY");
        Process p = pb.start();
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.exitValue()).isEqualTo(2);
        assertThat(out).isEmpty();
        assertThat(err.strip()).isEqualTo("crt: the studio needs a graphical display, and none is available (DISPLAY is not set)");
    }
}
