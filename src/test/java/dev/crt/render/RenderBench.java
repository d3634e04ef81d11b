package dev.crt.render;

import static dev.crt.render.Scenes.*;

import dev.crt.geom.Vec3;
import dev.crt.scene.ApertureShape;
import dev.crt.scene.Camera;
import dev.crt.scene.CsgOperation;
import dev.crt.scene.Entity;
import dev.crt.scene.GradientBackground;
import dev.crt.scene.Light;
import dev.crt.scene.Material;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import dev.crt.scene.SourceSpan;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

/**
 * Render throughput, not a unit test. Renders the benchmark scene of issue 3 (about 500 reflective
 * boxes, three CSG bowls, a few spheres, three point lights and a parallel light, depth 5,
 * 1280×720, one sample per pixel) on 2 threads, then n = 1,000 … 1,000,000 small random spheres to
 * show render time growing like log n. Run:
 * <pre>mvn -B -q -o test-compile && java -cp target/classes:target/test-classes dev.crt.render.RenderBench [all|boxes|spheres] [threads] [maxSpheres]</pre>
 * or, for one cold render in a fresh process (the figure to compare with POV-Ray's whole run),
 * {@code time java -cp target/classes:target/test-classes dev.crt.render.RenderBench once [out.png]}
 * (it writes the PNG too, as POV-Ray does).
 */
public final class RenderBench {
    private RenderBench() {}

    /** The benchmark scene of issue 3. */
    static Scene boxes(int width, int height) {
        List<Entity> es = new ArrayList<>();
        SplittableRandom r = new SplittableRandom(3);
        es.add(plane(Vec3.Y, Vec3.ZERO, material(rgb(0.8, 0.8, 0.8), 0.8, 0.2, 20, 0.2, 0, 1)));
        for (int i = 0; i < 25; i++) {
            for (int k = 0; k < 20; k++) {
                double x = (i - 12) * 1.6 + r.nextDouble() * 0.4, z = k * 1.6 + r.nextDouble() * 0.4;
                double h = 0.3 + r.nextDouble() * 1.5;
                Material m = material(rgb(0.3 + 0.6 * r.nextDouble(), 0.3 + 0.6 * r.nextDouble(), 0.3 + 0.6 * r.nextDouble()),
                        0.7, 0.4, 30, 0.4, 0, 1);
                es.add(box(v(x, 0, z), v(x + 0.9, h, z + 0.9), m));
            }
        }
        Material bowl = material(rgb(0.9, 0.7, 0.3), 0.7, 0.6, 50, 0.5, 0, 1);
        for (int b = 0; b < 3; b++) {
            Vec3 c = v(-5 + 5 * b, 3.2, 6 + 3 * b);
            es.add(csg(CsgOperation.DIFFERENCE, sphere(c, 1.5, bowl), box(c.plus(v(-2, 0, -2)), c.plus(v(2, 2, 2)), bowl)));
        }
        es.add(sphere(v(-2.5, 3, 2), 1, material(rgb(1, 1, 1), 0.05, 0.9, 120, 0.9, 0, 1)));
        es.add(sphere(v(2.5, 3, 2.5), 1, material(rgb(1, 1, 1), 0.05, 0.9, 120, 0.1, 0.9, 1.5)));
        es.add(sphere(v(0, 4.5, 12), 1.2, material(rgb(0.2, 0.5, 1), 0.9, 0.5, 40, 0.3, 0, 1)));
        es.add(sphere(v(7, 2.5, 9), 0.8, material(rgb(1, 0.3, 0.2), 0.9, 0.5, 40, 0.6, 0, 1)));
        List<Light> lights = List.of(point(v(-10, 12, -8), rgb(0.6, 0.6, 0.6), 0, 0.05),
                point(v(10, 8, -5), rgb(0.4, 0.35, 0.3), 0, 0),
                point(v(0, 10, 20), rgb(0.3, 0.3, 0.4), 0, 0),
                parallel(v(1, 3, -2), Vec3.ZERO, rgb(0.3, 0.3, 0.3), 0.02));
        Vec3 eye = v(0, 7, -12), at = v(0, 1, 10);
        Camera cam = new Camera(eye, at, 50, 0, 0, at.minus(eye).length(), ApertureShape.CIRCLE, SourceSpan.NONE);
        Settings s = new Settings("bench", "", "", "", lights, cam,
                new GradientBackground(rgb(0.8, 0.8, 0.9), rgb(0.2, 0.4, 0.8)), 1, 1, 5, 2.2, width, height);
        return new Scene("bench", s, es);
    }

