package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Vec3;
import dev.crt.scene.Background;
import dev.crt.scene.CsgOperation;
import dev.crt.scene.Entity;
import dev.crt.scene.Material;
import dev.crt.scene.Settings;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The 2015 model's shadow test with a cached blocker and an early stop answers as the closest hit does. */
class ShadowBlockedTest {
    private static final Material M = matte(rgb(0.5, 0.5, 0.5));
    private static final double STEP = 0.37, SHIFT = 0.1;

    private static Vec3 gridPoint(SplittableRandom r) {
        return v(STEP * (r.nextInt(9) - 4) + SHIFT, STEP * (r.nextInt(9) - 4) + SHIFT, STEP * (r.nextInt(9) - 4) + SHIFT);
    }

    /** Spheres, boxes packed on a grid (segments ending on or grazing their faces) and sphere-minus-box drops. */
    private static Tracer scene(SplittableRandom r) {
        List<Entity> es = new ArrayList<>();
        int n = 20 + r.nextInt(300);
        for (int k = 0; k < n; k++) {
            Vec3 c = gridPoint(r), e = v(STEP, STEP, STEP);
            switch (r.nextInt(3)) {
                case 0 -> es.add(box(c, c.plus(e), M));
                case 1 -> es.add(sphere(c.plus(e.times(r.nextDouble())), STEP * (0.1 + r.nextDouble() * 0.6), M));
                default -> es.add(csg(CsgOperation.DIFFERENCE, sphere(c, STEP * 0.7, M), box(c, c.plus(e), M)));
            }
        }
        Settings s = settings(camera(v(0, 0, -5), Vec3.ZERO, 60), List.of(), Background.BLACK, 4, 4);
        return new Tracer(new SceneGeometry(es), new Lights(s.lights()), new BackgroundShader(s.background(), 1));
    }

    @Test
    void blockedAnswersAsTheClosestHitWhateverTheCachedItem() {
        SplittableRandom r = new SplittableRandom(20261202);
        int blocked = 0, cachedAnswers = 0, total = 0;
        for (int s = 0; s < 20; s++) {
            Tracer t = scene(r);
            assertThat(t.blockedApplies()).isTrue();
            int[] items = t.items();
            int cache = Tracer.NONE;
            for (int k = 0; k < 3000; k++) {
                Vec3 o = r.nextBoolean() ? gridPoint(r) : v(r.nextGaussian() * 3, r.nextGaussian() * 3, r.nextGaussian() * 3);
                // to a grid point (box corners and edges), or a random point, or just short of a face
                Vec3 q = switch (r.nextInt(3)) {
                    case 0 -> gridPoint(r);
                    case 1 -> v(r.nextGaussian() * 3, r.nextGaussian() * 3, r.nextGaussian() * 3);
                    default -> gridPoint(r).plus(v(1e-13, -1e-13, 1e-13));
                };
                Vec3 d = q.minus(o);
                double len = d.length();
                if (len == 0) continue;
                Vec3 w = d.times(1 / len);
                double tMax = r.nextInt(4) == 0 ? len * (1 - 1e-15) : len;
                boolean lone = t.closestHit(o.x(), o.y(), o.z(), w.x(), w.y(), w.z(), tMax);
                // the cache as the shading keeps it, or now and then an item picked at random
                int cached = r.nextInt(4) == 0 ? items[r.nextInt(items.length)] : cache;
                boolean fast = t.blocked(o.x(), o.y(), o.z(), w.x(), w.y(), w.z(), tMax, cached);
                assertThat(fast).as("segment %d of scene %d", k, s).isEqualTo(lone);
                total++;
                if (fast) {
                    blocked++;
                    if (t.blocker == cached) cachedAnswers++;
                    cache = t.blocker;
                }
            }
        }
        // both ways of answering were taken
        assertThat(blocked).isBetween(total / 20, total - total / 20);
        assertThat(cachedAnswers).isPositive();
    }
}
