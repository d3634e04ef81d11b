package dev.crt.render;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.image.FrameBuffer;
import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;

class RaysTracedTest {
    @Test
    void theRaysOfEachTileAreReportedAsItFinishesAndSumToTheStats() {
        CompileResult r = CrtCompiler.compile(Source.of("rays.crt", """
                Settings { width -> 96 height -> 64 supersampling -> 2
                  lights -> [PointLight { origin -> vec3(2, 4, -3) }] }
                Scene {
                  Sphere { center -> vec3(0, 0, 2) radius -> 1 material -> Material { reflectivity -> 0.5 } }
                  Plane { normal -> vec3(0, 1, 0) position -> vec3(0, -1, 0) }
                }
                """), CompileOptions.DEFAULT);
        assertThat(r.hasErrors()).isFalse();
        Renderer renderer = Renderer.prepare(r.scene());
        AtomicLong reported = new AtomicLong();
        AtomicLong calls = new AtomicLong();
        AtomicLong reportedBeforeLastTile = new AtomicLong(-1);
        FrameBuffer image = renderer.render(2, new RenderMonitor() {
            @Override public void raysTraced(long rays) {
                assertThat(rays).isPositive();
                reported.addAndGet(rays);
                calls.incrementAndGet();
            }

            @Override public void progress(long done, long all) {
                if (done > 0 && done < all) reportedBeforeLastTile.accumulateAndGet(reported.get(), Math::max);
            }
        });
        assertThat(image.width()).isEqualTo(96);
        RenderStats stats = renderer.stats();
        assertThat(reported.get()).isEqualTo(stats.totalRays());
        assertThat(stats.shadowRays()).isPositive();
        assertThat(stats.reflectedRays()).isPositive();
        // Tiles are TILE pixels square: one report per tile, and rays counted before the render ended.
        int tiles = ((96 + Renderer.TILE - 1) / Renderer.TILE) * ((64 + Renderer.TILE - 1) / Renderer.TILE);
        int passes = r.scene().settings().sampler() == dev.crt.scene.Sampler.ADAPTIVE ? 2 : 1;
        assertThat(calls.get()).isEqualTo((long) tiles * passes);
        assertThat(reportedBeforeLastTile.get()).isPositive().isLessThan(stats.totalRays());
    }
}
