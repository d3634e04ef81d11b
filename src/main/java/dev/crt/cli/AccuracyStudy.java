package dev.crt.cli;

import dev.crt.image.FrameBuffer;
import dev.crt.image.ImageMetrics;
import dev.crt.render.RenderMonitor;
import dev.crt.render.RenderStats;
import dev.crt.render.Renderer;
import dev.crt.scene.Sampler;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import java.util.ArrayList;
import java.util.List;

/**
 * Error against time for a scene: each sampler at each sample budget, rendered and compared with a
 * converged reference by RMSE and SSIM (both on the 8-bit levels the user would see).
 */
final class AccuracyStudy {
    /** One render of the study. */
    record Point(Sampler sampler, int samplesPerPixel, int supersampling, int dofSamples, double seconds,
            long primaryRays, long totalRays, double rmse, double ssim, boolean paretoRmse, boolean paretoSsim) {
        Point pareto(boolean rmseFront, boolean ssimFront) {
            return new Point(sampler, samplesPerPixel, supersampling, dofSamples, seconds, primaryRays, totalRays, rmse,
                    ssim, rmseFront, ssimFront);
        }
    }

    /** What is being told while the study runs. */
    interface Listener {
        void rendering(String what);

        void measured(Point p);
    }

    /**
     * Mixed into the scene seed for the reference, so the reference's Sobol points are not the
     * first points of the sequence the Sobol and adaptive samplers draw: a shared prefix would
     * correlate their errors with the reference's and flatter them.
     */
    static final long REFERENCE_SEED = 0x5EED_0F_2EFL;

    private AccuracyStudy() {}

    /** The scene as the converged reference renders it: Sobol, {@code spp} samples, its own seed. */
    static Scene reference(Scene scene, int spp, double noise) {
        Scene s = withBudget(scene, Sampler.SOBOL, spp, noise);
        return s.withSettings(s.settings().withSeed(s.settings().seed() ^ REFERENCE_SEED));
    }

    /** Whether the scene's camera has a lens (its pixels then take dofsamples as well). */
    static boolean hasLens(Scene scene) {
        return scene.settings().camera().aperture() > 0;
    }

    /**
     * The supersampling n and lens samples m of a budget of {@code spp} samples per pixel: without
     * a lens n² = spp, so spp must be a square; with one, n = 2 when 4 divides spp (else 1) and
     * m = spp / n².
     * @throws IllegalArgumentException for a budget that cannot be split so
     */
    static int[] split(int spp, boolean lens) {
        if (spp < 1) throw new IllegalArgumentException("a budget must be at least 1 sample per pixel, got " + spp);
        if (lens) {
            int n = spp % 4 == 0 ? 2 : 1;
            return new int[] {n, spp / (n * n)};
        }
        int n = (int) Math.round(Math.sqrt(spp));
        if (n * n != spp) {
            throw new IllegalArgumentException("the scene has no depth of field, so each budget must be a square "
                    + "(1, 4, 9, 16…: an n×n grid), got " + spp);
        }
        return new int[] {n, 1};
    }

    static Scene withBudget(Scene scene, Sampler sampler, int spp, double noise) {
        int[] nm = split(spp, hasLens(scene));
        Settings s = scene.settings().withSampling(nm[0], nm[1]).withSampler(sampler, noise);
        return scene.withSettings(s);
    }

    /**
     * Renders every method at every budget (after one unrecorded warm-up render, so the first
     * method does not pay for the JIT) and compares each with {@code reference}.
     */
    static List<Point> run(Scene scene, FrameBuffer reference, List<Sampler> methods, List<Integer> budgets,
            double noise, int threads, RenderMonitor monitor, Listener listener) {
        double gamma = scene.settings().outputGamma();
        int w = scene.settings().width(), h = scene.settings().height();
        double[] ref = ImageMetrics.levels(reference, gamma);
        listener.rendering("warming up");
        Renderer.prepare(withBudget(scene, methods.get(0), budgets.get(0), noise)).render(threads, monitor);
        List<Point> points = new ArrayList<>();
        for (Sampler m : methods) {
            for (int spp : budgets) {
                Scene s = withBudget(scene, m, spp, noise);
                listener.rendering(m.word() + " at " + spp + " spp");
                Renderer r = Renderer.prepare(s);
                FrameBuffer image = r.render(threads, monitor);
                RenderStats st = r.stats();
                double[] levels = ImageMetrics.levels(image, gamma);
                Point p = new Point(m, spp, s.settings().supersampling(), s.settings().dofSamples(),
                        st.renderNanos() / 1e9, st.primaryRays(), st.totalRays(), ImageMetrics.rmse(levels, ref),
                        ImageMetrics.ssim(levels, ref, w, h), false, false);
                points.add(p);
                listener.measured(p);
            }
        }
        return markPareto(points);
    }

    /**
     * Marks the points no other point beats in both time and error: for each, nothing is at least
     * as fast and at least as accurate while strictly better in one of the two.
     */
    static List<Point> markPareto(List<Point> points) {
        List<Point> out = new ArrayList<>();
        for (Point p : points) {
            boolean rmseFront = true, ssimFront = true;
            for (Point q : points) {
                if (q == p) continue;
                if (dominates(q.seconds(), q.rmse(), p.seconds(), p.rmse())) rmseFront = false;
                if (dominates(q.seconds(), 1 - q.ssim(), p.seconds(), 1 - p.ssim())) ssimFront = false;
            }
            out.add(p.pareto(rmseFront, ssimFront));
        }
        return out;
    }

    private static boolean dominates(double t1, double e1, double t2, double e2) {
        return t1 <= t2 && e1 <= e2 && (t1 < t2 || e1 < e2);
    }
}
