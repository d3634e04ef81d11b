package dev.crt.render;

import dev.crt.geom.Sobol;
import dev.crt.scene.Sampler;
import dev.crt.scene.Settings;
import java.util.function.BooleanSupplier;

/**
 * The colour of one pixel: the mean of its samples, each a sub-pixel position and, with a lens,
 * a lens point. Every sampler spends the same budget, n² sub-pixel samples × m lens samples
 * (the adaptive one at most that), and draws its randomness from generators seeded by the pixel's
 * coordinates and the scene seed, so a pixel is the same whatever thread renders it.
 */
final class PixelSampler {
    /** The adaptive sampler's first pass takes this many samples per pixel (or its whole budget, if smaller). */
    static final int PILOT = 4;
    /** The Sobol samplers ask whether to stop once every STOP_RUN + 1 = 64 samples. */
    private static final int STOP_RUN = 63;

    private final Tracer tracer;
    /** The 2015 model, or null for CRT's own. */
    private final OriginalShading original;
    /**
     * Where in its cell of the n×n grid a grid sample lies: the centre (CRT), or the cell's top-left
     * corner, as the 2015 program placed them when n > 1.
     */
    private final double gridOffset;
    private final CameraRays camera;
    private final Sampler kind;
    private final int grid, lensSamples, depth, budget;
    private final long seed;
    private final double weight;
    /** The adaptive target: the standard error of the pixel's mean in 8-bit levels, squared. */
    private final double noise2;
    private final double inverseGamma;
    private final PixelRandom random = new PixelRandom();
    private final double[] origin = new double[3];
    private final double[] direction = new double[3];
    private final double[] lens = new double[2];
    /** The sub-pixel's part of its lens rays, {@link CameraRays#aim}. */
    private final double[] aim = new double[CameraRays.AIM];
    /** Whether the pixel being sampled takes its block's list of candidates (asked once a pixel). */
    private boolean blockRay;
    /** The jittered sampler's lens strata, in random orders: its Latin hypercube. */
    private final int[] lensStrataU, lensStrataV;
    private final int pilotCount, width, height;
    /** A sample's share of a pixel's width, 1/supersampling: its ray cone is that much narrower. */
    private final double spreadShare;
    /** Per pixel, the adaptive pilot's largest channel variance; shared by the render's samplers. */
    private final float[] pilotVariance;

    /** Whether camera rays take their block's list of candidates (a perspective camera, CRT's model, a BVH). */
    private final boolean blocks;
    /** Whether a pixel stops once its sum reaches 1 ({@link Tracer#saturating}). */
    private final boolean saturating;

    /** Asked between rows of sub-pixels (and runs of samples), so that a cancel is prompt however many samples a pixel takes. */
    private final BooleanSupplier stop;

    /**
     * A sampler for one render thread; {@code pilotVariance} (one value per pixel, shared by all the
     * render's samplers) is needed by the adaptive sampler only.
     */
    PixelSampler(Tracer tracer, OriginalShading original, CameraRays camera, Settings settings, float[] pilotVariance,
            BooleanSupplier stop) {
        this.tracer = tracer;
        this.stop = stop;
        this.original = original;
        gridOffset = original != null && settings.supersampling() > 1 ? 0 : 0.5;
        this.camera = camera;
        kind = settings.effectiveSampler();
        grid = settings.supersampling();
        lensSamples = camera.hasLens() ? settings.dofSamples() : 1;
        depth = settings.effectiveRecursionDepth();
        seed = settings.seed();
        budget = grid * grid * lensSamples;
        weight = 1.0 / ((double) grid * grid * lensSamples);
        noise2 = settings.noise() * settings.noise();
        inverseGamma = 1 / settings.outputGamma();
        int strata = kind == Sampler.JITTERED && camera.hasLens() ? budget : 0;
        lensStrataU = new int[strata];
        lensStrataV = new int[strata];
        pilotCount = Math.min(PILOT, budget);
        width = settings.width();
        height = settings.height();
        spreadShare = 1.0 / grid;
        this.pilotVariance = pilotVariance;
        blocks = tracer.candidates != null && camera.framed() && original == null;
        saturating = tracer.saturating;
    }

    /** Whether camera rays take their block's list of candidates: pixels are best visited block by block. */
    boolean blocks() {
        return blocks;
    }

    /** Writes the linear colour of pixel (i, j) into {@code out[0..2]}; a stopped pixel's colour is partial and unused. */
    void pixel(int i, int j, double[] out) {
        Tracer t = tracer;
        t.accR = 0;
        t.accG = 0;
        t.accB = 0;
        t.startPixel(i, j, seed, 0);
        if (blocks) blockRay = t.candidates.block(camera, i, j);
        if (!Features.SAMPLERS) {
            grid(i, j);
        } else {
            switch (kind) {
                case GRID -> grid(i, j);
                case JITTERED -> jittered(i, j);
                case SOBOL -> sobol(i, j);
                case ADAPTIVE -> pilot(i, j);
            }
        }
        out[0] = t.accR;
        out[1] = t.accG;
        out[2] = t.accB;
        if (Features.ORIGINAL && original != null) truncate(out);
    }

