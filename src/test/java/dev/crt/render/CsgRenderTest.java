package dev.crt.render;

import static dev.crt.render.Reference.assertNoNaN;
import static dev.crt.render.Reference.assertPixel;
import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.image.FrameBuffer;
import dev.crt.scene.Background;
import dev.crt.scene.CsgOperation;
import dev.crt.scene.Entity;
import dev.crt.scene.Material;
import dev.crt.scene.Rgb;
import dev.crt.scene.Settings;
import dev.crt.scene.SolidBackground;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * CSG renders against hand-computed hits. A point light at the eye lights every visible point
 * without shadows, so each pixel is kd·(N·ω)(C) with N from the surface the pixel must show.
 */
class CsgRenderTest {
    private static final Rgb RED = rgb(0.9, 0.2, 0.1), GREEN = rgb(0.1, 0.8, 0.2), BLUE = rgb(0.2, 0.3, 0.9);

    private static FrameBuffer render(Settings s, Entity e) {
        FrameBuffer fb = Renderer.prepare(scene(s, e)).render(1, RenderMonitor.NONE);
        assertNoNaN(fb);
        return fb;
    }

    private static Settings eyeLit(Vec3 eye, Vec3 at) {
        return settings(camera(eye, at, 50), List.of(point(eye, Rgb.WHITE, 0, 0)), Background.BLACK, 64, 48);
    }

    private static Rgb lit(Vec3 eye, Vec3 x, Vec3 n, Rgb c) {
        Vec3 w = eye.minus(x).normalize();
        return c.times(Math.abs(n.dot(w)));
    }

    /** The parameters where the ray enters and leaves a sphere, or null. */
    private static double[] roots(Vec3 o, Vec3 d, Vec3 c, double r) {
        Vec3 oc = o.minus(c);
        double b = oc.dot(d), disc = b * b - (oc.dot(oc) - r * r);
        if (disc < 0) return null;
        return new double[] {-b - Math.sqrt(disc), -b + Math.sqrt(disc), Math.sqrt(disc)};
    }

    @Test
    void bowlShowsOuterShellRimAndInnerWallWithTheirMaterials() {
        // (A − B) − C: a ball minus a smaller concentric ball minus the upper half-space box.
        Entity bowl = csg(CsgOperation.DIFFERENCE,
                csg(CsgOperation.DIFFERENCE, sphere(Vec3.ZERO, 1, matte(RED)), sphere(Vec3.ZERO, 0.8, matte(GREEN))),
                box(v(-3, 0, -3), v(3, 3, 3), matte(BLUE)));
        Vec3 eye = v(0.2, 3, -2.5);
        Settings s = eyeLit(eye, v(0, -0.2, 0));
        FrameBuffer fb = render(s, bowl);
        int outer = 0, rim = 0, inner = 0;
        for (int j = 0; j < s.height(); j++) {
            for (int i = 0; i < s.width(); i++) {
                Vec3 d = Reference.center(s, i, j);
                double tp = -eye.y() / d.y();
                Vec3 xp = eye.plus(d.times(tp));
                double rp = Math.hypot(xp.x(), xp.z());
                double[] a = roots(eye, d, Vec3.ZERO, 1);
                if (Math.abs(rp - 0.8) < 0.03 || Math.abs(rp - 1) < 0.03 || a != null && a[2] < 0.03) continue;
                Rgb expected;
                if (rp < 0.8) {
                    double[] b = roots(eye, d, Vec3.ZERO, 0.8);
                    Vec3 x = eye.plus(d.times(b[1]));
                    if (Math.abs(x.y()) < 0.03) continue;
                    expected = lit(eye, x, x.normalize(), GREEN);
                    inner++;
                } else if (rp < 1) {
                    expected = lit(eye, xp, Vec3.Y, BLUE);
                    rim++;
                } else if (a != null && eye.plus(d.times(a[0])).y() < -0.03) {
                    Vec3 x = eye.plus(d.times(a[0]));
                    expected = lit(eye, x, x.normalize(), RED);
                    outer++;
                } else if (a != null) {
                    continue;
                } else {
                    expected = Rgb.BLACK;
                }
                assertPixel(fb, i, j, expected);
            }
        }
        assertThat(outer).isGreaterThan(10);
        assertThat(rim).isGreaterThan(10);
        assertThat(inner).isGreaterThan(100);
    }

