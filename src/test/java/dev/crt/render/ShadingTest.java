package dev.crt.render;

import static dev.crt.render.Reference.assertNoNaN;
import static dev.crt.render.Reference.assertPixel;
import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Vec3;
import dev.crt.image.FrameBuffer;
import dev.crt.scene.Background;
import dev.crt.scene.GradientBackground;
import dev.crt.scene.Light;
import dev.crt.scene.Material;
import dev.crt.scene.Rgb;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import dev.crt.scene.SolidBackground;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Rendered pixels against values computed here from the formulas of rendering-model.md. */
class ShadingTest {
    private static final Vec3 EYE = v(0, 0, -5);

    private static FrameBuffer render(Scene s) {
        FrameBuffer fb = Renderer.prepare(s).render(1, dev.crt.render.RenderMonitor.NONE);
        assertNoNaN(fb);
        return fb;
    }

    /** Every pixel whose centre ray hits the unit sphere at the origin well inside its silhouette. */
    private static int checkSphere(Settings s, FrameBuffer fb, java.util.function.BiFunction<Vec3, Vec3, Rgb> shade) {
        int checked = 0;
        for (int j = 0; j < s.height(); j++) {
            for (int i = 0; i < s.width(); i++) {
                Vec3 d = Reference.center(s, i, j);
                Vec3 oc = EYE;
                double closest = oc.minus(d.times(oc.dot(d))).length();
                if (closest > 0.98) continue;
                double t = Reference.sphereHit(EYE, d, Vec3.ZERO, 1);
                Vec3 x = EYE.plus(d.times(t));
                assertPixel(fb, i, j, shade.apply(x, d));
                checked++;
            }
        }
        return checked;
    }

    @Test
    void diffuseSphereUnderAPointLight() {
        Rgb c = rgb(0.8, 0.6, 0.4);
        Material m = material(c, 0.9, 0, 30, 0, 0, 1);
        Vec3 q = v(-3, 4, -5);
        Settings s = settings(camera(EYE, Vec3.ZERO, 60), List.of(point(q, rgb(1, 1, 0.9), 0, 0)),
                Background.BLACK, 64, 48);
        FrameBuffer fb = render(scene(s, sphere(Vec3.ZERO, 1, m)));
        int n = checkSphere(s, fb, (x, d) -> {
            Vec3 nrm = x.normalize();
            return Reference.phong(nrm, q.minus(x).normalize(), d.negate(), rgb(1, 1, 0.9), c, 0.9, 0, 30, 1);
        });
        assertThat(n).isGreaterThan(100);
        assertPixel(fb, 0, 0, Rgb.BLACK);
    }

    @Test
    void falloffAmbientAndSpecularFromTwoLights() {
        Rgb c = rgb(0.3, 0.5, 0.7);
        Material m = new Material(c, 0.7, 0.6, 12, 0, 0, 1, rgb(0.05, 0, 0.02));
        Vec3 q1 = v(2, 2, -4), q2 = v(-4, -1, -3);
        Rgb c1 = rgb(1, 0.9, 0.8), c2 = rgb(0.3, 0.4, 1);
        List<Light> lights = List.of(point(q1, c1, 20, 0.1), point(q2, c2, 0, 0.25));
        Settings s = settings(camera(EYE, Vec3.ZERO, 50), lights, new SolidBackground(rgb(0.1, 0.2, 0.3)), 64, 48);
        FrameBuffer fb = render(scene(s, sphere(Vec3.ZERO, 1, m)));
        checkSphere(s, fb, (x, d) -> {
            Vec3 nrm = x.normalize();
            Rgb ambient = c1.times(c).times(0.1).plus(c2.times(c).times(0.25));
            double d1 = q1.minus(x).length();
            Rgb l1 = Reference.phong(nrm, q1.minus(x).normalize(), d.negate(), c1, c, 0.7, 0.6, 12, 20 / (d1 * d1));
            Rgb l2 = Reference.phong(nrm, q2.minus(x).normalize(), d.negate(), c2, c, 0.7, 0.6, 12, 1);
            // A light behind the surface reaches it only if nothing is in the way; the sphere is.
            if (nrm.dot(q1.minus(x)) <= 0) l1 = Rgb.BLACK;
            if (nrm.dot(q2.minus(x)) <= 0) l2 = Rgb.BLACK;
            return rgb(0.05, 0, 0.02).plus(ambient).plus(l1).plus(l2);
        });
        assertPixel(fb, 1, 1, rgb(0.1, 0.2, 0.3));
    }

