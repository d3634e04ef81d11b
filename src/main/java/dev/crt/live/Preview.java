package dev.crt.live;

import dev.crt.image.FrameBuffer;
import dev.crt.scene.Scene;

/**
 * One offscreen frame of a scene through its own camera at its own size: what {@code crt preview}
 * writes and what the alignment tests compare with the ray tracer.
 */
public final class Preview implements AutoCloseable {
    private final GlContext context;
    private final LiveRenderer renderer;

    private Preview(GlContext context, LiveRenderer renderer) {
        this.context = context;
        this.renderer = renderer;
    }

    /** Makes a headless context and the renderer on this thread. */
    public static Preview open() throws GlUnavailableException {
        GlContext context = GlContext.create();
        try {
            return new Preview(context, new LiveRenderer());
        } catch (RuntimeException e) {
            context.close();
            throw e;
        }
    }

    /** The GL version and renderer in use. */
    public String description() { return context.description(); }

    /** Draws {@code scene} from its camera at its settings' size; then read a pass. */
    public void draw(Scene scene) {
        draw(SceneConverter.convert(scene), ViewCamera.of(scene.settings().camera()), scene.settings().width(),
                scene.settings().height());
    }

    void draw(GpuScene gpu, ViewCamera view, int width, int height) {
        renderer.setScene(gpu);
        renderer.resize(width, height);
        renderer.clear();
        renderer.draw(view, 0, 0, width, height, LiveRenderer.Overlay.NONE);
    }

    /** The renderer, for callers that draw their own views. */
    public LiveRenderer renderer() { return renderer; }

    /** Entity index per pixel, −1 for background, rows top to bottom. */
    public int[] ids() { return renderer.readIds(); }

    /** Distance along the unit ray per pixel, +∞ for background. */
    public float[] depth() { return renderer.readDepth(); }

    /** The last drawn picture as a linear image for the image writers, which encode it back to the bytes drawn. */
    public FrameBuffer colourImage(double gamma) {
        int w = renderer.width(), h = renderer.height();
        int[] c = renderer.readColour();
        FrameBuffer image = new FrameBuffer(w, h);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int p = c[y * w + x];
                image.set(x, y, linear((p >> 16) & 255, gamma), linear((p >> 8) & 255, gamma), linear(p & 255, gamma));
            }
        }
        return image;
    }

    private static double linear(int byteValue, double gamma) {
        double v = byteValue / 255.0;
        return gamma == 1 ? v : Math.pow(v, gamma);
    }

    @Override
    public void close() {
        renderer.close();
        context.close();
    }
}
