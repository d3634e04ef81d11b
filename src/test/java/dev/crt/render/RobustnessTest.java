package dev.crt.render;

import static dev.crt.render.Reference.assertNoNaN;
import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.image.FrameBuffer;
import dev.crt.image.ImageFiles;
import dev.crt.scene.ApertureShape;
import dev.crt.scene.Camera;
import dev.crt.scene.CsgOperation;
import dev.crt.scene.Entity;
import dev.crt.scene.GradientBackground;
import dev.crt.scene.Light;
import dev.crt.scene.Material;
import dev.crt.scene.Rgb;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import dev.crt.scene.SolidBackground;
import dev.crt.scene.SourceSpan;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/** Scale invariance, thread determinism, cancellation and tricky configurations. */
class RobustnessTest {
    /**
     * A scene with contact shadows, a mirror, glass, a CSG bowl and a rotated box, with every
     * position mapped by p → f·p + shift (falloff scaled by f² so light reaching a point is unchanged).
     */
    static Scene content(double f, Vec3 shift, int w, int h) {
        Transform place = Transform.scaling(v(f, f, f)).then(Transform.translation(shift));
        Material floor = material(rgb(0.8, 0.8, 0.7), 0.9, 0.2, 20, 0.2, 0, 1);
        Material matte = material(rgb(0.9, 0.3, 0.2), 1, 0.5, 40, 0, 0, 1);
        Material mirror = material(rgb(0.9, 0.9, 0.9), 0.1, 0.5, 80, 0.85, 0, 1);
        Material glass = material(rgb(1, 1, 1), 0.05, 0.8, 100, 0.05, 0.9, 1.5);
        Material blue = material(rgb(0.2, 0.3, 0.9), 0.8, 0.3, 20, 0.3, 0, 1);
        List<Entity> objects = List.of(
                plane(Vec3.Y, v(0, -1, 0), floor),
                sphere(v(-1.6, 0, 0.5), 1, matte),
                sphere(v(0.6, -0.2, 1.2), 0.8, mirror),
                sphere(v(0.4, -0.4, -1.2), 0.6, glass),
                box(v(1.5, -1, -0.5), v(2.5, 0.2, 0.5), blue).transformed(Transform.rotation(v(0, 30, 0))),
                csg(CsgOperation.DIFFERENCE, sphere(v(-0.5, 0.5, 2.5), 0.9, blue),
                        box(v(-2, 0.7, 1), v(1, 2, 4), matte)));
        List<Entity> placed = new ArrayList<>();
        for (Entity e : objects) placed.add(e.transformed(place));
        Vec3 eye = place.applyToPoint(v(0.5, 2, -7)), at = place.applyToPoint(v(0, -0.2, 0.5));
        Camera cam = new Camera(eye, at, 45, 0, 0, at.minus(eye).length(), ApertureShape.CIRCLE, SourceSpan.NONE);
        List<Light> lights = List.of(
                point(place.applyToPoint(v(-3, 6, -4)), rgb(1, 0.95, 0.9), 50 * f * f, 0.05),
                point(place.applyToPoint(v(4, 3, -2)), rgb(0.4, 0.4, 0.6), 0, 0),
                parallel(v(1, 2, -1), v(0, 0, 0), rgb(0.3, 0.3, 0.3), 0.02));
        Settings s = new Settings("scale", "", "", "", lights, cam,
                new GradientBackground(rgb(0.7, 0.6, 0.5), rgb(0.2, 0.4, 0.9)), 1, 1, 5, 2.2, w, h);
        return new Scene("scale", s, placed);
    }

    private static int[] bytes(FrameBuffer fb) {
        float[] d = fb.data();
        int[] b = new int[d.length];
        for (int i = 0; i < d.length; i++) b[i] = ImageFiles.toByte(d[i], 2.2);
        return b;
    }