    @Test
    void parallelLightShinesFromFromTowardsPointing() {
        Rgb c = rgb(0.9, 0.9, 0.9);
        Material m = material(c, 1, 0.3, 8, 0, 0, 1);
        Vec3 from = v(3, 5, -2), to = v(1, 1, 1);
        Vec3 w = from.minus(to).normalize();
        Settings s = settings(camera(EYE, Vec3.ZERO, 50), List.of(parallel(from, to, rgb(0.8, 0.7, 0.6), 0)),
                Background.BLACK, 64, 48);
        FrameBuffer fb = render(scene(s, sphere(Vec3.ZERO, 1, m)));
        checkSphere(s, fb, (x, d) -> {
            Vec3 nrm = x.normalize();
            if (nrm.dot(w) <= 0) return Rgb.BLACK;
            return Reference.phong(nrm, w, d.negate(), rgb(0.8, 0.7, 0.6), c, 1, 0.3, 8, 1);
        });
    }

    @Test
    void sphereCastsAShadowOnAPlaneAndGlassCastsKtSquared() {
        for (double kt : new double[] {0, 0.6}) {
            Rgb floor = rgb(0.7, 0.7, 0.7);
            Vec3 q = v(4, 6, 0);
            Vec3 eye = v(0, 3, -7);
            Settings s = settings(camera(eye, v(0, -1, 0), 60), List.of(point(q, Rgb.WHITE, 0, 0)),
                    Background.BLACK, 64, 48);
            Material glass = material(rgb(1, 1, 1), 0, 0, 30, 0, kt, 1);
            FrameBuffer fb = render(scene(s, plane(Vec3.Y, v(0, -1, 0), matte(floor)), sphere(Vec3.ZERO, 1, glass)));
            int shadowed = 0, lit = 0;
            for (int j = 0; j < s.height(); j++) {
                for (int i = 0; i < s.width(); i++) {
                    Vec3 d = Reference.center(s, i, j);
                    if (d.y() >= 0) continue;
                    // Skip rays that pass near the sphere, seen or refracted.
                    if (eye.minus(d.times(eye.dot(d))).length() < 1.05) continue;
                    double t = (-1 - eye.y()) / d.y();
                    Vec3 x = eye.plus(d.times(t));
                    Vec3 w = q.minus(x).normalize();
                    double miss = x.minus(w.times(x.dot(w))).length();
                    if (Math.abs(miss - 1) < 0.02) continue;
                    double shadow = miss < 1 ? kt * kt : 1;
                    if (miss < 1) shadowed++;
                    else lit++;
                    Rgb expected = Reference.phong(Vec3.Y, w, d.negate(), Rgb.WHITE, floor, 1, 0, 30, shadow);
                    assertPixel(fb, i, j, expected);
                }
            }
            assertThat(shadowed).isGreaterThan(20);
            assertThat(lit).isGreaterThan(200);
        }
    }

