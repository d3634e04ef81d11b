package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.ApertureShape;
import dev.crt.scene.Background;
import dev.crt.scene.Camera;
import dev.crt.scene.CsgOperation;
import dev.crt.scene.Entity;
import dev.crt.scene.Material;
import dev.crt.scene.ParallelLight;
import dev.crt.scene.Light;
import dev.crt.scene.Mesh;
import dev.crt.scene.MeshData;
import dev.crt.scene.Rgb;
import dev.crt.scene.Settings;
import dev.crt.scene.SourceSpan;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The candidate lists give every ray what its own walk of the BVH gives: the same nearest hit, the same shadow factor to the bit. */
class CandidatesTest {
    private static final double STEP = 0.37, SHIFT = 0.1;
    private static final MeshData TORUS = Meshes.torus(0.3, 0.1, 10, 6);
    /** Opaque, transparent of several kt (so a product's order shows in its last bit), absorbing. */
    private static final Material[] PAINTS = {
        matte(rgb(0.5, 0.5, 0.5)),
        material(rgb(0.9, 0.9, 0.9), 0.2, 0, 30, 0, 0.3, 1.3),
        material(rgb(0.9, 0.9, 0.9), 0.2, 0, 30, 0, 0.77, 1.3),
        material(rgb(0.9, 0.9, 0.9), 0.2, 0, 30, 0, 0.9137, 1.3),
        new Material(rgb(0.8, 0.8, 0.8), 0.3, 0, 30, 0, 0.6, 1.5, Rgb.BLACK, true, false, rgb(0.3, 0.1, 0.7)),
    };

    private static Vec3 gridPoint(SplittableRandom r) {
        return v(STEP * (r.nextInt(9) - 4) + SHIFT, STEP * (r.nextInt(9) - 4) + SHIFT, STEP * (r.nextInt(9) - 4) + SHIFT);
    }

    /** Boxes packed on a grid (shared faces, edges and corners), spheres, sphere-minus-box drops, small meshes, now and then a plane. */
    private static List<Entity> field(SplittableRandom r, boolean transparent) {
        List<Entity> es = new ArrayList<>();
        int n = 20 + r.nextInt(250);
        for (int k = 0; k < n; k++) {
            Material m = transparent ? PAINTS[r.nextInt(PAINTS.length)] : PAINTS[0];
            Vec3 c = gridPoint(r), e = v(STEP, STEP, STEP);
            switch (r.nextInt(4)) {
                case 0 -> es.add(box(c, c.plus(e), m));
                case 1 -> es.add(sphere(c.plus(e.times(r.nextDouble())), STEP * (0.1 + r.nextDouble() * 0.6), m));
                case 2 -> es.add(csg(CsgOperation.DIFFERENCE, sphere(c, STEP * 0.7, m), box(c, c.plus(e), m)));
                default -> es.add(new Mesh(TORUS, r.nextBoolean(), m, Transform.translation(c), SourceSpan.NONE));
            }
        }
        if (r.nextInt(3) == 0) es.add(plane(v(0, 1, 0), v(0, -1.7, 0), PAINTS[0]));
        return es;
    }

    private static Tracer tracer(List<Entity> es, Settings s) {
        return new Tracer(new SceneGeometry(es), new Lights(s.lights()), new BackgroundShader(s.background(), 1));
    }

    private static Camera aimed(SplittableRandom r) {
        if (r.nextBoolean()) {
            // From a grid point straight along z: the middle column and row of rays run along box faces.
            Vec3 p = v(STEP * (r.nextInt(9) - 4) + SHIFT, STEP * (r.nextInt(9) - 4) + SHIFT, -4);
            return camera(p, p.plus(v(0, 0, 1)), 20 + r.nextInt(70));
        }
        Vec3 p = v(r.nextGaussian() * 3, r.nextGaussian() * 3, r.nextGaussian() * 3 - 5);
        return camera(p, v(r.nextGaussian(), r.nextGaussian(), r.nextGaussian()), 10 + r.nextInt(100));
    }

    @Test
    void aBlocksListGivesEachCameraRayTheHitOfItsOwnWalk() {
        checkBlocks(new SplittableRandom(20261202), false);
    }

    @Test
    void aBlocksListGivesEachLensRayTheHitOfItsOwnWalk() {
        checkBlocks(new SplittableRandom(20261203), true);
    }

