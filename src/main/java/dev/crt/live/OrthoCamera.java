package dev.crt.live;

import dev.crt.geom.Aabb;
import dev.crt.geom.Vec3;

/** An orthographic viewport's camera: the point at the view's centre and the half height shown, in scene units. */
public record OrthoCamera(Vec3 centre, double halfHeight) {
    /** Shows all of {@code box} (or the unit cube about the origin when it is empty or infinite), with a margin. */
    public static OrthoCamera framing(Aabb box) {
        if (box.isEmpty() || !box.isFinite()) return new OrthoCamera(Vec3.ZERO, 2);
        return new OrthoCamera(box.center(), Math.max(1e-6, 0.6 * box.max().minus(box.min()).length()));
    }

    /** The view along {@code v}'s axis, from outside a sphere of {@code reach} about the centre. */
    public ViewCamera view(Viewport v, double reach) {
        return ViewCamera.orthographic(centre.minus(v.forward.times(reach)), v.forward, v.up, halfHeight);
    }

    /** Moves the centre with the mouse: {@code dx, dy} pixels right and down in a view {@code height} pixels high. */
    public OrthoCamera pan(Viewport v, double dx, double dy, int height) {
        ViewCamera view = view(v, 1);
        double unitsPerPixel = 2 * halfHeight / Math.max(1, height);
        return new OrthoCamera(centre.plus(view.right().times(-dx * unitsPerPixel)).plus(view.up().times(dy * unitsPerPixel)),
                halfHeight);
    }

    public OrthoCamera zoom(double steps) { return new OrthoCamera(centre, halfHeight * Math.pow(1.1, -steps)); }

    /** Grid lines every power of ten that puts between 5 and 50 of them across the view's height. */
    public double gridSpacing() {
        return Math.pow(10, Math.floor(Math.log10(halfHeight / 2.5)));
    }
}
