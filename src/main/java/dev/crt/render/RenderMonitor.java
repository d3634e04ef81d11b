package dev.crt.render;

import dev.crt.image.FrameBuffer;

/** Watches a render: receives progress and finished tiles, and can ask it to stop. Called from render threads. */
public interface RenderMonitor {
    RenderMonitor NONE = new RenderMonitor() {};

    /** {@code done} of {@code total} pixels are finished. */
    default void progress(long done, long total) {}

    /**
     * The pixels of {@code image} in [x0, x1) × [y0, y1) have their values of this pass. Called once
     * per tile and pass (the adaptive sampler's pilot pass, then its refinement; other samplers have
     * one pass), from the thread that rendered it, before the progress that counts the tile; a
     * display copies the tile out.
     */
    default void tileDone(FrameBuffer image, int x0, int y0, int x1, int y1) {}

    /**
     * One render thread traced {@code rays} more rays (of every kind) since its last call: called once
     * per tile and pass, before {@link #tileDone}, so a chart can show the throughput while the render
     * runs. Summed over a finished render, these are {@link RenderStats#totalRays()}.
     */
    default void raysTraced(long rays) {}

    /** Polled often; a render that sees true stops within a fraction of a second. */
    default boolean isCancelled() { return false; }
}
