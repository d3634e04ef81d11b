package dev.crt.live;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.Background;
import dev.crt.scene.Box;
import dev.crt.scene.Camera;
import dev.crt.scene.Csg;
import dev.crt.scene.CsgOperation;
import dev.crt.scene.Entity;
import dev.crt.scene.GradientBackground;
import dev.crt.scene.Light;
import dev.crt.scene.Material;
import dev.crt.scene.ParallelLight;
import dev.crt.scene.PointLight;
import dev.crt.scene.Rgb;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import dev.crt.scene.SourceSpan;
import dev.crt.scene.Sphere;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Random;

/**
 * The live view's speed figures of docs/benchmarks.md: frames per second at 800×600 for 1,000
 * objects (spheres, boxes and 50 CSG trees) while orbiting, the converter's time for 10,000
 * objects, and the upload after a one-entity edit. Run with bench/live.sh.
 */
public final class LiveBenchmark {
    private LiveBenchmark() {}

    static Scene field(int count, int csgTrees, long seed) {
        Random r = new Random(seed);
        List<Entity> entities = new ArrayList<>();
        int side = (int) Math.ceil(Math.sqrt(count));
        for (int i = 0; i < count; i++) {
            double x = (i % side - side / 2.0) * 1.2, z = (i / side - side / 2.0) * 1.2;
            Material m = new Material(new Rgb(r.nextDouble(), r.nextDouble(), r.nextDouble()), 0.9, 0.4, 40, 0, 0, 1, Rgb.BLACK);
            Transform t = Transform.rotation(new Vec3(0, r.nextDouble() * 90, 0)).then(Transform.translation(new Vec3(x, 0.5, z)));
            Entity e;
            if (i < csgTrees) {
                Box b = new Box(new Vec3(-0.45, -0.45, -0.45), new Vec3(0.45, 0.45, 0.45), m, Transform.IDENTITY, SourceSpan.NONE);
                Sphere s = new Sphere(Vec3.ZERO, 0.58, m, Transform.IDENTITY, SourceSpan.NONE);
                Sphere bite = new Sphere(new Vec3(0.3, 0.4, -0.3), 0.3, m, Transform.IDENTITY, SourceSpan.NONE);
                e = new Csg(CsgOperation.DIFFERENCE, new Csg(CsgOperation.INTERSECTION, b, s, Transform.IDENTITY, SourceSpan.NONE),
                        bite, t, SourceSpan.NONE);
            } else if (i % 2 == 0) {
                e = new Sphere(Vec3.ZERO, 0.45, m, t, SourceSpan.NONE);
            } else {
                e = new Box(new Vec3(-0.4, -0.4, -0.4), new Vec3(0.4, 0.4, 0.4), m, t, SourceSpan.NONE);
            }
            entities.add(e);
        }
        List<Light> lights = List.of(
                new PointLight(new Vec3(-10, 20, -15), Rgb.WHITE, 0, 0.15, SourceSpan.NONE),
                new ParallelLight(new Vec3(5, 10, -3), Vec3.ZERO, new Rgb(0.3, 0.3, 0.35), 0, SourceSpan.NONE));
        Background bg = new GradientBackground(new Rgb(0.8, 0.8, 0.9), new Rgb(0.3, 0.4, 0.7));
        Camera camera = new Camera(new Vec3(0, side * 0.8, -side * 1.1), Vec3.ZERO, 50, 0, 0, 1,
                dev.crt.scene.ApertureShape.CIRCLE, SourceSpan.NONE);
        Settings s = new Settings("bench", "", "", "", lights, camera, bg, 1, 1, 5, 1, 800, 600);
        return new Scene("bench", s, entities);
    }

