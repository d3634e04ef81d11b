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
        Rgb emission) {

    public static final Material DEFAULT = new Material(Rgb.GREY, 1, 0, 30, 0, 0, 1, Rgb.BLACK);

    public boolean isOpaque() { return transparency == 0; }
}
