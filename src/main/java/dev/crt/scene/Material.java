package dev.crt.scene;

/**
 * How a surface shades: Phong terms, mirror reflection, transparency with refraction, emission,
 * and (second wave) Fresnel weights for reflection and refraction, Beer's-law absorption inside, and
 * a {@code texture} (or null) that replaces {@code color}, and the {@link Finish} of the other
 * channels' textures, bump map, glossiness and shading model.
 */
public record Material(
        Rgb color,
        double diffuse,
        double specular,
        double shininess,
        double reflectivity,
        double transparency,
        double ior,
        Rgb emission,
        boolean diffuseGiven,
        boolean fresnel,
        Rgb absorption,
        Texture texture,
        Finish finish) {

    /** A material whose only texture, if any, is on {@code color}. */
    public Material(Rgb color, double diffuse, double specular, double shininess, double reflectivity,
            double transparency, double ior, Rgb emission, boolean diffuseGiven, boolean fresnel, Rgb absorption,
            Texture texture) {
        this(color, diffuse, specular, shininess, reflectivity, transparency, ior, emission, diffuseGiven, fresnel,
                absorption, texture, Finish.NONE);
    }

    /** A material of one plain colour. */
    public Material(Rgb color, double diffuse, double specular, double shininess, double reflectivity,
            double transparency, double ior, Rgb emission, boolean diffuseGiven, boolean fresnel, Rgb absorption) {
        this(color, diffuse, specular, shininess, reflectivity, transparency, ior, emission, diffuseGiven, fresnel,
                absorption, null);
    }

    /** A material of wave 1's attributes, without Fresnel weights or absorption. */
    public Material(Rgb color, double diffuse, double specular, double shininess, double reflectivity,
            double transparency, double ior, Rgb emission, boolean diffuseGiven) {
        this(color, diffuse, specular, shininess, reflectivity, transparency, ior, emission, diffuseGiven, false, Rgb.BLACK);
    }

    /**
     * A material whose {@code diffuse} counts as given: the 2015 model then uses it as it is, where
     * it would otherwise use 1 − reflectivity.
     */
    public Material(Rgb color, double diffuse, double specular, double shininess, double reflectivity,
            double transparency, double ior, Rgb emission) {
        this(color, diffuse, specular, shininess, reflectivity, transparency, ior, emission, true);
    }

    public static final Material DEFAULT = new Material(Rgb.GREY, 1, 0, 30, 0, 0, 1, Rgb.BLACK, false);

    /** The diffuse factor of the 2015 model: {@code diffuse} when given, else 1 − reflectivity. */
    public double originalDiffuse() {
        return diffuseGiven ? diffuse : 1 - reflectivity;
    }

    public boolean isOpaque() { return transparency == 0; }
}
