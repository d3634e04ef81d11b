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

/** A packet's nearest hits are, ray by ray, the lone walk's: t, item, face and flip, ties included. */
class PacketWalkerTest {
    private static final Material M = matte(rgb(0.5, 0.5, 0.5));
    /** The grid's spacing and offset: not powers of two, so slab distances round. */
    private static final double STEP = 0.37, SHIFT = 0.1;

    private static Vec3 gridPoint(SplittableRandom r) {
        return v(STEP * (r.nextInt(9) - 4) + SHIFT, STEP * (r.nextInt(9) - 4) + SHIFT, STEP * (r.nextInt(9) - 4) + SHIFT);
    }

    /** Random spheres, boxes packed on a grid (shared faces, edges and corners: ties in t) and small CSG trees. */
    private static Tracer scene(SplittableRandom r) {
        List<Entity> es = new ArrayList<>();
        int n = 20 + r.nextInt(400);
        for (int k = 0; k < n; k++) {
            Vec3 c = gridPoint(r), e = v(STEP, STEP, STEP);
            switch (r.nextInt(4)) {
                case 0 -> es.add(box(c, c.plus(e), M));
                case 1 -> es.add(sphere(c.plus(e.times(r.nextDouble())), STEP * (0.1 + r.nextDouble() * 0.6), M));
                case 2 -> es.add(sphere(c, STEP / 2, M));
                default -> es.add(csg(CsgOperation.DIFFERENCE, sphere(c, STEP * 0.7, M), box(c, c.plus(e), M)));
            }
        }
        Settings s = settings(camera(v(0, 0, -5), Vec3.ZERO, 60), List.of(), Background.BLACK, 4, 4);
        return new Tracer(new SceneGeometry(es), new Lights(s.lights()), new BackgroundShader(s.background(), 1));
    }

    /** Fills the packet with {@code count} rays of one of several kinds and checks each against the lone walk. */
    private static void check(Tracer t, SplittableRandom r, int count) {
        RayPacket p = t.packet;
        int kind = r.nextInt(6);
        Vec3 o = v(r.nextDouble() * 16 - 8, r.nextDouble() * 16 - 8, -12 + r.nextDouble() * 4);
        if (kind == 5) o = gridPoint(r); // on grid planes, inside the field
        Vec3 aim = v(r.nextDouble() * 3 - 1.5, r.nextDouble() * 3 - 1.5, r.nextDouble() * 3 - 1.5);
        double spread = r.nextInt(3) == 0 ? 1 : 0.05;
        for (int k = 0; k < count; k++) {
            Vec3 d = switch (kind) {
                // a coherent bundle from one point
                case 0, 5 -> aim.plus(v(r.nextGaussian(), r.nextGaussian(), r.nextGaussian()).times(spread)).minus(o);
                // through grid points: the shared edges and corners of the boxes
                case 1 -> gridPoint(r).minus(o);
                // along an axis, or in a grid plane (zero direction components)
                case 2 -> r.nextBoolean() ? v(0, 0, 1) : v(r.nextGaussian(), 0, 1);
                // any direction (mixed octants)
                case 3 -> unit(r);
                // grazing a face: in the plane z = integer
                default -> v(r.nextGaussian(), r.nextGaussian(), 0);
            };
            Vec3 g = gridPoint(r);
            Vec3 from = kind == 4 ? v(o.x(), o.y(), g.z()) : kind == 2 ? v(g.x(), g.y(), -10) : o;
            p.set(k, from.x(), from.y(), from.z(), d.x(), d.y(), d.z());
        }
        p.count = count;
        t.closestHits();
        for (int k = 0; k < count; k++) {
            boolean found = t.closestHit(p.ox[k], p.oy[k], p.oz[k], p.dx[k], p.dy[k], p.dz[k], Double.POSITIVE_INFINITY);
            assertThat(p.found[k]).as("ray %d of kind %d found", k, kind).isEqualTo(found);
            if (!found) continue;
            Hit h = p.hits[k];
            assertThat(new double[] {h.t, h.shape, h.face, h.flip ? 1 : 0}).as("ray %d of kind %d", k, kind)
                    .containsExactly(t.hit.t, t.hit.shape, t.hit.face, t.hit.flip ? 1 : 0);
        }
    }

    @Test
    void everyRayOfRandomPacketsHitsWhatItsLoneWalkHits() {
        SplittableRandom r = new SplittableRandom(20261202);
        for (int s = 0; s < 30; s++) {
            Tracer t = scene(r);
            for (int k = 0; k < 60; k++) check(t, r, r.nextInt(3) == 0 ? RayPacket.SIZE : r.nextInt(RayPacket.SIZE + 1));
        }
    }

    @Test
    void emptyAndSingleRayPackets() {
        SplittableRandom r = new SplittableRandom(7);
        Tracer t = scene(r);
        check(t, r, 0);
        for (int k = 0; k < 50; k++) check(t, r, 1);
    }

    @Test
    void packetsOfMissesAndOfRaysDroppedByDisagreement() {
        SplittableRandom r = new SplittableRandom(11);
        Tracer t = scene(r);
        RayPacket p = t.packet;
        // every ray away from the field: nothing active below the root
        for (int k = 0; k < RayPacket.SIZE; k++) p.set(k, 0, 0, -20, r.nextDouble() - 0.5, r.nextDouble() - 0.5, -1);
        p.count = RayPacket.SIZE;
        t.closestHits();
        for (int k = 0; k < RayPacket.SIZE; k++) assertThat(p.found[k]).isFalse();
        // rays from both sides of the field towards each other order every node's children oppositely
        for (int k = 0; k < RayPacket.SIZE; k++) {
            double z = k % 2 == 0 ? -20 : 20;
            p.set(k, 0.1 * (k % 7) + 0.05, 0.1 * (k % 5) + 0.05, z, 0.01, 0.02, -z);
        }
        p.count = RayPacket.SIZE;
        t.closestHits();
        int found = 0;
        for (int k = 0; k < RayPacket.SIZE; k++) {
            boolean lone = t.closestHit(p.ox[k], p.oy[k], p.oz[k], p.dx[k], p.dy[k], p.dz[k], Double.POSITIVE_INFINITY);
            assertThat(p.found[k]).isEqualTo(lone);
            if (lone) {
                found++;
                assertThat(p.hits[k].t).isEqualTo(t.hit.t);
                assertThat(p.hits[k].shape).isEqualTo(t.hit.shape);
            }
        }
        assertThat(found).isPositive();
    }
}
