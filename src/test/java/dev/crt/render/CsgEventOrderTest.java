package dev.crt.render;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.SplittableRandom;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;

/** The order in which a CSG walk meets boundary events: by distance, ties in the order gathered. */
class CsgEventOrderTest {
    @Property(tries = 500)
    void eventsComeByDistanceAndTiesKeepTheirGatheredOrder(@ForAll long seed, @ForAll @IntRange(min = 0, max = 400) int n) {
        SplittableRandom r = new SplittableRandom(seed);
        double[] t = new double[n];
        // Few distinct values, so that many events tie; some infinities and negative distances.
        int distinct = 1 + r.nextInt(Math.max(1, n));
        for (int i = 0; i < n; i++) {
            int v = r.nextInt(distinct);
            t[i] = v == 0 && r.nextInt(8) == 0 ? Double.NEGATIVE_INFINITY : (v - distinct / 3.0) * 0.5;
        }
        List<Integer> expected = new ArrayList<>();
        for (int i = 0; i < n; i++) expected.add(i);
        expected.sort(Comparator.comparingDouble(i -> t[i])); // List.sort is stable
        int[] order = CsgSolids.sort(t, n, new int[n], new int[n]);
        List<Integer> got = new ArrayList<>();
        for (int i = 0; i < n; i++) got.add(order[i]);
        assertThat(got).isEqualTo(expected);
    }
}
