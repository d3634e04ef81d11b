package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.crt.geom.Vec3;
import dev.crt.scene.Background;
import dev.crt.scene.CsgOperation;
import dev.crt.scene.Entity;
import dev.crt.scene.Material;
import dev.crt.scene.Rgb;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * Picking and the id and depth passes against hits computed here by hand: every pixel's centre
 * ray is intersected with each entity in closed form, and the nearest names the entity and depth.
 */
class PickingTest {
    private static final int W = 64, H = 48;
    private static final double FOV = 50;
    private static final Material M = matte(Rgb.WHITE);

    /**
     * Entity 0 is a sphere of radius 0 (nothing to hit, so it must not shift the indices of the
     * rest); then a ball, a ball cut by a box (CSG: its cut face must count as the CSG entity),
     * five small balls (so the items go through the BVH, in an order other than the scene's), and
     * a floor plane (unbounded).
     */
    private static List<Entity> entities() {
        List<Entity> e = new ArrayList<>();
        e.add(sphere(v(0, 0, 5), 0, M));
        e.add(sphere(v(-0.5, 0.3, 5), 1, M));
        e.add(csg(CsgOperation.DIFFERENCE, sphere(v(1.5, 0, 6), 1.2, M), box(v(-10, -10, -10), v(1.5, 10, 10), M)));
        for (int k = 0; k < 5; k++) e.add(sphere(smallBall(k), 0.3, M));
        e.add(plane(v(0, 1, 0), v(0, -1.5, 0), M));
        return e;
    }

    /** Small ball k, in a column left of the others, each farther away. */
    private static Vec3 smallBall(int k) {
        double z = 7 + k;
        return v(-0.45 * z, (0.3 - 0.1 * k) * z, z);
    }

    private static Settings settings() {
        return Scenes.settings(camera(Vec3.ZERO, v(0, 0, 1), FOV), List.of(), Background.BLACK, W, H);
    }

    /** The unit direction of pixel (i, j)'s centre ray for a camera at the origin looking along +z. */
    private static Vec3 ray(int i, int j) {
        double tan = Math.tan(Math.toRadians(FOV) / 2);
        double x = 2 * (i + 0.5) / W - 1, y = 1 - 2 * (j + 0.5) / H;
        return v(x * tan * W / H, y * tan, 1).normalize();
    }

    /** The nearest positive parameter where the ray d from the origin meets entity k, or +∞. */
    private static double reference(int k, Vec3 d) {
        if (k == 0) return Double.POSITIVE_INFINITY;
        if (k == 1) return ballEntry(d, v(-0.5, 0.3, 5), 1);
        if (k == 2) {
            // The ball with x < 1.5 removed: its surface where x ≥ 1.5, else the cut disk at x = 1.5.
            double[] in = ballSpan(d, v(1.5, 0, 6), 1.2);
            if (in == null) return Double.POSITIVE_INFINITY;
            if (in[0] * d.x() >= 1.5) return in[0];
            if (in[1] * d.x() > 1.5) return 1.5 / d.x();
            return Double.POSITIVE_INFINITY;
        }
        if (k <= 7) {
            return ballEntry(d, smallBall(k - 3), 0.3);
        }
        return d.y() < 0 ? -1.5 / d.y() : Double.POSITIVE_INFINITY;
    }

    private static double ballEntry(Vec3 d, Vec3 c, double r) {
        double[] s = ballSpan(d, c, r);
        return s == null ? Double.POSITIVE_INFINITY : s[0];
    }

    private static double[] ballSpan(Vec3 d, Vec3 c, double r) {
        double b = d.dot(c), disc = b * b - (c.dot(c) - r * r);
        if (disc < 0) return null;
        return new double[] {b - Math.sqrt(disc), b + Math.sqrt(disc)};
    }

    @Test
    void idAndDepthPassesNameTheNearestEntityOfTheScenesListAtEveryPixel() {
        List<Entity> entities = entities();
        Renderer r = Renderer.prepare(new Scene("picking", settings(), entities));
        int[] ids = r.idPass();
        double[] depth = r.depthPass();
        int seen = 0;
        boolean[] shown = new boolean[entities.size()];
        for (int j = 0; j < H; j++) {
            for (int i = 0; i < W; i++) {
                Vec3 d = ray(i, j);
                int best = -1;
                double t = Double.POSITIVE_INFINITY;
                for (int k = 0; k < entities.size(); k++) {
                    double tk = reference(k, d);
                    if (tk < t) {
                        t = tk;
                        best = k;
                    }
                }
                int p = j * W + i;
                assertThat(ids[p]).as("id at (%d, %d)", i, j).isEqualTo(best);
                if (best < 0) {
                    assertThat(depth[p]).isEqualTo(Double.POSITIVE_INFINITY);
                } else {
                    assertThat(depth[p]).as("depth at (%d, %d)", i, j).isCloseTo(t, within(1e-9 * t));
                    shown[best] = true;
                    seen++;
                }
            }
        }
        // Every entity but the empty one shows somewhere, and some pixels show the background.
        for (int k = 1; k < shown.length; k++) assertThat(shown[k]).as("entity %d visible", k).isTrue();
        assertThat(seen).isBetween(1, W * H - 1);
    }

    @Test
    void pickReturnsTheSceneEntityItselfWithItsDistance() {
        List<Entity> entities = entities();
        Renderer r = Renderer.prepare(new Scene("picking", settings(), entities));
        int[] ids = r.idPass();
        double[] depth = r.depthPass();
        for (int j = 0; j < H; j += 3) {
            for (int i = 0; i < W; i += 5) {
                Optional<Pick> pick = r.pick(i, j);
                int p = j * W + i;
                if (ids[p] < 0) {
                    assertThat(pick).isEmpty();
                } else {
                    assertThat(pick).isPresent();
                    assertThat(pick.get().entityIndex()).isEqualTo(ids[p]);
                    assertThat(pick.get().entity()).isSameAs(entities.get(ids[p]));
                    assertThat(pick.get().distance()).isEqualTo(depth[p]);
                }
            }
        }
        assertThat(r.pick(-1, 0)).isEmpty();
        assertThat(r.pick(W, 0)).isEmpty();
        assertThat(r.pick(0, H)).isEmpty();
    }
}