    /**
     * The 2015 program wrote min(255, trunc(c·255)) and clamped negatives to 0: each channel
     * becomes that level's exact value, which the writers (at gamma 1) turn back into the level.
     */
    private static void truncate(double[] out) {
        for (int c = 0; c < 3; c++) {
            double v = out[c];
            out[c] = v > 0 ? Math.min(255, Math.floor(v * 255)) / 255 : v < 0 ? 0 : v;
        }
    }

    /** Wave 1's sampler, unchanged: the centres of an n×n grid, lens points in sequence from the pixel's generator. */
    private void grid(int i, int j) {
        if (camera.hasLens()) random.seed(i, j, seed);
        for (int b = 0; b < grid; b++) {
            if (b > 0 && stop.getAsBoolean()) return;
            double sy = (b + gridOffset) / grid;
            for (int a = 0; a < grid; a++) {
                double sx = (a + gridOffset) / grid;
                if (saturating && tracer.saturated()) return;
                if (!camera.hasLens()) {
                    trace(i, j, sx, sy, weight);
                    continue;
                }
                camera.aim(i, j, sx, sy, aim);
                for (int k = 0; k < lensSamples; k++) {
                    if (saturating && k > 0 && tracer.saturated()) return;
                    throughLens(random.next(), random.next(), random.next(), weight);
                }
            }
        }
    }

    /**
     * The n×n cells of the pixel each take m samples, every one at its own uniform point in its
     * cell (so the pixel's area is sampled n²·m times, not only n² with a lens); the lens's first
     * two coordinates each take one of the pixel's n²·m strata, in two random orders (a Latin
     * hypercube over the whole budget).
     */
    private void jittered(int i, int j) {
        random.seed(i, j, seed);
        if (camera.hasLens()) {
            shuffle(lensStrataU);
            shuffle(lensStrataV);
        }
        int k = 0;
        for (int b = 0; b < grid; b++) {
            if (b > 0 && stop.getAsBoolean()) return;
            for (int a = 0; a < grid; a++) {
                if (saturating && tracer.saturated()) return;
                if (!camera.hasLens()) {
                    trace(i, j, (a + random.next()) / grid, (b + random.next()) / grid, weight);
                    continue;
                }
                for (int l = 0; l < lensSamples; l++, k++) {
                    if (saturating && l > 0 && tracer.saturated()) return;
                    double sx = (a + random.next()) / grid, sy = (b + random.next()) / grid;
                    double u1 = (lensStrataU[k] + random.next()) / budget, u2 = (lensStrataV[k] + random.next()) / budget;
                    traceThroughLens(i, j, sx, sy, u1, u2, random.next(), weight);
                }
            }
        }
    }

    /** A uniformly random order of 0 … length − 1 (Fisher–Yates). */
    private void shuffle(int[] s) {
        for (int k = 0; k < s.length; k++) s[k] = k;
        for (int k = s.length - 1; k > 0; k--) {
            int r = (int) (random.next() * (k + 1));
            int x = s[k];
            s[k] = s[r];
            s[r] = x;
        }
    }

    /** The budget's points of the scrambled Sobol sequence: dimensions 0–1 in the pixel, 2–4 on the lens. */
    private void sobol(int i, int j) {
        long h = PixelRandom.pixelHash(i, j, seed);
        for (int k = 0; k < budget; k++) {
            if ((k & STOP_RUN) == STOP_RUN && stop.getAsBoolean()) return;
            if (saturating && tracer.saturated()) return;
            sobolSample(i, j, k, h, weight);
        }
    }

    private void sobolSample(int i, int j, int k, long h, double w) {
        double sx = Sobol.sample(k, 0, dimensionSeed(h, 0)), sy = Sobol.sample(k, 1, dimensionSeed(h, 1));
        if (!camera.hasLens()) {
            trace(i, j, sx, sy, w);
        } else {
            traceThroughLens(i, j, sx, sy, Sobol.sample(k, 2, dimensionSeed(h, 2)), Sobol.sample(k, 3, dimensionSeed(h, 3)),
                    Sobol.sample(k, 4, dimensionSeed(h, 4)), w);
        }
    }

    private static int dimensionSeed(long pixelHash, int dim) {
        return (int) (PixelRandom.mix(pixelHash + dim * 0x9E3779B97F4A7C15L) >>> 32);
    }

