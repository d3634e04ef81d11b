package dev.crt.lang;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class DegenerateTransformTest {
    private static CompileResult compile(String text) {
        return CrtCompiler.compile(Source.of("d.crt", text), CompileOptions.DEFAULT);
    }

    @Test
    void scalesThatUnderflowOrOverflowAreErrorsAtTheEntity() {
        CompileResult r = compile("Scene {\n  Sphere { } <scale 1e-300> <scale 1e-300>\n"
                + "  Box { cornerA -> vec3(0,0,0) cornerB -> vec3(1,1,1) } <scale 1e300, scale 1e300>\n}\n");
        assertThat(r.scene()).isNull();
        var errors = r.diagnostics().stream().filter(Diagnostic::isError).toList();
        assertThat(errors).hasSize(2);
        assertThat(errors.get(0).message()).contains("scale it too far");
        assertThat(errors.get(0).span().line()).isEqualTo(2);
        assertThat(errors.get(0).span().column()).isEqualTo(3);
        assertThat(errors.get(1).span().line()).isEqualTo(3);
    }

    @Test
    void theTransformOfACsgTreeIsCheckedDownToItsLeaves() {
        CompileResult r = compile("tiny = Sphere { } <scale 1e-200>\nScene { (tiny + Sphere { }) <scale 1e-200> }\n");
        assertThat(r.scene()).isNull();
        assertThat(r.diagnostics().stream().filter(Diagnostic::isError).findFirst().orElseThrow().span().line()).isEqualTo(1);
    }

    @Test
    void largeButRepresentableScalesAreFine() {
        CompileResult r = compile("Scene { Sphere { } <scale 1e-150> <scale 1e140> }\n");
        assertThat(r.hasErrors()).isFalse();
    }
}
