package dev.crt.live;

import dev.crt.geom.Vec3;
import dev.crt.scene.Camera;

/**
 * What a viewport looks through: a position and an orthonormal frame (forward, right, up, as in
 * rendering-model.md), with either a vertical field of view (perspective) or the half height of
 * the view in scene units (orthographic, rays parallel to forward from the image plane through
 * the position).
 */
public record ViewCamera(Vec3 position, Vec3 forward, Vec3 right, Vec3 up, double fov, boolean orthographic,
        double halfHeight) {

    /** The perspective view of a scene camera, roll included, exactly as the ray tracer builds it. */
    public static ViewCamera of(Camera c) {
        Vec3 f = c.pointing().minus(c.position()).normalize();
        Vec3[] ru = frame(f, c.roll());
        return new ViewCamera(c.position(), f, ru[0], ru[1], c.fov(), false, 0);
    }

    /** A perspective view from {@code position} along {@code forward}, rolled by {@code roll} degrees. */
    public static ViewCamera perspective(Vec3 position, Vec3 forward, double roll, double fov) {
        Vec3 f = forward.normalize();
        Vec3[] ru = frame(f, roll);
        return new ViewCamera(position, f, ru[0], ru[1], fov, false, 0);
    }

    /** An orthographic view from {@code position} along {@code forward}, {@code halfHeight} scene units above and below the centre. */
    public static ViewCamera orthographic(Vec3 position, Vec3 forward, Vec3 up, double halfHeight) {
        Vec3 f = forward.normalize();
        Vec3 r = up.cross(f).normalize();
        return new ViewCamera(position, f, r, f.cross(r), 0, true, halfHeight);
    }

    /** r = (0,1,0) × f (or +x when f is vertical), u = f × r, both turned by {@code roll} about f. */
    static Vec3[] frame(Vec3 f, double roll) {
        Vec3 r = Vec3.Y.cross(f);
        r = r.length() == 0 ? Vec3.X : r.normalize();
        Vec3 u = f.cross(r);
        if (roll != 0) {
            double a = Math.toRadians(roll), cos = Math.cos(a), sin = Math.sin(a);
            Vec3 r2 = r.times(cos).plus(u.times(sin));
            u = u.times(cos).minus(r.times(sin));
            r = r2;
        }
        return new Vec3[] {r, u};
    }

    /** tan(fov/2) for perspective views, the half height for orthographic ones: the shader's scale. */
    public double scale() {
        return orthographic ? halfHeight : Math.tan(Math.toRadians(fov) / 2);
    }

    /**
     * The column-major 4×4 matrix the proxy geometry is projected with: clip x, y from the camera
     * model, z = 0 (depth comes from the ray cast, with depth clamping on), w = distance along forward.
     */
    float[] projection(double aspect) {
        double s = scale();
        double sx = 1 / (s * aspect), sy = 1 / s;
        Vec3 p = position;
        double[] rows = new double[16];
        setRow(rows, 0, right.times(sx), -right.dot(p) * sx);
        setRow(rows, 1, up.times(sy), -up.dot(p) * sy);
        setRow(rows, 2, Vec3.ZERO, 0);
        if (orthographic) setRow(rows, 3, Vec3.ZERO, 1);
        else setRow(rows, 3, forward, -forward.dot(p));
        float[] m = new float[16];
        for (int r = 0; r < 4; r++) {
            for (int c = 0; c < 4; c++) m[c * 4 + r] = (float) rows[r * 4 + c];
        }
        return m;
    }

    private static void setRow(double[] rows, int r, Vec3 v, double w) {
        rows[r * 4] = v.x();
        rows[r * 4 + 1] = v.y();
        rows[r * 4 + 2] = v.z();
        rows[r * 4 + 3] = w;
    }
}