    /**
     * The adaptive sampler's first pass: the first {@link #pilotCount} Sobol samples, whose mean
     * is the pixel's colour for now and whose spread (the largest sample variance of the three
     * channels, in 8-bit levels after the gamma encoding, by Welford's running sums) goes to
     * {@code pilotVariance} for the second pass to judge this pixel and its neighbours by.
     */
    private void pilot(int i, int j) {
        Tracer t = tracer;
        long h = PixelRandom.pixelHash(i, j, seed);
        double sumR = 0, sumG = 0, sumB = 0;
        double meanR = 0, meanG = 0, meanB = 0, m2R = 0, m2G = 0, m2B = 0;
        int p = pilotCount;
        for (int n = 1; n <= p; n++) {
            t.accR = 0;
            t.accG = 0;
            t.accB = 0;
            sobolSample(i, j, n - 1, h, 1);
            sumR += t.accR;
            sumG += t.accG;
            sumB += t.accB;
            double lr = level(t.accR), lg = level(t.accG), lb = level(t.accB);
            double dr = lr - meanR, dg = lg - meanG, db = lb - meanB;
            meanR += dr / n;
            meanG += dg / n;
            meanB += db / n;
            m2R += dr * (lr - meanR);
            m2G += dg * (lg - meanG);
            m2B += db * (lb - meanB);
        }
        pilotVariance[j * width + i] = p < 2 ? 0f : (float) (Math.max(m2R, Math.max(m2G, m2B)) / (p - 1));
        t.accR = sumR / p;
        t.accG = sumG / p;
        t.accB = sumB / p;
    }

    /**
     * The adaptive sampler's second pass: how many samples pixel (i, j) needs for the standard
     * error of its mean, sqrt(variance / n), to fall to the noise target, with the variance taken
     * as the largest of its 3×3 neighbourhood's pilots (an edge that the pilot samples of one pixel
     * all missed is seen by its neighbours), rounded up to a power of two (where the Sobol points
     * are evenly spread) and capped by the budget. When more than the pilot are needed, the rest
     * are traced and merged with the pilot's mean {@code pilotMean}; returns false when the pilot
     * was enough and the pixel stays as it is.
     */
    boolean refine(int i, int j, float[] pilotMean, double[] out) {
        double v = 0;
        for (int y = Math.max(0, j - 1), y1 = Math.min(height - 1, j + 1); y <= y1; y++) {
            for (int x = Math.max(0, i - 1), x1 = Math.min(width - 1, i + 1); x <= x1; x++) {
                v = Math.max(v, pilotVariance[y * width + x]);
            }
        }
        if (v <= noise2 * pilotCount) return false;
        double wanted = Math.ceil(v / noise2);
        int n = wanted >= budget ? budget : Math.min(budget, Integer.highestOneBit((int) wanted - 1) << 1);
        if (n <= pilotCount) return false;
        Tracer t = tracer;
        t.accR = 0;
        t.accG = 0;
        t.accB = 0;
        t.startPixel(i, j, seed, 1);
        if (blocks) blockRay = t.candidates.block(camera, i, j);
        long h = PixelRandom.pixelHash(i, j, seed);
        for (int k = pilotCount; k < n; k++) {
            if ((k & STOP_RUN) == STOP_RUN && stop.getAsBoolean()) break;
            sobolSample(i, j, k, h, 1);
        }
        out[0] = (pilotMean[0] * (double) pilotCount + t.accR) / n;
        out[1] = (pilotMean[1] * (double) pilotCount + t.accG) / n;
        out[2] = (pilotMean[2] * (double) pilotCount + t.accB) / n;
        if (Features.ORIGINAL && original != null) truncate(out);
        return true;
    }

    /** A linear value as the 8-bit level it would be written as (without rounding). */
    private double level(double c) {
        double x = c <= 0 ? 0 : c >= 1 ? 1 : c;
        return 255 * (inverseGamma == 1 ? x : Math.pow(x, inverseGamma));
    }

    private void trace(int i, int j, double sx, double sy, double w) {
        camera.direction(i, j, sx, sy, direction);
        tracer.primaryRays++;
        if (blocks) tracer.blockRay = blockRay;
        if (Features.TEXTURES && tracer.footprints) tracer.spread = camera.spread(direction) * spreadShare;
        if (Features.ORIGINAL && original != null) {
            original.trace(camera.px, camera.py, camera.pz, direction[0], direction[1], direction[2], depth, 0, w, w, w);
        } else {
            tracer.trace(camera.px, camera.py, camera.pz, direction[0], direction[1], direction[2], depth, w, w, w);
        }
    }

    private void traceThroughLens(int i, int j, double sx, double sy, double u1, double u2, double u3, double w) {
        camera.aim(i, j, sx, sy, aim);
        throughLens(u1, u2, u3, w);
    }

    /** A lens sample from three uniform numbers through the sub-pixel {@link #aim} was last given. */
    private void throughLens(double u1, double u2, double u3, double w) {
        camera.aperture.sample(u1, u2, u3, lens);
        camera.throughLens(aim, lens[0], lens[1], origin, direction);
        tracer.primaryRays++;
        if (blocks) tracer.blockRay = blockRay;
        if (Features.TEXTURES && tracer.footprints) tracer.spread = camera.spread(direction) * spreadShare;
        if (Features.ORIGINAL && original != null) {
            original.trace(origin[0], origin[1], origin[2], direction[0], direction[1], direction[2], depth, 0, w, w, w);
        } else {
            tracer.trace(origin[0], origin[1], origin[2], direction[0], direction[1], direction[2], depth, w, w, w);
        }
    }
}
