package dev.crt.live;

import dev.crt.geom.Aabb;
import dev.crt.geom.Vec3;
import dev.crt.scene.Camera;

/**
 * The live view's free perspective camera: it orbits a target point at a distance (yaw about +y,
 * pitch up and down, roll about the view direction), pans the target across the view, zooms by
 * distance and frames boxes. Immutable; every move returns a new camera. Angles in degrees.
 */
public record FreeCamera(Vec3 target, double distance, double yaw, double pitch, double roll, double fov) {
    /** Pitch stays short of straight up or down, where yaw would lose its meaning. */
    static final double MAX_PITCH = 89;

    /** The free camera that sees exactly what {@code c} sees (the lens ignored). */
    public static FreeCamera of(Camera c) {
        Vec3 d = c.pointing().minus(c.position());
        double distance = d.length();
        Vec3 f = d.normalize();
        double pitch = Math.toDegrees(Math.asin(Math.max(-1, Math.min(1, -f.y()))));
        double yaw = Math.toDegrees(Math.atan2(f.x(), f.z()));
        return new FreeCamera(c.pointing(), distance, yaw, pitch, c.roll(), c.fov());
    }

    /** The unit view direction: yaw 0 looks along +z, positive pitch looks down. */
    public Vec3 forward() {
        double y = Math.toRadians(yaw), p = Math.toRadians(pitch);
        return new Vec3(Math.sin(y) * Math.cos(p), -Math.sin(p), Math.cos(y) * Math.cos(p));
    }

    public Vec3 position() { return target.minus(forward().times(distance)); }

    /** The view the renderer draws, with the ray tracer's frame. */
    public ViewCamera view() { return ViewCamera.perspective(position(), forward(), roll, fov); }

    /** This view as a scene camera: position, pointing at the target, fov and roll; pinhole. */
    public Camera toCamera(Camera lensFrom) {
        return new Camera(position(), target, fov, roll, lensFrom.aperture(), lensFrom.focalDistance(),
                lensFrom.apertureShape(), lensFrom.span());
    }

    /** Turns about the target: {@code dYaw} degrees about +y, {@code dPitch} degrees up or down. */
    public FreeCamera orbit(double dYaw, double dPitch) {
        double p = Math.max(-MAX_PITCH, Math.min(MAX_PITCH, pitch + dPitch));
        return new FreeCamera(target, distance, normalise(yaw + dYaw), p, roll, fov);
    }

    /**
     * Moves the target (and the camera with it) across the view so that a point on the target's
     * plane follows the mouse: {@code dx, dy} pixels right and down in a view {@code height} pixels high.
     */
    public FreeCamera pan(double dx, double dy, int height) {
        ViewCamera v = view();
        double unitsPerPixel = 2 * distance * Math.tan(Math.toRadians(fov) / 2) / Math.max(1, height);
        Vec3 move = v.right().times(-dx * unitsPerPixel).plus(v.up().times(dy * unitsPerPixel));
        return new FreeCamera(target.plus(move), distance, yaw, pitch, roll, fov);
    }

    /** Moves towards the target (positive steps) or away, 10% of the distance per step. */
    public FreeCamera zoom(double steps) {
        return new FreeCamera(target, distance * Math.pow(1.1, -steps), yaw, pitch, roll, fov);
    }

    public FreeCamera rolled(double degrees) {
        return new FreeCamera(target, distance, yaw, pitch, normalise(roll + degrees), fov);
    }

    /** Looks at the centre of {@code box} from far enough that its bounding sphere fills the view's height and width. */
    public FreeCamera frame(Aabb box, double aspect) {
        if (box.isEmpty() || !box.isFinite()) return this;
        double radius = Math.max(1e-9, box.max().minus(box.min()).length() / 2);
        double half = Math.toRadians(fov) / 2;
        double narrow = Math.min(half, Math.atan(Math.tan(half) * aspect));
        return new FreeCamera(box.center(), radius / Math.sin(narrow), yaw, pitch, roll, fov);
    }

    private static double normalise(double degrees) {
        double d = degrees % 360;
        if (d > 180) d -= 360;
        if (d <= -180) d += 360;
        return d;
    }
}
