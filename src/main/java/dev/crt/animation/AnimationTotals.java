package dev.crt.animation;

import dev.crt.render.RenderStats;

/** What the frames of an animation run cost, summed over frames; frames on several workers add up safely. */
public final class AnimationTotals {
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

    public synchronized long frames() { return frames; }

    public synchronized long compileNanos() { return compileNanos; }

    /** The renderer's counts and times and the write time, summed over the frames. */
    public synchronized FrameJob.Outcome sum() {
        return new FrameJob.Outcome(new RenderStats(primary, shadow, reflected, refracted, buildNanos, renderNanos), writeNanos);
    }

    public static double framesPerSecond(long frames, long wallNanos) { return wallNanos == 0 ? 0 : frames / (wallNanos / 1e9); }
}
