package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.crt.geom.Vec3;
import dev.crt.image.FrameBuffer;
import dev.crt.scene.ApertureShape;
import dev.crt.scene.Camera;
import dev.crt.scene.GradientBackground;
import dev.crt.scene.Projection;
import dev.crt.scene.Rgb;
import dev.crt.scene.Settings;
import dev.crt.scene.SourceSpan;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The spherical and cylindrical projections against the formulas of rendering-model.md. */
class ProjectionsTest {
    private static final Vec3 P = v(1, 2, 3), L = v(4, 1, 7);

    private static Camera camera(Projection p, double fov, double aperture) {
        return new Camera(P, L, fov, 0, aperture, 5, ApertureShape.CIRCLE, p, SourceSpan.NONE);
    }

    private static void assertDirection(CameraRays rays, int i, int j, double sx, double sy, Vec3 expected) {
        double[] d = new double[3];
        rays.direction(i, j, sx, sy, d);
        assertThat(d[0]).isCloseTo(expected.x(), within(1e-12));
        assertThat(d[1]).isCloseTo(expected.y(), within(1e-12));
        assertThat(d[2]).isCloseTo(expected.z(), within(1e-12));
    }

    @Test
    void sphericalAndCylindricalDirectionsFollowTheFormulas() {
        Vec3 f = L.minus(P).normalize(), r = Vec3.Y.cross(f).normalize(), u = f.cross(r);
        int w = 64, h = 32;
        CameraRays spherical = new CameraRays(camera(Projection.SPHERICAL, 60, 0), w, h);
        CameraRays cylindrical = new CameraRays(camera(Projection.CYLINDRICAL, 70, 0), w, h);
        double hh = Math.tan(Math.toRadians(35));
        Random random = new Random(4);
        for (int k = 0; k < 1000; k++) {
            int i = random.nextInt(w), j = random.nextInt(h);
            double sx = random.nextDouble(), sy = random.nextDouble();
            double phi = 2 * Math.PI * ((i + sx) / w - 0.5), theta = Math.PI * (0.5 - (j + sy) / h);
            Vec3 sph = r.times(Math.cos(theta) * Math.sin(phi)).plus(u.times(Math.sin(theta)))
                    .plus(f.times(Math.cos(theta) * Math.cos(phi)));
            assertDirection(spherical, i, j, sx, sy, sph);
            double y = 1 - 2 * (j + sy) / h;
            Vec3 cyl = r.times(Math.sin(phi)).plus(u.times(y * hh)).plus(f.times(Math.cos(phi))).normalize();
            assertDirection(cylindrical, i, j, sx, sy, cyl);
        }
        // The image's centre looks along f, its left and right edges straight back, its top row up.
        assertDirection(spherical, 32, 16, 0, 0, f);
        assertDirection(spherical, 0, 16, 0, 0, f.negate());
        assertDirection(spherical, 0, 0, 0, 0, u);
        assertDirection(cylindrical, 48, 16, 0, 0, r);
    }

    @Test
    void theThreeSixtyProjectionsArePinholesAndRenderWithoutNaNAtThePoles() {
        assertThat(new CameraRays(camera(Projection.SPHERICAL, 60, 50), 8, 8).hasLens()).isFalse();
        assertThat(new CameraRays(camera(Projection.PERSPECTIVE, 60, 50), 8, 8).hasLens()).isTrue();
        Settings s = settings(camera(Projection.SPHERICAL, 60, 0), List.of(),
                new GradientBackground(Rgb.BLACK, Rgb.WHITE), 40, 20);
        FrameBuffer fb = Renderer.prepare(scene(s)).render(2, RenderMonitor.NONE);
        Reference.assertNoNaN(fb);
        // The sky gradient reads each pixel's elevation back, up to the straight-up top row.
        for (int j = 0; j < 10; j++) {
            double[] d = new double[3];
            new CameraRays(s.camera(), 40, 20).direction(7, j, 0.5, 0.5, d);
            double e = Math.max(0, Math.min(1, Math.asin(d[1]) / (Math.PI / 2)));
            assertThat((double) fb.get(7, j, 0)).isCloseTo(e, within(1e-6));
        }
    }
}