    /** No fixed epsilon passes this: the last two variants need one below 1e-8 and one above 1e-5. */
    @Test
    void sceneMovedOrScaledRendersTheSamePicture() {
        int w = 96, h = 72;
        int[] base = bytes(Renderer.prepare(content(1, Vec3.ZERO, w, h)).render(2, RenderMonitor.NONE));
        record Variant(String name, double f, Vec3 shift) {}
        for (Variant vt : List.of(new Variant("moved 1e5", 1, v(1e5, -1e5, 1e5)), new Variant("scaled 1e-4", 1e-4, Vec3.ZERO),
                new Variant("scaled 1e4", 1e4, Vec3.ZERO), new Variant("scaled 1e4 and moved 1e11", 1e4, v(1e11, 0, -1e11)),
                new Variant("scaled 1e-7", 1e-7, Vec3.ZERO))) {
            FrameBuffer fb = Renderer.prepare(content(vt.f(), vt.shift(), w, h)).render(2, RenderMonitor.NONE);
            assertNoNaN(fb);
            int[] other = bytes(fb);
            int bad = 0;
            for (int i = 0; i < base.length; i++) if (Math.abs(base[i] - other[i]) > 1) bad++;
            assertThat(bad).as("%s: channels differing by more than 1", vt.name()).isLessThanOrEqualTo(base.length / 200);
        }
    }

    @Test
    void anyThreadCountGivesIdenticalFloats() {
        Scene s = content(1, Vec3.ZERO, 70, 45);
        Settings lens = new Settings("t", "", "", "", s.settings().lights(),
                new Camera(s.settings().camera().position(), s.settings().camera().pointing(), 45, 10, 80, 7,
                        ApertureShape.PENTAGON, SourceSpan.NONE),
                s.settings().background(), 2, 3, 5, 1, 70, 45);
        Renderer r = Renderer.prepare(s.withSettings(lens));
        float[] one = r.render(1, RenderMonitor.NONE).data();
        assertThat(r.stats().primaryRays()).isEqualTo(70L * 45 * 2 * 2 * 3);
        assertThat(Arrays.equals(one, r.render(2, RenderMonitor.NONE).data())).isTrue();
        assertThat(Arrays.equals(one, r.render(7, RenderMonitor.NONE).data())).isTrue();
        assertThat(Arrays.equals(one, r.render(0, RenderMonitor.NONE).data())).isTrue();
    }

    @Test
    void cancelStopsTheRenderQuickly() {
        Scene big = content(1, Vec3.ZERO, 1600, 1600);
        Renderer r = Renderer.prepare(big.withSettings(big.settings().withSampling(4, 1)));
        AtomicInteger tiles = new AtomicInteger();
        RenderMonitor cancelAfterFirstTile = new RenderMonitor() {
            @Override
            public void progress(long done, long total) { tiles.incrementAndGet(); }

            @Override
            public boolean isCancelled() { return tiles.get() > 0; }
        };
        long start = System.nanoTime();
        assertThatThrownBy(() -> r.render(2, cancelAfterFirstTile)).isInstanceOf(RenderCancelledException.class);
        // The whole render takes tens of seconds; a cancelled one ends within a tile row (bound generous for a loaded machine).
        assertThat((System.nanoTime() - start) / 1e9).isLessThan(5.0);
        assertThat(tiles.get()).isLessThan(20);
    }

    @Test
    void progressReachesEveryPixel() {
        Renderer r = Renderer.prepare(content(1, Vec3.ZERO, 100, 70));
        long[] last = new long[2];
        r.render(3, new RenderMonitor() {
            @Override
            public synchronized void progress(long done, long total) {
                last[0] = Math.max(last[0], done);
                last[1] = total;
            }
        });
        assertThat(last[0]).isEqualTo(7000);
        assertThat(last[1]).isEqualTo(7000);
    }

    private static FrameBuffer render(Settings s, Entity... es) {
        FrameBuffer fb = Renderer.prepare(scene(s, es)).render(2, RenderMonitor.NONE);
        assertNoNaN(fb);
        return fb;
    }

    @Test
    void cameraInsideASphereAndInsideCsgSeesTheInsideWithoutNaN() {
        Material m = material(rgb(0.6, 0.6, 0.6), 1, 0.5, 10, 0.3, 0.2, 1.3);
        Settings s = settings(camera(Vec3.ZERO, v(0, 0, 1), 90), List.of(point(v(0.2, 0.3, 0.1), Rgb.WHITE, 0, 0.1)),
                new SolidBackground(rgb(0, 0, 1)), 32, 32);
        FrameBuffer fb = render(s, sphere(Vec3.ZERO, 2, m));
        // Every pixel sees the inner wall, never the background.
        for (int j = 0; j < 32; j++) for (int i = 0; i < 32; i++) assertThat(fb.get(i, j, 0)).isGreaterThan(0.01f);
        render(s, csg(CsgOperation.DIFFERENCE, box(v(-3, -3, -3), v(3, 3, 3), m), sphere(v(0, 0, 2), 1, m)));
        render(s, csg(CsgOperation.INTERSECTION, sphere(Vec3.ZERO, 2, m), plane(v(0, 1, 0), v(0, 0.5, 0), m)));
    }

