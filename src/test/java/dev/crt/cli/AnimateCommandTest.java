package dev.crt.cli;

import static dev.crt.cli.AnimateTestSupport.ORBIT;
import static dev.crt.cli.AnimateTestSupport.assertSameFiles;
import static dev.crt.cli.AnimateTestSupport.contents;
import static dev.crt.cli.AnimateTestSupport.crt;
import static dev.crt.cli.AnimateTestSupport.crtCaptured;
import static dev.crt.cli.AnimateTestSupport.temporaryFiles;
import static dev.crt.cli.AnimateTestSupport.write;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.cli.AnimateTestSupport.Run;
import dev.crt.image.GifWriterTest;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class AnimateCommandTest {
    @TempDir
    Path dir;

    private Path scene() { return write(dir.resolve("orbit.crt"), ORBIT); }

    private String pattern(String folder) { return dir.resolve(folder).resolve("f_%03d.png").toString(); }

    @Test
    void rendersEveryFrameOfTheRangeWithTheFrameNumberAsT() throws IOException {
        Run run = crt("animate", scene().toString(), "--frames", "0..5:2", "-o", pattern("out"));
        assertThat(run.exit()).as(run.err()).isZero();
        assertThat(contents(dir.resolve("out")).keySet()).containsExactly("f_000.png", "f_002.png", "f_004.png");
        BufferedImage f0 = ImageIO.read(dir.resolve("out/f_000.png").toFile());
        BufferedImage f2 = ImageIO.read(dir.resolve("out/f_002.png").toFile());
        assertThat(f0.getWidth()).isEqualTo(32);
        assertThat(pixels(f0)).isNotEqualTo(pixels(f2));
        assertThat(run.err()).contains("crt: frames 0..5:2: 3 rendered, 0 skipped, 0 failed");
    }

    @Test
    void threeShardsRunTogetherWriteExactlyTheFilesOfOneRun() {
        Path scene = scene();
        Run whole = crt("animate", scene.toString(), "--frames", "1..10", "-o", pattern("whole"), "--jobs", "2", "-q");
        assertThat(whole.exit()).as(whole.err()).isZero();
        List<CompletableFuture<Run>> shards = new ArrayList<>();
        for (int i = 0; i < 3; i++) {
            String shard = i + "/3";
            shards.add(CompletableFuture.supplyAsync(() -> crtCaptured("animate", scene.toString(), "--frames", "1..10",
                    "-o", pattern("shared"), "--shard", shard, "--threads", "1", "-q")));
        }
        for (CompletableFuture<Run> s : shards) assertThat(s.join().exit()).as(s.join().err()).isZero();
        assertThat(contents(dir.resolve("whole"))).hasSize(10);
        assertSameFiles(dir.resolve("shared"), dir.resolve("whole"));
    }

    @Test
    void shardRendersOnlyItsShareOfTheRange() {
        Run run = crt("animate", scene().toString(), "--frames", "0..7", "-o", pattern("out"), "--shard", "1/3", "-q");
        assertThat(run.exit()).as(run.err()).isZero();
        assertThat(contents(dir.resolve("out")).keySet()).containsExactly("f_001.png", "f_004.png", "f_007.png");
    }

    @Test
    void existingFramesAreAnErrorBeforeAnyWorkWithoutResumeOrForce() throws IOException {
        Path scene = scene();
        assertThat(crt("animate", scene.toString(), "--frames", "0..1", "-o", pattern("out"), "-q").exit()).isZero();
        Path f0 = dir.resolve("out/f_000.png");
        FileTime before = Files.getLastModifiedTime(f0);
        Files.delete(dir.resolve("out/f_001.png"));
        Run again = crt("animate", scene.toString(), "--frames", "0..2", "-o", pattern("out"), "-q");
        assertThat(again.exit()).isEqualTo(ExitCode.FILE_ERROR);
        assertThat(again.err()).contains("crt: 1 of the 3 frame files exist already (" + f0 + ")")
                .contains("use --resume").contains("--force");
        assertThat(contents(dir.resolve("out")).keySet()).containsExactly("f_000.png");
        assertThat(Files.getLastModifiedTime(f0)).isEqualTo(before);
    }

    @Test
    void resumeSkipsFramesThatExistAndForceRendersThemAgain() throws IOException {
        Path scene = scene();
        assertThat(crt("animate", scene.toString(), "--frames", "0..1", "-o", pattern("out"), "-q").exit()).isZero();
        Path f0 = dir.resolve("out/f_000.png");
        Object inode = Files.getAttribute(f0, "unix:ino");
        Run resumed = crt("animate", scene.toString(), "--frames", "0..3", "-o", pattern("out"), "--resume");
        assertThat(resumed.exit()).as(resumed.err()).isZero();
        assertThat(resumed.err()).contains("2 rendered, 2 skipped, 0 failed");
        assertThat(Files.getAttribute(f0, "unix:ino")).isEqualTo(inode);
        Run forced = crt("animate", scene.toString(), "--frames", "0..3", "-o", pattern("out"), "--force");
        assertThat(forced.exit()).as(forced.err()).isZero();
        assertThat(forced.err()).contains("4 rendered, 0 skipped, 0 failed");
        assertThat(Files.getAttribute(f0, "unix:ino")).isNotEqualTo(inode);
        assertThat(crt("animate", scene.toString(), "--frames", "0..3", "-o", pattern("out"), "--force", "--resume").exit())
                .isEqualTo(ExitCode.USAGE);
    }

    @Test
    void jobsShareTheThreadsAndGiveTheSameBytes() {
        Path scene = scene();
        Run one = crt("animate", scene.toString(), "--frames", "0..5", "-o", pattern("one"), "--jobs", "1", "-q");
        Run three = crt("animate", scene.toString(), "--frames", "0..5", "-o", pattern("three"), "--jobs", "3", "--threads", "2", "-q");
        assertThat(one.exit()).as(one.err()).isZero();
        assertThat(three.exit()).as(three.err()).isZero();
        assertSameFiles(dir.resolve("three"), dir.resolve("one"));
    }

    @Test
    void gifHasOneFramePerFrameFileInFrameOrder() throws IOException {
        Path gif = dir.resolve("gifs/orbit.gif");
        Run run = crt("animate", scene().toString(), "--frames", "0..4", "-o", pattern("out"), "--gif", gif.toString(),
                "--fps", "10");
        assertThat(run.exit()).as(run.err()).isZero();
        assertThat(run.err()).contains("crt: wrote " + gif + " (5 frames at 10.0 fps)");
        try (ImageInputStream in = ImageIO.createImageInputStream(gif.toFile())) {
            ImageReader reader = ImageIO.getImageReadersByFormatName("gif").next();
            reader.setInput(in);
            assertThat(reader.getNumImages(true)).isEqualTo(5);
            assertThat(reader.read(0).getWidth()).isEqualTo(32);
            reader.dispose();
        }
        // In frame order: each GIF frame is closest to the frame file of its own number.
        List<int[]> shown = GifWriterTest.composited(gif, new ArrayList<>());
        for (int i = 0; i < 5; i++) {
            int closest = -1;
            double best = Double.MAX_VALUE;
            for (int f = 0; f < 5; f++) {
                double d = difference(shown.get(i), pixels(ImageIO.read(dir.resolve("out/f_00" + f + ".png").toFile())));
                if (d < best) { best = d; closest = f; }
            }
            assertThat(closest).isEqualTo(i);
        }
        // The GIF is derived from the frames: --resume remakes it from what exists.
        Files.delete(dir.resolve("out/f_002.png"));
        Run resumed = crt("animate", scene().toString(), "--frames", "0..4", "-o", pattern("out"), "--gif", gif.toString(),
                "--resume", "-q");
        assertThat(resumed.exit()).as(resumed.err()).isZero();
        assertThat(contents(dir.resolve("out"))).hasSize(5);
        assertThat(temporaryFiles(dir)).isEmpty();
    }

    @Test
    void statsSumThePhasesOverFramesAndShowTheOverhead() {
        Run run = crt("animate", scene().toString(), "--frames", "0..2", "-o", pattern("out"), "--stats", "-q");
        assertThat(run.exit()).as(run.err()).isZero();
        assertThat(run.out()).contains("times and rays summed over 3 frames").contains("compile").contains("bvh build")
                .contains("render").contains("write").contains("frames/s").containsPattern("overhead +\\d+\\.\\d %");
        assertThat(run.err()).isEmpty();
    }

    private static double difference(int[] a, int[] b) {
        double sum = 0;
        for (int i = 0; i < a.length; i++) {
            for (int shift = 0; shift <= 16; shift += 8) sum += Math.abs((a[i] >> shift & 0xff) - (b[i] >> shift & 0xff));
        }
        return sum;
    }

    private static int[] pixels(BufferedImage image) {
        return image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
    }

}
