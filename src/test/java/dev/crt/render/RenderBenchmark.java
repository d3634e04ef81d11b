package dev.crt.render;

import dev.crt.image.FrameBuffer;
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
 * A whole render on one thread of the box field of docs/benchmarks.md section 1 ({@link RenderBench#boxes}:
 * 500 reflective boxes, CSG bowls, spheres, four lights, depth 5) at 64 × 48, prepared once.
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
@State(Scope.Thread)
public class RenderBenchmark {
    private Renderer renderer;

    @Setup
    public void setUp() {
        renderer = Renderer.prepare(RenderBench.boxes(64, 48));
    }

    @Benchmark
    public FrameBuffer boxField64x48() {
        return renderer.render(1, RenderMonitor.NONE);
    }
}