    /**
     * Camera rays of 24 random fields, each through its block's list and by its own walk: the same
     * hit. With {@code lens}, the camera has a lens (up to a tenth of the field's size, focused
     * before, inside or behind the field) and each ray leaves it at a random point, its edge included.
     */
    private static void checkBlocks(SplittableRandom r, boolean lens) {
        int listed = 0, walked = 0, hits = 0, ties = 0;
        double[] d = new double[3], o = new double[3], l = new double[2];
        for (int scene = 0; scene < 24; scene++) {
            // Odd sizes too: the last row and column of blocks are cut short.
            int w = 2 * (8 + r.nextInt(40)) + (scene % 3 == 0 ? 1 : 0), h = 2 * (6 + r.nextInt(30));
            Camera aimed = aimed(r);
            if (lens) {
                aimed = new Camera(aimed.position(), aimed.pointing(), aimed.fov(), 0, 1 + r.nextInt(300),
                        0.5 + 9 * r.nextDouble(), scene % 2 == 0 ? ApertureShape.CIRCLE : ApertureShape.HEXAGON, SourceSpan.NONE);
            }
            Settings s = settings(aimed, List.of(), Background.BLACK, w, h);
            Tracer t = tracer(field(r, r.nextBoolean()), s);
            CameraRays camera = new CameraRays(s.camera(), w, h);
            assertThat(camera.framed()).isTrue();
            assertThat(camera.hasLens()).isEqualTo(lens);
            for (int k = 0; k < 4000; k++) {
                int i = r.nextInt(w), j = r.nextInt(h);
                if (k % 5 == 0) {
                    // through the middle of the image, along the camera's axis
                    i = w / 2;
                    j = h / 2;
                }
                double sx = sub(r), sy = sub(r);
                camera.direction(i, j, sx, sy, d);
                o[0] = camera.px;
                o[1] = camera.py;
                o[2] = camera.pz;
                if (lens) {
                    // The lens's rim (u1 near 1) as often as anywhere on it.
                    camera.aperture.sample(r.nextBoolean() ? Math.nextDown(1.0) : r.nextDouble(), r.nextDouble(), r.nextDouble(), l);
                    double[] aim = new double[CameraRays.AIM];
                    camera.aim(i, j, sx, sy, aim);
                    camera.throughLens(aim, l[0], l[1], o, d);
                }
                boolean lone = t.closestHit(o[0], o[1], o[2], d[0], d[1], d[2], Double.POSITIVE_INFINITY);
                double tLone = t.hit.t;
                int shape = t.hit.shape, face = t.hit.face;
                boolean flip = t.hit.flip;
                if (!t.candidates.block(camera, i, j)) {
                    walked++;
                    continue;
                }
                listed++;
                boolean fast = t.blockHit(o[0], o[1], o[2], d[0], d[1], d[2]);
                String what = "scene " + scene + ", pixel (" + i + ", " + j + ") + (" + sx + ", " + sy + ")";
                assertThat(fast).as(what).isEqualTo(lone);
                if (!lone) continue;
                hits++;
                if (t.hit.t != tLone || t.hit.shape != shape) {
                    // Two surfaces within rounding of each other (the field may place two items
                    // alike): the walk may cull the one whose box it enters at the other's t.
                    assertThat(t.hit.t).as(what).isCloseTo(tLone, org.assertj.core.data.Offset.offset(1e-12 * tLone));
                    ties++;
                    continue;
                }
                assertThat(t.hit.face).as(what).isEqualTo(face);
                assertThat(t.hit.flip).as(what).isEqualTo(flip);
            }
        }
        System.out.printf("block lists%s: %d rays listed, %d walked, %d hits, %d ties%n", lens ? " (lens)" : "", listed, walked,
                hits, ties);
        // All of them, when counted, between two tori meshes placed at the same point (most at exactly the same t).
        assertThat(ties).isLessThan(hits / 200);
        assertThat(listed).isGreaterThan(10 * walked);
        assertThat(hits).isBetween(listed / 10, listed - listed / 10);
    }

    /** A sub-pixel position: the pixel's edges, its centre, or anywhere. */
    private static double sub(SplittableRandom r) {
        return switch (r.nextInt(4)) {
            case 0 -> 0;
            case 1 -> Math.nextDown(1.0);
            case 2 -> 0.5;
            default -> r.nextDouble();
        };
    }

    @Test
    void aShadowListGivesEachShadowRayTheFactorOfItsOwnWalkToTheBit() {
        checkShadows(new SplittableRandom(42), false);
    }

    @Test
    void aShadowListAlongAParallelLightGivesEachShadowRayTheFactorOfItsOwnWalkToTheBit() {
        checkShadows(new SplittableRandom(43), true);
    }

