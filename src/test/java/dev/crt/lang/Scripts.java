package dev.crt.lang;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.scene.Scene;
import java.util.List;
import java.util.stream.Collectors;

/** Helpers to compile test scripts and look at the outcome. */
final class Scripts {
    private Scripts() {}

    static CompileResult compile(String text) {
        return CrtCompiler.compile(Source.of("test.crt", text), CompileOptions.DEFAULT);
    }

    /** Compiles a script that must have no errors and returns its scene. */
    static Scene scene(String text) {
        CompileResult r = compile(text);
        assertThat(r.hasErrors()).as("errors: %s", render(r, text)).isFalse();
        assertThat(r.scene()).isNotNull();
        return r.scene();
    }

    /** Compiles a script that must fail and returns its errors. */
    static List<Diagnostic> errors(String text) {
        CompileResult r = compile(text);
        assertThat(r.scene()).as("a script with errors has no scene").isNull();
        assertThat(r.hasErrors()).isTrue();
        return r.diagnostics().stream().filter(Diagnostic::isError).toList();
    }

    /** The only error of a script. */
    static Diagnostic error(String text) {
        List<Diagnostic> errors = errors(text);
        assertThat(errors).as(render(errors, text)).hasSize(1);
        return errors.get(0);
    }

    static String render(CompileResult r, String text) { return render(r.diagnostics(), text); }

    static String render(List<Diagnostic> ds, String text) {
        return ds.stream().map(d -> DiagnosticFormatter.format(d, text)).collect(Collectors.joining("\n"));
    }

    /** A minimal valid Settings block so tests do not collect the default-camera warning. */
    static final String CAMERA = "Settings { camera -> Camera { position -> vec3(0,0,-5) pointing -> vec3(0,0,0) } }\n";
}
