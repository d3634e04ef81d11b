package dev.crt.render;

import dev.crt.image.FrameBuffer;
import dev.crt.scene.Scene;

/**
 * Renders a Scene as docs/rendering.md defines it. {@link #prepare} builds the acceleration
 * structures once; {@link #render} may then run any number of times.
 */
public final class Renderer {
    private Renderer() {}

    /** Builds what rendering {@code scene} needs (BVH and flattened primitive data). */
    public static Renderer prepare(Scene scene) {
        throw new UnsupportedOperationException("lands with issue 3");
    }

    /**
     * Renders the scene at its Settings' width and height on {@code threads} threads (0: all cores).
     * The result is bit-identical for any thread count.
     * @throws RenderCancelledException when the monitor cancels
     */
    public FrameBuffer render(int threads, RenderMonitor monitor) {
        throw new UnsupportedOperationException("lands with issue 3");
    }

    /** Counts and timings of the last render (and of {@link #prepare}). */
    public RenderStats stats() {
        throw new UnsupportedOperationException("lands with issue 3");
    }
}
