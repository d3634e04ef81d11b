package dev.crt.scene;

import java.util.List;

/** Everything about a render that is not geometry: metadata, lights, camera, background, quality. */
public record Settings(
        String title,
        String author,
        String date,
        String notes,
        List<Light> lights,
        Camera camera,
        Background background,
        int supersampling,
        int dofSamples,
        int recursionDepth,
        double gamma,
        int width,
        int height,
        Sampler sampler,
        long seed,
        double noise) {

    /** The adaptive sampler's default target: the standard error of a pixel's mean, in 8-bit levels. */
    public static final double DEFAULT_NOISE = 0.5;

    public Settings {
        lights = List.copyOf(lights);
    }

    /** Settings with the grid sampler, scene seed 0 and the default noise target. */
    public Settings(String title, String author, String date, String notes, List<Light> lights, Camera camera,
            Background background, int supersampling, int dofSamples, int recursionDepth, double gamma, int width,
            int height) {
        this(title, author, date, notes, lights, camera, background, supersampling, dofSamples, recursionDepth, gamma,
                width, height, Sampler.GRID, 0, DEFAULT_NOISE);
    }

    public static final Settings DEFAULT = new Settings("", "", "", "", List.of(), Camera.DEFAULT,
            Background.BLACK, 1, 1, 5, 1, 800, 600);

    public Settings withSize(int w, int h) {
        return new Settings(title, author, date, notes, lights, camera, background, supersampling,
                dofSamples, recursionDepth, gamma, w, h, sampler, seed, noise);
    }

    public Settings withSampling(int ss, int dof) {
        return new Settings(title, author, date, notes, lights, camera, background, ss, dof,
                recursionDepth, gamma, width, height, sampler, seed, noise);
    }

    /** These settings with another sampler and adaptive noise target (in 8-bit levels). */
    public Settings withSampler(Sampler s, double noiseTarget) {
        return new Settings(title, author, date, notes, lights, camera, background, supersampling,
                dofSamples, recursionDepth, gamma, width, height, s, seed, noiseTarget);
    }
}
