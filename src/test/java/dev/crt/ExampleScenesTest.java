package dev.crt;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.image.FrameBuffer;
import dev.crt.lang.CompileResult;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

/**
 * Every script in scenes/ and bench/scenes/ compiles without errors and renders, small, to the
 * picture stored for it in src/test/resources/example-scenes (48×27 linear floats). "Not black,
 * not flat" let a renderer that lost its shadows or its reflections pass; a stored picture does
 * not. The tolerance (mean difference under 0.004, 98% of channels within 0.02) allows rounding
 * changes of the tracer's arithmetic but not a missing light, shadow, bounce or object.
 * The stored pictures are made by ExampleSceneReferences: see there when a change is intended.
 */
class ExampleScenesTest {
    @TestFactory
    List<DynamicTest> everyExampleSceneRendersAsStored() throws IOException {
        List<Path> scripts = ExampleSceneReferences.scripts();
        assertThat(scripts).hasSizeGreaterThan(5);
        return scripts.stream().map(p -> DynamicTest.dynamicTest(p.toString(), () -> {
            CompileResult r = ExampleSceneReferences.compile(p);
            assertThat(r.hasErrors()).as(r.diagnostics().toString()).isFalse();
            FrameBuffer image = ExampleSceneReferences.render(r.scene());
            float[] got = image.data();
            Path stored = ExampleSceneReferences.referenceOf(p);
            assertThat(stored).as("a new example scene needs its stored picture: run ExampleSceneReferences").exists();
            float[] want = ExampleSceneReferences.readPfm(stored);
            assertThat(got.length).isEqualTo(want.length);
            double sum = 0;
            int far = 0;
            for (int i = 0; i < got.length; i++) {
                assertThat(Float.isFinite(got[i])).isTrue();
                double d = Math.abs(got[i] - want[i]);
                sum += d;
                if (d > 0.02) far++;
            }
            assertThat(sum / got.length).as("mean difference from the stored picture").isLessThan(0.004);
            assertThat(far).as("channels more than 0.02 from the stored picture").isLessThanOrEqualTo(got.length / 50);
        })).toList();
    }
}
