package dev.crt.live;

import dev.crt.geom.Vec3;
import dev.crt.scene.ApertureShape;
import dev.crt.scene.Camera;
import java.math.BigDecimal;
import java.math.MathContext;

/** "Copy camera to script": the text of a script's Camera block for a camera. */
public final class CameraScript {
    private CameraScript() {}

    /**
     * {@code Camera { position -> vec3(…) pointing -> vec3(…) fov -> … roll -> … }}, numbers with
     * six significant digits; the lens attributes only when the camera has a lens.
     */
    public static String cameraBlock(Camera c) {
        StringBuilder b = new StringBuilder("Camera { position -> ").append(vec(c.position()))
                .append(" pointing -> ").append(vec(c.pointing()))
                .append(" fov -> ").append(number(c.fov()))
                .append(" roll -> ").append(number(c.roll()));
        if (c.aperture() > 0) {
            b.append(" aperture -> ").append(number(c.aperture()))
                    .append(" focaldistance -> ").append(number(c.focalDistance()));
            if (c.apertureShape() != ApertureShape.CIRCLE) {
                b.append(" apertureshape -> \"").append(c.apertureShape().scriptName()).append('"');
            }
        }
        return b.append(" }").toString();
    }

    static String vec(Vec3 v) {
        return "vec3(" + number(v.x()) + ", " + number(v.y()) + ", " + number(v.z()) + ")";
    }

    /** Six significant digits, no exponent, no trailing zeros: 1.5, -0.25, 120. */
    static String number(double v) {
        if (Math.abs(v) < 1e-9) return "0";
        String s = new BigDecimal(v).round(new MathContext(6)).stripTrailingZeros().toPlainString();
        return s.equals("-0") ? "0" : s;
    }
}
