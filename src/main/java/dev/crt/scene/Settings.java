package dev.crt.scene;

import java.util.List;
import java.util.Set;

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
        double noise,
        Shading shading,
        Set<String> given) {

    /** The adaptive sampler's default target: the standard error of a pixel's mean, in 8-bit levels. */
    public static final double DEFAULT_NOISE = 0.5;

    /** The largest n of n×n supersampling: 4,096 samples per pixel. */
    public static final int MAX_SUPERSAMPLING = 64;
    /** The most lens samples per pixel sample. */
    public static final int MAX_DOF_SAMPLES = 4096;
    /** The most camera rays per pixel (n×n times the lens samples): a pixel then takes well under a second. */
    public static final long MAX_SAMPLES_PER_PIXEL = 65_536;
    /** The most camera rays of one image: about a day of rendering at 10 million rays per second. */
    public static final long MAX_SAMPLES_PER_IMAGE = 1L << 40;

    public Settings {
        lights = List.copyOf(lights);
        given = Set.copyOf(given);
    }

    /** The attributes of a Settings block: settings made in code count all of them as given. */
    public static final Set<String> ATTRIBUTES = Set.of("title", "author", "date", "notes", "lights", "camera",
            "background", "supersampling", "dofsamples", "recursiondepth", "gamma", "width", "height", "sampler", "seed",
            "shading");

    /** Settings with the CRT shading model, every attribute counted as given. */
    public Settings(String title, String author, String date, String notes, List<Light> lights, Camera camera,
            Background background, int supersampling, int dofSamples, int recursionDepth, double gamma, int width,
            int height, Sampler sampler, long seed, double noise) {
        this(title, author, date, notes, lights, camera, background, supersampling, dofSamples, recursionDepth, gamma,
                width, height, sampler, seed, noise, Shading.CRT, ATTRIBUTES);
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
                dofSamples, recursionDepth, gamma, w, h, sampler, seed, noise, shading, given);
    }

    public Settings withSampling(int ss, int dof) {
        return new Settings(title, author, date, notes, lights, camera, background, ss, dof,
                recursionDepth, gamma, width, height, sampler, seed, noise, shading, given);
    }

    /** These settings with another sampler, chosen as a script's {@code sampler} would be, and adaptive noise target (in 8-bit levels). */
    public Settings withSampler(Sampler s, double noiseTarget) {
        Set<String> named = new java.util.HashSet<>(given);
        named.add("sampler");
        return new Settings(title, author, date, notes, lights, camera, background, supersampling,
                dofSamples, recursionDepth, gamma, width, height, s, seed, noiseTarget, shading, named);
    }

    /** These settings with another adaptive noise target (in 8-bit levels). */
    public Settings withNoise(double noiseTarget) {
        return new Settings(title, author, date, notes, lights, camera, background, supersampling,
                dofSamples, recursionDepth, gamma, width, height, sampler, seed, noiseTarget, shading, given);
    }

    /**
     * The sampler in force: the one named, else the grid, except with depth of field (an aperture
     * and more than one lens sample), where the grid's four fixed sub-pixel points stop the picture
     * converging and Sobol points reach its error with an eighth of the samples (docs/accuracy.md).
     * The look of CRT 2015 keeps the grid that program used.
     */
    public Sampler effectiveSampler() {
        if (gave("sampler")) return sampler;
        return camera.aperture() > 0 && dofSamples > 1 && shading != Shading.ORIGINAL ? Sampler.SOBOL : Sampler.GRID;
    }

    /** These settings with another scene seed. */
    public Settings withSeed(long newSeed) {
        return new Settings(title, author, date, notes, lights, camera, background, supersampling,
                dofSamples, recursionDepth, gamma, width, height, sampler, newSeed, noise, shading, given);
    }

    /** These settings with another shading model. */
    public Settings withShading(Shading model) {
        return new Settings(title, author, date, notes, lights, camera, background, supersampling,
                dofSamples, recursionDepth, gamma, width, height, sampler, seed, noise, model, given);
    }

    /** Whether the script set attribute {@code name} (the 2015 model's defaults differ where it did not). */
    public boolean gave(String name) {
        return given.contains(name);
    }

    /** The gamma images are written with: the 2015 model ignores {@code gamma}. */
    public double outputGamma() {
        return shading == Shading.ORIGINAL ? 1 : gamma;
    }

    /** The recursion depth in force: the 2015 model's default is 3 where the script gives none. */
    public int effectiveRecursionDepth() {
        return shading == Shading.ORIGINAL && !gave("recursiondepth") ? 3 : recursionDepth;
    }

    /** The background in force: the 2015 model's default is white where the script gives none. */
    public Background effectiveBackground() {
        return shading == Shading.ORIGINAL && !gave("background") ? new SolidBackground(Rgb.WHITE) : background;
    }
}
