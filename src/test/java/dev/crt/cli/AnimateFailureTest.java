package dev.crt.cli;

import static dev.crt.cli.AnimateTestSupport.ORBIT;
import static dev.crt.cli.AnimateTestSupport.contents;
import static dev.crt.cli.AnimateTestSupport.crt;
import static dev.crt.cli.AnimateTestSupport.temporaryFiles;
import static dev.crt.cli.AnimateTestSupport.write;
import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import dev.crt.cli.AnimateTestSupport.Run;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Everything that goes wrong in crt animate: clear message, the right exit code, nothing half-written. */
class AnimateFailureTest {
    /** The orbit scene with an error at t = 3 only. */
    private static final String BREAKS_AT_3 = ORBIT + "if (t == 3) { broken = nothing_here }\n";

    @TempDir
    Path dir;

    private Path scene(String text) { return write(dir.resolve("scene.crt"), text); }

    private String pattern() { return dir.resolve("out/f_%02d.png").toString(); }

    private Run animate(String text, String... more) {
        String[] args = new String[4 + more.length];
        args[0] = "animate";
        args[1] = scene(text).toString();
        args[2] = "-o";
        args[3] = pattern();
        System.arraycopy(more, 0, args, 4, more.length);
        return crt(args);
    }

    @Test
    void scriptErrorAtOneFrameStopsTheRunWithTheFrameNumber() {
        Run run = animate(BREAKS_AT_3, "--frames", "0..6");
        assertThat(run.exit()).isEqualTo(ExitCode.SCRIPT_ERROR);
        assertThat(run.err()).contains("crt: frame 3 (t = 3):\n" + dir.resolve("scene.crt") + ":9:24: error: variable 'nothing_here' is not assigned")
                .contains("crt: frame 3 failed: the script has errors at t = 3")
                .contains("3 rendered, 0 skipped, 1 failed")
                .contains("--resume").contains("--keep-going");
        assertThat(contents(dir.resolve("out")).keySet()).containsExactly("f_00.png", "f_01.png", "f_02.png");
    }

    @Test
    void keepGoingRendersTheOtherFramesAndReportsEveryFailureAtTheEnd() {
        String breaksTwice = ORBIT + "if (t == 1 || t == 3) { broken = nothing_here }\n";
        Run run = animate(breaksTwice, "--frames", "0..5", "--keep-going", "--jobs", "2");
        assertThat(run.exit()).isEqualTo(ExitCode.SCRIPT_ERROR);
        assertThat(run.err()).contains("4 rendered, 0 skipped, 2 failed")
                .contains("crt: frame 1 failed: the script has errors at t = 1\ncrt: frame 3 failed: the script has errors at t = 3");
        assertThat(contents(dir.resolve("out")).keySet()).containsExactly("f_00.png", "f_02.png", "f_04.png", "f_05.png");
    }

    @Test
    void keepGoingStillMakesTheGifOfTheFramesThatExist() throws IOException {
        Path gif = dir.resolve("anim.gif");
        Run run = animate(BREAKS_AT_3, "--frames", "0..4", "--keep-going", "--gif", gif.toString(), "-q");
        assertThat(run.exit()).isEqualTo(ExitCode.SCRIPT_ERROR);
        assertThat(Files.exists(gif)).isTrue();
        assertThat(run.err()).doesNotContain("wrote");
    }

    @Test
    void warningsArePrintedOncePerRunNotOncePerFrame() {
        String warns = ORBIT.replace("Settings { camera -> Camera { position -> vec3(0, 2, -6) pointing -> vec3(0, 0.5, 0) }",
                "Settings {");
        Run run = animate(warns, "--frames", "0..3", "-q");
        assertThat(run.exit()).as(run.err()).isZero();
        assertThat(run.err()).contains("warning:");
        assertThat(run.err().split("warning:", -1)).hasSize(2);
    }

    @Test
    void outputFolderThatCannotBeCreatedFailsBeforeAnyWork() throws IOException {
        Files.writeString(dir.resolve("out"), "a file where the folder should be");
        Run run = animate(ORBIT, "--frames", "0..2");
        assertThat(run.exit()).isEqualTo(ExitCode.FILE_ERROR);
        assertThat(run.err()).startsWith("crt: cannot create folder " + dir.resolve("out")).contains("in the way");
        assertThat(run.err()).doesNotContain("rendered");
    }

