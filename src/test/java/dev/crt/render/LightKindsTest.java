package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.crt.geom.Vec3;
import dev.crt.image.FrameBuffer;
import dev.crt.scene.AreaLight;
import dev.crt.scene.Background;
import dev.crt.scene.Light;
import dev.crt.scene.Rgb;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import dev.crt.scene.SourceSpan;
import dev.crt.scene.SpotLight;
import java.util.List;
import org.junit.jupiter.api.Test;

/** SpotLight and AreaLight renders against the formulas of rendering-model.md, "Second wave". */
class LightKindsTest {
    /** The camera looks along +z at the wall z = 0, whose outward normal faces it. */
    private static final Vec3 EYE = v(0, 0, -4);
    private static final Vec3 WALL_NORMAL = v(0, 0, -1);

    private static Scene wall(List<Light> lights, int w, int h) {
        Settings s = settings(camera(EYE, Vec3.ZERO, 90), lights, Background.BLACK, w, h);
        return scene(s, plane(WALL_NORMAL, Vec3.ZERO, matte(Rgb.WHITE)));
    }

    /** Where pixel (i, j)'s centre ray meets the wall. */
    private static Vec3 onWall(Settings s, int i, int j) {
        Vec3 d = Reference.center(s, i, j);
        return EYE.plus(d.times(-EYE.z() / d.z()));
    }

    private static double smoothstep(double e0, double e1, double x) {
        if (e0 == e1) return x >= e1 ? 1 : 0;
        double t = Math.max(0, Math.min(1, (x - e0) / (e1 - e0)));
        return t * t * (3 - 2 * t);
    }

    @Test
    void everyLightTypeHasItsOwnKindTag() {
        // A new Light record must get a tag and a class in Lights' dispatch, or this fails.
        List<Light> one = List.of(point(v(0, 1, 0), Rgb.WHITE, 0, 0), parallel(v(0, 1, 0), Vec3.ZERO, Rgb.WHITE, 0),
                new SpotLight(v(0, 1, 0), Vec3.ZERO, 30, 20, Rgb.WHITE, 0, 0, SourceSpan.NONE),
                new AreaLight(v(0, 1, 0), v(1, 0, 0), v(0, 0, 1), 2, Rgb.WHITE, 0, 0, SourceSpan.NONE));
        assertThat(one.stream().map(Object::getClass)).containsExactlyInAnyOrder(Light.class.getPermittedSubclasses());
        Lights lights = new Lights(one);
        assertThat(new byte[] {lights.kind[0], lights.kind[1], lights.kind[2], lights.kind[3]})
                .containsExactly(Lights.POINT, Lights.PARALLEL, Lights.SPOT, Lights.AREA);
        assertThat(lights.sampleCount(3)).isEqualTo(4);
        assertThat(lights.random).isTrue();
        assertThat(new Lights(one.subList(0, 3)).random).isFalse();
    }

    @Test
    void spotIsFullInsideTheInnerConeZeroOutsideTheAngleAndMonotoneBetween() {
        Vec3 q = v(0, 0, -2);
        double angle = 30, inner = 12;
        SpotLight spot = new SpotLight(q, v(0, 0, 5), angle, inner, Rgb.WHITE, 0, 0, SourceSpan.NONE);
        Scene scene = wall(List.of(spot), 81, 81);
        Settings s = scene.settings();
        FrameBuffer fb = Renderer.prepare(scene).render(1, RenderMonitor.NONE);
        Vec3 axis = v(0, 0, 1);
        int full = 0, dark = 0, between = 0;
        for (int j = 0; j < s.height(); j++) {
            for (int i = 0; i < s.width(); i++) {
                Vec3 x = onWall(s, i, j);
                Vec3 w = q.minus(x).normalize();
                double lambert = WALL_NORMAL.dot(w);
                double c = x.minus(q).normalize().dot(axis);
                double cone = smoothstep(Math.cos(Math.toRadians(angle)), Math.cos(Math.toRadians(inner)), c);
                assertThat((double) fb.get(i, j, 0)).as("pixel %d,%d", i, j).isCloseTo(lambert * cone, within(1e-6));
                if (c >= Math.cos(Math.toRadians(inner))) {
                    full++;
                    assertThat((double) fb.get(i, j, 1)).isCloseTo(lambert, within(1e-6));
                } else if (c <= Math.cos(Math.toRadians(angle))) {
                    dark++;
                    assertThat(fb.get(i, j, 1)).isEqualTo(0f);
                } else {
                    between++;
                }
            }
        }
        assertThat(full).isGreaterThan(50);
        assertThat(dark).isGreaterThan(50);
        assertThat(between).isGreaterThan(50);
        // Along the middle row from the centre outwards the cone factor never grows.
        int mid = s.height() / 2;
        double previous = Double.POSITIVE_INFINITY;
        for (int i = s.width() / 2; i < s.width(); i++) {
            Vec3 x = onWall(s, i, mid);
            double cone = fb.get(i, mid, 2) / WALL_NORMAL.dot(q.minus(x).normalize());
            assertThat(cone).isLessThanOrEqualTo(previous + 1e-6);
            previous = cone;
        }
        assertThat(previous).isEqualTo(0.0);
    }