    /**
     * Shadow rays from the surface points camera rays find in 16 random fields, each through its
     * (shape, light) list and by its own walk: the same factor to the bit. The light is a point
     * (on the grid or above the field) or, with {@code parallel}, a parallel light.
     */
    private static void checkShadows(SplittableRandom r, boolean parallel) {
        checkShadows(r, parallel, false);
    }

    @Test
    void aShadowListGrownOverAFieldOfColumnsGivesEachShadowRayTheFactorOfItsOwnWalkToTheBit() {
        checkShadows(new SplittableRandom(44), false, true);
        checkShadows(new SplittableRandom(45), true, true);
    }

    /**
     * Columns of random heights packed on a grid (the 2015 drops scene's field), some transparent,
     * seen from above: a column's top face and the upper parts of its sides cast the shadow rays,
     * so its lists cover a small region that grows as rays come from farther parts of it.
     */
    private static List<Entity> columns(SplittableRandom r) {
        List<Entity> es = new ArrayList<>();
        for (int i = -6; i < 6; i++) {
            for (int j = -6; j < 6; j++) {
                double top = 0.01 + r.nextDouble() * (r.nextInt(4) == 0 ? 0.6 : 0.2);
                Material m = r.nextInt(3) == 0 ? PAINTS[r.nextInt(PAINTS.length)] : PAINTS[0];
                es.add(box(v(0.5 * i, -3, 0.5 * j), v(0.5 * i + 0.5, top, 0.5 * j + 0.5), m));
            }
        }
        if (r.nextBoolean()) {
            es.add(csg(CsgOperation.DIFFERENCE, sphere(v(0.3, 1.2, 0.2), 0.6, PAINTS[2]), box(v(-1, 1.1, -1), v(1, 3, 1), PAINTS[0])));
        }
        return es;
    }

    private static void checkShadows(SplittableRandom r, boolean parallel, boolean columns) {
        int listed = 0, partial = 0, rays = 0;
        double[] d = new double[3];
        LightSample sample = new LightSample();
        for (int scene = 0; scene < 16; scene++) {
            // Among the columns' lights, some below their tops: rays from the sides then go down.
            Vec3 light = columns ? v(r.nextGaussian() * 3, -0.5 + r.nextDouble() * 4, r.nextGaussian() * 3)
                    : r.nextBoolean() ? gridPoint(r) : v(r.nextGaussian() * 8, 5 + r.nextDouble() * 10, r.nextGaussian() * 8);
            if (columns && parallel) light = v(r.nextGaussian(), 0.1 + r.nextDouble(), r.nextGaussian());
            Light source = parallel ? parallel(light, v(0, 0, 0), rgb(1, 1, 1), 0.1) : point(light, rgb(1, 1, 1), 0, 0.1);
            Camera eye = columns ? camera(v(r.nextGaussian() * 2, 1 + r.nextDouble() * 2, 4), v(r.nextGaussian(), 0, 0), 40 + r.nextInt(40))
                    : aimed(r);
            Settings s = settings(eye, List.of(source), Background.BLACK, 64, 48);
            Vec3 towards = parallel ? ((ParallelLight) source).towardsLight() : null;
            Lights lights = new Lights(s.lights());
            List<Entity> es = columns ? columns(r) : field(r, true);
            Tracer listing = tracer(es, s), walking = tracer(es, s);
            CameraRays camera = new CameraRays(s.camera(), 64, 48);
            SurfacePoint p = new SurfacePoint();
            for (int k = 0; k < 3000; k++) {
                // A shadow ray from a surface point a camera ray finds, off the surface by the tracer's offset, to the light.
                camera.direction(r.nextInt(64), r.nextInt(48), r.nextDouble(), r.nextDouble(), d);
                if (!walking.closestHit(camera.px, camera.py, camera.pz, d[0], d[1], d[2], Double.POSITIVE_INFINITY)) continue;
                int shape = walking.hit.shape;
                walking.shapes().surface(shape, walking.hit.face, walking.hit.t, walking.ray, p);
                double delta = Tracer.OFFSET * Math.max(Math.max(Math.abs(p.px), Math.abs(p.py)),
                        Math.max(Math.abs(p.pz), walking.shapes().scale[shape]));
                double nw = parallel ? p.nx * towards.x() + p.ny * towards.y() + p.nz * towards.z()
                        : p.nx * (light.x() - p.px) + p.ny * (light.y() - p.py) + p.nz * (light.z() - p.pz);
                double side = nw > 0 ? delta : -delta;
                double ox = p.px + side * p.nx, oy = p.py + side * p.ny, oz = p.pz + side * p.nz;
                walking.shading = Tracer.NONE;
                listing.shading = shape;
                listing.shadingFace = walking.hit.face;
                double lone, fast;
                boolean list;
                if (parallel) {
                    lights.sample(0, 0, p.px, p.py, p.pz, null, sample);
                    lone = walking.shadow(sample, p.px, p.py, p.pz, p.nx, p.ny, p.nz, side, 0);
                    list = listing.candidates.shadow(shape, walking.hit.face, 0, ox, oy, oz) >= 0;
                    fast = listing.shadow(sample, p.px, p.py, p.pz, p.nx, p.ny, p.nz, side, 0);
                } else {
                    lone = walking.shadowTo(ox, oy, oz, light.x(), light.y(), light.z(), side, 0);
                    list = listing.candidates.shadow(shape, walking.hit.face, 0, ox, oy, oz) >= 0;
                    fast = listing.shadowTo(ox, oy, oz, light.x(), light.y(), light.z(), side, 0);
                }
                String what = "scene " + scene + ", ray " + k + " from shape " + shape;
                assertThat(Double.doubleToRawLongBits(fast)).as(what).isEqualTo(Double.doubleToRawLongBits(lone));
                assertThat(listing.shadowR).as(what).isEqualTo(walking.shadowR);
                assertThat(listing.shadowG).as(what).isEqualTo(walking.shadowG);
                assertThat(listing.shadowB).as(what).isEqualTo(walking.shadowB);
                rays++;
                if (list) {
                    listed++;
                    if (lone > 0 && lone < 1) partial++;
                }
            }
        }
        System.out.printf("shadow lists%s%s: %d rays, %d listed, %d partly lit%n", parallel ? " (parallel light)" : "",
                columns ? " (columns)" : "", rays, listed, partial);
        // The lists were taken for many rays (the others' pairs weigh more listed than walked), and
        // many of those crossed transparent casters.
        // (A parallel light's sweep crosses the whole field: fewer of its lists pay.)
        assertThat(listed).isGreaterThan(rays / (parallel ? 20 : 10));
        assertThat(partial).isGreaterThan(listed / 20);
    }

