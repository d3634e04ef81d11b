package dev.crt.render;

import dev.crt.geom.Vec3;
import dev.crt.lang.CompileOptions;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import dev.crt.scene.Background;
import dev.crt.scene.Scene;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;

/**
 * What one step of the BVH walk costs, and how much of it is the processor guessing the walk's
 * branches wrong: mirror rays of a scene (camera rays through random points of the image,
 * reflected where they hit) walked through its BVH from the root with no far end, no item
 * tested, in three sets of the same size: every ray its own, 64 rays over and over, and one ray
 * over and over. The steps (inner nodes opened) are counted, so each set reports nanoseconds a
 * step. Compiled against the jar (it lives in the renderer's package to reach the walker):
 *
 * <pre>
 * javac -cp target/crt.jar -d /tmp/mirrorwalk bench/tools/MirrorWalk.java
 * java -Dcrt.assets=DIR -cp /tmp/mirrorwalk:target/crt.jar dev.crt.render.MirrorWalk SCENE.crt [RAYS]
 * </pre>
 */
public class MirrorWalk {
    public static void main(String[] a) throws Exception {
        Scene scene = CrtCompiler.compile(Source.of(a[0], Files.readString(Path.of(a[0]))), CompileOptions.DEFAULT).scene();
        if (scene == null) throw new IllegalArgumentException(a[0] + " does not compile");
        int n = a.length > 1 ? Integer.parseInt(a[1]) : 200_000;
        SceneGeometry g = new SceneGeometry(scene.entities());
        if (g.bvh == null) throw new IllegalArgumentException(a[0] + " has too few items for a BVH");
        Tracer tracer = new Tracer(g, new Lights(List.of()), new BackgroundShader(Background.BLACK, 1));
        int w = 800, h = 600;
        CameraRays camera = new CameraRays(scene.settings().camera(), w, h);
        double[] rays = mirrorRays(g, tracer, camera, scene.settings().camera().position(), w, h, n);
        BvhWalker walker = new BvhWalker(g.bvh.depth + 2);
        Ray ray = new Ray();
        // The single ray: the first that opens at least as many nodes as the rays on average.
        long all = 0;
        int[] own = new int[n];
        for (int i = 0; i < n; i++) {
            int before = walker.nearestSteps;
            walk(walker, g.bvh, ray, rays, i);
            all += own[i] = walker.nearestSteps - before;
        }
        int one = 0;
        while (own[one] * (long) n < all) one++;
        double[][] sets = {rays, repeat(rays, 0, 64), repeat(rays, one, 1)};
        String[] names = {"every ray its own", "64 rays repeated", "one ray repeated"};
        double[][] ns = new double[3][9];
        long[] steps = new long[3];
        for (int round = -3; round < 9; round++) {
            for (int s = 0; s < 3; s++) {
                double[] r = sets[s];
                int before = walker.nearestSteps;
                long t0 = System.nanoTime();
                int leaves = 0;
                for (int i = 0; i < n; i++) leaves += walk(walker, g.bvh, ray, r, i);
                long t = System.nanoTime() - t0;
                steps[s] = walker.nearestSteps - before;
                if (leaves < 0) throw new AssertionError();
                if (round >= 0) ns[s][round] = t / (double) steps[s];
            }
        }
        System.out.printf(Locale.ROOT, "%s: %d mirror rays, a tree of %d nodes, depth %d%n", a[0], n, g.bvh.nodeCount, g.bvh.depth);
        for (int s = 0; s < 3; s++) {
            double[] t = ns[s].clone();
            Arrays.sort(t);
            System.out.printf(Locale.ROOT, "%-18s %5.1f steps a ray   %5.1f ns a step (median of 9; fastest %.1f)%n", names[s],
                    steps[s] / (double) n, t[4], t[0]);
        }
    }

    /** n mirror rays (origin, direction) of pinhole camera rays through random points of a w × h image that hit something. */
    private static double[] mirrorRays(SceneGeometry g, Tracer tracer, CameraRays camera, Vec3 o, int w, int h, int n) {
        SplittableRandom r = new SplittableRandom(7);
        double[] out = new double[6 * n], d = new double[3];
        SurfacePoint p = new SurfacePoint();
        Tracer t = tracer;
        for (int k = 0, tries = 0; k < n; tries++) {
            if (tries > 100 * n) throw new IllegalArgumentException("too few camera rays hit anything");
            camera.direction(r.nextInt(w), r.nextInt(h), r.nextDouble(), r.nextDouble(), d);
            if (!t.closestHit(o.x(), o.y(), o.z(), d[0], d[1], d[2], Double.POSITIVE_INFINITY)) continue;
            g.shapes.surface(t.hit.shape, t.hit.face, t.hit.t, t.ray, p);
            double nx = p.nx, ny = p.ny, nz = p.nz, dn = d[0] * nx + d[1] * ny + d[2] * nz;
            if (dn > 0) {
                nx = -nx;
                ny = -ny;
                nz = -nz;
                dn = -dn;
            }
            double off = Tracer.OFFSET * Math.max(Math.max(Math.abs(p.px), Math.abs(p.py)), Math.max(Math.abs(p.pz), g.shapes.scale[t.hit.shape]));
            out[6 * k] = p.px + off * nx;
            out[6 * k + 1] = p.py + off * ny;
            out[6 * k + 2] = p.pz + off * nz;
            out[6 * k + 3] = d[0] - 2 * dn * nx;
            out[6 * k + 4] = d[1] - 2 * dn * ny;
            out[6 * k + 5] = d[2] - 2 * dn * nz;
            k++;
        }
        return out;
    }

    /** Walks ray i of {@code r} from the root with no far end; returns the leaves it passed. */
    private static int walk(BvhWalker walker, Bvh bvh, Ray ray, double[] r, int i) {
        ray.set(r[6 * i], r[6 * i + 1], r[6 * i + 2], r[6 * i + 3], r[6 * i + 4], r[6 * i + 5]);
        if (!walker.start(bvh, ray, 0, Double.POSITIVE_INFINITY)) return 0;
        int leaves = 0;
        while (walker.nextNearest(Double.POSITIVE_INFINITY) != BvhWalker.END) leaves++;
        return leaves;
    }

    /** Rays first … first + m − 1 of {@code rays}, over and over, as many as {@code rays} holds. */
    private static double[] repeat(double[] rays, int first, int m) {
        double[] out = new double[rays.length];
        for (int i = 0; i < out.length; i += 6) System.arraycopy(rays, 6 * (first + (i / 6) % m), out, i, 6);
        return out;
    }
}
