package dev.crt;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.image.FrameBuffer;
import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.ScriptFiles;
import dev.crt.render.Renderer;
import dev.crt.scene.Scene;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

/**
 * Every script in scenes/ and bench/scenes/ compiles without errors and renders (small) to finite
 * pixels, not all black; the example scenes are not one flat colour either.
 */
class ExampleScenesTest {
    @TestFactory
    List<DynamicTest> everyExampleSceneCompilesAndRenders() throws IOException {
        List<Path> scripts = new java.util.ArrayList<>();
        for (String folder : List.of("scenes", "bench/scenes")) {
            try (Stream<Path> s = Files.list(Path.of(folder))) {
                List<Path> found = s.filter(p -> p.toString().endsWith(".crt")).sorted().toList();
                assertThat(found).as(folder).isNotEmpty();
                scripts.addAll(found);
            }
        }
        return scripts.stream().map(p -> DynamicTest.dynamicTest(p.toString(), () -> {
            CompileResult r = CrtCompiler.compile(ScriptFiles.read(p),
                    new CompileOptions(3, List.of(Path.of("assets")), CompileOptions.DEFAULT_LOOP_BUDGET,
                            CompileOptions.DEFAULT_TIME_BUDGET));
            assertThat(r.hasErrors()).as(r.diagnostics().toString()).isFalse();
            Scene scene = r.scene().withSettings(r.scene().settings().withSize(48, 27).withSampling(1, 1));
            FrameBuffer image = Renderer.prepare(scene).render(0, dev.crt.render.RenderMonitor.NONE);
            float min = Float.MAX_VALUE, max = -Float.MAX_VALUE;
            for (float v : image.data()) {
                assertThat(Float.isFinite(v)).isTrue();
                min = Math.min(min, v);
                max = Math.max(max, v);
            }
            assertThat(max).as("the picture is not black").isGreaterThan(0.05f);
            // bench/scenes/recursion-check.crt is one flat colour on purpose: every pixel counts bounces.
            if (p.startsWith("scenes")) assertThat(max - min).as("the picture is not one flat colour").isGreaterThan(0.05f);
        })).toList();
    }
}