    @Test
    void spotWithEqualAnglesHasAHardEdgeAndLeavesAmbientUnscaled() {
        Vec3 q = v(0, 0, -2);
        SpotLight spot = new SpotLight(q, Vec3.ZERO, 20, 20, rgb(1, 1, 1), 0, 0.25, SourceSpan.NONE);
        Scene scene = wall(List.of(spot), 41, 41);
        Settings s = scene.settings();
        FrameBuffer fb = Renderer.prepare(scene).render(2, RenderMonitor.NONE);
        double cosAngle = Math.cos(Math.toRadians(20));
        for (int j = 0; j < s.height(); j++) {
            for (int i = 0; i < s.width(); i++) {
                Vec3 x = onWall(s, i, j);
                double c = x.minus(q).normalize().dot(v(0, 0, 1));
                double expected = 0.25 + (c >= cosAngle ? WALL_NORMAL.dot(q.minus(x).normalize()) : 0);
                assertThat((double) fb.get(i, j, 0)).isCloseTo(expected, within(1e-6));
            }
        }
    }

    /**
     * ∫ over the parallelogram of cosθ·cosθl/d² dA, the contour form: ½ Σ βᵢ (N·γᵢ), with βᵢ the
     * angle edge i subtends at x and γᵢ the unit normal of the plane through x and that edge.
     */
    static double polygonIrradiance(Vec3 x, Vec3 n, Vec3... corners) {
        double sum = 0;
        for (int k = 0; k < corners.length; k++) {
            Vec3 a = corners[k].minus(x).normalize(), b = corners[(k + 1) % corners.length].minus(x).normalize();
            double beta = Math.acos(Math.max(-1, Math.min(1, a.dot(b))));
            Vec3 gamma = a.cross(b).normalize();
            sum += beta * n.dot(gamma);
        }
        return 0.5 * Math.abs(sum);
    }

    /** RMS relative error of the wall's diffuse value against the closed form, for n×n samples. */
    static double areaLightError(int n) {
        Vec3 corner = v(-0.5, -0.4, -1.5), e1 = v(1.2, 0, 0), e2 = v(0, 0.3, -0.8);
        double falloff = 2;
        AreaLight light = new AreaLight(corner, e1, e2, n, Rgb.WHITE, falloff, 0, SourceSpan.NONE);
        Scene scene = wall(List.of(light), 24, 24);
        Settings s = scene.settings();
        FrameBuffer fb = Renderer.prepare(scene).render(2, RenderMonitor.NONE);
        double area = e1.cross(e2).length();
        Vec3[] poly = {corner, corner.plus(e1), corner.plus(e1).plus(e2), corner.plus(e2)};
        double sum = 0;
        for (int j = 0; j < s.height(); j++) {
            for (int i = 0; i < s.width(); i++) {
                double exact = falloff * polygonIrradiance(onWall(s, i, j), WALL_NORMAL, poly) / area;
                double rel = (fb.get(i, j, 0) - exact) / exact;
                sum += rel * rel;
            }
        }
        return Math.sqrt(sum / (s.width() * s.height()));
    }

