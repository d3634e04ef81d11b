package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.crt.geom.Vec3;
import dev.crt.scene.ApertureShape;
import dev.crt.scene.Camera;
import dev.crt.scene.PanoramaBackground;
import dev.crt.scene.Picture;
import dev.crt.scene.SourceSpan;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The thin lens, aperture shapes, roll and the panorama lookup. */
class CameraAndBackgroundTest {
    @Test
    void pointsOnTheFocusPlaneStaySharpForEveryLensSample() {
        Camera c = new Camera(v(1, 2, -6), v(0, 0.5, 1), 50, 0, 250, 4.5, ApertureShape.HEXAGON, SourceSpan.NONE);
        CameraRays cam = new CameraRays(c, 64, 48);
        PixelRandom rnd = new PixelRandom();
        rnd.seed(5, 7, 0);
        double[] d0 = new double[3], o = new double[3], d = new double[3], lens = new double[2];
        cam.direction(5, 7, 0.5, 0.5, d0);
        Vec3 f = c.pointing().minus(c.position()).normalize();
        Vec3 dir0 = new Vec3(d0[0], d0[1], d0[2]);
        Vec3 focus = c.position().plus(dir0.times(4.5 / dir0.dot(f)));
        for (int k = 0; k < 200; k++) {
            cam.aperture.sample(rnd.next(), rnd.next(), rnd.next(), lens);
            double[] aim = new double[CameraRays.AIM];
            cam.aim(5, 7, 0.5, 0.5, aim);
            cam.throughLens(aim, lens[0], lens[1], o, d);
            Vec3 origin = new Vec3(o[0], o[1], o[2]), dir = new Vec3(d[0], d[1], d[2]);
            assertThat(origin.minus(c.position()).length()).isLessThanOrEqualTo(0.25 + 1e-12);
            assertThat(focus.minus(origin).cross(dir).length()).isLessThan(1e-12);
            assertThat(Math.abs(origin.minus(c.position()).dot(f))).isLessThan(1e-12);
        }
    }

    @Test
    void discPointsAreAtTheLibrarysAngleToTheLastBits() {
        // The disc's point is √u1·(cos 2πu2, sin 2πu2), its cosine and sine by a quarter turn and
        // polynomials: within 2e-15 of the library's (whose 2π·u2 is itself rounded), the quarter turns' edges included.
        ApertureSampler s = new ApertureSampler(ApertureShape.CIRCLE);
        SplittableRandom r = new SplittableRandom(3);
        double[] p = new double[2];
        for (int k = 0; k < 400_000; k++) {
            double u1 = r.nextDouble(), u2 = k % 4 == 0 ? Math.min(Math.nextDown(1.0), Math.max(0, (k / 4 % 9) / 8.0 + r.nextDouble(-1e-9, 1e-9)))
                    : r.nextDouble();
            s.sample(u1, u2, 0, p);
            double a = 2 * Math.PI * u2, rad = Math.sqrt(u1);
            assertThat(p[0]).as("u2 = %s", u2).isCloseTo(rad * Math.cos(a), within(2e-15));
            assertThat(p[1]).as("u2 = %s", u2).isCloseTo(rad * Math.sin(a), within(2e-15));
        }
        s.sample(1, 0, 0, p);
        assertThat(p).containsExactly(1, 0);
        s.sample(1, 0.25, 0, p);
        assertThat(p).containsExactly(0, 1);
    }

    @Test
    void apertureSamplesFillThePolygonWithAVertexUp() {
        SplittableRandom r = new SplittableRandom(1);
        double[] p = new double[2];
        for (ApertureShape shape : ApertureShape.values()) {
            ApertureSampler s = new ApertureSampler(shape);
            int n = shape.sides();
            double maxY = -1, sumX = 0, sumY = 0, inner = 0;
            for (int k = 0; k < 20000; k++) {
                s.sample(r.nextDouble(), r.nextDouble(), r.nextDouble(), p);
                double rad = Math.hypot(p[0], p[1]);
                assertThat(rad).isLessThanOrEqualTo(1 + 1e-12);
                if (n > 0) {
                    // Inside every edge: the apothem cos(π/n) bounds the projection on each edge normal.
                    for (int e = 0; e < n; e++) {
                        double a = Math.PI / 2 + 2 * Math.PI * (e + 0.5) / n;
                        assertThat(p[0] * Math.cos(a) + p[1] * Math.sin(a)).isLessThanOrEqualTo(Math.cos(Math.PI / n) + 1e-12);
                    }
                }
                maxY = Math.max(maxY, p[1]);
                sumX += p[0];
                sumY += p[1];
                if (rad < 0.5) inner++;
            }
            assertThat(maxY).as("%s reaches its top vertex", shape).isGreaterThan(0.97);
            assertThat(sumX / 20000).isCloseTo(0, within(0.02));
            assertThat(sumY / 20000).isCloseTo(0, within(0.02));
            // Uniform by area: the disc of radius 1/2 holds a quarter of the disc's samples.
            if (n == 0) assertThat(inner / 20000).isCloseTo(0.25, within(0.015));
        }
    }

