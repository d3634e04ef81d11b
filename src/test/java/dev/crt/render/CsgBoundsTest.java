package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.crt.geom.Aabb;
import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.image.FrameBuffer;
import dev.crt.scene.Box;
import dev.crt.scene.Csg;
import dev.crt.scene.CsgOperation;
import dev.crt.scene.Entity;
import dev.crt.scene.Material;
import dev.crt.scene.Rgb;
import dev.crt.scene.Settings;
import dev.crt.scene.SolidBackground;
import dev.crt.scene.SourceSpan;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A difference's bounds are trimmed by an axis-aligned box taken away (a bowl cut from a ball
 * bounds only the bowl), and the tighter bounds change no pixel: the same scenes rendered with
 * each cut written so that it cannot trim (the box intersected with a larger box, the same solid)
 * give the same floats.
 */
class CsgBoundsTest {
    private static final Material WHITE = material(rgb(0.9, 0.9, 0.9), 0.8, 0.4, 20, 0.6, 0, 1);

    private static Aabb bounds(Entity csg) {
        Shapes shapes = new Shapes();
        Materials materials = new Materials();
        return new CsgSolids().bounds((Csg) csg, Transform.IDENTITY, shapes, p -> materials.indexOf(p.material()));
    }

    @Test
    void aBoxOverTheTopOfABallTrimsItsBoundsToTheBowl() {
        Entity bowl = csg(CsgOperation.DIFFERENCE, sphere(v(0.5, 1.5, 1.2), 0.85, WHITE),
                box(v(-10, 1.3, -10), v(10, 10, 10), WHITE));
        Aabb b = bounds(bowl);
        assertThat(b.max().y()).isCloseTo(1.3, within(1e-7)).isGreaterThan(1.3);
        assertThat(b.min().y()).isEqualTo(1.5 - 0.85);
        assertThat(b.min().x()).isEqualTo(0.5 - 0.85);
        assertThat(b.max().z()).isEqualTo(1.2 + 0.85);
    }

    @Test
    void boxesTakenAwayFromBelowAndFromTheSideTrimThoseSides() {
        Entity below = csg(CsgOperation.DIFFERENCE, sphere(Vec3.ZERO, 1, WHITE), box(v(-2, -2, -2), v(2, -0.5, 2), WHITE));
        assertThat(bounds(below).min().y()).isCloseTo(-0.5, within(1e-7)).isLessThan(-0.5);
        Entity side = csg(CsgOperation.DIFFERENCE, sphere(Vec3.ZERO, 1, WHITE), box(v(0.25, -2, -2), v(3, 2, 2), WHITE));
        Aabb s = bounds(side);
        assertThat(s.max().x()).isCloseTo(0.25, within(1e-7));
        assertThat(s.min().x()).isEqualTo(-1);
        // Several boxes taken away (a − b − c) trim one after the other.
        Entity both = csg(CsgOperation.DIFFERENCE, side, box(v(-2, -2, -3), v(2, 2, -0.75), WHITE));
        Aabb t = bounds(both);
        assertThat(t.max().x()).isCloseTo(0.25, within(1e-7));
        assertThat(t.min().z()).isCloseTo(-0.75, within(1e-7));
    }

    @Test
    void aCutThatSpansTooLittleOrIsTurnedOrIsNoBoxLeavesTheBounds() {
        Vec3 lo = v(-1, -1, -1), hi = v(1, 1, 1);
        // Through the middle: both sides of the ball remain.
        Entity middle = csg(CsgOperation.DIFFERENCE, sphere(Vec3.ZERO, 1, WHITE), box(v(-0.1, -2, -2), v(0.1, 2, 2), WHITE));
        assertThat(bounds(middle)).isEqualTo(new Aabb(lo, hi));
        // Spanning one axis only: a notch, not a slice.
        Entity notch = csg(CsgOperation.DIFFERENCE, sphere(Vec3.ZERO, 1, WHITE), box(v(0.5, 0.5, -2), v(2, 2, 2), WHITE));
        assertThat(bounds(notch)).isEqualTo(new Aabb(lo, hi));
        // A turned box is not its own bounds.
        Box turned = Box.ofCorners(v(-2, 0.5, -2), v(2, 2, 2), WHITE, Transform.rotation(v(0, 10, 0)), SourceSpan.NONE);
        assertThat(bounds(csg(CsgOperation.DIFFERENCE, sphere(Vec3.ZERO, 1, WHITE), turned))).isEqualTo(new Aabb(lo, hi));
        // A ball taken away is not a box.
        Entity ball = csg(CsgOperation.DIFFERENCE, sphere(Vec3.ZERO, 1, WHITE), sphere(v(0, 3, 0), 2.5, WHITE));
        assertThat(bounds(ball)).isEqualTo(new Aabb(lo, hi));
    }

    /** Bowls cut from every side, a mirror floor, lights whose shadow rays graze the cut faces. */
    private static FrameBuffer render(boolean trimmable, Vec3 eye, Vec3 at) {
        List<Entity> things = new ArrayList<>();
        Vec3[] centres = {v(0, 1, 0), v(2.2, 1, 0.3), v(-2.1, 1.2, -0.4), v(0.3, 1.1, 2.4), v(-0.2, 0.9, -2.3), v(1.9, 2.6, 2.1)};
        for (int k = 0; k < centres.length; k++) {
            Vec3 c = centres[k];
            double r = 0.9;
            int axis = k % 3;
            boolean upper = k % 2 == 0;
            double cut = (axis == 0 ? c.x() : axis == 1 ? c.y() : c.z()) + (upper ? 0.3 : -0.3);
            double[] a = {-10, -10, -10}, b = {10, 10, 10};
            if (upper) a[axis] = cut;
            else b[axis] = cut;
            Entity knife = box(v(a[0], a[1], a[2]), v(b[0], b[1], b[2]), WHITE);
            if (!trimmable) knife = csg(CsgOperation.INTERSECTION, knife, box(v(-20, -20, -20), v(20, 20, 20), WHITE));
            things.add(csg(CsgOperation.DIFFERENCE, sphere(c, r, WHITE), knife));
        }
        things.add(box(v(-6, -1, -6), v(6, 0, 6), material(rgb(0.4, 0.5, 0.6), 0.7, 0.2, 10, 0.5, 0, 1)));
        Settings s = settings(camera(eye, at, 60),
                List.of(point(v(3, 5, 2), rgb(0.9, 0.8, 0.7), 0, 0.05), point(v(-4, 1.3, -1), rgb(0.3, 0.4, 0.9), 0, 0),
                        parallel(v(-2, 1, -10), Vec3.ZERO, rgb(0.5, 0.5, 0.5), 0)),
                new SolidBackground(rgb(0.2, 0.3, 0.5)), 96, 72);
        return Renderer.prepare(new dev.crt.scene.Scene("test", s, things)).render(2, RenderMonitor.NONE);
    }

    @Test
    void trimmedBoundsChangeNoPixel() {
        // From above, and level with a cut face (rays along its plane).
        Vec3[][] views = {{v(4, 5, 6), v(0, 0.8, 0)}, {v(5, 1.3, 4), v(0, 1.3, 0)}, {v(-3, 0.7, 5), v(0.3, 1.1, 2.4)}};
        for (Vec3[] view : views) {
            FrameBuffer trimmed = render(true, view[0], view[1]), plain = render(false, view[0], view[1]);
            assertThat(trimmed.data()).as("view from " + view[0]).containsExactly(plain.data());
        }
    }
}
