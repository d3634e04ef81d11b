package dev.crt.animation;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class FrameRangeTest {
    private static List<Integer> frames(FrameRange r) {
        List<Integer> out = new ArrayList<>();
        for (int k = 0; k < r.size(); k++) out.add(r.frame(k));
        return out;
    }

    @Test
    void rangeIncludesBothEnds() {
        assertThat(frames(FrameRange.parse("1..5"))).containsExactly(1, 2, 3, 4, 5);
    }

    @Test
    void stepSkipsFramesAndStopsAtOrBeforeTheLast() {
        assertThat(frames(FrameRange.parse("0..10:3"))).containsExactly(0, 3, 6, 9);
        assertThat(frames(FrameRange.parse("0..9:3"))).containsExactly(0, 3, 6, 9);
    }

    @Test
    void singleFrameAndNegativeFrames() {
        assertThat(frames(FrameRange.parse("7"))).containsExactly(7);
        assertThat(frames(FrameRange.parse("-2..1"))).containsExactly(-2, -1, 0, 1);
    }

    @Test
    void hugeRangeDoesNotOverflow() {
        FrameRange r = FrameRange.parse("-2147483648..2147483647:1000000000");
        assertThat(r.size()).isEqualTo(5);
        assertThat(r.frame(4)).isEqualTo(1852516352);
        assertThat(FrameRange.parse("1..1000000").size()).isEqualTo(1_000_000);
        assertThatThrownBy(() -> FrameRange.parse("0..1000000")).hasMessageContaining("more than 1000000 frames");
    }

    @Test
    void badValuesSayWhatIsExpected() {
        assertThatThrownBy(() -> FrameRange.parse("1-10")).hasMessageContaining("FIRST..LAST");
        assertThatThrownBy(() -> FrameRange.parse("1..")).hasMessageContaining("FIRST..LAST");
        assertThatThrownBy(() -> FrameRange.parse("10..5")).hasMessage("--frames 10..5: the last frame 5 comes before the first 10");
        assertThatThrownBy(() -> FrameRange.parse("1..5:0")).hasMessage("--frames 1..5:0: the step must be at least 1, got 0");
        assertThatThrownBy(() -> FrameRange.parse("1..99999999999")).hasMessageContaining("must lie between");
    }
}
