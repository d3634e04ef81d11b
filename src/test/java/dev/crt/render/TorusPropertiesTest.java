package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.Material;
import dev.crt.scene.SourceSpan;
import dev.crt.scene.Torus;
import java.util.SplittableRandom;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;

/**
 * Tori against the annulus they cut in a plane across the axis: at height h the solid is the
 * ring between radii R ± √(r² − h²) (a disc when the inner radius is not positive, as for a
 * spindle torus, whose inner sheet is not a surface). A ray in that plane at distance δ from the
 * axis is inside exactly where it is inside that ring, so its intervals are known in closed form.
 * Rays graze either circle (δ within 1e-8 of it), start up to 1e4 radii away, and tori sit up
 * to 1e5 from the origin at scales from 1e-3 to 1e3. Rays along the axis cross only spindle tori.
 */
class TorusPropertiesTest {
    private static final Material M = matte(rgb(0.5, 0.5, 0.5));

    @Property(tries = 4000)
    void raysAcrossTheAxisMatchTheAnnulusAtTheirHeight(@ForAll long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        double scale = Math.pow(10, r.nextInt(-3, 4));
        Vec3 c = unit(r).times(r.nextBoolean() ? 1e5 : r.nextDouble() * 3 * scale);
        Vec3 axis = unit(r);
        double big = scale * (0.5 + r.nextDouble());
        double small = r.nextInt(4) == 0 ? big * (1.05 + r.nextDouble()) : big * (0.05 + 0.9 * r.nextDouble());
        Torus torus = new Torus(c, axis, big, small, M, Transform.IDENTITY, SourceSpan.NONE);
        double h = small * (r.nextInt(5) == 0 ? 0 : 2 * r.nextDouble() - 1) * 0.999;
        double w = Math.sqrt((small - h) * (small + h));
        double outer = big + w, inner = big - w;
        Vec3 side = axis.cross(unit(r)).normalize();
        Vec3 d = axis.cross(side).normalize();
        double delta = switch (r.nextInt(4)) {
            case 0 -> outer * (1 + (r.nextBoolean() ? 1e-8 : -1e-8));
            case 1 -> inner > 0 ? inner * (1 + (r.nextBoolean() ? 1e-8 : -1e-8)) : outer * r.nextDouble();
            default -> outer * 1.2 * r.nextDouble();
        };
        double back = (big + small) * (r.nextBoolean() ? 1e4 : 2 + 3 * r.nextDouble());
        Vec3 o = c.plus(axis.times(h)).plus(side.times(delta)).minus(d.times(back));
        Shapes shapes = new Shapes();
        int k = shapes.add(torus, Transform.IDENTITY, 0);
        Ray ray = new Ray();
        ray.set(o.x(), o.y(), o.z(), d.x(), d.y(), d.z());
        LineSpan span = new LineSpan();
        boolean hit = shapes.span(k, ray, span);
        double slack = 1e-6;
        if (delta > outer * (1 + slack)) {
            assertThat(hit).as("outside the outer circle").isFalse();
            return;
        }
        if (delta > outer * (1 - slack)) return;
        assertThat(hit).as("inside the outer circle").isTrue();
        double half = Math.sqrt((outer - delta) * (outer + delta));
        double tol = 1e-9 * (back + c.length() + big + small);
        boolean twoPieces = inner > 0 && delta < inner * (1 - slack);
        boolean onePiece = inner <= 0 || delta > inner * (1 + slack);
        if (!twoPieces && !onePiece) return;
        assertThat(span.count).isEqualTo(twoPieces ? 2 : 1);
        assertThat(Math.abs(span.tIn[0] - (back - half))).as("entry").isLessThanOrEqualTo(tol);
        assertThat(Math.abs(span.tOut[span.count - 1] - (back + half))).as("exit").isLessThanOrEqualTo(tol);
        if (twoPieces) {
            double halfIn = Math.sqrt((inner - delta) * (inner + delta));
            assertThat(Math.abs(span.tOut[0] - (back - halfIn))).as("into the hole").isLessThanOrEqualTo(tol);
            assertThat(Math.abs(span.tIn[1] - (back + halfIn))).as("out of the hole").isLessThanOrEqualTo(tol);
        }
        SurfacePoint q = new SurfacePoint();
        shapes.surface(k, 0, span.tIn[0], ray, q);
        Vec3 p = new Vec3(q.px, q.py, q.pz).minus(c);
        double hp = p.dot(axis);
        double rho = p.minus(axis.times(hp)).length();
        assertThat(Math.abs(Math.hypot(rho - big, hp) - small)).as("on the surface").isLessThanOrEqualTo(1e-12 * (c.length() + big + small) * 16);
        Vec3 ring = p.minus(axis.times(hp)).normalize().times(big);
        Vec3 expected = p.minus(ring).normalize();
        assertThat(new Vec3(q.nx, q.ny, q.nz).minus(expected).length()).isLessThan(1e-6);
    }

    @Property(tries = 1000)
    void raysAlongTheAxisCrossOnlyASpindleTorus(@ForAll long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        double scale = Math.pow(10, r.nextInt(-3, 4));
        Vec3 c = unit(r).times(r.nextDouble() * 1e3 * scale);
        Vec3 axis = unit(r);
        double big = scale * (0.5 + r.nextDouble());
        boolean spindle = r.nextBoolean();
        double small = spindle ? big * (1.05 + r.nextDouble()) : big * (0.1 + 0.8 * r.nextDouble());
        Torus torus = new Torus(c, axis, big, small, M, Transform.IDENTITY, SourceSpan.NONE);
        double back = (big + small) * (2 + r.nextDouble() * 1e4);
        Vec3 o = c.minus(axis.times(back));
        Shapes shapes = new Shapes();
        int k = shapes.add(torus, Transform.IDENTITY, 0);
        Ray ray = new Ray();
        ray.set(o.x(), o.y(), o.z(), axis.x(), axis.y(), axis.z());
        LineSpan span = new LineSpan();
        boolean hit = shapes.span(k, ray, span);
        assertThat(hit).isEqualTo(spindle);
        if (!spindle) return;
        // On the axis ρ = 0: R² + h² ≤ r², so |h| ≤ √(r² − R²).
        double half = Math.sqrt((small - big) * (small + big));
        double tol = 1e-9 * (back + c.length() + big + small);
        assertThat(span.count).isEqualTo(1);
        assertThat(Math.abs(span.tIn[0] - (back - half))).isLessThanOrEqualTo(tol);
        assertThat(Math.abs(span.tOut[0] - (back + half))).isLessThanOrEqualTo(tol);
    }
}