    @Test
    void grazingPlaneAtTheHorizonAndDegenerateShapesGiveNoNaN() {
        Material m = material(rgb(0.5, 0.7, 0.5), 1, 0.4, 10, 0.5, 0, 1);
        // The camera lies in the plane: the middle row of rays runs exactly along it.
        Settings s = settings(camera(v(0, 0, -5), v(0, 0, 5), 60), List.of(point(v(0, 5, 0), Rgb.WHITE, 0, 0.1)),
                new GradientBackground(rgb(1, 1, 1), rgb(0, 0, 1)), 33, 33);
        render(s, plane(Vec3.Y, Vec3.ZERO, m), sphere(v(0, 0, 3), 0, m), box(v(1, 0, 1), v(2, 0, 2), m),
                sphere(v(0, 1, 3), 1, m), csg(CsgOperation.UNION, sphere(v(-2, 1, 3), 1, m), sphere(v(-2, 1, 3), 1, m)));
    }

    @Test
    void radiusZeroSphereIsInvisible() {
        Settings s = settings(camera(v(0, 0, -5), Vec3.ZERO, 60), List.of(), new SolidBackground(rgb(0.2, 0.4, 0.6)), 9, 9);
        FrameBuffer fb = render(s, sphere(Vec3.ZERO, 0, matte(Rgb.WHITE)));
        for (int j = 0; j < 9; j++) for (int i = 0; i < 9; i++) Reference.assertPixel(fb, i, j, rgb(0.2, 0.4, 0.6));
    }

    @Test
    void manyItemsUseTheBvhAndRenderLikeTheList() {
        List<Entity> few = new ArrayList<>(), many = new ArrayList<>();
        Material m = material(rgb(0.8, 0.5, 0.3), 1, 0.3, 20, 0.3, 0, 1);
        java.util.SplittableRandom r = new java.util.SplittableRandom(7);
        for (int i = 0; i < 300; i++) {
            Vec3 c = v(r.nextDouble() * 8 - 4, r.nextDouble() * 6 - 3, r.nextDouble() * 6);
            many.add(i % 3 == 0 ? box(c, c.plus(v(0.3, 0.3, 0.3)), m) : sphere(c, 0.2, m));
        }
        few.add(csg(CsgOperation.UNION, csg(CsgOperation.UNION, many.get(0), many.get(1)), many.get(2)));
        Settings s = settings(camera(v(0, 0, -6), v(0, 0, 2), 60), List.of(point(v(2, 5, -6), Rgb.WHITE, 0, 0.1)),
                new SolidBackground(rgb(0.1, 0.1, 0.1)), 80, 60);
        Renderer bvh = Renderer.prepare(scene(s, many.toArray(new Entity[0])));
        assertThat(bvh.structure().bvhNodes()).isGreaterThan(50);
        // The same entities as one flat union tree (no BVH) must give the same picture.
        Entity all = many.get(0);
        for (int i = 1; i < many.size(); i++) all = csg(CsgOperation.UNION, all, many.get(i));
        Renderer list = Renderer.prepare(scene(s, all));
        assertThat(list.structure().bvhNodes()).isZero();
        float[] a = bvh.render(2, RenderMonitor.NONE).data(), b = list.render(2, RenderMonitor.NONE).data();
        int differ = 0;
        for (int i = 0; i < a.length; i++) if (Math.abs(a[i] - b[i]) > 1.5 / 255) differ++;
        assertThat(differ).isLessThan(a.length / 100);
    }

    @Test
    void mirrorsFacingEachOtherSurviveADeepRecursionDepth() {
        Material mirror = material(rgb(0.5, 0.5, 0.5), 0.1, 0, 30, 0.9, 0, 1);
        Settings base = settings(camera(v(0, 0, 0), v(0, 0, 1), 20), List.of(point(Vec3.ZERO, Rgb.WHITE, 0, 0.1)),
                new SolidBackground(rgb(0, 0, 1)), 4, 4);
        Settings deep = new Settings("deep", "", "", "", base.lights(), base.camera(), base.background(), 1, 1, 200_000, 1, 1, 1);
        FrameBuffer fb = render(deep, box(v(-5, -5, 2), v(5, 5, 3), mirror), box(v(-5, -5, -3), v(5, 5, -2), mirror));
        assertThat(fb.get(0, 0, 0)).isPositive();
    }
}
