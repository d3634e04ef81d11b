package dev.crt.render;

import static dev.crt.render.Scenes.*;

import dev.crt.scene.Background;
import dev.crt.scene.CsgOperation;
import dev.crt.scene.Entity;
import dev.crt.scene.Material;
import java.util.List;
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
 * The nearest hit through CSG solids: a bowl (a sphere minus a smaller sphere minus a box over
 * its top half) and the plate of bench/scenes/csg-lattice.crt at n = 1,600 (a box minus one
 * union of 1,600 balls on a 40 × 40 grid, built as a left-leaning chain as the script does).
 * Each call traces the next of 1,024 fixed rays from a camera to random points of the solid's box.
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
@State(Scope.Thread)
public class CsgBenchmark {
    private static final Material M = matte(rgb(0.9, 0.6, 0.3));
    private static final int BALLS = 1600;

    private Tracer bowl, lattice;
    private RayBatch bowlRays, latticeRays;

    private static Tracer tracer(Entity e) {
        return new Tracer(new SceneGeometry(List.of(e)), new Lights(List.of()), new BackgroundShader(Background.BLACK, 1));
    }

    @Setup
    public void setUp() {
        Entity shell = csg(CsgOperation.DIFFERENCE, sphere(v(0, 0, 0), 1.5, M), sphere(v(0, 0.2, 0), 1.3, M));
        bowl = tracer(csg(CsgOperation.DIFFERENCE, shell, box(v(-2, 0, -2), v(2, 2, 2), M)));
        bowlRays = RayBatch.fromPoint(new double[] {0, 3, -5}, new double[] {-1.5, -1.5, -1.5}, new double[] {1.5, 0, 1.5}, 3);

        int side = (int) Math.ceil(Math.sqrt(BALLS));
        double step = 20.0 / side;
        Entity holes = null;
        for (int i = 0; i < BALLS; i++) {
            Entity ball = sphere(v(-10 + step * (i % side + 0.5), 0, -10 + step * (i / side + 0.5)), 0.42 * step, M);
            holes = holes == null ? ball : csg(CsgOperation.UNION, holes, ball);
        }
        lattice = tracer(csg(CsgOperation.DIFFERENCE, box(v(-10.5, -1.5, -10.5), v(10.5, 0, 10.5), M), holes));
        latticeRays = RayBatch.fromPoint(new double[] {0, 14, -22}, new double[] {-10.5, 0, -10.5}, new double[] {10.5, 0, 10.5}, 4);

        if (bowlRays.hits(bowl) == 0 || latticeRays.hits(lattice) != RayBatch.SIZE) throw new IllegalStateException("rays miss the solids");
    }

    @Benchmark
    public double bowl() {
        return bowlRays.closest(bowl, bowlRays.next());
    }

    @Benchmark
    public double lattice() {
        return latticeRays.closest(lattice, latticeRays.next());
    }
}