    @Test
    void folderThatTakesNoFilesFailsBeforeAnyWorkEvenForRoot() {
        // Permission bits do not stop root, but /proc takes no new files for anyone.
        assumeTrue(Files.isDirectory(Path.of("/proc/self")), "a Linux /proc");
        Run run = crt("animate", scene(ORBIT).toString(), "--frames", "0..2", "-o", "/proc/f_%02d.png");
        assertThat(run.exit()).isEqualTo(ExitCode.FILE_ERROR);
        assertThat(run.err()).isEqualTo("crt: cannot write into folder /proc: files cannot be created there" + System.lineSeparator());
    }

    @Test
    void missingScriptIsAFileError() {
        Run run = crt("animate", dir.resolve("nope.crt").toString(), "--frames", "0..2", "-o", pattern());
        assertThat(run.exit()).isEqualTo(ExitCode.FILE_ERROR);
        assertThat(run.err()).contains("cannot read").contains("no such file");
        assertThat(Files.exists(dir.resolve("out"))).isFalse();
    }

    @Test
    void badFramesAreUsageErrors() {
        assertUsage(animate(ORBIT, "--frames", "10..2"), "--frames 10..2: the last frame 2 comes before the first 10");
        assertUsage(animate(ORBIT, "--frames", "1-10"), "--frames takes FIRST..LAST or FIRST..LAST:STEP");
        assertUsage(animate(ORBIT, "--frames", "0..9:0"), "the step must be at least 1");
        assertUsage(animate(ORBIT), "Missing required option: '--frames=A..B[:STEP]'");
    }

    @Test
    void badShardsAreUsageErrors() {
        assertUsage(animate(ORBIT, "--frames", "0..9", "--shard", "3/3"), "--shard 3/3: the shard index must be from 0 to 2, got 3");
        assertUsage(animate(ORBIT, "--frames", "0..9", "--shard", "0/0"), "the shard count must be at least 1");
        assertUsage(animate(ORBIT, "--frames", "0..9", "--shard", "two"), "--shard takes I/N");
    }

    @Test
    void badPatternsAndOptionsAreUsageErrors() {
        Path scene = scene(ORBIT);
        assertUsage(crt("animate", scene.toString(), "--frames", "0..3", "-o", dir.resolve("out/frame.png").toString()),
                "needs the frame number");
        assertUsage(crt("animate", scene.toString(), "--frames", "0..3", "-o", dir.resolve("out/f%d.jpg").toString()),
                "unsupported image type '.jpg'");
        assertUsage(animate(ORBIT, "--frames", "0..3", "--jobs", "0"), "--jobs must be from 1 to 256, got 0");
        assertUsage(animate(ORBIT, "--frames", "0..3", "--time", "2"), "t is the frame number");
        assertUsage(animate(ORBIT, "--frames", "0..3", "--fps", "12"), "give --gif FILE too");
        assertUsage(animate(ORBIT, "--frames", "0..3", "--gif", dir.resolve("a.gif").toString(), "--fps", "60"), "at most 50");
        assertUsage(animate(ORBIT, "--frames", "0..3", "--gif", dir.resolve("a.png").toString()), "must end in .gif");
        assertUsage(animate(ORBIT, "--frames", "0..3", "--gif", dir.resolve("a.gif").toString(), "--shard", "0/2"),
                "after all shards finish");
    }

    @Test
    void leftoversOfThisRunsFramesAreCleanedUpAndOtherFilesKept() throws IOException {
        Path out = Files.createDirectories(dir.resolve("out"));
        Path mine = Files.writeString(out.resolve(".f_01.png.tmp-5eed"), "half a frame");
        Path otherShard = Files.writeString(out.resolve(".f_02.png.tmp-5eed"), "another shard is writing this");
        Path unrelated = Files.writeString(out.resolve("notes.txt"), "keep me");
        Run run = animate(ORBIT, "--frames", "0..3", "--shard", "1/2");
        assertThat(run.exit()).as(run.err()).isZero();
        assertThat(run.err()).startsWith("crt: removed 1 temporary file that an interrupted run left");
        assertThat(Files.exists(mine)).isFalse();
        assertThat(Files.exists(otherShard)).isTrue();
        assertThat(Files.exists(unrelated)).isTrue();
        assertThat(contents(out).keySet()).containsExactlyInAnyOrder("f_01.png", "f_03.png", ".f_02.png.tmp-5eed", "notes.txt");
    }

    private void assertUsage(Run run, String message) {
        assertThat(run.exit()).as(run.err()).isEqualTo(ExitCode.USAGE);
        assertThat(run.err()).contains(message);
        assertThat(Files.exists(dir.resolve("out"))).isFalse();
        assertThat(temporaryFiles(dir)).isEmpty();
    }
}
