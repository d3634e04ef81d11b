package dev.crt.cli;

import dev.crt.animation.FrameRange;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class ShardTest {
    @Test
    void sharesAreDisjointAndCoverTheRangeExactly() {
        FrameRange range = FrameRange.parse("3..40:2");
        for (int n = 1; n <= 7; n++) {
            List<Integer> covered = new ArrayList<>();
            for (int i = 0; i < n; i++) {
                Shard shard = new Shard(i, n);
                for (int k = 0; k < range.size(); k++) if (shard.owns(k)) covered.add(range.frame(k));
            }
            covered.sort(null);
            List<Integer> all = new ArrayList<>();
            for (int k = 0; k < range.size(); k++) all.add(range.frame(k));
            assertThat(covered).as("%d shards", n).isEqualTo(all);
        }
    }

    @Test
    void shardTakesEveryNthFrameByIndex() {
        Shard shard = Shard.parse("1/3");
        assertThat(List.of(0, 1, 2, 3, 4, 5, 6, 7).stream().filter(shard::owns)).containsExactly(1, 4, 7);
    }

    @Test
    void badValuesSayWhatIsExpected() {
        assertThatThrownBy(() -> Shard.parse("3/3")).hasMessage("--shard 3/3: the shard index must be from 0 to 2, got 3");
        assertThatThrownBy(() -> Shard.parse("0/0")).hasMessage("--shard 0/0: the shard count must be at least 1, got 0");
        assertThatThrownBy(() -> Shard.parse("1of3")).hasMessageContaining("I/N");
        assertThatThrownBy(() -> Shard.parse("-1/3")).hasMessageContaining("I/N");
    }
}
