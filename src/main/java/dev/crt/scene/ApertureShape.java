package dev.crt.scene;

/** The shape of a thin-lens aperture: a disc or a regular polygon inscribed in the unit disc. */
public enum ApertureShape {
    CIRCLE(0), TRIANGLE(3), SQUARE(4), PENTAGON(5), HEXAGON(6), OCTAGON(8);

    private final int sides;

    ApertureShape(int sides) { this.sides = sides; }

    /** Number of polygon sides, 0 for the circle. */
    public int sides() { return sides; }

    /** The name scripts use: "circle", "triangle", … */
    public String scriptName() { return name().toLowerCase(java.util.Locale.ROOT); }
}
