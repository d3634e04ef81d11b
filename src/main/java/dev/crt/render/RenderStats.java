package dev.crt.render;

/** What a render did: rays by kind and time per phase, in nanoseconds. */
public record RenderStats(
        long primaryRays,
        long shadowRays,
        long reflectedRays,
        long refractedRays,
        long buildNanos,
        long renderNanos) {
    public long totalRays() { return primaryRays + shadowRays + reflectedRays + refractedRays; }

    /** Millions of rays of every kind per second of render time. */
    public double megaRaysPerSecond() {
        return renderNanos == 0 ? 0 : totalRays() / (renderNanos / 1e9) / 1e6;
    }
}
