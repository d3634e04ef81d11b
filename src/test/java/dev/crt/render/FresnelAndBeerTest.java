package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.crt.geom.Vec3;
import dev.crt.image.FrameBuffer;
import dev.crt.scene.Csg;
import dev.crt.scene.CsgOperation;
import dev.crt.scene.Entity;
import dev.crt.scene.Material;
import dev.crt.scene.Rgb;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import dev.crt.scene.SolidBackground;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The Fresnel equations and Beer's law against their formulas (rendering-model.md, "Second wave"). */
class FresnelAndBeerTest {
    private static double cosT(double cosI, double eta) { return Math.sqrt(1 - eta * eta * (1 - cosI * cosI)); }

    @Test
    void atNormalIncidenceTheReflectanceIsTheSquaredIndexContrast() {
        for (double n : new double[] {1.0, 1.33, 1.5, 2.42, 0.7}) {
            double expected = Math.pow((n - 1) / (n + 1), 2);
            assertThat(Fresnel.reflectance(1, 1, 1 / n)).isCloseTo(expected, within(1e-15));
            assertThat(Fresnel.reflectance(1, 1, n)).as("leaving").isCloseTo(expected, within(1e-15));
        }
    }

    @Test
    void atBrewstersAngleTheParallelPartVanishes() {
        for (double n : new double[] {1.33, 1.5, 2.42}) {
            double theta = Math.atan(n);
            double cosI = Math.cos(theta), eta = 1 / n;
            assertThat(Fresnel.parallel(cosI, cosT(cosI, eta), eta)).isCloseTo(0, within(1e-15));
            assertThat(Math.abs(Fresnel.perpendicular(cosI, cosT(cosI, eta), eta))).isGreaterThan(0.1);
            // Leaving the denser medium, Brewster's angle is atan(1/n).
            double inside = Math.cos(Math.atan(1 / n));
            assertThat(Fresnel.parallel(inside, cosT(inside, n), n)).isCloseTo(0, within(1e-15));
        }
    }

    @Test
    void reflectedAndTransmittedPowerAddUpToOne() {
        // The transmitted power from the Fresnel transmission coefficients, not from 1 − R.
        Random random = new Random(13);
        for (int k = 0; k < 10_000; k++) {
            double n1 = 1 + random.nextDouble() * 1.5, n2 = 1 + random.nextDouble() * 1.5;
            double cosI = random.nextDouble();
            double eta = n1 / n2;
            double k2 = 1 - eta * eta * (1 - cosI * cosI);
            if (k2 < 0) continue;
            double cosT = Math.sqrt(k2);
            double ts = 2 * n1 * cosI / (n1 * cosI + n2 * cosT), tp = 2 * n1 * cosI / (n2 * cosI + n1 * cosT);
            double transmitted = n2 * cosT / (n1 * cosI) * 0.5 * (ts * ts + tp * tp);
            if (cosI < 1e-6) continue;
            assertThat(Fresnel.reflectance(cosI, cosT, eta) + transmitted).isCloseTo(1, within(1e-12));
        }
    }

    private static Settings straightOn(Rgb background, int depth, List<dev.crt.scene.Light> lights) {
        Settings s = settings(camera(v(0, 0, -5), Vec3.ZERO, 10), lights, new SolidBackground(background), 9, 9);
        return new Settings(s.title(), s.author(), s.date(), s.notes(), s.lights(), s.camera(), s.background(), 1, 1,
                depth, 1, s.width(), s.height());
    }

    private static Material glass(double ior, boolean fresnel, Rgb absorption) {
        return new Material(Rgb.WHITE, 1, 0, 30, 0, 1, ior, Rgb.BLACK, true, fresnel, absorption);
    }

    @Test
    void aSlabOfThicknessDTintsByExpMinusAD() {
        Rgb bg = rgb(0.9, 0.8, 0.7), a = rgb(0.5, 1.5, 3);
        double d = 0.75;
        Settings s = straightOn(bg, 5, List.of());
        Scene scene = scene(s, box(v(-10, -10, -1), v(10, 10, -1 + d), glass(1, false, a)));
        FrameBuffer fb = Renderer.prepare(scene).render(1, RenderMonitor.NONE);
        // The centre pixel's ray is the axis: no bending, a path of exactly d inside.
        assertThat((double) fb.get(4, 4, 0)).isCloseTo(0.9 * Math.exp(-0.5 * d), within(1e-6));
        assertThat((double) fb.get(4, 4, 1)).isCloseTo(0.8 * Math.exp(-1.5 * d), within(1e-6));
        assertThat((double) fb.get(4, 4, 2)).isCloseTo(0.7 * Math.exp(-3 * d), within(1e-6));
    }

