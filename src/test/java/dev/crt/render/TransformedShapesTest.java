package dev.crt.render;

import static dev.crt.render.Reference.assertNoNaN;
import static dev.crt.render.Reference.assertPixel;
import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.image.FrameBuffer;
import dev.crt.scene.Background;
import dev.crt.scene.Rgb;
import dev.crt.scene.Settings;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Primitives under general transforms, checked against hits computed by hand in object space. */
class TransformedShapesTest {
    private static final Vec3 EYE = v(0.4, 0.8, -6);
    private static final Rgb C = rgb(0.7, 0.5, 0.9);

    private static Settings eyeLit() {
        return settings(camera(EYE, Vec3.ZERO, 45), List.of(point(EYE, Rgb.WHITE, 0, 0)), Background.BLACK, 64, 48);
    }

    @Test
    void ellipsoidFromANonUniformScaleShadesWithTheInverseTransposeNormal() {
        Transform t = Transform.scaling(v(2, 0.7, 1)).then(Transform.rotation(v(0, 20, 30)));
        Settings s = eyeLit();
        FrameBuffer fb = Renderer.prepare(scene(s, sphere(Vec3.ZERO, 1, matte(C)).transformed(t)))
                .render(1, RenderMonitor.NONE);
        assertNoNaN(fb);
        int n = 0;
        for (int j = 0; j < s.height(); j++) {
            for (int i = 0; i < s.width(); i++) {
                Vec3 d = Reference.center(s, i, j);
                Vec3 o = t.inverse().applyToPoint(EYE), dl = t.inverse().applyToVector(d);
                double a = dl.dot(dl), b = o.dot(dl), c = o.dot(o) - 1, disc = b * b - a * c;
                if (disc < 0.05 * a) {
                    if (disc < -0.05 * a) assertPixel(fb, i, j, Rgb.BLACK);
                    continue;
                }
                double th = (-b - Math.sqrt(disc)) / a;
                Vec3 local = o.plus(dl.times(th));
                Vec3 normal = t.applyToNormal(local).normalize();
                Vec3 x = t.applyToPoint(local);
                assertPixel(fb, i, j, C.times(normal.dot(EYE.minus(x).normalize())));
                n++;
            }
        }
        assertThat(n).isGreaterThan(200);
    }

    @Test
    void rotatedBoxShowsItsTurnedFaces() {
        Vec3 lo = v(-1, -0.5, -0.7), hi = v(1, 0.5, 0.7);
        Transform t = Transform.rotation(v(10, 35, 0)).then(Transform.translation(v(0.2, 0, 0.3)));
        Settings s = eyeLit();
        FrameBuffer fb = Renderer.prepare(scene(s, box(lo, hi, matte(C)).transformed(t))).render(1, RenderMonitor.NONE);
        assertNoNaN(fb);
        int n = 0;
        for (int j = 0; j < s.height(); j++) {
            for (int i = 0; i < s.width(); i++) {
                Vec3 d = Reference.center(s, i, j);
                Vec3 o = t.inverse().applyToPoint(EYE), dl = t.inverse().applyToVector(d);
                double tin = -1e300, tout = 1e300;
                int axis = -1;
                for (int k = 0; k < 3; k++) {
                    double t0 = (lo.get(k) - o.get(k)) / dl.get(k), t1 = (hi.get(k) - o.get(k)) / dl.get(k);
                    if (Math.min(t0, t1) > tin) {
                        tin = Math.min(t0, t1);
                        axis = k;
                    }
                    tout = Math.min(tout, Math.max(t0, t1));
                }
                if (tout - tin < 0.05 && tout - tin > -0.05) continue;
                if (tin > tout) {
                    assertPixel(fb, i, j, Rgb.BLACK);
                    continue;
                }
                // Stay clear of edges, where the face seen may change within the pixel.
                Vec3 local = o.plus(dl.times(tin));
                boolean nearEdge = false;
                for (int k = 0; k < 3; k++) {
                    if (k != axis) nearEdge |= Math.min(local.get(k) - lo.get(k), hi.get(k) - local.get(k)) < 0.03;
                }
                if (nearEdge) continue;
                double sign = dl.get(axis) > 0 ? -1 : 1;
                Vec3 nl = new Vec3(axis == 0 ? sign : 0, axis == 1 ? sign : 0, axis == 2 ? sign : 0);
                Vec3 normal = t.applyToNormal(nl).normalize();
                Vec3 x = t.applyToPoint(local);
                assertPixel(fb, i, j, C.times(normal.dot(EYE.minus(x).normalize())));
                n++;
            }
        }
        assertThat(n).isGreaterThan(200);
    }

    @Test
    void simpleTransformsAreFoldedIntoWorldSpaceShapes() {
        Renderer r = Renderer.prepare(scene(eyeLit(),
                sphere(v(1, 2, 3), 0.5, matte(C)).transformed(Transform.scaling(v(3, 3, 3)).then(Transform.rotation(v(10, 20, 30)))),
                box(v(0, 0, 0), v(1, 2, 3), matte(C)).transformed(Transform.rotation(v(0, 90, 0)).then(Transform.scaling(v(1, 2, 3))))));
        SceneGeometry g = geometryOf(r);
        assertThat(g.shapes.kind[0]).isEqualTo(Shapes.SPHERE);
        assertThat(g.shapes.kind[1]).isEqualTo(Shapes.BOX);
    }

    static SceneGeometry geometryOf(Renderer r) {
        try {
            var f = Renderer.class.getDeclaredField("geometry");
            f.setAccessible(true);
            return (SceneGeometry) f.get(r);
        } catch (ReflectiveOperationException e) {
            throw new AssertionError(e);
        }
    }
}