    @Test
    void rollTurnsRightTowardsUpByTheLeftHandRule() {
        Camera c = new Camera(v(0, 0, -5), Vec3.ZERO, 60, 90, 0, 5, ApertureShape.CIRCLE, SourceSpan.NONE);
        CameraRays cam = new CameraRays(c, 10, 10);
        assertThat(cam.rx).isCloseTo(0, within(1e-12));
        assertThat(cam.ry).isCloseTo(1, within(1e-12));
        assertThat(cam.ux).isCloseTo(-1, within(1e-12));
        assertThat(cam.uy).isCloseTo(0, within(1e-12));
    }

    /** A 4×2 picture whose texel (x, y) has red x/4, green y/2 and blue 0.5. */
    private static Picture ramp() {
        float[] rgb = new float[4 * 2 * 3];
        for (int y = 0; y < 2; y++) {
            for (int x = 0; x < 4; x++) {
                rgb[(y * 4 + x) * 3] = x / 4f;
                rgb[(y * 4 + x) * 3 + 1] = y / 2f;
                rgb[(y * 4 + x) * 3 + 2] = 0.5f;
            }
        }
        return new Picture(4, 2, rgb);
    }

    /** The unit direction with the given u and v of the equirectangular mapping (angle 0). */
    private static Vec3 toward(double u, double v) {
        double phi = (u - 0.5) * 2 * Math.PI, elev = (0.5 - v) * Math.PI;
        return new Vec3(Math.sin(phi) * Math.cos(elev), Math.sin(elev), Math.cos(phi) * Math.cos(elev));
    }

    @Test
    void panoramaMapsUAndVToTexelCentresAndFiltersBilinearly() {
        BackgroundShader bg = new BackgroundShader(new PanoramaBackground("ramp", ramp(), 0), 1);
        double[] out = new double[3];
        // Texel (2, 0) centre: u = 2.5/4, v = 0.5/2.
        Vec3 d = toward(2.5 / 4, 0.25);
        bg.shade(d.x(), d.y(), d.z(), out);
        assertThat(out).containsExactly(new double[] {0.5, 0, 0.5}, within(1e-6));
        // Halfway between texels (1, 1) and (2, 1), below the centre of the last row: clamped in v.
        d = toward(2.0 / 4, 0.95);
        bg.shade(d.x(), d.y(), d.z(), out);
        assertThat(out).containsExactly(new double[] {0.375, 0.5, 0.5}, within(1e-6));
        // Bilinear in v between rows 0 and 1 at v = 0.5: equal weights.
        d = toward(0.5 / 4, 0.5);
        bg.shade(d.x(), d.y(), d.z(), out);
        assertThat(out).containsExactly(new double[] {0, 0.25, 0.5}, within(1e-6));
        // Wrapping in u: at u = 0 the texels 3 and 0 mix half and half.
        d = toward(0.0, 0.25);
        bg.shade(d.x(), d.y(), d.z(), out);
        assertThat(out[0]).isCloseTo((0.75 + 0) / 2, within(1e-6));
    }

    @Test
    void panoramaAngleTurnsTheImageAboutY() {
        BackgroundShader turned = new BackgroundShader(new PanoramaBackground("ramp", ramp(), Math.PI / 2), 1);
        double[] out = new double[3];
        // With angle π/2, u grows by a quarter: the direction of u = 1.5/4 shows texel 2.5/4.
        Vec3 d = toward(1.5 / 4, 0.25);
        turned.shade(d.x(), d.y(), d.z(), out);
        assertThat(out[0]).isCloseTo(0.5, within(1e-6));
    }

