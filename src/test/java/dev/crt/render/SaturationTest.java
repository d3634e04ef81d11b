package dev.crt.render;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.animation.FrameJob;
import dev.crt.image.FrameBuffer;
import dev.crt.image.ImageFiles;
import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.ScriptFiles;
import dev.crt.lang.Source;
import dev.crt.scene.Sampler;
import dev.crt.scene.Scene;
import dev.crt.scene.Shading;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@link Renderer#forClampedOutput}: pixels stop once their sum reaches 1 in every channel. The
 * 8-bit file must be the same to the bit as the plain renderer's, every pixel below 1 in some
 * channel the same float, on any thread count; scenes where a term can be negative, and the
 * samplers and models it does not serve, must render exactly as without it.
 */
class SaturationTest {
    /** A bright reflective field under strong lights through a lens: many white pixels, some not. */
    private static final String BRIGHT = """
            Settings {
                width -> 48
                height -> 36
                supersampling -> 2
                dofsamples -> 8
                lights -> [PointLight { origin -> vec3(1, 4, -2) color -> rgb(0.9, 0.4, 0.3) falloff -> 70 },
                           PointLight { origin -> vec3(-2, 4, 1) color -> rgb(0.3, 0.5, 0.9) falloff -> 70 },
                           ParallelLight { from -> vec3(-0.3, 1.5, -10) pointing -> vec3(0, 0, 0) }]
                camera -> Camera { position -> vec3(1.9, 1.7, 4.2) pointing -> vec3(0, 1, 0) fov -> 75
                                   aperture -> 20 focaldistance -> 3 }
                background -> Background { horizon -> rgb(0.9, 0.9, 1.0) sky -> rgb(0.2, 0.4, 0.9) }
            }
            m = Material { color -> rgb(1, 1, 1) reflectivity -> 0.7 }
            field = Macro () {
                i = 0
                while (i < 64) {
                    x = i % 8 - 4
                    z = (i - i % 8) / 8 - 4
                    Box { cornerA -> vec3(x, -2, z) cornerB -> vec3(x + 0.5, 0.05 * (i % 5), z + 0.5) material -> m }
                    i = i + 1
                }
            }
            Scene {
                field()
                Sphere { center -> vec3(0.5, 1.2, 0.5) radius -> 0.6 material -> m } - Box { cornerA -> vec3(-2, 1.3, -2) cornerB -> vec3(2, 3, 2) material -> m }
            }
            """;

    private static Scene compile(String name, String script) {
        CompileResult r = CrtCompiler.compile(Source.of(name, script), CompileOptions.DEFAULT);
        assertThat(r.hasErrors()).as("%s", r.diagnostics()).isFalse();
        return r.scene();
    }

    private record Pair(FrameBuffer plain, FrameBuffer clamped, RenderStats plainStats, RenderStats clampedStats) {}

    private static Pair render(Scene scene, int threads) {
        Renderer plain = Renderer.prepare(scene);
        FrameBuffer a = plain.render(threads, RenderMonitor.NONE);
        Renderer clamped = plain.forClampedOutput();
        FrameBuffer b = clamped.render(threads, RenderMonitor.NONE);
        return new Pair(a, b, plain.stats(), clamped.stats());
    }

    /** Asserts that every pixel is the same float or white in both, and that the 8-bit files agree; returns the white pixels. */
    private static int assertSameFile(String what, FrameBuffer plain, FrameBuffer clamped, double gamma) {
        int white = 0;
        for (int y = 0; y < plain.height(); y++) {
            for (int x = 0; x < plain.width(); x++) {
                boolean whiteInPlain = true, whiteInClamped = true;
                for (int c = 0; c < 3; c++) {
                    whiteInPlain &= plain.get(x, y, c) >= 1;
                    whiteInClamped &= clamped.get(x, y, c) >= 1;
                    assertThat(ImageFiles.toByte(clamped.get(x, y, c), gamma)).as("%s (%d, %d) channel %d", what, x, y, c)
                            .isEqualTo(ImageFiles.toByte(plain.get(x, y, c), gamma));
                }
                assertThat(whiteInClamped).as("%s (%d, %d) white", what, x, y).isEqualTo(whiteInPlain);
                if (whiteInPlain) {
                    white++;
                } else {
                    for (int c = 0; c < 3; c++) {
                        assertThat(clamped.get(x, y, c)).as("%s (%d, %d) channel %d", what, x, y, c).isEqualTo(plain.get(x, y, c));
                    }
                }
            }
        }
        return white;
    }

    @Test
    void whitePixelsStopEarlyAndTheFileIsTheSameWithEverySamplerItServes() {
        Scene scene = compile("bright.crt", BRIGHT);
        for (Sampler sampler : List.of(Sampler.GRID, Sampler.JITTERED, Sampler.SOBOL)) {
            Scene s = scene.withSettings(scene.settings().withSampler(sampler, 0.5));
            Pair p = render(s, 1);
            int white = assertSameFile(sampler.name(), p.plain(), p.clamped(), s.settings().outputGamma());
            int pixels = p.plain().width() * p.plain().height();
            assertThat(white).as("%s: white pixels", sampler).isBetween(pixels / 10, pixels * 9 / 10);
            assertThat(p.clampedStats().shadowRays()).as("%s: shadow rays", sampler).isLessThan(p.plainStats().shadowRays() * 9 / 10);
            assertThat(p.clampedStats().primaryRays()).as("%s: camera rays", sampler).isLessThan(p.plainStats().primaryRays());
        }
    }

