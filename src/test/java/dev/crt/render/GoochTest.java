package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Vec3;
import dev.crt.image.FrameBuffer;
import dev.crt.scene.Finish;
import dev.crt.scene.Material;
import dev.crt.scene.Rgb;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import dev.crt.scene.ShadingModel;
import dev.crt.scene.SolidBackground;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Gooch shading: the cool-to-warm formula inside, outlines of the set width on silhouettes and creases. */
class GoochTest {
    private static final Vec3 EYE = v(0, 0.5, -5), LIGHT = v(-3, 4, -4);
    private static final Rgb C = rgb(0.8, 0.3, 0.2), COOL = rgb(0, 0, 0.5), WARM = rgb(0.4, 0.4, 0), BG = rgb(1, 1, 1);

    private static Material gooch(double outline) {
        Finish n = Finish.NONE;
        Finish f = new Finish(null, null, null, null, null, 1, 0, n.glossySamples(), ShadingModel.GOOCH, COOL, WARM, outline);
        return new Material(C, 0.9, 0.3, 20, 0, 0, 1, Rgb.BLACK, true, false, Rgb.BLACK, null, f);
    }

    private static Settings settings() {
        return Scenes.settings(camera(EYE, v(0, 0, 0), 40), List.of(point(LIGHT, Rgb.WHITE, 0, 0.3)), new SolidBackground(BG), 64, 48);
    }

    private static boolean black(FrameBuffer fb, int i, int j) {
        return fb.get(i, j, 0) == 0 && fb.get(i, j, 1) == 0 && fb.get(i, j, 2) == 0;
    }

    @Test
    void aSphereShadesCoolToWarmInsideAndHasASilhouetteOfTheSetWidth() {
        for (int width : new int[] {1, 3}) {
            Settings s = settings();
            Scene scene = scene(s, sphere(Vec3.ZERO, 1, gooch(width)));
            Renderer r = Renderer.prepare(scene);
            FrameBuffer fb = r.render(2, RenderMonitor.NONE);
            int[] ids = r.idPass();
            int w = s.width(), h = s.height(), inside = 0, lines = 0;
            for (int j = 0; j < h; j++) {
                for (int i = 0; i < w; i++) {
                    boolean sphere = ids[j * w + i] == 0;
                    if (!sphere) {
                        assertThat(black(fb, i, j)).as("background pixel (%d,%d)", i, j).isFalse();
                        continue;
                    }
                    // The distance (in 4-neighbour steps along a row or column) to the nearest background pixel.
                    int edge = Integer.MAX_VALUE;
                    int[][] dirs = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
                    for (int[] dir : dirs) {
                        for (int k = 1; k <= width + 2; k++) {
                            int x = i + k * dir[0], y = j + k * dir[1];
                            if (x < 0 || y < 0 || x >= w || y >= h || ids[y * w + x] != 0) {
                                edge = Math.min(edge, k);
                                break;
                            }
                        }
                    }
                    if (edge <= width) {
                        assertThat(black(fb, i, j)).as("pixel (%d,%d), %d from the silhouette, width %d", i, j, edge, width).isTrue();
                        lines++;
                    } else if (edge > width + 2) {
                        Vec3 d = Reference.center(s, i, j);
                        double t = Reference.sphereHit(EYE, d, Vec3.ZERO, 1);
                        Vec3 x = EYE.plus(d.times(t)), n = x.normalize(), wl = LIGHT.minus(x).normalize(), v = d.times(-1);
                        double tt = (1 + n.dot(wl)) / 2;
                        Rgb cool = COOL.plus(C.times(GoochShading.ALPHA * 0.9)), warm = WARM.plus(C.times(GoochShading.BETA * 0.9));
                        Vec3 refl = n.times(2 * n.dot(wl)).minus(wl);
                        double spec = 0.3 * Math.pow(Math.max(0, refl.dot(v)), 20);
                        Rgb want = warm.times(tt).plus(cool.times(1 - tt)).plus(new Rgb(spec, spec, spec));
                        Reference.assertPixel(fb, i, j, want);
                        inside++;
                    }
                }
            }
            assertThat(inside).isGreaterThan(200);
            assertThat(lines).isGreaterThan(40 * width);
        }
    }

    @Test
    void creasesOfABoxAreOutlinedAndAPhongBoxIsNot() {
        Settings s = Scenes.settings(camera(v(3, 3.5, -4), v(0, 0, 0), 40), List.of(point(LIGHT, Rgb.WHITE, 0, 0.3)),
                new SolidBackground(BG), 64, 48);
        Renderer r = Renderer.prepare(scene(s, box(v(-1, -1, -1), v(1, 1, 1), gooch(1))));
        FrameBuffer fb = r.render(2, RenderMonitor.NONE);
        int[] ids = r.idPass();
        int interior = 0;
        for (int j = 2; j < s.height() - 2; j++) {
            for (int i = 2; i < s.width() - 2; i++) {
                boolean allBox = true;
                for (int y = j - 2; y <= j + 2; y++) for (int x = i - 2; x <= i + 2; x++) allBox &= ids[y * s.width() + x] == 0;
                if (allBox && black(fb, i, j)) interior++;
            }
        }
        // Three faces show: three crease lines run from the near corner, each tens of pixels long.
        assertThat(interior).isGreaterThan(30);
        FrameBuffer phong = Renderer.prepare(scene(s, box(v(-1, -1, -1), v(1, 1, 1), matte(C)))).render(2, RenderMonitor.NONE);
        for (int j = 0; j < s.height(); j++) for (int i = 0; i < s.width(); i++) assertThat(black(phong, i, j)).isFalse();
    }
}