    @Test
    void panoramaTexelsAreSrgbDecodedWhenGammaIsNotOne() {
        BackgroundShader bg = new BackgroundShader(new PanoramaBackground("ramp", ramp(), 0), 2.2);
        double[] out = new double[3];
        Vec3 d = toward(2.5 / 4, 0.25);
        bg.shade(d.x(), d.y(), d.z(), out);
        double half = Math.pow((0.5 + 0.055) / 1.055, 2.4);
        assertThat(out).containsExactly(new double[] {half, 0, half}, within(1e-6));
    }

    @Test
    void thinLensKeepsTheFocusPlaneSharpAndBlursWhatLiesBehind() {
        dev.crt.scene.Material red = new dev.crt.scene.Material(dev.crt.scene.Rgb.BLACK, 0, 0, 1, 0, 0, 1, rgb(1, 0, 0));
        dev.crt.scene.Material green = new dev.crt.scene.Material(dev.crt.scene.Rgb.BLACK, 0, 0, 1, 0, 0, 1, rgb(0, 1, 0));
        Camera lens = new Camera(v(0, 0, -5), Vec3.ZERO, 40, 0, 300, 4.6, ApertureShape.CIRCLE, SourceSpan.NONE);
        dev.crt.scene.Settings s = new dev.crt.scene.Settings("dof", "", "", "", java.util.List.of(), lens,
                dev.crt.scene.Background.BLACK, 1, 16, 0, 1, 41, 41);
        // In focus: the front of the red ball (4.6 from the eye). Far behind: a small green ball.
        var scene = scene(s, sphere(Vec3.ZERO, 0.4, red), sphere(v(3.2, 0, 15), 0.5, green));
        dev.crt.image.FrameBuffer fb = Renderer.prepare(scene).render(2, RenderMonitor.NONE);
        assertThat(fb.get(20, 20, 0)).isEqualTo(1f);
        int gi = greenColumn(s);
        assertThat(fb.get(gi, 20, 1)).as("the out-of-focus ball's centre mixes with black").isLessThan(0.9f).isGreaterThan(0.05f);
        dev.crt.image.FrameBuffer pinhole = Renderer.prepare(scene.withSettings(new dev.crt.scene.Settings("dof", "", "", "",
                java.util.List.of(), new Camera(v(0, 0, -5), Vec3.ZERO, 40, 0, 0, 4.6, ApertureShape.CIRCLE, SourceSpan.NONE),
                dev.crt.scene.Background.BLACK, 1, 16, 0, 1, 41, 41))).render(2, RenderMonitor.NONE);
        assertThat(pinhole.get(gi, 20, 1)).isEqualTo(1f);
    }

    @Test
    void aFocalDistanceNearTheLargestDoubleFocusesAtInfinity() {
        // The point in focus, P + d·1e308/(d·f), overflows; the lens ray must still be finite and
        // parallel to the pinhole ray (a lens focused at infinity), starting on the lens.
        Camera c = new Camera(v(1, 2, -6), v(0, 0.5, 1), 50, 0, 250, 1e308, ApertureShape.CIRCLE, SourceSpan.NONE);
        CameraRays cam = new CameraRays(c, 64, 48);
        double[] d0 = new double[3], o = new double[3], d = new double[3];
        for (int i = 0; i < 64; i += 9) {
            cam.direction(i, 40, 0.5, 0.5, d0);
            double[] aim = new double[CameraRays.AIM];
            cam.aim(i, 40, 0.5, 0.5, aim);
            cam.throughLens(aim, 0.6, -0.7, o, d);
            assertThat(d).containsExactly(d0, within(1e-12));
            assertThat(new Vec3(o[0], o[1], o[2]).minus(c.position()).length()).isCloseTo(0.25 * Math.hypot(0.6, 0.7), within(1e-12));
        }
    }

    /** The pixel column through the green ball's centre. */
    private static int greenColumn(dev.crt.scene.Settings s) {
        Vec3 d = v(3.2, 0, 20).normalize();
        double h = Math.tan(Math.toRadians(20));
        double x = d.x() / d.z() / h;
        return (int) Math.floor((x + 1) / 2 * s.width());
    }
}
