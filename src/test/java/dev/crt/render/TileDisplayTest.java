package dev.crt.render;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.image.FrameBuffer;
import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/** The tile callback hands over every pixel exactly once, already final, before the render ends. */
class TileDisplayTest {
    private static final String SCRIPT = """
            Settings { width -> 83 height -> 45 supersampling -> 2
              camera -> Camera { position -> vec3(0, 0, -5) pointing -> vec3(0, 0, 0) }
              lights -> [ PointLight { origin -> vec3(-3, 4, -5) } ] }
            Scene { Sphere { radius -> 1.2 } Plane { normal -> vec3(0, 1, 0) position -> vec3(0, -1, 0) } }
            """;

    @Test
    void everyPixelIsDeliveredOnceWithItsFinalValue() {
        CompileResult compiled = CrtCompiler.compile(Source.of("tiles.crt", SCRIPT), CompileOptions.DEFAULT);
        Renderer renderer = Renderer.prepare(compiled.scene());
        int w = 83, h = 45;
        int[] deliveries = new int[w * h];
        float[] seen = new float[w * h * 3];
        AtomicInteger tiles = new AtomicInteger();
        FrameBuffer image = renderer.render(3, new RenderMonitor() {
            @Override public void tileDone(FrameBuffer fb, int x0, int y0, int x1, int y1) {
                tiles.incrementAndGet();
                synchronized (deliveries) {
                    for (int y = y0; y < y1; y++) {
                        for (int x = x0; x < x1; x++) {
                            deliveries[y * w + x]++;
                            for (int c = 0; c < 3; c++) seen[(y * w + x) * 3 + c] = fb.get(x, y, c);
                        }
                    }
                }
            }
        });
        assertThat(tiles.get()).isEqualTo(((w + Renderer.TILE - 1) / Renderer.TILE) * ((h + Renderer.TILE - 1) / Renderer.TILE));
        assertThat(deliveries).containsOnly(1);
        assertThat(seen).containsExactly(image.data());
    }

    @Test
    void aPreviewAtAnotherSizeIsThePictureOfThatSize() {
        CompileResult compiled = CrtCompiler.compile(Source.of("tiles.crt", SCRIPT), CompileOptions.DEFAULT);
        Renderer full = Renderer.prepare(compiled.scene());
        FrameBuffer preview = full.withImage(11, 6, 1, 1).render(2, RenderMonitor.NONE);
        FrameBuffer fresh = Renderer.prepare(compiled.scene().withSettings(
                compiled.scene().settings().withSize(11, 6).withSampling(1, 1))).render(2, RenderMonitor.NONE);
        assertThat(preview.width()).isEqualTo(11);
        assertThat(preview.data()).containsExactly(fresh.data());
        // The prepared renderer itself keeps its own size.
        assertThat(full.render(2, RenderMonitor.NONE).width()).isEqualTo(83);
    }

    @Test
    void aCancelledRenderDeliversOnlyFinishedTiles() {
        CompileResult compiled = CrtCompiler.compile(Source.of("tiles.crt", SCRIPT), CompileOptions.DEFAULT);
        Renderer renderer = Renderer.prepare(compiled.scene());
        AtomicInteger tiles = new AtomicInteger();
        try {
            renderer.render(1, new RenderMonitor() {
                @Override public void tileDone(FrameBuffer fb, int x0, int y0, int x1, int y1) { tiles.incrementAndGet(); }

                @Override public boolean isCancelled() { return tiles.get() >= 2; }
            });
        } catch (RenderCancelledException expected) {
            assertThat(tiles.get()).isEqualTo(2);
            return;
        }
        throw new AssertionError("the render was not cancelled");
    }
}
