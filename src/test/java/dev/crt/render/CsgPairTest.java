package dev.crt.render;

import static dev.crt.render.Scenes.box;
import static dev.crt.render.Scenes.material;
import static dev.crt.render.Scenes.plane;
import static dev.crt.render.Scenes.rgb;
import static dev.crt.render.Scenes.sphere;
import static dev.crt.render.Scenes.v;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Aabb;
import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.Csg;
import dev.crt.scene.CsgOperation;
import dev.crt.scene.Material;
import dev.crt.scene.Primitive;
import dev.crt.scene.SourceSpan;
import dev.crt.scene.Torus;
import java.util.SplittableRandom;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;

/**
 * The two-operand CSG walk answers exactly as the general event walk: the same hit (distance,
 * shape, face, side) and the same transmittance, on trees built to have coincident faces, rays
 * along faces and through edges, and operands (a torus) that send it to the general walk.
 */
class CsgPairTest {
    private static final CsgOperation[] OPS = CsgOperation.values();

    @Property(tries = 300)
    void pairWalkEqualsTheGeneralWalk(@ForAll long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        check(r, new Material[] {material(rgb(1, 0, 0), 1, 0, 1, 0, 0, 1), material(rgb(0, 1, 0), 1, 0, 1, 0, 0.5, 1.5)});
    }

    /**
     * Both operands opaque, as in drops.crt's bowls: a shadow ray's pair walk then answers 0 without
     * sorting when one event stands alone where the inside changes, which must agree with the
     * general walk on coincident faces, rays along faces and events within the tie tolerance.
     */
    @Property(tries = 300)
    void opaquePairsShadowAsTheGeneralWalk(@ForAll long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        check(r, new Material[] {material(rgb(1, 0, 0), 1, 0, 1, 0, 0, 1), material(rgb(0, 1, 0), 1, 0.5, 1, 0, 0, 1)});
    }

    private static void check(SplittableRandom r, Material[] mats) {
        Csg tree = new Csg(OPS[r.nextInt(OPS.length)], operand(r, mats), operand(r, mats), Transform.IDENTITY,
                SourceSpan.NONE);
        Pair pair = new Pair(tree);
        Ray ray = new Ray();
        Hit fast = new Hit(), general = new Hit();
        for (int k = 0; k < 200; k++) {
            Vec3 o = v(grid(r, 3), grid(r, 3), grid(r, 3));
            Vec3 d = r.nextInt(3) == 0 ? axis(r) : Scenes.unit(r);
            ray.set(o.x(), o.y(), o.z(), d.x(), d.y(), d.z());
            // Half units too: axis rays from grid points meet faces there, exactly at tMax.
            int kind = r.nextInt(3);
            double tMax = kind == 0 ? Double.POSITIVE_INFINITY : kind == 1 ? r.nextDouble() * 6 : r.nextInt(13) * 0.5;
            fast.t = general.t = -1;
            boolean a = pair.closestHit(ray, tMax, fast);
            boolean b = pair.walk(ray, tMax, general) != 0;
            assertThat(a).as("hit at all").isEqualTo(b);
            if (a) {
                assertThat(fast.t).as("distance").isEqualTo(general.t);
                assertThat(fast.shape).isEqualTo(general.shape);
                assertThat(fast.face).isEqualTo(general.face);
                assertThat(fast.flip).isEqualTo(general.flip);
            }
            assertThat(pair.transmittance(ray, tMax))
                    .isEqualTo(pair.walk(ray, tMax, null));
        }
    }

    /**
     * Sphere − box where the box's exit lies a hair (inside the tie tolerance) before the sphere's
     * entry and tMax between them: the walk groups the two events and finds the box's exit, so the
     * pair walk may not give up on a first operand entered just beyond tMax.
     */
    @org.junit.jupiter.api.Test
    void aDifferenceFindsAnExitJustBeforeItsFirstOperandsEntryBeyondTMax() {
        Material m = material(rgb(1, 1, 1), 1, 0, 1, 0, 0, 1);
        double eps = 1e-15;
        Csg tree = new Csg(CsgOperation.DIFFERENCE, sphere(v(0, 0, 0), 1, m), box(v(-5, -5, -5), v(-1 - eps, 5, 5), m),
                Transform.IDENTITY, SourceSpan.NONE);
        Pair pair = new Pair(tree);
        Ray ray = new Ray();
        ray.set(-3, 0, 0, 1, 0, 0);
        double tMax = 2 - eps / 2;
        Hit fast = new Hit(), general = new Hit();
        assertThat(pair.walk(ray, tMax, general)).isEqualTo(1);
        assertThat(general.t).isLessThan(tMax);
        assertThat(pair.closestHit(ray, tMax, fast)).isTrue();
        assertThat(fast.t).isEqualTo(general.t);
        assertThat(fast.shape).isEqualTo(general.shape);
        assertThat(pair.transmittance(ray, tMax)).isEqualTo(0.0);
    }