    @Test
    void aReflectedRaysListGivesEachMirrorRayTheHitOfItsOwnWalk() {
        checkReflected(new SplittableRandom(46), false);
        checkReflected(new SplittableRandom(47), true);
    }

    /**
     * Mirror-reflected rays, three bounces deep, from the surface points camera rays find in random
     * fields (or fields of columns seen from above, with {@code columns}): each ray once through its
     * (shape, face) list and once by its own walk, the same t, shape, face and flip but where two
     * surfaces are within rounding of each other.
     */
    private static void checkReflected(SplittableRandom r, boolean columns) {
        int listed = 0, rays = 0, hits = 0, ties = 0;
        double[] d = new double[3];
        SurfacePoint p = new SurfacePoint();
        for (int scene = 0; scene < 16; scene++) {
            Camera eye = columns ? camera(v(r.nextGaussian() * 2, 1 + r.nextDouble() * 2, 4), v(r.nextGaussian(), 0, 0), 40 + r.nextInt(40))
                    : aimed(r);
            Settings s = settings(eye, List.of(), Background.BLACK, 64, 48);
            List<Entity> es = columns ? columns(r) : field(r, false);
            Tracer listing = tracer(es, s), walking = tracer(es, s);
            CameraRays camera = new CameraRays(s.camera(), 64, 48);
            for (int k = 0; k < 6000; k++) {
                camera.direction(r.nextInt(64), r.nextInt(48), r.nextDouble(), r.nextDouble(), d);
                double ox = camera.px, oy = camera.py, oz = camera.pz, dx = d[0], dy = d[1], dz = d[2];
                for (int bounce = 0; bounce < 3; bounce++) {
                    if (!walking.closestHit(ox, oy, oz, dx, dy, dz, Double.POSITIVE_INFINITY)) break;
                    // The mirror ray as Tracer.trace casts it: off the surface along the ray-facing geometric normal.
                    int shape = walking.hit.shape, face = walking.hit.face;
                    walking.shapes().surface(shape, face, walking.hit.t, walking.ray, p);
                    double nx = p.nx, ny = p.ny, nz = p.nz;
                    if (walking.hit.flip) {
                        nx = -nx;
                        ny = -ny;
                        nz = -nz;
                    }
                    double dn = dx * nx + dy * ny + dz * nz;
                    if (dn > 0) {
                        nx = -nx;
                        ny = -ny;
                        nz = -nz;
                        dn = -dn;
                    }
                    double delta = Tracer.OFFSET * Math.max(Math.max(Math.abs(p.px), Math.abs(p.py)),
                            Math.max(Math.abs(p.pz), walking.shapes().scale[shape]));
                    ox = p.px + delta * nx;
                    oy = p.py + delta * ny;
                    oz = p.pz + delta * nz;
                    dx -= 2 * dn * nx;
                    dy -= 2 * dn * ny;
                    dz -= 2 * dn * nz;
                    if (k % 8 == 0) {
                        // Now and then a ray from the same point in a direction near the mirror's, off
                        // the surface: a list must not take a ray whose direction lies outside its own.
                        double gx = dx + 0.3 * r.nextGaussian(), gy = dy + 0.3 * r.nextGaussian(), gz = dz + 0.3 * r.nextGaussian();
                        double g = Math.sqrt(gx * gx + gy * gy + gz * gz), gn = gx * nx + gy * ny + gz * nz;
                        if (gn < 0) g = -g;
                        sameHit(listing, walking, shape, face, ox, oy, oz, gx / g, gy / g, gz / g, "scene " + scene + ", ray " + k);
                    }
                    boolean lone = walking.closestHit(ox, oy, oz, dx, dy, dz, Double.POSITIVE_INFINITY);
                    double tLone = walking.hit.t;
                    boolean list = listing.candidates.reflected(shape, face, ox, oy, oz, dx, dy, dz) >= 0;
                    boolean fast = listing.reflectedHit(shape, face, ox, oy, oz, dx, dy, dz);
                    String what = "scene " + scene + ", ray " + k + ", bounce " + bounce + " from shape " + shape;
                    rays++;
                    if (list) listed++;
                    assertThat(fast).as(what).isEqualTo(lone);
                    if (!lone) break;
                    hits++;
                    if (listing.hit.t != tLone || listing.hit.shape != walking.hit.shape) {
                        assertThat(listing.hit.t).as(what).isCloseTo(tLone, org.assertj.core.data.Offset.offset(1e-12 * tLone));
                        ties++;
                        continue;
                    }
                    assertThat(listing.hit.face).as(what).isEqualTo(walking.hit.face);
                    assertThat(listing.hit.flip).as(what).isEqualTo(walking.hit.flip);
                }
            }
        }
        System.out.printf("reflected lists%s: %d rays, %d listed, %d hits, %d ties%n", columns ? " (columns)" : "", rays, listed,
                hits, ties);
        assertThat(ties).isLessThan(hits / 200 + 1);
        // Random fields scatter mirror rays every way: few of their lists pay; a field of columns' do.
        assertThat(listed).isGreaterThan(rays / (columns ? 10 : 60));
        assertThat(hits).isGreaterThan(rays / 10);
    }

