package dev.crt.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;

class AnimateProgressTest {
    @Test
    void durationsReadAsPeopleSayThem() {
        assertThat(AnimationProgress.duration(4_240_000_000L)).isEqualTo("4.2 s");
        assertThat(AnimationProgress.duration(185_000_000_000L)).isEqualTo("3 min 05 s");
        assertThat(AnimationProgress.duration(7_620_000_000_000L)).isEqualTo("2 h 07 min");
    }

    @Test
    void withoutATerminalEachWrittenFramePrintsALineWithCountAndTimeLeft() {
        StringWriter text = new StringWriter();
        try (AnimationProgress progress = AnimationProgress.start(3, false, new PrintWriter(text))) {
            progress.started(10);
            progress.rendering(10, 50, 100);
            progress.finished(10, true);
            progress.started(11);
            progress.finished(11, false);
        }
        assertThat(text.toString()).matches("crt: frame 10 written \\(1 of 3, [0-9.]+ s elapsed, about [0-9.]+ s left\\)\\R");
    }

    @Test
    void quietPrintsNothing() {
        StringWriter text = new StringWriter();
        try (AnimationProgress progress = AnimationProgress.start(3, true, new PrintWriter(text))) {
            progress.finished(10, true);
        }
        assertThat(text.toString()).isEmpty();
    }
}