    @Test
    void areaLightDiffuseConvergesToThePolygonIrradianceAtTheStratifiedRate() {
        int[] ns = {1, 2, 4, 8, 16, 32};
        double[] errors = new double[ns.length];
        for (int k = 0; k < ns.length; k++) errors[k] = areaLightError(ns[k]);
        for (int k = 1; k < ns.length; k++) assertThat(errors[k]).isLessThan(errors[k - 1]);
        // Jittered stratification of a smooth integrand in 2D: RMS error ~ N^(-1) = n^(-2) with
        // N = n² samples (variance N^(-1-2/d)); plain Monte Carlo would give n^(-1).
        double slope = Math.log(errors[ns.length - 1] / errors[1]) / Math.log((double) ns[ns.length - 1] / ns[1]);
        assertThat(slope).isBetween(-2.3, -1.7);
        assertThat(errors[ns.length - 1]).isLessThan(2e-3);
    }

    @Test
    void areaLightRendersBitIdenticalForAnyThreadCount() {
        AreaLight light = new AreaLight(v(-1, 1, -2), v(2, 0, 0), v(0, 0, 1), 3, Rgb.WHITE, 0, 0.1, SourceSpan.NONE);
        Settings s = settings(camera(EYE, Vec3.ZERO, 60), List.of(light), Background.BLACK, 48, 32);
        Scene scene = scene(s, plane(WALL_NORMAL, Vec3.ZERO, matte(Rgb.WHITE)),
                sphere(v(0, 0, -0.8), 0.5, matte(rgb(0.8, 0.3, 0.2))));
        Renderer r = Renderer.prepare(scene);
        float[] one = r.render(1, RenderMonitor.NONE).data();
        assertThat(r.render(2, RenderMonitor.NONE).data()).isEqualTo(one);
        assertThat(r.render(7, RenderMonitor.NONE).data()).isEqualTo(one);
    }

    @Test
    void areaLightCastsSoftShadowsBetweenUmbraAndFullLight() {
        // The light spans x ∈ [−3, −1] at z = −3; the ball sits on the line from its centre to the
        // wall point (1, 0, 0), out of the camera's way to that point.
        AreaLight light = new AreaLight(v(-3, -1, -3), v(2, 0, 0), v(0, 2, 0), 8, Rgb.WHITE, 0, 0, SourceSpan.NONE);
        Settings s = settings(camera(EYE, Vec3.ZERO, 90), List.of(light), Background.BLACK, 61, 61);
        Scene scene = scene(s, plane(WALL_NORMAL, Vec3.ZERO, matte(Rgb.WHITE)), sphere(v(0.4, 0, -0.6), 0.25, matte(Rgb.WHITE)));
        FrameBuffer fb = Renderer.prepare(scene).render(2, RenderMonitor.NONE);
        int mid = 30;
        double lit = fb.get(55, mid, 0), penumbra = fb.get(41, mid, 0), umbra = fb.get(38, mid, 0);
        assertThat(lit).isCloseTo(meanOverLight(onWall(s, 55, mid)), within(0.01));
        assertThat(penumbra).isCloseTo(meanOverLight(onWall(s, 41, mid)), within(0.03));
        assertThat(umbra).isCloseTo(meanOverLight(onWall(s, 38, mid)), within(0.03));
        assertThat(umbra).isLessThan(0.2 * penumbra);
    }

    /**
     * falloff 0: Aℓ = |nl·ω|, so the light's mean of cosθl·cosθ over the points the ball (centre
     * (0.4, 0, −0.6), radius 0.25) does not hide, here by a fine midpoint rule.
     */
    private static double meanOverLight(Vec3 x) {
        int m = 400;
        double sum = 0;
        for (int a = 0; a < m; a++) {
            for (int b = 0; b < m; b++) {
                Vec3 q = v(-3 + 2 * (a + 0.5) / m, -1 + 2 * (b + 0.5) / m, -3);
                Vec3 w = q.minus(x).normalize();
                Vec3 toBall = v(0.4, 0, -0.6).minus(x);
                double along = toBall.dot(w);
                if (toBall.minus(w.times(along)).length() < 0.25 && along > 0) continue;
                sum += Math.abs(w.z()) * WALL_NORMAL.dot(w);
            }
        }
        return sum / (m * m);
    }
}
