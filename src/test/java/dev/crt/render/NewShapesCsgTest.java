package dev.crt.render;

import static dev.crt.render.Reference.assertNoNaN;
import static dev.crt.render.Reference.assertPixel;
import static dev.crt.render.Reference.center;
import static dev.crt.render.Scenes.*;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.image.FrameBuffer;
import dev.crt.scene.Cone;
import dev.crt.scene.CsgOperation;
import dev.crt.scene.Cylinder;
import dev.crt.scene.Entity;
import dev.crt.scene.Rgb;
import dev.crt.scene.Settings;
import dev.crt.scene.SolidBackground;
import dev.crt.scene.SourceSpan;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Cylinders and cones as CSG operands, against hits computed by hand. A point light at the eye
 * lights every visible point without shadows, so each pixel is kd·|N·ω|·C for the surface it must show.
 */
class NewShapesCsgTest {
    private static final Rgb RED = rgb(0.9, 0.2, 0.1), GREEN = rgb(0.1, 0.8, 0.2), GREY = rgb(0.3, 0.3, 0.3);

    private static Rgb lit(Vec3 eye, Vec3 x, Vec3 n, Rgb c) {
        return c.times(Math.abs(n.dot(eye.minus(x).normalize())));
    }

    /**
     * A cube minus a cylinder exactly as long as the cube is deep: the hole is flush with both
     * faces and goes right through (the background shows), its wall shows the cylinder's
     * material, and the front face shows the cube's.
     */
    @Test
    void aFlushCylinderDrillsAHoleRightThroughACube() {
        for (Transform turn : new Transform[] {Transform.IDENTITY, Transform.rotation(v(10, 20, 5))}) {
            Entity cube = box(v(-1, -1, -1), v(1, 1, 1), matte(RED)).transformed(turn);
            Entity drill = new Cylinder(v(0, 0, -1), v(0, 0, 1), 0.5, true, matte(GREEN), Transform.IDENTITY, SourceSpan.NONE)
                    .transformed(turn);
            Vec3 eye = turn.applyToPoint(v(0.05, 0.1, -6));
            Settings s = settings(camera(eye, turn.applyToPoint(Vec3.ZERO), 40), List.of(point(eye, Rgb.WHITE, 0, 0)),
                    new SolidBackground(GREY), 64, 64);
            FrameBuffer fb = Renderer.prepare(scene(s, csg(CsgOperation.DIFFERENCE, cube, drill))).render(1, RenderMonitor.NONE);
            assertNoNaN(fb);
            Transform back = turn.inverse();
            int checked = 0;
            for (int j = 0; j < 64; j++) {
                for (int i = 0; i < 64; i++) {
                    Vec3 o = back.applyToPoint(eye), d = back.applyToVector(center(s, i, j)).normalize();
                    // In the cube's frame: the front face z = −1, then the hole's wall or its far opening.
                    double tf = (-1 - o.z()) / d.z();
                    Vec3 f = o.plus(d.times(tf));
                    if (Math.max(Math.abs(f.x()), Math.abs(f.y())) > 0.97) continue;
                    double rf = Math.hypot(f.x(), f.y());
                    Rgb expected;
                    if (rf > 0.52) {
                        expected = lit(eye, turn.applyToPoint(f), turn.applyToNormal(v(0, 0, -1)).normalize(), RED);
                    } else if (rf < 0.48) {
                        // Where the line leaves the cylinder x² + y² = 0.25.
                        double a = d.x() * d.x() + d.y() * d.y(), b = o.x() * d.x() + o.y() * d.y();
                        double c = o.x() * o.x() + o.y() * o.y() - 0.25;
                        double tw = (-b + Math.sqrt(b * b - a * c)) / a;
                        Vec3 w = o.plus(d.times(tw));
                        if (w.z() > 1.02) expected = GREY;
                        else if (w.z() < 0.98) expected = lit(eye, turn.applyToPoint(w),
                                turn.applyToNormal(v(-w.x(), -w.y(), 0)).normalize(), GREEN);
                        else continue;
                    } else {
                        continue;
                    }
                    assertPixel(fb, i, j, expected);
                    checked++;
                }
            }
            org.assertj.core.api.Assertions.assertThat(checked).isGreaterThan(1000);
        }
    }

    /** A ball intersected with a cone through its centre shows the cone's side where the cone is narrower. */
    @Test
    void aBallIntersectedWithAConeShowsTheConesSide() {
        Entity ball = sphere(Vec3.ZERO, 1, matte(RED));
        Entity cone = new Cone(v(0, -2, 0), v(0, 2, 0), 1, 0, true, matte(GREEN), Transform.IDENTITY, SourceSpan.NONE);
        Vec3 eye = v(0, 0.2, -6);
        Settings s = settings(camera(eye, Vec3.ZERO, 40), List.of(point(eye, Rgb.WHITE, 0, 0)), new SolidBackground(GREY), 64, 64);
        FrameBuffer fb = Renderer.prepare(scene(s, csg(CsgOperation.INTERSECTION, ball, cone))).render(1, RenderMonitor.NONE);
        assertNoNaN(fb);
        int checked = 0;
        for (int j = 0; j < 64; j++) {
            for (int i = 0; i < 64; i++) {
                Vec3 d = center(s, i, j);
                // The cone x² + z² = ((2 − y)/4)²: entry of the line eye + t·d, then is it inside the ball?
                double k = 0.25;
                double ax = d.x(), ay = d.y(), az = d.z();
                double rho = (2 - eye.y()) * k, kap = -ay * k;
                double qa = ax * ax + az * az - kap * kap, qb = eye.x() * ax + eye.z() * az - rho * kap;
                double qc = eye.x() * eye.x() + eye.z() * eye.z() - rho * rho;
                double disc = qb * qb - qa * qc;
                double ts = Reference.sphereHit(eye, d, Vec3.ZERO, 1);
                if (disc < 0 || Double.isNaN(ts)) continue;
                double tc = (-qb - Math.sqrt(disc)) / qa;
                Vec3 pc = eye.plus(d.times(tc));
                if (tc > ts && pc.length() < 0.98 && pc.y() > -1.9) {
                    double r = (2 - pc.y()) * k;
                    Vec3 n = v(pc.x() / r, k, pc.z() / r).normalize();
                    assertPixel(fb, i, j, lit(eye, pc, n, GREEN));
                    checked++;
                } else if (ts > tc + 0.02) {
                    Vec3 ps = eye.plus(d.times(ts));
                    double r = (2 - ps.y()) * k;
                    if (Math.hypot(ps.x(), ps.z()) < r * 0.98) {
                        assertPixel(fb, i, j, lit(eye, ps, ps, RED));
                        checked++;
                    }
                }
            }
        }
        org.assertj.core.api.Assertions.assertThat(checked).isGreaterThan(300);
    }
}
