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
    void aFractionalTimeIsAFloatAndCannotIndex() {
        CompileResult r = at(2.5);
        assertThat(r.hasErrors()).isTrue();
        assertThat(r.diagnostics().get(0).span().line()).isEqualTo(2);
    }
}