    @Test
    void mirrorSphereReflectsTheSkyGradient() {
        Rgb horizon = rgb(0.9, 0.6, 0.3), sky = rgb(0.1, 0.3, 1.0);
        Material mirror = material(rgb(0.5, 0.5, 0.5), 0, 0, 30, 1, 0, 1);
        Settings s = settings(camera(v(0, 0.5, -5), Vec3.ZERO, 50), List.of(), new GradientBackground(horizon, sky), 64, 48);
        FrameBuffer fb = render(scene(s, sphere(Vec3.ZERO, 1, mirror)));
        Vec3 eye = v(0, 0.5, -5);
        int n = 0;
        for (int j = 0; j < s.height(); j++) {
            for (int i = 0; i < s.width(); i++) {
                Vec3 d = Reference.center(s, i, j);
                double closest = eye.minus(d.times(eye.dot(d))).length();
                if (Math.abs(closest - 1) < 0.02) continue;
                Rgb expected;
                if (closest < 1) {
                    Vec3 x = eye.plus(d.times(Reference.sphereHit(eye, d, Vec3.ZERO, 1)));
                    expected = Reference.gradient(horizon, sky, Reference.reflect(d, x.normalize()));
                    n++;
                } else {
                    expected = Reference.gradient(horizon, sky, d);
                }
                assertPixel(fb, i, j, expected);
            }
        }
        assertThat(n).isGreaterThan(100);
    }

    @Test
    void glassSphereRefractsByHandComputedSnell() {
        Rgb horizon = rgb(1, 0.2, 0.1), sky = rgb(0.1, 0.4, 1.0);
        double ior = 1.5;
        Material glass = material(rgb(1, 1, 1), 0, 0, 30, 0, 1, ior);
        Settings s = settings(camera(EYE, Vec3.ZERO, 40), List.of(), new GradientBackground(horizon, sky), 48, 48);
        FrameBuffer fb = render(scene(s, sphere(Vec3.ZERO, 1, glass)));
        // The centre pixel and two off-centre ones, all well inside the silhouette (radius ≈ 14 px).
        int[][] pixels = {{24, 24}, {24, 17}, {29, 30}, {18, 20}};
        for (int[] p : pixels) {
            Vec3 d = Reference.center(s, p[0], p[1]);
            Vec3 x1 = EYE.plus(d.times(Reference.sphereHit(EYE, d, Vec3.ZERO, 1)));
            Vec3 inside = Reference.refract(d, x1.normalize(), 1 / ior).normalize();
            double t2 = Reference.sphereHit(x1.plus(inside.times(1e-9)), inside, Vec3.ZERO, 1);
            Vec3 x2 = x1.plus(inside.times(t2));
            Vec3 out = Reference.refract(inside, x2.normalize().negate(), ior);
            assertThat(out).isNotNull();
            assertPixel(fb, p[0], p[1], Reference.gradient(horizon, sky, out));
        }
        // The refracted image differs from the unrefracted background: the test can fail.
        Vec3 d = Reference.center(s, 24, 17);
        assertThat(Math.abs(fb.get(24, 17, 0) - Reference.gradient(horizon, sky, d).r())).isGreaterThan(0.02);
    }

    @Test
    void depthZeroDropsReflections() {
        Material mirror = material(rgb(0.5, 0.5, 0.5), 0, 0, 30, 1, 0, 1);
        Settings base = settings(camera(EYE, Vec3.ZERO, 50), List.of(), new SolidBackground(rgb(0.2, 0.4, 0.6)), 16, 16);
        Settings s = new Settings("t", "", "", "", List.of(), base.camera(), base.background(), 1, 1, 0, 1, 16, 16);
        FrameBuffer fb = render(scene(s, sphere(Vec3.ZERO, 1, mirror)));
        assertPixel(fb, 8, 8, Rgb.BLACK);
        assertPixel(fb, 0, 0, rgb(0.2, 0.4, 0.6));
        FrameBuffer deep = render(scene(base, sphere(Vec3.ZERO, 1, mirror)));
        assertPixel(deep, 8, 8, rgb(0.2, 0.4, 0.6));
    }

