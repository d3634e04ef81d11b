package dev.crt.studio;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;

class ThroughputTest {
    private static final long S = 1_000_000_000L;

    @Test
    void raysAreCountedInTheirSecondAndTheRecentRateIsTheLastWholeSecond() {
        Throughput t = new Throughput();
        long base = 1000 * S;
        // 2 million rays in each tenth of second 1000, then 1 million in the first half of second 1001.
        for (int i = 0; i < 10; i++) t.add(2_000_000, base + i * S / 10 + 1);
        for (int i = 0; i < 5; i++) t.add(1_000_000, base + S + i * S / 10 + 1);
        assertThat(t.megaRays(1000)).isCloseTo(20, within(1e-9));
        assertThat(t.megaRays(1001)).isCloseTo(5, within(1e-9));
        assertThat(t.megaRays(999)).isZero();
        // At 1001.5 s the last whole second is [1000.5, 1001.5): five tenths at 2 and five at 1.
        assertThat(t.recentMegaRaysPerSecond(base + S + S / 2 + 1)).isCloseTo(15, within(1e-9));
        // The tenth under way does not count yet; two seconds later nothing was traced.
        t.add(7_000_000, base + 3 * S + 1);
        assertThat(t.recentMegaRaysPerSecond(base + 3 * S + 2)).isZero();
        assertThat(t.recentMegaRaysPerSecond(base + 3 * S + S / 10 + 1)).isCloseTo(7, within(1e-9));
    }

    @Test
    void oldHistoryIsDropped() {
        Throughput t = new Throughput();
        t.add(1_000_000, 5 * S);
        t.add(-3, 6 * S);
        assertThat(t.megaRays(5)).isCloseTo(1, within(1e-9));
        t.add(1_000_000, (5 + Throughput.KEEP_SECONDS + 2) * S);
        assertThat(t.megaRays(5)).isZero();
        assertThat(t.megaRays(5 + Throughput.KEEP_SECONDS + 2)).isCloseTo(1, within(1e-9));
    }
}
