package dev.crt.render;

import com.sun.management.OperatingSystemMXBean;
import dev.crt.lang.CompileOptions;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import dev.crt.scene.Scene;
import java.lang.management.ManagementFactory;
import java.lang.management.MemoryMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;

/**
 * The BVH build benchmark of bench/bvh-build.sh (compiled there against target/classes: it lives
 * in the renderer's package to reach the builder).
 *
 * <pre>
 * BvhBuild boxes  KIND N ROUNDS      KIND spheres (bench/scenes/spheres.crt's distribution) or ball
 *                                    (the triangles of bench/tools/MeshGen.java's ball): BvhBuilder.build
 *                                    alone, ROUNDS times in one JVM
 * BvhBuild scene  SCRIPT.crt TIME    compile the script (at time TIME), then prepare its geometry
 *                                    (SceneGeometry: meshes, BVHs) once, and measure the heap held
 * </pre>
 *
 * Times are wall and process CPU (user + system of every thread, the collector's included); the
 * heap is what is in use after full collections with the result still held.
 */
public final class BvhBuild {
    private static final OperatingSystemMXBean OS = (OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
    private static final MemoryMXBean MEMORY = ManagementFactory.getMemoryMXBean();

    public static void main(String[] args) throws Exception {
        Locale.setDefault(Locale.ROOT);
        if (args.length == 4 && args[0].equals("boxes")) {
            boxes(args[1], Integer.parseInt(args[2].replace("_", "")), Integer.parseInt(args[3]));
        } else if (args.length == 3 && args[0].equals("scene")) {
            scene(Path.of(args[1]), Double.parseDouble(args[2]));
        } else {
            System.err.println("usage: BvhBuild boxes spheres|ball N ROUNDS | BvhBuild scene SCRIPT.crt TIME");
            System.exit(2);
        }
    }

    private static void boxes(String kind, int n, int rounds) {
        double[] wall = new double[rounds], cpu = new double[rounds];
        Bvh bvh = null;
        int items = 0;
        long held = 0, peak = 0;
        for (int r = 0; r < rounds; r++) {
            bvh = null;
            // A fresh array each round: the builder reorders the boxes it is given.
            double[] flat = kind.equals("ball") ? ball(n) : kind.equals("spheres") ? spheres(n) : null;
            if (flat == null) throw new IllegalArgumentException("kind: " + kind);
            items = flat.length / 6;
            int[] order = new int[items];
            long before = heap();
            resetPeaks();
            long c0 = OS.getProcessCpuTime(), w0 = System.nanoTime();
            bvh = BvhBuilder.build(flat, items, order);
            wall[r] = (System.nanoTime() - w0) / 1e9;
            cpu[r] = (OS.getProcessCpuTime() - c0) / 1e9;
            peak = Math.max(peak, peakUsed() - before);
            held = heap() - before;
            System.out.printf("  %s %,d round %d: wall %.3f s, cpu %.3f s%n", kind, items, r + 1, wall[r], cpu[r]);
        }
        System.out.printf("%s %,d: build wall %.3f s, cpu %.3f s (medians of %d; first %.3f / %.3f); nodes %,d, depth %d,"
                        + " SAH cost %.2f; heap per item: tree %.1f bytes, peak while building (tree included) at most %.1f%n",
                kind, items, median(wall), median(cpu), rounds, wall[0], cpu[0], bvh.nodeCount, bvh.depth, sah(bvh),
                (double) held / items, (double) peak / items);
    }

    private static void scene(Path script, double time) throws Exception {
        long base = heap();
        long c0 = OS.getProcessCpuTime(), w0 = System.nanoTime();
        var result = CrtCompiler.compile(new Source(script.toString(), Files.readString(script), script),
                new CompileOptions(time, List.of(), 1_000_000_000L, Duration.ofSeconds(600)));
        double compileWall = (System.nanoTime() - w0) / 1e9, compileCpu = (OS.getProcessCpuTime() - c0) / 1e9;
        Scene scene = result.scene();
        if (scene == null) throw new IllegalStateException(result.diagnostics().get(0).message());
        c0 = OS.getProcessCpuTime();
        w0 = System.nanoTime();
        SceneGeometry geometry = new SceneGeometry(scene.entities());
        double geometryWall = (System.nanoTime() - w0) / 1e9, geometryCpu = (OS.getProcessCpuTime() - c0) / 1e9;
        long held = heap() - base;
        long items = geometry.items.length;
        for (MeshGeometry m : geometry.shapes.meshes) if (m != null) items = Math.max(items, m.count);
        System.out.printf("%s (time %s): compile wall %.2f s cpu %.2f s; geometry (BVH builds included) wall %.2f s cpu %.2f s;"
                        + " heap held %.1f MB, %.1f bytes per item (%,d items)%n",
                script.getFileName(), time, compileWall, compileCpu, geometryWall, geometryCpu, held / 1e6,
                (double) held / items, items);
        // The scene is read after the measure, so that it is held (not collected) while measured.
        System.out.printf("  %,d entities%n", scene.entities().size());
    }

    /** Random spheres as bench/scenes/spheres.crt places them: centres in a 20-cube, radius 16/√n. */
    static double[] spheres(int n) {
        SplittableRandom random = new SplittableRandom(1);
        double r = 16 / Math.sqrt(n);
        double[] flat = new double[6 * n];
        for (int i = 0; i < n; i++) {
            for (int a = 0; a < 3; a++) {
                double c = random.nextDouble(-10, 10);
                flat[6 * i + a] = Math.nextDown(c - r);
                flat[6 * i + 3 + a] = Math.nextUp(c + r);
            }
        }
        return flat;
    }

    /** The triangles' boxes of a latitude–longitude ball of about n triangles, as bench/tools/MeshGen.java makes it. */
    static double[] ball(int wanted) {
        int nv = Math.max(3, (int) Math.round(Math.sqrt(wanted / 4.0))), nu = 2 * nv;
        List<double[]> rows = new ArrayList<>();
        double[] north = {0, 1, 0}, south = {0, -1, 0};
        double[][] grid = new double[nv + 1][];
        for (int j = 1; j < nv; j++) {
            double theta = Math.PI * j / nv;
            double[] row = new double[3 * nu];
            for (int i = 0; i < nu; i++) {
                double phi = 2 * Math.PI * i / nu;
                double r = 1 + 0.03 * Math.sin(17 * phi) * Math.sin(13 * theta);
                row[3 * i] = (float) (r * Math.sin(theta) * Math.cos(phi));
                row[3 * i + 1] = (float) (r * Math.cos(theta));
                row[3 * i + 2] = (float) (r * Math.sin(theta) * Math.sin(phi));
            }
            grid[j] = row;
        }
        int triangles = 2 * nu * (nv - 2) + 2 * nu;
        double[] flat = new double[6 * triangles];
        int[] t = {0};
        for (int i = 0; i < nu; i++) {
            int b = (i + 1) % nu;
            triangle(flat, t, north, 0, grid[1], 3 * b, grid[1], 3 * i);
            triangle(flat, t, south, 0, grid[nv - 1], 3 * i, grid[nv - 1], 3 * b);
        }
        for (int j = 1; j < nv - 1; j++) {
            for (int i = 0; i < nu; i++) {
                int b = (i + 1) % nu;
                triangle(flat, t, grid[j], 3 * i, grid[j], 3 * b, grid[j + 1], 3 * b);
                triangle(flat, t, grid[j], 3 * i, grid[j + 1], 3 * b, grid[j + 1], 3 * i);
            }
        }
        return flat;
    }

    private static void triangle(double[] flat, int[] t, double[] p, int a, double[] q, int b, double[] s, int c) {
        int k = 6 * t[0]++;
        for (int x = 0; x < 3; x++) {
            flat[k + x] = Math.nextDown(Math.min(p[a + x], Math.min(q[b + x], s[c + x])));
            flat[k + 3 + x] = Math.nextUp(Math.max(p[a + x], Math.max(q[b + x], s[c + x])));
        }
    }

    /** The tree's SAH cost (traversal 1, intersection 1.5 per item, as the builder weighs them) relative to its root box. */
    static double sah(Bvh bvh) {
        double rootArea = area(bvh.root[0], bvh.root[1], bvh.root[2], bvh.root[3], bvh.root[4], bvh.root[5]);
        double cost = 1;
        int inner = bvh.children.length / 2;
        for (int node = 0; node < inner; node++) {
            for (int c = 0; c < 2; c++) {
                double a = area(bvh.bound(node, c, 0), bvh.bound(node, c, 1), bvh.bound(node, c, 2),
                        bvh.bound(node, c, 3), bvh.bound(node, c, 4), bvh.bound(node, c, 5)) / rootArea;
                int child = bvh.children[2 * node + c];
                cost += Bvh.isLeaf(child) ? 1.5 * Bvh.leafCount(child) * a : a;
            }
        }
        return cost;
    }

    private static double area(double x0, double y0, double z0, double x1, double y1, double z1) {
        double x = x1 - x0, y = y1 - y0, z = z1 - z0;
        return x * y + y * z + z * x;
    }

    private static long heap() {
        for (int i = 0; i < 3; i++) System.gc();
        return MEMORY.getHeapMemoryUsage().getUsed();
    }

    private static void resetPeaks() {
        for (var pool : ManagementFactory.getMemoryPoolMXBeans()) pool.resetPeakUsage();
    }

    /** The sum of the heap pools' peaks since {@link #resetPeaks}: at least the peak of the heap in use. */
    private static long peakUsed() {
        long sum = 0;
        for (var pool : ManagementFactory.getMemoryPoolMXBeans()) {
            if (pool.getType() == java.lang.management.MemoryType.HEAP) sum += pool.getPeakUsage().getUsed();
        }
        return sum;
    }

    private static double median(double[] v) {
        double[] s = v.clone();
        Arrays.sort(s);
        return s.length % 2 == 1 ? s[s.length / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
    }
}