    @Test
    void supersamplingAveragesTheSubPixelGrid() {
        Rgb c = rgb(1, 1, 1);
        Settings one = settings(camera(EYE, Vec3.ZERO, 50), List.of(point(v(0, 0, -10), Rgb.WHITE, 0, 0)),
                new SolidBackground(rgb(0, 0, 1)), 24, 24);
        Settings s = one.withSampling(3, 1);
        FrameBuffer fb = render(scene(s, sphere(Vec3.ZERO, 1, matte(c))));
        int mixed = 0;
        for (int j = 0; j < 24; j++) {
            for (int i = 0; i < 24; i++) {
                Rgb sum = Rgb.BLACK;
                boolean nearEdge = false;
                for (int b = 0; b < 3; b++) {
                    for (int a = 0; a < 3; a++) {
                        Vec3 d = Reference.direction(s, i, j, (a + 0.5) / 3, (b + 0.5) / 3);
                        double closest = EYE.minus(d.times(EYE.dot(d))).length();
                        nearEdge |= Math.abs(closest - 1) < 1e-6;
                        if (closest < 1) {
                            Vec3 x = EYE.plus(d.times(Reference.sphereHit(EYE, d, Vec3.ZERO, 1)));
                            Vec3 w = v(0, 0, -10).minus(x).normalize();
                            sum = sum.plus(Reference.phong(x.normalize(), w, d.negate(), Rgb.WHITE, c, 1, 0, 30, 1));
                        } else {
                            sum = sum.plus(rgb(0, 0, 1));
                        }
                    }
                }
                if (nearEdge) continue;
                Rgb mean = sum.div(9);
                if (mean.b() > 0.05 && mean.r() > 0.05) mixed++;
                assertPixel(fb, i, j, mean);
            }
        }
        assertThat(mixed).as("pixels straddling the silhouette").isGreaterThan(10);
    }

    @Test
    void wholePhongExponentsBySquaringAgreeWithMathPow() {
        java.util.SplittableRandom r = new java.util.SplittableRandom(11);
        for (int k = 0; k < 20000; k++) {
            double x = r.nextDouble();
            double n = k % 10 == 0 ? r.nextDouble() * 100 : r.nextInt(0, 300);
            double expected = Math.pow(x, n);
            assertThat(Math.abs(Tracer.power(x, n) - expected)).isLessThanOrEqualTo(1e-13 * expected + Double.MIN_NORMAL);
        }
    }

    /**
     * A light lying exactly on the floor plane lights the sphere above it: the shadow segment ends on
     * the floor, it does not cross it (at any scale and distance from the origin).
     */
    @Test
    void aLightLyingOnASurfaceIsNotShadowedByIt() {
        for (double scale : new double[] {1, 1e-4, 1e4}) {
            Vec3 q = v(0.3, 0, 0.1).times(scale);
            Material m = material(rgb(1, 1, 1), 1, 0, 30, 0, 0, 1);
            // The one pixel looks along the view axis at the sphere's lower half.
            Settings look = settings(camera(v(0, 0.5, -6).times(scale), v(0, 1.4, 0).times(scale), 10),
                    List.of(point(q, rgb(1, 1, 1), 0, 0)), Background.BLACK, 1, 1);
            Vec3 eye = v(0, 0.5, -6).times(scale), d = v(0, 1.4, 0).times(scale).minus(eye).normalize();
            Vec3 c = v(0, 2, 0).times(scale);
            double t = Reference.sphereHit(eye, d, c, scale);
            Vec3 x = eye.plus(d.times(t));
            Vec3 n = x.minus(c).normalize();
            FrameBuffer fb = render(scene(look, sphere(c, scale, m),
                    plane(v(0, 1, 0), Vec3.ZERO, matte(rgb(1, 1, 1)))));
            double expected = Math.max(0, n.dot(q.minus(x).normalize()));
            assertThat(expected).as("the point is lit by the formula").isGreaterThan(0.1);
            assertPixel(fb, 0, 0, rgb(expected, expected, expected));
        }
    }
}
