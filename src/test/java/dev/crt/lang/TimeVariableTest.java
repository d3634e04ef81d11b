package dev.crt.lang;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.scene.Sphere;
import org.junit.jupiter.api.Test;

class TimeVariableTest {
    private static final String SCRIPT = "radii = [1, 2, 3, 4]\nScene { Sphere { radius -> radii[t % 4] } }\n";

    private static CompileResult at(double t) {
        return CrtCompiler.compile(Source.of("t.crt", SCRIPT), CompileOptions.DEFAULT.withTime(t));
    }

    @Test
    void aWholeTimeIsAnIntegerThatIndexesLists() {
        CompileResult r = at(6);
        assertThat(r.hasErrors()).as(r.diagnostics().toString()).isFalse();
        assertThat(((Sphere) r.scene().entities().get(0)).radius()).isEqualTo(3);
    }

    @Test
    void everyWholeTimePicksItsItem() {
        for (int t = 0; t < 8; t++) {
            assertThat(((Sphere) at(t).scene().entities().get(0)).radius()).as("t = %d", t).isEqualTo(t % 4 + 1);
        }
    }

    @Test
    void aFractionalTimeIsAFloatAndCannotIndex() {
        CompileResult r = at(2.5);
        assertThat(r.scene()).isNull();
        // Exactly one error, the index's, at the index expression 't % 4'.
        assertThat(r.diagnostics()).singleElement().satisfies(d -> {
            assertThat(d.message()).isEqualTo("an index must be an integer, got the float 2.5");
            assertThat(d.span().line()).isEqualTo(2);
            assertThat(d.span().column()).isEqualTo(SCRIPT.lines().toList().get(1).indexOf("t % 4") + 1);
        });
    }
}
