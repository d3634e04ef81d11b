package dev.crt.render;

import java.util.function.BooleanSupplier;

/**
 * The colour of one pixel: the mean over its n×n sub-pixel grid and, with a lens, over m lens
 * samples per sub-pixel, drawn from a generator seeded by the pixel's coordinates.
 */
final class PixelSampler {
    private final Tracer tracer;
    private final CameraRays camera;
    private final int grid, lensSamples, depth;
    private final double weight;
    private final PixelRandom random = new PixelRandom();
    private final double[] origin = new double[3];
    private final double[] direction = new double[3];
    private final double[] lens = new double[2];

    private final BooleanSupplier stop;

    /** {@code stop} is asked between rows of sub-pixels, so that a cancel is prompt however many samples a pixel takes. */
    PixelSampler(Tracer tracer, CameraRays camera, int supersampling, int dofSamples, int recursionDepth,
            BooleanSupplier stop) {
        this.tracer = tracer;
        this.stop = stop;
        this.camera = camera;
        grid = supersampling;
        lensSamples = camera.hasLens() ? dofSamples : 1;
        depth = recursionDepth;
        weight = 1.0 / ((double) grid * grid * lensSamples);
    }

    /** Writes the linear colour of pixel (i, j) into {@code out[0..2]}; a stopped pixel's colour is partial and unused. */
    void pixel(int i, int j, double[] out) {
        Tracer t = tracer;
        t.accR = 0;
        t.accG = 0;
        t.accB = 0;
        if (camera.hasLens()) random.seed(i, j);
        for (int b = 0; b < grid; b++) {
            if (b > 0 && stop.getAsBoolean()) break;
            double sy = (b + 0.5) / grid;
            for (int a = 0; a < grid; a++) {
                double sx = (a + 0.5) / grid;
                if (!camera.hasLens()) {
                    camera.direction(i, j, sx, sy, direction);
                    t.primaryRays++;
                    t.trace(camera.px, camera.py, camera.pz, direction[0], direction[1], direction[2], depth,
                            weight, weight, weight);
                    continue;
                }
                for (int k = 0; k < lensSamples; k++) {
                    camera.direction(i, j, sx, sy, direction);
                    camera.aperture.sample(random.next(), random.next(), random.next(), lens);
                    camera.throughLens(lens[0], lens[1], origin, direction);
                    t.primaryRays++;
                    t.trace(origin[0], origin[1], origin[2], direction[0], direction[1], direction[2], depth,
                            weight, weight, weight);
                }
            }
        }
        out[0] = t.accR;
        out[1] = t.accG;
        out[2] = t.accB;
    }
}