    @Test
    void intersectionAndUnionOfTwoBallsShowTheRightSurface() {
        Vec3 ca = v(-0.5, 0, 0), cb = v(0.5, 0.1, 0.2);
        Vec3 eye = v(0.3, 0.5, -5);
        Settings s = eyeLit(eye, Vec3.ZERO);
        for (CsgOperation op : new CsgOperation[] {CsgOperation.INTERSECTION, CsgOperation.UNION}) {
            FrameBuffer fb = render(s, csg(op, sphere(ca, 1, matte(RED)), sphere(cb, 1, matte(GREEN))));
            int a = 0, b = 0;
            for (int j = 0; j < s.height(); j++) {
                for (int i = 0; i < s.width(); i++) {
                    Vec3 d = Reference.center(s, i, j);
                    double[] ra = roots(eye, d, ca, 1), rb = roots(eye, d, cb, 1);
                    if (ra != null && ra[2] < 0.03 || rb != null && rb[2] < 0.03) continue;
                    Rgb expected = Rgb.BLACK;
                    boolean fromA;
                    if (op == CsgOperation.INTERSECTION) {
                        if (ra == null || rb == null || Math.max(ra[0], rb[0]) > Math.min(ra[1], rb[1]) - 0.03) {
                            if (ra != null && rb != null && Math.max(ra[0], rb[0]) > Math.min(ra[1], rb[1]) - 0.03
                                    && Math.max(ra[0], rb[0]) < Math.min(ra[1], rb[1]) + 0.03) continue;
                            assertPixel(fb, i, j, expected);
                            continue;
                        }
                        fromA = ra[0] > rb[0];
                    } else {
                        if (ra == null && rb == null) {
                            assertPixel(fb, i, j, expected);
                            continue;
                        }
                        fromA = rb == null || ra != null && ra[0] < rb[0];
                    }
                    double t = fromA ? ra[0] : rb[0];
                    if (ra != null && rb != null && Math.abs(ra[0] - rb[0]) < 0.03) continue;
                    Vec3 x = eye.plus(d.times(t));
                    expected = lit(eye, x, x.minus(fromA ? ca : cb).normalize(), fromA ? RED : GREEN);
                    if (fromA) a++;
                    else b++;
                    assertPixel(fb, i, j, expected);
                }
            }
            assertThat(a).as("%s pixels on A", op).isGreaterThan(30);
            assertThat(b).as("%s pixels on B", op).isGreaterThan(30);
        }
    }

    @Test
    void boxMinusAnIdenticalBoxIsEmptyEverywhere() {
        Rgb bg = rgb(0.3, 0.3, 0.3);
        for (Transform t : new Transform[] {Transform.IDENTITY, Transform.rotation(v(20, 35, 10))}) {
            Material m = matte(RED);
            Entity a = box(v(-1, -1, -1), v(1, 1, 1), m).transformed(t);
            Entity b = box(v(-1, -1, -1), v(1, 1, 1), matte(GREEN)).transformed(t);
            Settings s = settings(camera(v(0.5, 1, -5), Vec3.ZERO, 50), List.of(point(v(0, 0, -5), Rgb.WHITE, 0, 0.2)),
                    new SolidBackground(bg), 48, 48);
            FrameBuffer fb = render(s, csg(CsgOperation.DIFFERENCE, a, b));
            for (int j = 0; j < 48; j++) for (int i = 0; i < 48; i++) assertPixel(fb, i, j, bg);
        }
    }

