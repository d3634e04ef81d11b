package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Aabb;
import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.Material;
import dev.crt.scene.Primitive;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;

/**
 * Walks every primitive type of the scene model and every kind tag of {@link Shapes}, so a new
 * kind that is missing from a switch of the dispatch (or a type with no shape class) fails here
 * rather than in a render.
 */
class ShapeKindsTest {
    private static final Material M = matte(rgb(0.5, 0.5, 0.5));

    /** One or more instances of every primitive type, plain and under a shearing transform. */
    static List<Primitive> samples() {
        List<Primitive> plain = new ArrayList<>(List.of(
                sphere(v(0.2, 0.1, 0), 1, M),
                sphere(v(0, 0, 0), 0, M),
                box(v(-1, -0.5, -0.7), v(0.8, 1.1, 0.4), M),
                plane(v(0.3, 1, -0.2), v(0, -0.5, 0), M)));
        plain.addAll(ShapeSamples.secondWave(M));
        Transform shear = Transform.scaling(v(1, 0.5, 2)).then(Transform.rotation(v(20, 35, 10)));
        List<Primitive> all = new ArrayList<>(plain);
        for (Primitive p : plain) all.add((Primitive) p.transformed(shear));
        return all;
    }

    @Test
    void everyPrimitiveTypeHasASample() {
        Set<Class<?>> sampled = new HashSet<>();
        for (Primitive p : samples()) sampled.add(p.getClass());
        assertThat(sampled).containsExactlyInAnyOrder(Primitive.class.getPermittedSubclasses());
    }

    @Test
    void everyKindTagIsReachedAndEveryOperationDispatchesIt() {
        Set<Integer> reached = new HashSet<>();
        Ray ray = new Ray();
        LineSpan span = new LineSpan();
        SurfacePoint point = new SurfacePoint();
        Hit hit = new Hit();
        for (Primitive p : samples()) {
            Shapes shapes = new Shapes();
            int s = shapes.add(p, p.transform(), 0);
            int kind = shapes.kind[s];
            reached.add(kind);
            Aabb b = shapes.bounds(s);
            if (kind == Shapes.EMPTY) {
                assertThat(b.isEmpty()).isTrue();
                ray.set(0, 0, -5, 0, 0, 1);
                assertThat(shapes.firstHit(s, ray, Double.POSITIVE_INFINITY, span, hit)).isFalse();
                assertThat(shapes.anyHit(s, ray, Double.POSITIVE_INFINITY, span)).isFalse();
                continue;
            }
            // Aimed from outside through the middle of what the shape occupies, or, for a ring,
            // through a point between its middle and its edge.
            boolean crossed = false;
            for (double f : new double[] {0.5, 0.3, 0.7, 0.2}) {
                Vec3 target = b.isFinite() ? b.min().times(1 - f).plus(b.max().times(f)) : v(0, -0.5, 0);
                Vec3 o = target.plus(v(0.31, 0.52, -20));
                Vec3 d = target.minus(o).normalize();
                ray.set(o.x(), o.y(), o.z(), d.x(), d.y(), d.z());
                if (crossed = shapes.span(s, ray, span)) break;
            }
            assertThat(crossed).as("kind %d is crossed", kind).isTrue();
            assertThat(span.count).isPositive();
            double t = Double.isFinite(span.tIn[0]) ? span.tIn[0] : span.tOut[0];
            int face = Double.isFinite(span.tIn[0]) ? span.faceIn[0] : span.faceOut[0];
            // The first-hit and shadow paths of a shape standing alone reach the same crossing.
            assertThat(shapes.anyHit(s, ray, Double.POSITIVE_INFINITY, new LineSpan())).as("kind %d shadow", kind).isTrue();
            assertThat(shapes.firstHit(s, ray, Double.POSITIVE_INFINITY, new LineSpan(), hit)).as("kind %d first hit", kind).isTrue();
            assertThat(hit.t).isEqualTo(t);
            assertThat(hit.face).isEqualTo(face);
            shapes.surface(s, face, t, ray, point);
            assertThat(Math.sqrt(point.nx * point.nx + point.ny * point.ny + point.nz * point.nz)).isCloseTo(1, org.assertj.core.data.Offset.offset(1e-12));
            shapes.frame(s, face, point);
            assertThat(Double.isFinite(point.u) && Double.isFinite(point.v)).isTrue();
        }
        Set<Integer> all = new HashSet<>();
        for (int k = 0; k < Shapes.KINDS; k++) all.add(k);
        assertThat(reached).isEqualTo(all);
    }
}
