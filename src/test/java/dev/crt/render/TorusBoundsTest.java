package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Aabb;
import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.SourceSpan;
import dev.crt.scene.Torus;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * A torus's box holds every point of its surface and is no larger than it must be: under turns,
 * uneven scales and moves, points sampled densely over the surface (mapped by the shape's own
 * local-to-world matrix) lie inside the box and reach each of its six faces to within a sliver.
 */
class TorusBoundsTest {
    @Test
    void boxHoldsTheSurfaceAndTouchesIt() {
        SplittableRandom r = new SplittableRandom(7);
        int n = 720;
        double[] cosPsi = new double[n / 2], sinPsi = new double[n / 2];
        for (int j = 0; j < n / 2; j++) {
            cosPsi[j] = Math.cos(4 * Math.PI * j / n);
            sinPsi[j] = Math.sin(4 * Math.PI * j / n);
        }
        for (int k = 0; k < 100; k++) {
            Vec3 axis = unit(r);
            double big = 0.2 + r.nextDouble(), small = big * (k % 5 == 0 ? 1.05 + r.nextDouble() : 0.05 + 0.9 * r.nextDouble());
            Transform place = Transform.rotation(new Vec3(360 * r.nextDouble(), 360 * r.nextDouble(), 360 * r.nextDouble()))
                    .then(Transform.scaling(new Vec3(0.3 + 2 * r.nextDouble(), 0.3 + 2 * r.nextDouble(), 0.3 + 2 * r.nextDouble())))
                    .then(Transform.translation(unit(r).times(100 * r.nextDouble())));
            Torus torus = new Torus(unit(r), axis, big, small, matte(rgb(1, 1, 1)), place, SourceSpan.NONE);
            Shapes shapes = new Shapes();
            int s = shapes.add(torus, place, 0);
            Aabb box = shapes.bounds(s);
            double[] a = shapes.data;
            int m = shapes.offset[s] + 12;
            double[] lo = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
            double[] hi = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
            for (int i = 0; i < n; i++) {
                double cosPhi = Math.cos(2 * Math.PI * i / n), sinPhi = Math.sin(2 * Math.PI * i / n);
                for (int j = 0; j < n / 2; j++) {
                    double rho = big + small * cosPsi[j];
                    double x = rho * cosPhi, y = rho * sinPhi, z = small * sinPsi[j];
                    for (int c = 0; c < 3; c++) {
                        double w = a[m + 4 * c] * x + a[m + 4 * c + 1] * y + a[m + 4 * c + 2] * z + a[m + 4 * c + 3];
                        lo[c] = Math.min(lo[c], w);
                        hi[c] = Math.max(hi[c], w);
                    }
                }
            }
            double[] min = {box.min().x(), box.min().y(), box.min().z()}, max = {box.max().x(), box.max().y(), box.max().z()};
            for (int c = 0; c < 3; c++) {
                double size = max[c] - min[c];
                assertThat(lo[c]).as("torus %d axis %d low side inside", k, c).isGreaterThanOrEqualTo(min[c]);
                assertThat(hi[c]).as("torus %d axis %d high side inside", k, c).isLessThanOrEqualTo(max[c]);
                // The samples are 0.5° apart: they come within 1e-4 of the extent along each axis.
                assertThat(lo[c] - min[c]).as("torus %d axis %d low side tight", k, c).isLessThan(1e-4 * size);
                assertThat(max[c] - hi[c]).as("torus %d axis %d high side tight", k, c).isLessThan(1e-4 * size);
            }
        }
    }

    private static Vec3 unit(SplittableRandom r) {
        while (true) {
            Vec3 v = new Vec3(2 * r.nextDouble() - 1, 2 * r.nextDouble() - 1, 2 * r.nextDouble() - 1);
            double l = v.length();
            if (l > 0.1 && l <= 1) return v.div(l);
        }
    }
}
