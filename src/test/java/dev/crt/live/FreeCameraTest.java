package dev.crt.live;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.crt.geom.Aabb;
import dev.crt.geom.Vec3;
import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import dev.crt.scene.ApertureShape;
import dev.crt.scene.Camera;
import dev.crt.scene.SourceSpan;
import org.junit.jupiter.api.Test;

class FreeCameraTest {
    static final Camera CAMERA = new Camera(new Vec3(1, 3, -7), new Vec3(0.5, 0.2, 1), 45, 12, 0, 5,
            ApertureShape.CIRCLE, SourceSpan.NONE);

    static void assertClose(Vec3 a, Vec3 b, double eps) {
        assertThat(a.minus(b).length()).as("%s vs %s", a, b).isLessThan(eps);
    }

    @Test
    void aSceneCameraBecomesAFreeCameraWithTheSameView() {
        ViewCamera expected = ViewCamera.of(CAMERA);
        ViewCamera free = FreeCamera.of(CAMERA).view();
        assertClose(free.position(), expected.position(), 1e-12);
        assertClose(free.forward(), expected.forward(), 1e-12);
        assertClose(free.right(), expected.right(), 1e-12);
        assertClose(free.up(), expected.up(), 1e-12);
        assertThat(free.fov()).isEqualTo(45);
    }

    @Test
    void orbitingKeepsTheDistanceToTheTarget() {
        FreeCamera c = FreeCamera.of(CAMERA).orbit(37, -20);
        assertThat(c.position().minus(c.target()).length()).isCloseTo(FreeCamera.of(CAMERA).distance(), within(1e-9));
        assertThat(FreeCamera.of(CAMERA).orbit(0, 500).pitch()).isEqualTo(FreeCamera.MAX_PITCH);
    }

    @Test
    void yawTurnsAboutTheVerticalAndPositivePitchLooksDown() {
        FreeCamera c = new FreeCamera(Vec3.ZERO, 10, 0, 0, 0, 60);
        assertClose(c.position(), new Vec3(0, 0, -10), 1e-12);
        assertClose(c.orbit(90, 0).position(), new Vec3(-10, 0, 0), 1e-12);
        assertThat(c.orbit(0, 30).position().y()).isCloseTo(5, within(1e-12));
    }

    @Test
    void panningMovesTheTargetWithTheMouseOnTheTargetsPlane() {
        FreeCamera c = new FreeCamera(Vec3.ZERO, 10, 0, 0, 0, 90);
        // 100 px high, tan(45°) = 1: the view is 20 units high at the target, 0.2 units per pixel.
        FreeCamera moved = c.pan(50, 0, 100);
        assertClose(moved.target(), new Vec3(-10, 0, 0), 1e-9);
        assertClose(c.pan(0, 50, 100).target(), new Vec3(0, 10, 0), 1e-9);
    }

    @Test
    void zoomRollAndFraming() {
        FreeCamera c = new FreeCamera(Vec3.ZERO, 10, 0, 0, 0, 60);
        assertThat(c.zoom(1).distance()).isCloseTo(10 / 1.1, within(1e-12));
        assertThat(c.rolled(200).roll()).isCloseTo(-160, within(1e-12));
        FreeCamera framed = c.frame(new Aabb(new Vec3(1, 1, 1), new Vec3(3, 3, 3)), 2);
        assertClose(framed.target(), new Vec3(2, 2, 2), 1e-12);
        // Radius √3 seen under 30° half-angle: distance √3 / sin 30° = 2√3.
        assertThat(framed.distance()).isCloseTo(2 * Math.sqrt(3), within(1e-9));
    }

    @Test
    void theCameraBlockCompilesBackToTheSameCamera() {
        FreeCamera free = FreeCamera.of(CAMERA).orbit(33, 11).rolled(-5).zoom(2);
        Camera c = free.toCamera(CAMERA);
        String block = CameraScript.cameraBlock(c);
        assertThat(block).startsWith("Camera { position -> vec3(").contains(" fov -> 45 roll -> 7 }");
        CompileResult r = CrtCompiler.compile(Source.of("t.crt", "Settings { camera -> " + block + " }\n"
                + "Scene { Sphere { radius -> 1 } }\n"), CompileOptions.DEFAULT);
        assertThat(r.hasErrors()).as("%s", r.diagnostics()).isFalse();
        Camera back = r.scene().settings().camera();
        assertClose(back.position(), c.position(), 1e-4);
        assertClose(back.pointing(), c.pointing(), 1e-4);
        assertThat(back.fov()).isEqualTo(45);
        assertThat(back.roll()).isEqualTo(7);
    }

    @Test
    void numbersAreShortAndLensAttributesAppearOnlyWithALens() {
        assertThat(CameraScript.number(1.0)).isEqualTo("1");
        assertThat(CameraScript.number(-0.25)).isEqualTo("-0.25");
        assertThat(CameraScript.number(1234567.0)).isEqualTo("1234570");
        assertThat(CameraScript.number(1e-12)).isEqualTo("0");
        Camera lens = new Camera(Vec3.ZERO, Vec3.Z, 60, 0, 50, 4, ApertureShape.HEXAGON, SourceSpan.NONE);
        assertThat(CameraScript.cameraBlock(lens)).isEqualTo("Camera { position -> vec3(0, 0, 0) pointing -> vec3(0, 0, 1)"
                + " fov -> 60 roll -> 0 aperture -> 50 focaldistance -> 4 apertureshape -> \"hexagon\" }");
        assertThat(CameraScript.cameraBlock(Camera.DEFAULT)).isEqualTo(
                "Camera { position -> vec3(0, 0, -5) pointing -> vec3(0, 0, 0) fov -> 60 roll -> 0 }");
    }
}