    /**
     * Two opaque boxes united, the second's face a hair (inside the tie tolerance) beyond the
     * first's: a shadow ray from inside the first to inside the second crosses no boundary of the
     * union (the walk takes the two events together), so neither event may be taken alone as a
     * crossing.
     */
    @org.junit.jupiter.api.Test
    void anOpaqueUnionsInnerSeamDoesNotBlock() {
        Material m = material(rgb(1, 1, 1), 1, 0, 1, 0, 0, 1);
        double eps = 1e-15;
        Csg tree = new Csg(CsgOperation.UNION, box(v(-2, -1, -1), v(0, 1, 1), m), box(v(eps, -1, -1), v(2, 1, 1), m),
                Transform.IDENTITY, SourceSpan.NONE);
        Pair pair = new Pair(tree);
        Ray ray = new Ray();
        ray.set(-1, 0, 0, 1, 0, 0);
        assertThat(pair.walk(ray, 2, null)).isEqualTo(1.0);
        assertThat(pair.transmittance(ray, 2)).isEqualTo(1.0);
        // Past the second box's far face the segment leaves the union: blocked.
        assertThat(pair.transmittance(ray, 4)).isEqualTo(0.0);
    }

    /** A CSG tree added to fresh stores as the renderer adds one, and its three queries. */
    private static final class Pair {
        private final Shapes shapes = new Shapes();
        private final Materials materials = new Materials();
        private final CsgSolids csg = new CsgSolids();
        private final LineSpan span = new LineSpan();
        private final int tree;
        private final CsgSolids.Scratch scratch;

        Pair(Csg tree) {
            this.tree = csg.add(tree, Transform.IDENTITY, shapes, p -> materials.indexOf(p.material()), new Aabb[1]);
            scratch = new CsgSolids.Scratch(csg);
        }

        boolean closestHit(Ray ray, double tMax, Hit hit) {
            return csg.closestHit(tree, ray, tMax, shapes, materials, span, scratch, hit);
        }

        double walk(Ray ray, double tMax, Hit hit) {
            return csg.walk(tree, ray, tMax, hit, shapes, materials, span, scratch);
        }

        double transmittance(Ray ray, double tMax) {
            return csg.transmittance(tree, ray, tMax, shapes, materials, span, scratch);
        }
    }

    /** Coordinates on a half-unit grid, so that operands share faces and rays run along them. */
    private static double grid(SplittableRandom r, int n) {
        return (r.nextInt(4 * n + 1) - 2 * n) * 0.5;
    }

    private static Vec3 axis(SplittableRandom r) {
        double s = r.nextBoolean() ? 1 : -1;
        return switch (r.nextInt(3)) {
            case 0 -> v(s, 0, 0);
            case 1 -> v(0, s, 0);
            default -> v(0, 0, s);
        };
    }

    private static Primitive operand(SplittableRandom r, Material[] mats) {
        Material m = mats[r.nextInt(mats.length)];
        switch (r.nextInt(6)) {
            case 0, 1: {
                Vec3 a = v(grid(r, 1), grid(r, 1), grid(r, 1));
                return box(a, a.plus(v(0.5 + r.nextInt(4) * 0.5, 0.5 + r.nextInt(4) * 0.5, 0.5 + r.nextInt(4) * 0.5)), m);
            }
            case 2:
                return sphere(v(grid(r, 1), grid(r, 1), grid(r, 1)), 0.5 + r.nextInt(3) * 0.5, m);
            case 3:
                return plane(axis(r), v(grid(r, 1), grid(r, 1), grid(r, 1)), m);
            case 4:
                return box(v(-1, -1, -1), v(1, 1, 1), m).transformed(Transform.rotation(v(0, 45 * r.nextInt(2), 30)));
            default:
                return new Torus(v(0, 0, 0), v(0, 1, 0), 1.5, 0.5, m, Transform.IDENTITY, SourceSpan.NONE);
        }
    }
}
