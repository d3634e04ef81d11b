package dev.crt.scene;

import dev.crt.geom.Vec3;

/**
 * The viewpoint: a pinhole when {@code aperture} is 0, else a thin lens of radius aperture/1000
 * focused at {@code focalDistance} along the view direction; or, with a spherical or cylindrical
 * {@code projection}, a 360° view (always a pinhole). Angles in degrees.
 */
public record Camera(
        Vec3 position,
        Vec3 pointing,
        double fov,
        double roll,
        double aperture,
        double focalDistance,
        ApertureShape apertureShape,
        Projection projection,
        SourceSpan span) {

    /** A perspective camera. */
    public Camera(Vec3 position, Vec3 pointing, double fov, double roll, double aperture, double focalDistance,
            ApertureShape apertureShape, SourceSpan span) {
        this(position, pointing, fov, roll, aperture, focalDistance, apertureShape, Projection.PERSPECTIVE, span);
    }

    /** The camera a script without one gets: at (0,0,-5) looking at the origin. */
    public static final Camera DEFAULT = new Camera(new Vec3(0, 0, -5), Vec3.ZERO, 60, 0, 0, 5,
            ApertureShape.CIRCLE, SourceSpan.NONE);
}