    public static void main(String[] args) throws Exception {
        System.out.println("machine: " + Runtime.getRuntime().availableProcessors() + " cores, load average "
                + java.lang.management.ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
        Scene thousand = field(1000, 50, 1);
        try (Preview preview = Preview.open()) {
            System.out.println("GL: " + preview.description());
            LiveRenderer r = preview.renderer();
            GpuScene gpu = SceneConverter.convert(thousand);
            r.setScene(gpu);
            r.resize(800, 600);
            FreeCamera cam = FreeCamera.of(thousand.settings().camera());
            for (boolean readBack : new boolean[] {false, true}) {
                for (int warm = 0; warm < 5; warm++) frame(r, cam.orbit(warm, 0), readBack);
                int frames = 60;
                long cpu0 = cpuNanos();
                long start = System.nanoTime();
                for (int i = 0; i < frames; i++) frame(r, cam.orbit(3 * i, 0), readBack);
                double seconds = (System.nanoTime() - start) / 1e9;
                double cpu = (cpuNanos() - cpu0) / 1e9;
                // llvmpipe draws on this process's threads: its CPU time says what the frames cost
                // whatever else the machine is doing; two cores' worth of it is the quiet-machine rate.
                System.out.printf(Locale.ROOT, "orbit, 1,000 objects (50 CSG trees), 800x600%s: %.1f frames/s wall clock"
                        + " (%d frames in %.2f s); %.1f ms CPU per frame, so %.1f frames/s on 2 free cores%n",
                        readBack ? ", with read-back into the panel's image" : ", GPU only (glFinish)", frames / seconds,
                        frames, seconds, 1000 * cpu / frames, 2 * frames / cpu);
            }

            Scene big = field(10_000, 500, 2);
            long[] times = new long[9], cpuTimes = new long[9];
            java.lang.management.ThreadMXBean threads = java.lang.management.ManagementFactory.getThreadMXBean();
            for (int i = 0; i < times.length; i++) {
                long c0 = threads.getCurrentThreadCpuTime();
                long t0 = System.nanoTime();
                SceneConverter.convert(big);
                times[i] = System.nanoTime() - t0;
                cpuTimes[i] = threads.getCurrentThreadCpuTime() - c0;
            }
            Arrays.sort(times);
            Arrays.sort(cpuTimes);
            System.out.printf(Locale.ROOT, "converter, 10,000 objects (500 CSG trees): median %.1f ms wall clock (best %.1f),"
                    + " median %.1f ms CPU, of %d runs%n", times[times.length / 2] / 1e6, times[0] / 1e6,
                    cpuTimes[cpuTimes.length / 2] / 1e6, times.length);

            GpuScene bigGpu = SceneConverter.convert(big);
            r.setScene(bigGpu);
            List<Entity> edited = new ArrayList<>(big.entities());
            Sphere s = (Sphere) edited.get(9_998);
            edited.set(9_998, new Sphere(s.center(), s.radius() * 1.2, s.material(), s.transform(), s.span()));
            Scene next = new Scene("bench", big.settings(), edited);
            long[] updates = new long[7];
            for (int i = 0; i < updates.length; i++) {
                Scene which = i % 2 == 0 ? next : big;
                long t0 = System.nanoTime();
                r.setScene(SceneConverter.convert(which));
                org.lwjgl.opengl.GL11.glFinish();
                updates[i] = System.nanoTime() - t0;
            }
            Arrays.sort(updates);
            System.out.printf(Locale.ROOT, "edit one of 10,000 objects, convert + upload: median %.1f ms, %d floats sent of %d%n",
                    updates[updates.length / 2] / 1e6, r.lastUploadFloats(), bigGpu.texels * 4);
        }
    }

    private static long cpuNanos() {
        return ((com.sun.management.OperatingSystemMXBean) java.lang.management.ManagementFactory.getOperatingSystemMXBean())
                .getProcessCpuTime();
    }

    private static void frame(LiveRenderer r, FreeCamera cam, boolean readBack) {
        r.clear();
        r.draw(cam.view(), 0, 0, 800, 600, LiveRenderer.Overlay.NONE);
        if (readBack) r.readColour();
        else org.lwjgl.opengl.GL11.glFinish();
    }
}
