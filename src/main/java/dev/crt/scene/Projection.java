package dev.crt.scene;

/** How the camera maps pixels to directions: a pinhole (or thin lens), a 360° equirectangular sphere, or a 360° cylinder. */
public enum Projection {
    PERSPECTIVE("perspective"), SPHERICAL("spherical"), CYLINDRICAL("cylindrical");

    private final String scriptName;

    Projection(String scriptName) { this.scriptName = scriptName; }

    /** The name scripts use for it. */
    public String scriptName() { return scriptName; }
}
