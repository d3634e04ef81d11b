package dev.crt.render;

import static dev.crt.render.Scenes.*;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.Background;
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
 * One ray against a scene of one primitive, through {@link Tracer#closestHit}: a sphere, an
 * axis-aligned box and a rotated box (which the tracer intersects in its own frame), each with a
 * ray that hits it and one that misses it. Run with bench/jmh.sh.
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
@State(Scope.Thread)
public class ShapeBenchmark {
    private static final Material M = matte(rgb(0.5, 0.5, 0.5));

    private Tracer sphere, box, rotatedBox;
    /** The eye, a direction at the centre (hits all three) and one beside them (misses all three). */
    private double ox, oy, oz, hx, hy, hz, mx, my, mz;

    static Tracer tracer(Entity... entities) {
        return new Tracer(new SceneGeometry(List.of(entities)), new Lights(List.of()), new BackgroundShader(Background.BLACK, 1));
    }

    @Setup
    public void setUp() {
        sphere = tracer(sphere(Vec3.ZERO, 1, M));
        box = tracer(box(v(-1, -1, -1), v(1, 1, 1), M));
        rotatedBox = tracer(box(v(-1, -1, -1), v(1, 1, 1), M).transformed(Transform.rotation(v(30, 45, 10))));
        ox = 0.1; oy = 0.2; oz = -5;
        Vec3 hit = v(-0.1, -0.2, 5).normalize(), miss = v(2.5, -0.2, 5).normalize();
        hx = hit.x(); hy = hit.y(); hz = hit.z();
        mx = miss.x(); my = miss.y(); mz = miss.z();
        for (Tracer t : List.of(sphere, box, rotatedBox)) {
            if (!t.closestHit(ox, oy, oz, hx, hy, hz, Double.POSITIVE_INFINITY)) throw new IllegalStateException("the hit ray misses");
            if (t.closestHit(ox, oy, oz, mx, my, mz, Double.POSITIVE_INFINITY)) throw new IllegalStateException("the miss ray hits");
        }
    }

    private double hit(Tracer t) {
        return t.closestHit(ox, oy, oz, hx, hy, hz, Double.POSITIVE_INFINITY) ? t.hit.t : -1;
    }

    private double miss(Tracer t) {
        return t.closestHit(ox, oy, oz, mx, my, mz, Double.POSITIVE_INFINITY) ? t.hit.t : -1;
    }

    @Benchmark public double sphereHit() { return hit(sphere); }

    @Benchmark public double sphereMiss() { return miss(sphere); }

    @Benchmark public double boxHit() { return hit(box); }

    @Benchmark public double boxMiss() { return miss(box); }

    @Benchmark public double rotatedBoxHit() { return hit(rotatedBox); }

    @Benchmark public double rotatedBoxMiss() { return miss(rotatedBox); }
}
