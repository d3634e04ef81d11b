package dev.crt.cli;

import dev.crt.animation.FramePattern;
import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** What a hostile user tried on the command line (issue 11): every edge ends in one clear sentence and the right exit code. */
class HardeningTest {
    @TempDir
    Path dir;

    private Path script(String text) throws IOException {
        return Files.writeString(dir.resolve("s.crt"), text);
    }

    private static final String CAMERA = "camera -> Camera { position -> vec3(0, 0, -5) pointing -> vec3(0, 0, 0) aperture -> 50 }";
    private static final String SCENE = "Settings { width -> 8 height -> 6 " + CAMERA + " }\nScene { Sphere { } }\n";

    private static void usageError(CliRun run, String command, String message) {
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).isEqualTo("crt: error: " + message + "\nTry '" + command + " --help' for more information.\n");
    }

    @Test
    void everyUsageErrorIsOneLineAndAPointerToHelp() throws IOException {
        String s = script(SCENE).toString();
        usageError(CliRun.of("render", s, "--bogus"), "crt render", "Unknown option: '--bogus'");
        usageError(CliRun.of("render", s, "--supersampling", "100000"), "crt render",
                "--supersampling must be from 1 to 64, got 100000");
        usageError(CliRun.of("render", s, "-o", dir.resolve("x.jpg").toString()), "crt render",
                "cannot write " + dir.resolve("x.jpg") + ": unsupported image type '.jpg' (use .png, .ppm or .pfm)");
        usageError(CliRun.of("animate", s, "--frames", "0..1", "-o", dir + "/f%d.png", "--resume", "--force"),
                "crt animate", "--resume, --force are mutually exclusive (specify only one)");
        usageError(CliRun.of("check", "--assets", dir.resolve("none").toString(), s), "crt check",
                "--assets " + dir.resolve("none") + ": no such folder");
        usageError(CliRun.of(), "crt", "a command is needed: check, render, animate, accuracy, preview or studio");
        usageError(CliRun.of("rendr", s), "crt", "unknown command 'rendr' (the commands are check, render, animate and help)");
    }

    @Test
    void helpNamesEveryExitCode() {
        for (String command : List.of("render", "check", "animate")) {
            String help = CliRun.of(command, "--help").out().replaceAll("\\s+", " ");
            assertThat(help).contains("70 internal error or out of memory", "130 cancelled (Ctrl-C)", "143 terminated (SIGTERM)");
        }
    }

    @Test
    void sampleCountsAreBoundedWhereverTheyAreGiven() throws IOException {
        // 46341² overflows an int: refused before any arithmetic on it.
        usageError(CliRun.of("render", script(SCENE).toString(), "--supersampling", "46341"), "crt render",
                "--supersampling must be from 1 to 64, got 46341");
        usageError(CliRun.of("render", script(SCENE).toString(), "--threads", "100000"), "crt render",
                "--threads must be from 0 to 256, got 100000");
        CliRun inScript = CliRun.of("check", script("Settings { supersampling -> 100000 }\n").toString());
        assertThat(inScript.exitCode()).isEqualTo(1);
        assertThat(inScript.err()).contains("supersampling must be an integer from 1 to 64, got 100000");
        // Each is allowed alone; together, with a lens, they are too many rays for one pixel.
        CliRun both = CliRun.of("render", script(SCENE).toString(), "-o", dir.resolve("x.png").toString(),
                "--supersampling", "64", "--dof-samples", "4096");
        assertThat(both.exitCode()).isEqualTo(2);
        assertThat(both.err()).startsWith("crt: error: supersampling 64 with 4096 lens samples is 16,777,216 camera rays per pixel");
        assertThat(dir.resolve("x.png")).doesNotExist();
    }

    @Test
    void outputPathsSayWhatIsWrongWithThem() throws IOException {
        String s = script(SCENE).toString();
        CliRun folder = CliRun.of("render", s, "-o", dir.toString());
        assertThat(folder.exitCode()).isEqualTo(3);
        assertThat(folder.err()).startsWith("crt: cannot write " + dir + ": it is a folder");
        CliRun proc = CliRun.of("render", s, "-o", "/proc/x.png");
        assertThat(proc.exitCode()).isEqualTo(3);
        assertThat(proc.err()).startsWith("crt: cannot write into folder /proc: ");
        Path created = dir.resolve("new/deeper/x.png");
        assertThat(CliRun.of("render", s, "-q", "-o", created.toString()).exitCode()).isEqualTo(0);
        assertThat(created).isRegularFile();
    }

    @Test
    void aDashReadsTheScriptFromStandardInput() throws IOException {
        InputStream saved = System.in;
        try {
            System.setIn(new ByteArrayInputStream("x = 1 +\n".getBytes(StandardCharsets.UTF_8)));
            CliRun run = CliRun.of("check", "-");
            assertThat(run.exitCode()).isEqualTo(1);
            assertThat(run.err()).startsWith("<stdin>:1:7: error: expected an expression after '+' at the end of line 1");
            System.setIn(new ByteArrayInputStream(SCENE.getBytes(StandardCharsets.UTF_8)));
            Path out = dir.resolve("in.png");
            assertThat(CliRun.of("render", "-", "-q", "-o", out.toString()).exitCode()).isEqualTo(0);
            assertThat(out).isRegularFile();
        } finally {
            System.setIn(saved);
        }
    }

    /** Runs crt in a JVM of its own with {@code heap} (-Xmx); returns exit code and stderr. */
    private CliRun separateJvm(String heap, String... args) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx" + heap, "-cp", System.getProperty("java.class.path"), "dev.crt.cli.Main"));
        command.addAll(List.of(args));
        Path err = dir.resolve("err.txt");
        Process p = new ProcessBuilder(command).redirectError(err.toFile()).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
        return new CliRun(p.exitValue(), "", Files.readString(err));
    }

    @Test
    void aRenderTooLargeForTheHeapIsRefusedAndAnOutOfMemoryErrorIsOneSentence() throws Exception {
        Path out = dir.resolve("big.png");
        CliRun refused = separateJvm("64m", "render", script(SCENE).toString(), "-o", out.toString(),
                "--width", "4000", "--height", "4000");
        assertThat(refused.exitCode()).isEqualTo(2);
        assertThat(refused.err()).matches("(?s)crt: error: a 4000×4000 render needs about 191 MiB of memory and the Java heap"
                + " has \\d+ MiB free: give Java more \\(CRT_JAVA_OPTS=-Xmx1g ./crt …\\) or render fewer pixels.*");
        assertThat(out).doesNotExist();
        // 160,000 spheres compile in 40 MiB (200,000 still do), but their BVH does not fit (from
        // about 130,000 on): the estimate cannot see that, so the error itself must be one
        // sentence with the internal-error code, never 1.
        Path many = Files.writeString(dir.resolve("many.crt"), "Settings { width -> 8 height -> 8 " + CAMERA + " }\ni = 0\n"
                + "while (i < 160000) { Scene { Sphere { center -> vec3(i, 0, 0) } } i = i + 1 }\n");
        CliRun oom = separateJvm("40m", "render", many.toString(), "-q", "-o", out.toString());
        assertThat(oom.exitCode()).isEqualTo(70);
        assertThat(oom.err()).contains("crt: error: out of memory: the Java heap of 40 MiB is too small for this scene")
                .doesNotContain("\tat ").doesNotContain("Exception");
        assertThat(out).doesNotExist();
    }

    @Test
    void aRunawayLoopThatFillsTheHeapIsTheOutOfMemoryExitCodeNotAScriptError() throws Exception {
        // The loop's entities fill a 40 MiB heap long before the iteration budget would stop it.
        Path runaway = Files.writeString(dir.resolve("runaway.crt"), "Settings { width -> 8 height -> 8 " + CAMERA + " }\ni = 0\n"
                + "while (true) { Scene { Sphere { center -> vec3(i, 0, 0) } } i = i + 1 }\n");
        for (String command : List.of("check", "render")) {
            Path out = dir.resolve(command + ".png");
            CliRun run = command.equals("check") ? separateJvm("40m", "check", runaway.toString())
                    : separateJvm("40m", "render", runaway.toString(), "-q", "-o", out.toString());
            assertThat(run.exitCode()).as(command).isEqualTo(70);
            assertThat(run.err()).as(command).contains("runaway.crt:3:1: error: evaluation stopped: the loops' values filled the memory")
                    .contains("CRT_JAVA_OPTS=-Xmx").doesNotContain("\tat ").doesNotContain("Exception");
            assertThat(out).doesNotExist();
        }
    }

    @Test
    void framePatternWidthsPadWithZeros() {
        assertThat(FramePattern.parse("f%5d.png").path(42)).isEqualTo(Path.of("f00042.png"));
    }

    @Test
    void docsShowWhatTheCommandsPrint() throws IOException {
        String docs = Files.readString(Path.of("docs/cli.md"));
        CliRun check = CliRun.of("check", "--assets", "assets", "scenes/csg-sculpture.crt");
        assertThat(check.exitCode()).isEqualTo(0);
        assertThat(docs).contains(check.out().strip());
        Path bad = Files.writeString(dir.resolve("bad.crt"), "Settings { camera -> Camera { position -> vec3(0, 0, -5)"
                + " pointing -> vec3(0, 0, 0) } }\nScene {\n    Sphere { radus -> 2 }\n}\n");
        assertThat(docs).contains(bad.getFileName() + ": 1 error, 0 warnings")
                .contains(CliRun.of("check", bad.toString()).err().replace(dir + "/", "").strip());
        assertThat(docs).contains(CliRun.of("render", bad.toString(), "--bogus").err().strip());
    }
}