    @Test
    void theSamePixelsOnAnyThreadCount() {
        Scene scene = compile("bright.crt", BRIGHT);
        FrameBuffer one = Renderer.prepare(scene).forClampedOutput().render(1, RenderMonitor.NONE);
        FrameBuffer three = Renderer.prepare(scene).forClampedOutput().render(3, RenderMonitor.NONE);
        assertThat(three.data()).isEqualTo(one.data());
    }

    @Test
    void everyExampleSceneWritesTheSameFile() throws IOException {
        List<Path> scripts;
        try (Stream<Path> s = Files.list(Path.of("scenes"))) {
            scripts = s.filter(p -> p.toString().endsWith(".crt")).sorted().toList();
        }
        assertThat(scripts).hasSizeGreaterThan(5);
        CompileOptions options = new CompileOptions(3, List.of(Path.of("assets")), CompileOptions.DEFAULT_LOOP_BUDGET,
                CompileOptions.DEFAULT_TIME_BUDGET);
        for (Path script : scripts) {
            CompileResult r = CrtCompiler.compile(ScriptFiles.read(script), options);
            assertThat(r.hasErrors()).as("%s: %s", script, r.diagnostics()).isFalse();
            Scene small = r.scene().withSettings(r.scene().settings().withSize(40, 24).withSampling(2, 2));
            Pair p = render(small, 2);
            assertSameFile(script.toString(), p.plain(), p.clamped(), small.settings().outputGamma());
        }
    }

    /**
     * A light of negative colour takes away what an emissive surface gave: the sum passes 1 and
     * falls back below it, so stopping at 1 would be wrong; such a scene renders as without it.
     */
    @Test
    void aSceneWithANegativeTermRendersAsWithout() {
        Scene scene = compile("negative.crt", """
                Settings {
                    width -> 24
                    height -> 18
                    supersampling -> 2
                    lights -> [PointLight { origin -> vec3(0, 0, -5) color -> rgb(-1.5, -1.5, -1.5) ambient -> 0 }]
                    camera -> Camera { position -> vec3(0, 0, -5) pointing -> vec3(0, 0, 0) fov -> 40 }
                }
                Scene { Sphere { radius -> 1.5 material -> Material { color -> rgb(1, 1, 1) emission -> rgb(2, 2, 2) } } }
                """);
        Pair p = render(scene, 1);
        assertThat(p.clamped().data()).isEqualTo(p.plain().data());
        assertThat(p.clampedStats().shadowRays()).isEqualTo(p.plainStats().shadowRays());
        // The centre is below 1 in the plain render: stopping when the emission alone reached 1 would have made it white.
        assertThat(p.plain().get(12, 9, 0)).isLessThan(1f);
    }

    @Test
    void theAdaptiveSamplerAndThe2015ModelRenderAsWithout() {
        Scene scene = compile("bright.crt", BRIGHT);
        for (Scene s : List.of(scene.withSettings(scene.settings().withSampler(Sampler.ADAPTIVE, 0.5)),
                scene.withSettings(scene.settings().withShading(Shading.ORIGINAL)))) {
            Pair p = render(s, 1);
            assertThat(p.clamped().data()).isEqualTo(p.plain().data());
            assertThat(p.clampedStats().shadowRays()).isEqualTo(p.plainStats().shadowRays());
        }
    }

    /** {@code crt render} and {@code crt animate} stop white pixels for .png and .ppm files, and keep the full colour for .pfm. */
    @Test
    void frameFilesStopAtWhiteOnlyWhenTheyClamp(@TempDir Path dir) throws Exception {
        Scene scene = compile("bright.crt", BRIGHT);
        Renderer plain = Renderer.prepare(scene);
        FrameBuffer linear = plain.render(0, RenderMonitor.NONE);
        long plainRays = plain.stats().shadowRays();
        FrameJob.Outcome png = FrameJob.run(scene, dir.resolve("a.png"), 0, RenderMonitor.NONE);
        FrameJob.Outcome ppm = FrameJob.run(scene, dir.resolve("a.ppm"), 0, RenderMonitor.NONE);
        FrameJob.Outcome pfm = FrameJob.run(scene, dir.resolve("a.pfm"), 0, RenderMonitor.NONE);
        assertThat(png.stats().shadowRays()).isLessThan(plainRays);
        assertThat(ppm.stats().shadowRays()).isEqualTo(png.stats().shadowRays());
        assertThat(pfm.stats().shadowRays()).isEqualTo(plainRays);
        assertThat(ImageFiles.clampsColours(Path.of("x.PNG"))).isTrue();
        assertThat(ImageFiles.clampsColours(Path.of("x.pfm"))).isFalse();
        // The PFM holds the plain render's linear colours, white pixels included.
        float[] written = dev.crt.ExampleSceneReferences.readPfm(dir.resolve("a.pfm"));
        assertThat(written).isEqualTo(linear.data());
    }
}
