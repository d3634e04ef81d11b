package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.image.FrameBuffer;
import dev.crt.scene.Background;
import dev.crt.scene.Box;
import dev.crt.scene.Checker;
import dev.crt.scene.Entity;
import dev.crt.scene.Material;
import dev.crt.scene.Plane;
import dev.crt.scene.Rgb;
import dev.crt.scene.Settings;
import dev.crt.scene.SourceSpan;
import java.util.List;
import java.util.function.Function;
import org.junit.jupiter.api.Test;

/** The Checker texture against the exact rule of rendering-model.md. */
class CheckerTest {
    private static final Rgb C1 = rgb(0.9, 0.8, 0.1), C2 = rgb(0.1, 0.2, 0.7);
    private static final Vec3 EYE = v(0.3, 6, -4);

    /** Lit only by ambient light from a light below everything: each pixel shows C itself. */
    private static Settings settings() {
        return Scenes.settings(camera(EYE, v(0.3, 0, 1), 60), List.of(point(v(0, -100, 0), Rgb.WHITE, 0, 1)),
                Background.BLACK, 80, 60);
    }

    private static Material checker(double scale) {
        return new Material(Rgb.GREY, 1, 0, 30, 0, 0, 1, Rgb.BLACK, true, false, Rgb.BLACK, new Checker(C1, C2, scale));
    }

    /**
     * Every pixel whose centre ray meets the plane y = h (in world space) away from a cell edge
     * shows the cell of its entity point, with y taken as just below h (inside the solid).
     */
    private static int check(FrameBuffer fb, Settings s, double h, double scale, Function<Vec3, Vec3> toEntity,
            double xMin, double xMax, double zMin, double zMax) {
        int checked = 0;
        for (int j = 0; j < s.height(); j++) {
            for (int i = 0; i < s.width(); i++) {
                Vec3 d = Reference.center(s, i, j);
                if (d.y() >= 0) continue;
                Vec3 x = EYE.plus(d.times((h - EYE.y()) / d.y()));
                if (x.x() < xMin || x.x() > xMax || x.z() < zMin || x.z() > zMax) continue;
                Vec3 e = toEntity.apply(x);
                double fx = e.x() / scale, fz = e.z() / scale;
                if (Math.abs(fx - Math.rint(fx)) < 1e-3 || Math.abs(fz - Math.rint(fz)) < 1e-3) continue;
                long cell = (long) Math.floor(fx) + (long) Math.floor(fz) + (long) Math.floor((e.y() - 1e-9) / scale);
                Rgb expected = (cell & 1) == 0 ? C1 : C2;
                Reference.assertPixel(fb, i, j, expected);
                checked++;
            }
        }
        return checked;
    }

    @Test
    void aPlaneOnACellBoundaryTakesTheCellsInsideIt() {
        Settings s = settings();
        FrameBuffer fb = Renderer.prepare(scene(s, plane(Vec3.Y, Vec3.ZERO, checker(0.7)))).render(2, RenderMonitor.NONE);
        int n = check(fb, s, 0, 0.7, x -> x, -1e9, 1e9, -1e9, 1e9);
        assertThat(n).isGreaterThan(1500);
    }

    @Test
    void theCheckerMovesWithTheEntitysModifiersAndNotWithItsOwnPosition() {
        Settings s = settings();
        // translate and position are different things: the position is part of the entity's
        // coordinates (the plane y = 0.5 cuts through cells), the modifier moves the pattern along.
        Vec3 shift = v(0.35, 0, 0.2);
        Entity moved = new Plane(Vec3.Y, v(0, 0.5, 0), checker(1), Transform.translation(shift), SourceSpan.NONE);
        FrameBuffer fb = Renderer.prepare(scene(s, moved)).render(2, RenderMonitor.NONE);
        assertThat(check(fb, s, 0.5, 1, x -> x.minus(shift), -1e9, 1e9, -1e9, 1e9)).isGreaterThan(1500);
    }

    @Test
    void aBoxsTopFaceOnACellBoundaryShowsNoSpeckle() {
        Settings s = settings();
        Box b = box(v(-2, 0, -1), v(2.5, 2, 3), checker(1));
        FrameBuffer fb = Renderer.prepare(scene(s, b)).render(2, RenderMonitor.NONE);
        assertThat(check(fb, s, 2, 1, x -> x, -2, 2.5, -1, 3)).isGreaterThan(500);
    }

    @Test
    void aCellColourMayItselfBeATexture() {
        Settings s = settings();
        Rgb a = rgb(1, 0.5, 0), b = rgb(0, 0.5, 1);
        Checker inner = new Checker(a, b, 0.25);
        Material m = new Material(Rgb.GREY, 1, 0, 30, 0, 0, 1, Rgb.BLACK, true, false, Rgb.BLACK,
                new Checker(Rgb.WHITE, C2, 1, inner, null));
        FrameBuffer fb = Renderer.prepare(scene(s, plane(Vec3.Y, Vec3.ZERO, m))).render(2, RenderMonitor.NONE);
        int checked = 0;
        for (int j = 0; j < s.height(); j++) {
            for (int i = 0; i < s.width(); i++) {
                Vec3 d = Reference.center(s, i, j);
                if (d.y() >= 0) continue;
                Vec3 x = EYE.plus(d.times(-EYE.y() / d.y()));
                double fx = x.x() / 0.25, fz = x.z() / 0.25;
                if (Math.abs(fx - Math.rint(fx)) < 1e-2 || Math.abs(fz - Math.rint(fz)) < 1e-2) continue;
                boolean outerEven = ((long) Math.floor(x.x()) + (long) Math.floor(x.z()) - 1 & 1) == 0;
                boolean innerEven = ((long) Math.floor(fx) + (long) Math.floor(fz) - 1 & 1) == 0;
                Reference.assertPixel(fb, i, j, outerEven ? (innerEven ? a : b) : C2);
                checked++;
            }
        }
        assertThat(checked).isGreaterThan(1500);
    }
}