    /** The ray through {@code listing}'s reflected-ray list (or walk) and by {@code walking}'s walk: the same hit, ties aside. */
    private static void sameHit(Tracer listing, Tracer walking, int shape, int face, double ox, double oy, double oz, double dx,
            double dy, double dz, String what) {
        boolean lone = walking.closestHit(ox, oy, oz, dx, dy, dz, Double.POSITIVE_INFINITY);
        boolean fast = listing.reflectedHit(shape, face, ox, oy, oz, dx, dy, dz);
        assertThat(fast).as(what).isEqualTo(lone);
        if (!lone || listing.hit.t != walking.hit.t) {
            if (lone) assertThat(listing.hit.t).as(what).isCloseTo(walking.hit.t, org.assertj.core.data.Offset.offset(1e-12 * walking.hit.t));
            return;
        }
        assertThat(listing.hit.shape).as(what).isEqualTo(walking.hit.shape);
        assertThat(listing.hit.face).as(what).isEqualTo(walking.hit.face);
    }

    /**
     * A pixel's shadow rays leave the surfaces its camera rays and their reflections hit, in turn:
     * rays leaving two columns' tops by turns find their lists in the cache once those are built,
     * without searching the records (one cache entry per light searched every time).
     */
    @Test
    void shadowRaysLeavingTwoSurfacesByTurnsFindTheirListsInTheCache() {
        SplittableRandom r = new SplittableRandom(46);
        List<Entity> es = columns(r);
        Vec3 light = v(0.4, 3.9, 0.5);
        Settings s = settings(camera(v(1.9, 1.7, 4.2), v(0, 0, 0), 60), List.of(point(light, rgb(1, 1, 1), 0, 0)),
                Background.BLACK, 64, 48);
        Tracer t = tracer(es, s), probe = tracer(es, s);
        // Two columns whose tops (the face a ray straight down meets) take different cache entries.
        int[] shape = new int[2], face = new int[2];
        double[][] centre = new double[2][];
        int found = 0;
        for (int i = -5; i < 5 && found < 2; i += 3) {
            double x = 0.5 * i + 0.25, z = 0.25 - 0.5 * found;
            assertThat(probe.closestHit(x, 5, z, 0, -1, 0, Double.POSITIVE_INFINITY)).isTrue();
            if (found == 1 && Candidates.way(probe.hit.shape, probe.hit.face) == Candidates.way(shape[0], face[0])) continue;
            shape[found] = probe.hit.shape;
            face[found] = probe.hit.face;
            centre[found] = new double[] {x, 5 - probe.hit.t, z};
            found++;
        }
        assertThat(found).isEqualTo(2);
        long before = 0;
        for (int k = 0; k < 400; k++) {
            if (k == 200) before = t.candidates.searches;
            int c = k % 2;
            // A point of the top's middle part, just above it.
            double ox = centre[c][0] + (r.nextDouble() - 0.5) * 0.3, oz = centre[c][2] + (r.nextDouble() - 0.5) * 0.3;
            double oy = centre[c][1] + 1e-9;
            t.shading = shape[c];
            t.shadingFace = face[c];
            t.shadowTo(ox, oy, oz, light.x(), light.y(), light.z(), 1e-9, 0);
        }
        // Past their trials and growths, the last 200 rays (100 from each top) search at most a few times.
        assertThat(t.candidates.searches - before).isLessThan(10);
    }

