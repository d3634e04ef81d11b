package dev.crt.render;

import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import dev.crt.scene.Scene;

/**
 * Renders a script inside a class loader of its own (FeatureSwitchesTest loads this class once per
 * setting of -Dcrt.without, so each loader has its own Features): the picture, or the refusal.
 */
final class FeatureProbe {
    private FeatureProbe() {}

    /** The linear RGB floats of {@code script} rendered on one thread, or the message of its refusal as a String. */
    static Object render(String script) {
        CompileResult r = CrtCompiler.compile(Source.of("probe.crt", script), CompileOptions.DEFAULT);
        if (r.hasErrors()) throw new AssertionError("the probe script does not compile: " + r.diagnostics());
        Scene scene = r.scene();
        try {
            return Renderer.prepare(scene).render(1, RenderMonitor.NONE).data();
        } catch (FeatureSwitchedOffException e) {
            return e.getMessage();
        }
    }
}
