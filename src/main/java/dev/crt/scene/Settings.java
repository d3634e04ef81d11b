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
