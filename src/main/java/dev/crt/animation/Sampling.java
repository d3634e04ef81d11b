package dev.crt.animation;

import dev.crt.scene.Settings;
import java.util.Locale;

/** Refuses, before any work, a sampling that could not finish: too many rays per pixel or per image. */
public final class Sampling {
    private Sampling() {}

    /** Fails with a usage error naming the figure when {@code s} asks for more rays than can be traced. */
    public static void check(Settings s) throws FrameFailure {
        long grid = (long) s.supersampling() * s.supersampling();
        long perPixel = grid * (s.camera().aperture() > 0 ? s.dofSamples() : 1);
        if (perPixel > Settings.MAX_SAMPLES_PER_PIXEL) {
            throw new FrameFailure(FrameFailure.Kind.SETTINGS, String.format(Locale.ROOT,
                    "supersampling %d with %d lens samples is %,d camera rays per pixel, more than the %,d that"
                            + " can finish: lower --supersampling or --dof-samples",
                    s.supersampling(), s.dofSamples(), perPixel, Settings.MAX_SAMPLES_PER_PIXEL));
        }
        long perImage = perPixel * s.width() * s.height();
        if (perImage > Settings.MAX_SAMPLES_PER_IMAGE) {
            throw new FrameFailure(FrameFailure.Kind.SETTINGS, String.format(Locale.ROOT,
                    "%d×%d pixels at %,d camera rays each is %,d rays, more than the %,d that can finish in a day:"
                            + " lower the size or the sampling",
                    s.width(), s.height(), perPixel, perImage, Settings.MAX_SAMPLES_PER_IMAGE));
        }
    }
}
