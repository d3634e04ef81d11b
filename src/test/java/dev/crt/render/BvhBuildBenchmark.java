package dev.crt.render;

import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * {@link BvhBuilder#build} over 100,000 random boxes (sides 0.01 to 0.5 in a 20 × 20 × 20 cube).
 * Above 10,000 items the builder works on a pool of all cores, so this is a multi-threaded figure.
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
@State(Scope.Thread)
public class BvhBuildBenchmark {
    private static final int BOXES = 100_000;

    private final double[] bounds = new double[6 * BOXES];
    private final int[] order = new int[BOXES];

    @Setup
    public void setUp() {
        SplittableRandom r = new SplittableRandom(5);
        for (int i = 0; i < BOXES; i++) {
            for (int a = 0; a < 3; a++) {
                double lo = r.nextDouble(-10, 10);
                bounds[6 * i + a] = lo;
                bounds[6 * i + 3 + a] = lo + r.nextDouble(0.01, 0.5);
            }
        }
    }

    @Benchmark
    public Bvh build() {
        return BvhBuilder.build(bounds, BOXES, order);
    }
}