    @Test
    void listedRaysAllocateNothingOnceTheirListsAreBuilt() {
        final int PASSES = Candidates.REFLECTED_AFTER + 4;
        SplittableRandom r = new SplittableRandom(7);
        List<Entity> es = new ArrayList<>();
        for (int k = 0; k < 2000; k++) {
            es.add(sphere(v(r.nextDouble() * 8 - 4, r.nextDouble() * 8 - 4, r.nextDouble() * 8 - 4), 0.15, PAINTS[0]));
        }
        Vec3 light = v(-6, 9, -10);
        Settings s = settings(camera(v(0, 0, -12), Vec3.ZERO, 40), List.of(point(light, rgb(1, 1, 1), 0, 0.1)),
                Background.BLACK, 64, 48);
        Tracer t = tracer(es, s);
        CameraRays camera = new CameraRays(s.camera(), 64, 48);
        double[] d = new double[3];
        var threads = (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        long id = Thread.currentThread().getId();
        long allocated = 0;
        int listed = 0;
        for (int pass = 0; pass < PASSES; pass++) {
            long before = threads.getThreadAllocatedBytes(id);
            for (int j = 0; j < 48; j++) {
                for (int i = 0; i < 64; i++) {
                    camera.direction(i, j, 0.5, 0.5, d);
                    if (!t.candidates.block(camera, i, j)) continue;
                    if (!t.blockHit(camera.px, camera.py, camera.pz, d[0], d[1], d[2])) continue;
                    int shape = t.hit.shape, face = t.hit.face;
                    double hx = camera.px + t.hit.t * d[0], hy = camera.py + t.hit.t * d[1], hz = camera.pz + t.hit.t * d[2];
                    t.shading = shape;
                    t.shadingFace = t.hit.face;
                    if (pass == PASSES - 1 && t.candidates.shadow(shape, t.hit.face, 0, hx, hy, hz) >= 0) listed++;
                    t.shadowTo(hx, hy, hz, light.x(), light.y(), light.z(), 0, 0);
                    // A ray leaving the hit, as a mirror ray would take its list (or walk).
                    t.reflectedHit(shape, face, hx, hy, hz, d[0], -d[1], d[2]);
                }
            }
            // A list is built after its record's trial walks (16 for reflected rays) and grown as
            // rays outside it come: by the last pass every list is built.
            if (pass == PASSES - 1) allocated = threads.getThreadAllocatedBytes(id) - before;
        }
        assertThat(listed).isGreaterThan(100);
        assertThat(allocated).as("bytes allocated by %d listed shadow rays, their blocks' camera rays and reflected rays", listed).isZero();
    }
}
