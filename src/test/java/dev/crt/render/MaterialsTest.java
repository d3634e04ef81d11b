package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.scene.Material;
import dev.crt.scene.Rgb;
import java.util.HashMap;
import java.util.Map;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** Materials are shared exactly when Material's equals says they are equal, and keep their values. */
class MaterialsTest {
    @Test
    void equalMaterialsShareAnIndexAndOthersDoNot() {
        Materials m = new Materials();
        int a = m.indexOf(matte(rgb(0.2, 0.4, 0.6)));
        assertThat(m.indexOf(matte(rgb(0.2, 0.4, 0.6)))).isEqualTo(a);
        assertThat(m.indexOf(matte(rgb(0.2, 0.4, 0.7)))).isNotEqualTo(a);
        // As Double.compare: 0.0 and −0.0 differ, NaN equals NaN.
        int zero = m.indexOf(matte(rgb(0.0, 0, 0)));
        assertThat(m.indexOf(matte(rgb(-0.0, 0, 0)))).isNotEqualTo(zero);
        int nan = m.indexOf(new Material(Rgb.WHITE, 1, 0, Double.NaN, 0, 0, 1, Rgb.BLACK));
        assertThat(m.indexOf(new Material(Rgb.WHITE, 1, 0, Double.NaN, 0, 0, 1, Rgb.BLACK))).isEqualTo(nan);
        assertThat(m.indexOf(new Material(Rgb.WHITE, 1, 0, 30, 0, 0, 1, new Rgb(0, 0, 1e-300)))).isNotEqualTo(m.indexOf(matte(Rgb.WHITE)));
    }

    @Test
    void manyMaterialsAgreeWithAMapAndKeepTheirValues() {
        Materials m = new Materials();
        Map<Material, Integer> expected = new HashMap<>();
        SplittableRandom r = new SplittableRandom(7);
        for (int i = 0; i < 50_000; i++) {
            // Few distinct values, so that most materials are repeats made as new objects.
            Material q = material(rgb(r.nextInt(40) / 8.0, 0.5, r.nextInt(40) / 8.0), 0.7, r.nextInt(5) * 0.25, 30, 0, 0, 1);
            int k = m.indexOf(q);
            assertThat(k).isEqualTo(expected.computeIfAbsent(q, x -> expected.size()));
            int at = k * Materials.STRIDE;
            assertThat(m.data[at + Materials.R]).isEqualTo(q.color().r());
            assertThat(m.data[at + Materials.B]).isEqualTo(q.color().b());
            assertThat(m.data[at + Materials.SPECULAR]).isEqualTo(q.specular());
        }
        assertThat(expected).hasSizeGreaterThan(1000);
    }
}
