package dev.crt.render;

import dev.crt.geom.Vec3;
import dev.crt.image.FrameBuffer;
import dev.crt.image.ImageFiles;
import dev.crt.scene.Camera;
import dev.crt.scene.Rgb;
import dev.crt.scene.Settings;
import static org.assertj.core.api.Assertions.assertThat;

/**
 * The formulas of rendering-model.md written out plainly with Vec3, for computing expected pixel
 * values by hand in tests, independently of the renderer's flat-array code.
 */
final class Reference {
    private Reference() {}

    /** The pinhole ray direction through sample (sx, sy) of pixel (i, j). */
    static Vec3 direction(Settings s, int i, int j, double sx, double sy) {
        Camera c = s.camera();
        Vec3 f = c.pointing().minus(c.position()).normalize();
        Vec3 r = Vec3.Y.cross(f).normalize();
        Vec3 u = f.cross(r);
        double x = 2 * (i + sx) / s.width() - 1, y = 1 - 2 * (j + sy) / s.height();
        double h = Math.tan(Math.toRadians(c.fov()) / 2), a = (double) s.width() / s.height();
        return f.plus(r.times(x * h * a)).plus(u.times(y * h)).normalize();
    }

    static Vec3 center(Settings s, int i, int j) { return direction(s, i, j, 0.5, 0.5); }

    /** The nearer positive root of |o + t d − c|² = r², or NaN. */
    static double sphereHit(Vec3 o, Vec3 d, Vec3 c, double r) {
        Vec3 oc = o.minus(c);
        double a = d.dot(d), b = 2 * oc.dot(d), cc = oc.dot(oc) - r * r;
        double disc = b * b - 4 * a * cc;
        if (disc < 0) return Double.NaN;
        double t0 = (-b - Math.sqrt(disc)) / (2 * a), t1 = (-b + Math.sqrt(disc)) / (2 * a);
        return t0 > 1e-9 ? t0 : t1 > 1e-9 ? t1 : Double.NaN;
    }

    /** Phong for one unshadowed light: kd·max(0,N·ω)(Cℓ⊙C) + ks·max(0,R·V)^n·Cℓ, times A. */
    static Rgb phong(Vec3 n, Vec3 w, Vec3 v, Rgb light, Rgb c, double kd, double ks, double shininess, double a) {
        double nw = n.dot(w);
        Vec3 r = n.times(2 * nw).minus(w);
        double spec = ks * Math.pow(Math.max(0, r.dot(v)), shininess);
        return light.times(c).times(kd * Math.max(0, nw)).plus(light.times(spec)).times(a);
    }

    static Vec3 reflect(Vec3 d, Vec3 n) { return d.minus(n.times(2 * d.dot(n))); }

    /** Snell with η = η₁/η₂ and n facing the incoming d; null under total internal reflection. */
    static Vec3 refract(Vec3 d, Vec3 n, double eta) {
        double cos = -d.dot(n);
        double k = 1 - eta * eta * (1 - cos * cos);
        if (k < 0) return null;
        return d.times(eta).plus(n.times(eta * cos - Math.sqrt(k)));
    }

    static Rgb gradient(Rgb horizon, Rgb sky, Vec3 d) {
        double e = Math.max(0, Math.min(1, Math.asin(d.normalize().y()) / (Math.PI / 2)));
        return horizon.times(1 - e).plus(sky.times(e));
    }

    /** Asserts that pixel (i, j) encodes to within one 8-bit step of {@code expected} in every channel. */
    static void assertPixel(FrameBuffer fb, int i, int j, Rgb expected) {
        for (int c = 0; c < 3; c++) {
            int got = ImageFiles.toByte(fb.get(i, j, c), 1);
            int want = ImageFiles.toByte(expected.get(c), 1);
            assertThat(Math.abs(got - want))
                    .as("pixel (%d,%d) channel %d: got %s (%d), expected %s (%d)", i, j, c, fb.get(i, j, c), got,
                            expected.get(c), want)
                    .isLessThanOrEqualTo(1);
        }
    }

    static void assertNoNaN(FrameBuffer fb) {
        for (float f : fb.data()) assertThat(Float.isFinite(f)).as("every pixel value is finite").isTrue();
    }
}
