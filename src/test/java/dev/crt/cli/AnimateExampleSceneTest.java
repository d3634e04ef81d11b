package dev.crt.cli;

import static dev.crt.cli.AnimateTestSupport.crt;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.cli.AnimateTestSupport.Run;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The animated examples in scenes/ animate; the orbit's loop closes: frame 48 is frame 0 again. */
class AnimateExampleSceneTest {
    @TempDir
    Path dir;

    @Test
    void orbitMovesAndLoopsAfterFortyEightFrames() throws Exception {
        Run run = crt("animate", "scenes/orbit.crt", "--frames", "0..48:24", "-o", dir.resolve("o_%02d.png").toString(),
                "--width", "40", "--height", "30", "-q");
        assertThat(run.exit()).as(run.err()).isZero();
        byte[] first = Files.readAllBytes(dir.resolve("o_00.png"));
        assertThat(Files.readAllBytes(dir.resolve("o_24.png"))).isNotEqualTo(first);
        assertThat(Files.readAllBytes(dir.resolve("o_48.png"))).isEqualTo(first);
    }

    @Test
    void animationBasicsRendersAcrossItsRange() {
        Run run = crt("animate", "scenes/animation-basics.crt", "--frames", "0..60:30", "-o", dir.resolve("b_%02d.png").toString(),
                "--width", "32", "--height", "24", "-q");
        assertThat(run.exit()).as(run.err()).isZero();
        assertThat(dir.resolve("b_60.png")).exists();
    }
}
