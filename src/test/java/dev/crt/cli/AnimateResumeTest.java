package dev.crt.cli;

import static dev.crt.cli.AnimateTestSupport.ORBIT;
import static dev.crt.cli.AnimateTestSupport.assertSameFiles;
import static dev.crt.cli.AnimateTestSupport.contents;
import static dev.crt.cli.AnimateTestSupport.crt;
import static dev.crt.cli.AnimateTestSupport.temporaryFiles;
import static dev.crt.cli.AnimateTestSupport.write;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.cli.AnimateTestSupport.Run;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A run killed mid-way and resumed ends with the files of an uninterrupted run, and keeps the frames it had. */
class AnimateResumeTest {
    private static final int FRAMES = 16;

    @TempDir
    Path dir;

    private List<String> args(Path scene, String folder, String... more) {
        List<String> args = new ArrayList<>(List.of("animate", scene.toString(), "--frames", "0.." + (FRAMES - 1),
                "-o", dir.resolve(folder).resolve("f_%02d.png").toString(),
                // Heavy enough per frame (64×48, 36 samples a pixel) that the kill lands mid-way.
                "--width", "64", "--height", "48", "--supersampling", "6", "--threads", "1", "-q"));
        args.addAll(List.of(more));
        return args;
    }

    @Test
    void killedRunResumesToTheSameFilesWithoutRedoingFinishedFrames() throws Exception {
        Path scene = write(dir.resolve("orbit.crt"), ORBIT);
        Path killed = dir.resolve("killed");

        // A real crt process, killed with SIGKILL (no chance to clean up) once a few frames are written.
        Process process = start(scene, "killed", "killed.log");
        try {
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while (frameCount(killed) < 3 && process.isAlive() && System.nanoTime() < deadline) Thread.sleep(5);
            process.destroyForcibly();
            process.waitFor(30, TimeUnit.SECONDS);
        } finally {
            process.destroyForcibly();
        }
        int survivors = frameCount(killed);
        assertThat(survivors).as(Files.readString(dir.resolve("killed.log"))).isBetween(3, FRAMES - 1);

        // What a kill during a write leaves: a temporary file next to a frame that does not exist yet.
        Path leftover = Files.writeString(killed.resolve(".f_" + String.format("%02d", FRAMES - 1) + ".png.tmp-0badf00d"),
                "half a frame");
        Map<Path, FileTime> times = new HashMap<>();
        Map<Path, Object> inodes = new HashMap<>();
        for (String name : contents(killed).keySet()) {
            if (name.contains(".tmp-")) continue;
            Path f = killed.resolve(name);
            times.put(f, Files.getLastModifiedTime(f));
            inodes.put(f, Files.getAttribute(f, "unix:ino"));
        }

        Run resumed = crt(args(scene, "killed", "--resume").toArray(String[]::new));
        assertThat(resumed.exit()).as(resumed.err()).isZero();
        Run whole = crt(args(scene, "whole").toArray(String[]::new));
        assertThat(whole.exit()).as(whole.err()).isZero();

        assertThat(Files.exists(leftover)).isFalse();
        assertThat(temporaryFiles(killed)).isEmpty();
        assertSameFiles(killed, dir.resolve("whole"));
        for (Path f : times.keySet()) {
            assertThat(Files.getLastModifiedTime(f)).as(f.toString()).isEqualTo(times.get(f));
            assertThat(Files.getAttribute(f, "unix:ino")).as(f.toString()).isEqualTo(inodes.get(f));
        }
    }

    @Test
    void terminatedRunFinishesItsWritesAndSaysHowToGoOn() throws Exception {
        Path scene = write(dir.resolve("orbit.crt"), ORBIT);
        Path out = dir.resolve("out");
        Process process = start(scene, "out", "terminated.log");
        try {
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while (frameCount(out) < 2 && process.isAlive() && System.nanoTime() < deadline) Thread.sleep(5);
            process.destroy();
            assertThat(process.waitFor(30, TimeUnit.SECONDS)).isTrue();
        } finally {
            process.destroyForcibly();
        }
        String log = Files.readString(dir.resolve("terminated.log"));
        // SIGTERM: the JVM reports 128 + 15 after the shutdown hook let the frames in progress stop cleanly.
        assertThat(process.exitValue()).as(log).isEqualTo(143);
        assertThat(log).contains("crt: cancelled; the frames written are complete: rerun with --resume");
        assertThat(temporaryFiles(out)).isEmpty();
        assertThat(frameCount(out)).isBetween(2, FRAMES - 1);
    }

    /** A real crt process rendering the frames into {@code folder}, its output going to {@code log}. */
    private Process start(Path scene, String folder, String log) throws IOException {
        List<String> command = new ArrayList<>(List.of(
                Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), Main.class.getName()));
        command.addAll(args(scene, folder));
        command.remove("-q");
        return new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(dir.resolve(log).toFile()).start();
    }

    @Test
    void resumeAfterAFixedScriptErrorRendersOnlyTheMissingFrames() throws IOException {
        Path scene = write(dir.resolve("orbit.crt"), ORBIT + "if (t == 5) { broken = nothing_here }\n");
        Run failed = crt(args(scene, "out").toArray(String[]::new));
        assertThat(failed.exit()).isEqualTo(ExitCode.SCRIPT_ERROR);
        assertThat(contents(dir.resolve("out"))).hasSize(5);

        write(scene, ORBIT);
        Run resumed = crt(args(scene, "out", "--resume").toArray(String[]::new));
        assertThat(resumed.exit()).as(resumed.err()).isZero();
        Run whole = crt(args(scene, "whole").toArray(String[]::new));
        assertThat(whole.exit()).isZero();
        assertSameFiles(dir.resolve("out"), dir.resolve("whole"));
    }

    /** Frames written so far; only names are read, as files come and go while crt runs. */
    private static int frameCount(Path folder) throws IOException {
        if (!Files.isDirectory(folder)) return 0;
        try (Stream<Path> files = Files.list(folder)) {
            return (int) files.map(f -> f.getFileName().toString()).filter(n -> n.endsWith(".png") && !n.startsWith(".")).count();
        }
    }
}