    @Test
    void fresnelGlassReflectsAndTransmitsByTheEquations() {
        // At normal incidence through a slab with depth 2: Fr·bg from the front face, then the ray
        // inside leaves through the back face with (1 − Fr) (the back reflection reaches depth 0,
        // where a fully transparent surface shows black): bg·(Fr + (1 − Fr)²·exp(−a·d)).
        double ior = 1.5, fr = Math.pow((ior - 1) / (ior + 1), 2), d = 0.5;
        Rgb bg = rgb(1, 0.5, 0.25);
        Settings s = straightOn(bg, 2, List.of());
        Scene scene = scene(s, box(v(-10, -10, -1), v(10, 10, -1 + d), glass(ior, true, rgb(0.4, 0.4, 0.4))));
        FrameBuffer fb = Renderer.prepare(scene).render(1, RenderMonitor.NONE);
        double factor = fr + (1 - fr) * (1 - fr) * Math.exp(-0.4 * d);
        assertThat((double) fb.get(4, 4, 0)).isCloseTo(1 * factor, within(1e-6));
        assertThat((double) fb.get(4, 4, 1)).isCloseTo(0.5 * factor, within(1e-6));
        assertThat((double) fb.get(4, 4, 2)).isCloseTo(0.25 * factor, within(1e-6));
        // Without fresnel the same slab passes everything: kt = 1, no reflection.
        Scene plain = scene(s, box(v(-10, -10, -1), v(10, 10, -1 + d), glass(ior, false, Rgb.BLACK)));
        assertThat(Renderer.prepare(plain).render(1, RenderMonitor.NONE).get(4, 4, 0)).isCloseTo(1f, within(1e-6f));
    }

    /** The absorbing slabs below: thickness, transparency, and the absorption of each channel. */
    private static final double D = 0.5, KT = 0.8;
    private static final double[] ABSORPTION = {0.2, 1, 2};
    private static final Material SLAB = new Material(Rgb.WHITE, 1, 0, 30, 0, KT, 1.5, Rgb.BLACK, true, false,
            rgb(ABSORPTION[0], ABSORPTION[1], ABSORPTION[2]));

    /**
     * The camera sits between {@code solid} (behind it) and a white wall; the parallel light shines
     * through the solid along +z, so each wall point's shadow ray crosses it. 9 × 9 pixels.
     */
    private static FrameBuffer wallLitThrough(Entity solid) {
        Settings s = settings(camera(v(0, 0, -0.9), Vec3.ZERO, 40), List.of(parallel(v(0, 0, -10), Vec3.ZERO, Rgb.WHITE, 0)),
                new SolidBackground(Rgb.BLACK), 9, 9);
        return Renderer.prepare(scene(s, plane(v(0, 0, -1), Vec3.ZERO, matte(Rgb.WHITE)), solid)).render(1, RenderMonitor.NONE);
    }

    /** Channel c of the wall behind {@code thickness} of the slabs' glass, crossed at two faces: kt²·exp(−a·thickness). */
    private static double throughSlab(int c, double thickness) {
        return KT * KT * Math.exp(-ABSORPTION[c] * thickness);
    }

    @Test
    void shadowRaysThroughAbsorbingGlassAreTintedByTheDistanceInside() {
        FrameBuffer fb = wallLitThrough(box(v(-50, -50, -1 - D), v(50, 50, -1), SLAB));
        for (int c = 0; c < 3; c++) {
            assertThat((double) fb.get(4, 4, c)).isCloseTo(throughSlab(c, D), within(1e-6));
            assertThat((double) fb.get(0, 0, c)).isCloseTo(throughSlab(c, D), within(1e-6));
        }
    }

    @Test
    void shadowRaysThroughAbsorbingCsgSolidsAreTintedByTheDistanceInsideTheResult() {
        // As above, with the slab made by CSG: a thick slab minus its back part (d left), and the
        // union of two overlapping slabs (1.5·d in all, crossed at its two outer faces only).
        Csg cut = csg(CsgOperation.DIFFERENCE, box(v(-50, -50, -1 - 2 * D), v(50, 50, -1), SLAB),
                box(v(-60, -60, -5), v(60, 60, -1 - D), SLAB));
        Csg joined = csg(CsgOperation.UNION, box(v(-50, -50, -1 - D), v(50, 50, -1), SLAB),
                box(v(-50, -50, -1 - 1.5 * D), v(50, 50, -1 - 0.5 * D), SLAB));
        double[] thickness = {D, 1.5 * D};
        Csg[] solids = {cut, joined};
        for (int k = 0; k < 2; k++) {
            FrameBuffer fb = wallLitThrough(solids[k]);
            for (int c = 0; c < 3; c++) {
                assertThat((double) fb.get(4, 4, c)).as("solid %d channel %d", k, c)
                        .isCloseTo(throughSlab(c, thickness[k]), within(1e-6));
            }
        }
    }

    /**
     * The union of an absorbing slab and an opaque block over half of it: the wall's shadow rays on
     * the block's side are stopped by the union, which each render thread then tests first for the
     * next shadow ray; on the other side that ray crosses the slab alone, and its absorption must
     * be counted once, not once for that first test and again in the ray's own walk.
     */
    @Test
    void aShadowRayTestingItsLastOccluderFirstCountsItsAbsorptionOnce() {
        Csg half = csg(CsgOperation.UNION, box(v(-50, -50, -1 - D), v(50, 50, -1), SLAB),
                box(v(-50, -50, -1 - D), v(0, 50, -1), matte(Rgb.WHITE)));
        FrameBuffer fb = wallLitThrough(half);
        int lit = 0, dark = 0;
        for (int y = 0; y < 9; y++) {
            for (int x = 0; x < 9; x++) {
                if (fb.get(x, y, 0) == 0) {
                    dark++;
                    continue;
                }
                lit++;
                for (int c = 0; c < 3; c++) {
                    assertThat((double) fb.get(x, y, c)).as("(%d, %d) channel %d", x, y, c).isCloseTo(throughSlab(c, D), within(1e-6));
                }
            }
        }
        assertThat(lit).isGreaterThan(20);
        assertThat(dark).isGreaterThan(20);
    }
}
