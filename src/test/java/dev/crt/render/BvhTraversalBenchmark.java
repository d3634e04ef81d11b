package dev.crt.render;

import static dev.crt.render.Scenes.*;

import dev.crt.scene.Background;
import dev.crt.scene.Entity;
import dev.crt.scene.Material;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * Rays through the BVH of n random small spheres in a 20 × 20 × 20 cube, laid out like
 * bench/scenes/spheres.crt (radius 16/√n): the nearest hit of rays from the camera, and the
 * shadow factor of segments from random points of the cube to the light. Each call traces the
 * next of 1,024 fixed rays.
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
@State(Scope.Thread)
public class BvhTraversalBenchmark {
    private static final double[] EYE = {0, 0, -32}, LIGHT = {-30, 40, -50}, LO = {-10, -10, -10}, HI = {10, 10, 10};

    @Param({"1000", "100000"})
    int spheres;

    private Tracer tracer;
    private RayBatch primary, shadow;

    @Setup
    public void setUp() {
        SplittableRandom r = new SplittableRandom(42);
        Material m = matte(rgb(0.8, 0.3, 0.25));
        double radius = 16 / Math.sqrt(spheres);
        List<Entity> es = new ArrayList<>(spheres);
        for (int i = 0; i < spheres; i++) {
            es.add(sphere(v(r.nextDouble(-10, 10), r.nextDouble(-10, 10), r.nextDouble(-10, 10)), radius, m));
        }
        tracer = new Tracer(new SceneGeometry(es), new Lights(List.of(point(v(LIGHT[0], LIGHT[1], LIGHT[2]), rgb(1, 1, 1), 0, 0.2))),
                new BackgroundShader(Background.BLACK, 1));
        primary = RayBatch.fromPoint(EYE, LO, HI, 1);
        shadow = RayBatch.toPoint(LO, HI, LIGHT, 2);
        if (primary.hits(tracer) == 0) throw new IllegalStateException("no camera ray hits a sphere");
    }

    @Benchmark
    public double closestHit() {
        return primary.closest(tracer, primary.next());
    }

    @Benchmark
    public double shadow() {
        return shadow.transmittance(tracer, shadow.next());
    }
}
