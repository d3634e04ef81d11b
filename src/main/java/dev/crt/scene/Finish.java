package dev.crt.scene;

/**
 * A material's second-wave extras: textures on the channels other than {@code color} (emission
 * by colour; specular, reflectivity and transparency by luminance), a bump map with its height
 * scale, glossy {@code roughness} with its lobe sample count, and the shading model (Phong, or
 * Gooch with its cool and warm colours and its outline width in pixels). Null textures are plain.
 */
public record Finish(
        Texture emission,
        Texture specular,
        Texture reflectivity,
        Texture transparency,
        Texture bump,
        double bumpScale,
        double roughness,
        int glossySamples,
        ShadingModel model,
        Rgb cool,
        Rgb warm,
        double outline) {

    /** Plain channels, no bump, mirror-sharp, Phong. */
    public static final Finish NONE = new Finish(null, null, null, null, null, 1, 0, 8, ShadingModel.PHONG,
            new Rgb(0, 0, 0.55), new Rgb(0.3, 0.3, 0), 1);

    /** Whether any channel or the bump map has a texture. */
    public boolean textured() {
        return emission != null || specular != null || reflectivity != null || transparency != null || bump != null;
    }
}
