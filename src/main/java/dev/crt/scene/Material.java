package dev.crt.scene;

/** How a surface shades: Phong terms, mirror reflection, transparency with refraction, emission. */
public record Material(
        Rgb color,
        double diffuse,
        double specular,
        double shininess,
        double reflectivity,
        double transparency,
        double ior,
        Rgb emission,
        boolean diffuseGiven) {

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