    @Test
    void boxMinusABoxSharingFacesShowsOneUniformCutFace() {
        // A = [−1,1]³ minus its front half B = [−1,1]²×[−1,0]: B shares A's front face and half of four
        // sides. What remains shows B's back face z = 0 with B's material, and nothing of the shared faces.
        Transform turn = Transform.rotation(v(0, 25, 0));
        Entity a = box(v(-1, -1, -1), v(1, 1, 1), matte(RED)).transformed(turn);
        // B is built another way (a unit cube scaled and moved) so its matrix rounds differently.
        Entity b = box(v(-0.5, -0.5, -0.5), v(0.5, 0.5, 0.5), matte(GREEN))
                .transformed(Transform.scaling(v(2, 2, 1)).then(Transform.translation(v(0, 0, -0.5))).then(turn));
        Vec3 eye = v(0, 0.3, -6);
        Settings s = eyeLit(eye, Vec3.ZERO);
        FrameBuffer fb = render(s, csg(CsgOperation.DIFFERENCE, a, b));
        Vec3 n = turn.applyToNormal(v(0, 0, -1)).normalize();
        int face = 0;
        for (int j = 0; j < s.height(); j++) {
            for (int i = 0; i < s.width(); i++) {
                Vec3 d = Reference.center(s, i, j);
                double t = -n.dot(eye) / n.dot(d);
                Vec3 x = eye.plus(d.times(t));
                Vec3 local = turn.inverse().applyToPoint(x);
                if (Math.abs(local.x()) > 0.97 || Math.abs(local.y()) > 0.97) continue;
                assertPixel(fb, i, j, lit(eye, x, n, GREEN));
                face++;
            }
        }
        assertThat(face).isGreaterThan(200);
    }

    /**
     * A union of opaque balls shows exactly what the balls show placed one by one (only inner
     * surfaces differ, and those are hidden). 200,000 operands, chained the way a script's loop
     * chains them, to the left ({@code u = u + s}) and to the right ({@code u = s + u}), and
     * subtracted as a group ({@code slab - (s + (s + …))}): far deeper than a recursive walk of
     * the tree survives on a test thread's stack.
     */
    @Test
    void unionsOfTwoHundredThousandBallsRenderLikeTheBallsThemselves() {
        int n = 200_000, side = 447;
        List<Entity> balls = new java.util.ArrayList<>(n);
        for (int k = 0; k < n; k++) {
            balls.add(sphere(v(k % side - side / 2.0, 0, k / side - side / 2.0).times(0.1), 0.07, matte(RED)));
        }
        Entity left = balls.get(0), right = balls.get(0);
        for (int k = 1; k < n; k++) {
            left = csg(CsgOperation.UNION, left, balls.get(k));
            right = csg(CsgOperation.UNION, balls.get(k), right);
        }
        Vec3 eye = v(3, 4, -6);
        Settings s = eyeLit(eye, v(0, 0, 0));
        FrameBuffer separate = Renderer.prepare(new dev.crt.scene.Scene("balls", s, balls)).render(2, RenderMonitor.NONE);
        for (Entity union : List.of(left, right)) {
            FrameBuffer fb = render(s, union);
            int lit = 0;
            for (int j = 0; j < fb.height(); j++) {
                for (int i = 0; i < fb.width(); i++) {
                    for (int c = 0; c < 3; c++) {
                        assertThat((double) fb.get(i, j, c)).as("pixel %d,%d", i, j).isCloseTo(separate.get(i, j, c), within(1e-9));
                    }
                    if (fb.get(i, j, 0) > 0) lit++;
                }
            }
            assertThat(lit).as("pixels showing balls").isGreaterThan(fb.width() * fb.height() / 4);
        }
        // A slab with every ball cut out of its top face: where a ball was, the cut shows inside walls.
        Entity slab = box(v(-30, -1, -30), v(30, 0, 30), matte(GREEN));
        FrameBuffer cut = render(s, csg(CsgOperation.DIFFERENCE, slab, right));
        FrameBuffer plain = render(s, slab);
        int differ = 0;
        for (int j = 0; j < cut.height(); j++) {
            for (int i = 0; i < cut.width(); i++) {
                if (Math.abs(cut.get(i, j, 1) - plain.get(i, j, 1)) > 1e-6) differ++;
            }
        }
        assertThat(differ).as("pixels where the cut shows").isGreaterThan(cut.width() * cut.height() / 8);
    }
}