    /** n matte spheres of radius ~0.05 scattered in a cube of side 20 (density kept the same by scaling r). */
    static Scene spheres(int n, int width, int height) {
        SplittableRandom r = new SplittableRandom(n);
        List<Entity> es = new ArrayList<>(n);
        double radius = 3.0 / Math.cbrt(n);
        for (int i = 0; i < n; i++) {
            Material m = matte(rgb(0.2 + 0.8 * r.nextDouble(), 0.2 + 0.8 * r.nextDouble(), 0.5));
            es.add(sphere(v(r.nextDouble() * 20 - 10, r.nextDouble() * 20 - 10, r.nextDouble() * 20), radius * (0.5 + r.nextDouble()), m));
        }
        Settings s = settings(camera(v(0, 0, -25), v(0, 0, 10), 45), List.of(point(v(-20, 30, -30), rgb(1, 1, 1), 0, 0.1)),
                new GradientBackground(rgb(0.1, 0.1, 0.1), rgb(0.3, 0.3, 0.5)), width, height);
        return new Scene("spheres", s, es);
    }

    private static void run(String name, Scene scene, int threads, int repeats) {
        Renderer renderer = Renderer.prepare(scene);
        RenderStats best = null;
        long bestCpu = Long.MAX_VALUE;
        for (int k = 0; k < repeats; k++) {
            long cpu = cpuNanos();
            renderer.render(threads, RenderMonitor.NONE);
            bestCpu = Math.min(bestCpu, cpuNanos() - cpu);
            RenderStats s = renderer.stats();
            if (best == null || s.renderNanos() < best.renderNanos()) best = s;
        }
        SceneStructure st = renderer.structure();
        System.out.printf("%-22s build %8.1f ms  render %8.1f ms (cpu %8.1f ms)  rays %,12d (primary %,d shadow %,d reflected %,d refracted %,d)"
                        + "  %6.2f Mrays/s  bvh nodes %,d depth %d%n",
                name, best.buildNanos() / 1e6, best.renderNanos() / 1e6, bestCpu / 1e6, best.totalRays(), best.primaryRays(),
                best.shadowRays(), best.reflectedRays(), best.refractedRays(), best.megaRaysPerSecond(), st.bvhNodes(),
                st.bvhDepth());
    }

    /** CPU time of the whole process: steadier than wall time on a shared machine. */
    private static long cpuNanos() {
        return ((com.sun.management.OperatingSystemMXBean) java.lang.management.ManagementFactory.getOperatingSystemMXBean())
                .getProcessCpuTime();
    }

    public static void main(String[] args) throws java.io.IOException {
        if (args.length > 0 && args[0].equals("once")) {
            // One cold render, as a whole process would do it: compare with `time povray …`.
            Scene scene = boxes(1280, 720);
            Renderer r = Renderer.prepare(scene);
            dev.crt.image.FrameBuffer image = r.render(2, RenderMonitor.NONE);
            long write = System.nanoTime();
            java.nio.file.Path out = java.nio.file.Path.of(args.length > 1 ? args[1] : "bench-crt.png");
            dev.crt.image.ImageFiles.write(image, out, scene.settings().gamma(), java.util.Map.of("Title", "bench"));
            System.out.printf("cold render %.1f ms, %.2f Mrays/s, png %.1f ms%n", r.stats().renderNanos() / 1e6,
                    r.stats().megaRaysPerSecond(), (System.nanoTime() - write) / 1e6);
            return;
        }
        String what = args.length > 0 ? args[0] : "all";
        int threads = args.length > 1 ? Integer.parseInt(args[1]) : 2;
        int maxSpheres = args.length > 2 ? Integer.parseInt(args[2]) : 1_000_000;
        long start = System.nanoTime();
        if (!what.equals("spheres")) {
            run("boxes 1280x720 cold", boxes(1280, 720), threads, 1);
            run("boxes 1280x720 warm", boxes(1280, 720), threads, 3);
        }
        if (!what.equals("boxes")) {
            for (int n = 1000; n <= maxSpheres; n *= 10) run("spheres " + n, spheres(n, 640, 480), threads, 2);
        }
        System.out.printf("total %.1f s%n", (System.nanoTime() - start) / 1e9);
    }
}
