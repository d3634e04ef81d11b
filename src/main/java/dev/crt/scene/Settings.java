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
        int height) {

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
    }

    public static final Settings DEFAULT = new Settings("", "", "", "", List.of(), Camera.DEFAULT,
            Background.BLACK, 1, 1, 5, 1, 800, 600);

    public Settings withSize(int w, int h) {
        return new Settings(title, author, date, notes, lights, camera, background, supersampling,
                dofSamples, recursionDepth, gamma, w, h);
    }

    public Settings withSampling(int ss, int dof) {
        return new Settings(title, author, date, notes, lights, camera, background, ss, dof,
                recursionDepth, gamma, width, height);
    }
}
