package dev.crt.cli;

import dev.crt.render.RenderStats;
import java.io.PrintWriter;
import java.util.Locale;

/** What the frames of an animate run cost, summed over frames; frames on several workers add up safely. */
final class AnimationTotals {
    private long frames;
    private long compileNanos;
    private long primary;
    private long shadow;
    private long reflected;
    private long refracted;
    private long buildNanos;
    private long renderNanos;
    private long writeNanos;

    synchronized void add(long compile, FrameJob.Outcome outcome) {
        RenderStats s = outcome.stats();
        frames++;
        compileNanos += compile;
        primary += s.primaryRays();
        shadow += s.shadowRays();
        reflected += s.reflectedRays();
        refracted += s.refractedRays();
        buildNanos += s.buildNanos();
        renderNanos += s.renderNanos();
        writeNanos += outcome.writeNanos();
    }

    synchronized long frames() { return frames; }

    /**
     * The {@code --stats} table: the render command's table over all frames, then frame counts,
     * the wall-clock time and the share of frame time spent outside tracing (compile, BVH, write).
     */
    synchronized void print(PrintWriter out, int skipped, int failed, long wallNanos) {
        FrameJob.Outcome sum = new FrameJob.Outcome(
                new RenderStats(primary, shadow, reflected, refracted, buildNanos, renderNanos), writeNanos);
        out.println("times and rays summed over " + frames + (frames == 1 ? " frame" : " frames"));
        StatsReport.print(out, compileNanos, sum);
        long frameNanos = compileNanos + buildNanos + renderNanos + writeNanos;
        out.println("frames");
        out.printf(Locale.ROOT, "  %-10s %14d%n", "rendered", frames);
        out.printf(Locale.ROOT, "  %-10s %14d%n", "skipped", skipped);
        out.printf(Locale.ROOT, "  %-10s %14d%n", "failed", failed);
        out.printf(Locale.ROOT, "  %-10s %14.3f s%n", "wall clock", wallNanos / 1e9);
        out.printf(Locale.ROOT, "  %-10s %14.2f frames/s%n", "speed", framesPerSecond(frames, wallNanos));
        out.printf(Locale.ROOT, "  %-10s %14.1f %% (compile, bvh build and write of frame time)%n", "overhead",
                frameNanos == 0 ? 0 : 100.0 * (frameNanos - renderNanos) / frameNanos);
    }

    static double framesPerSecond(long frames, long wallNanos) { return wallNanos == 0 ? 0 : frames / (wallNanos / 1e9); }
}
