package dev.crt.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class CheckCommandTest {
    @TempDir
    Path dir;

    private Path script(String name, String text) throws IOException {
        Path p = dir.resolve(name);
        Files.writeString(p, text);
        return p;
    }

    private static final String GOOD = """
            Settings { camera -> Camera { position -> vec3(0, 0, -5) pointing -> vec3(0, 0, 0) }
                       lights -> [PointLight { origin -> vec3(1, 2, -3) }] }
            Scene { Sphere { } Box { cornerA -> vec3(1, 1, 1) cornerB -> vec3(2, 2, 2) } }
            """;

    @Test
    void aValidScriptPrintsASummaryAndExitsZero() throws IOException {
        Path good = script("good.crt", GOOD);
        CliRun run = CliRun.of("check", good.toString());
        assertThat(run.exitCode()).isZero();
        assertThat(run.out()).isEqualTo(good + ": ok, 2 entities, 1 light, 0 warnings" + System.lineSeparator());
        assertThat(run.err()).isEmpty();
    }

    @Test
    void anErrorIsPrintedWithFileLineAndColumnAndExitsOne() throws IOException {
        Path bad = script("bad.crt", "Scene {\n  Sphere { radus -> 2 }\n}\n");
        CliRun run = CliRun.of("check", bad.toString());
        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.err()).contains(bad + ":2:12: error: ").contains("radius").contains("^");
        assertThat(run.out()).startsWith(bad + ": 1 error");
    }

    @Test
    void theTooManyErrorsNoteIsPrintedButNotCounted() throws IOException {
        Path bad = script("many.crt", "x = ]\n".repeat(25));
        CliRun run = CliRun.of("check", bad.toString());
        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.err()).contains(bad + ":20:5: note: too many errors; stopped after 20");
        assertThat(run.out()).isEqualTo(bad + ": 20 errors, 0 warnings" + System.lineSeparator());
    }

    @Test
    void warningsDoNotFailTheCheck() throws IOException {
        Path noScene = script("empty.crt", "x = 1\n");
        CliRun run = CliRun.of("check", noScene.toString());
        assertThat(run.exitCode()).isZero();
        assertThat(run.err()).contains("warning:");
        assertThat(run.out()).contains("ok, 0 entities").doesNotContain(" 0 warnings");
    }

    @Test
    void everyFileIsCheckedAndTheWorstOutcomeDecidesTheExitCode() throws IOException {
        Path good = script("good.crt", GOOD);
        Path bad = script("bad.crt", "Scene { Sphere { radius -> -1 } }");
        Path missing = dir.resolve("missing.crt");
        CliRun run = CliRun.of("check", good.toString(), bad.toString(), missing.toString());
        assertThat(run.exitCode()).isEqualTo(3);
        assertThat(run.out().lines()).hasSize(3);
        assertThat(run.err()).contains("crt: cannot read " + missing + ": no such file");

        assertThat(CliRun.of("check", good.toString(), bad.toString()).exitCode()).isEqualTo(1);
    }

    @Test
    void aFolderIsNotAScript() {
        CliRun run = CliRun.of("check", dir.toString());
        assertThat(run.exitCode()).isEqualTo(3);
        assertThat(run.err()).contains("it is a folder");
    }

    @Test
    void badUsageExitsTwo() {
        assertThat(CliRun.of("check").exitCode()).isEqualTo(2);
        assertThat(CliRun.of("check", "--no-such-option", "x.crt").exitCode()).isEqualTo(2);
        assertThat(CliRun.of("check", "--time-budget", "0", "x.crt").exitCode()).isEqualTo(2);
        for (String time : new String[] {"NaN", "Infinity", "-Infinity"}) {
            CliRun run = CliRun.of("check", "--time", time, "x.crt");
            assertThat(run.exitCode()).as(time).isEqualTo(2);
            assertThat(run.err()).contains("--time must be a finite number, got " + time);
        }
        assertThat(CliRun.of().exitCode()).isEqualTo(2);
        assertThat(CliRun.of("frobnicate").exitCode()).isEqualTo(2);
    }

    @Test
    void helpAndVersionWork() {
        CliRun help = CliRun.of("--help");
        assertThat(help.exitCode()).isZero();
        assertThat(help.out()).contains("check", "render", "animate");
        CliRun checkHelp = CliRun.of("check", "--help");
        assertThat(checkHelp.exitCode()).isZero();
        assertThat(checkHelp.out()).contains("--assets", "--time");
        CliRun version = CliRun.of("--version");
        assertThat(version.exitCode()).isZero();
        assertThat(version.out()).startsWith("crt ");
    }

    @Test
    void theTimeOptionReachesTheScript() throws IOException {
        Path anim = script("anim.crt", "Scene { Sphere { radius -> 10 - t } }");
        assertThat(CliRun.of("check", anim.toString(), "--time", "3").exitCode()).isZero();
        CliRun negative = CliRun.of("check", anim.toString(), "--time", "11");
        assertThat(negative.exitCode()).isEqualTo(1);
        assertThat(negative.err()).contains(anim + ":1:");
    }
}
