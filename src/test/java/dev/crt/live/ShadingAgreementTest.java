package dev.crt.live;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.image.FrameBuffer;
import dev.crt.render.RenderMonitor;
import dev.crt.render.Renderer;
import dev.crt.scene.Scene;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The live view's colours agree with the ray tracer's where the ray tracer's picture needs no
 * secondary rays: scenes without mirrors, glass or area lights, whose shadows (CSG casting onto a
 * plane and onto itself) the live view's shadow rays must find. AlignmentTest checks the shapes;
 * this checks the shading, the shadow rays above all (a scan that missed an entity lights pixels
 * the ray tracer leaves in shadow).
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class ShadingAgreementTest {
    static final int WIDTH = 160, HEIGHT = 120;
    private Preview preview;

    @BeforeAll
    void open() {
        preview = GlAvailability.open();
    }

    @AfterAll
    void close() {
        if (preview != null) preview.close();
    }

    @ParameterizedTest
    @ValueSource(strings = {"scenes/dice.crt", "src/test/resources/dev/crt/live/csg-nested.crt",
        "src/test/resources/dev/crt/live/mesh-knot.crt"})
    void coloursAgreeAwayFromSilhouettes(String file) throws IOException {
        Scene scene = AlignmentTest.compile(Path.of(file));
        scene = scene.withSettings(scene.settings().withSize(WIDTH, HEIGHT).withSampling(1, 1));
        Renderer tracer = Renderer.prepare(scene);
        FrameBuffer traced = tracer.render(1, RenderMonitor.NONE);
        int[] ids = tracer.idPass();
        preview.draw(scene);
        int[] drawn = preview.renderer().readColour();
        double gamma = scene.settings().gamma();

        int compared = 0, agreeing = 0, dark = 0, darkAgreeing = 0;
        for (int y = 1; y < HEIGHT - 1; y++) {
            for (int x = 1; x < WIDTH - 1; x++) {
                if (nearSilhouette(ids, x, y) || ids[y * WIDTH + x] < 0) continue;
                compared++;
                int p = drawn[y * WIDTH + x];
                boolean close = true;
                double brightness = 0;
                for (int c = 0; c < 3; c++) {
                    double live = ((p >> (16 - 8 * c)) & 255) / 255.0;
                    double ray = Math.pow(Math.min(1, Math.max(0, traced.get(x, y, c))), 1 / gamma);
                    close &= Math.abs(live - ray) <= 3 / 255.0;
                    brightness += ray;
                }
                if (close) agreeing++;
                if (brightness < DARK) {
                    dark++;
                    if (close) darkAgreeing++;
                }
            }
        }
        System.out.printf(Locale.ROOT, "%s: %d pixels compared, %.2f%% within 3/255; %d dark, %.2f%% of them within%n",
                file, compared, 100.0 * agreeing / compared, dark, 100.0 * darkAgreeing / Math.max(1, dark));
        assertThat(compared).isGreaterThan(WIDTH * HEIGHT / 3);
        assertThat((double) agreeing / compared).as("colour agreement of %s", file).isGreaterThanOrEqualTo(0.98);
        // The shadows themselves: the dark pixels are few, so they are held to the same bar on their own.
        assertThat(dark).as("dark pixels of %s", file).isGreaterThan(compared / 50);
        assertThat((double) darkAgreeing / dark).as("colour agreement of the dark pixels of %s", file)
                .isGreaterThanOrEqualTo(0.98);
    }

    /** The sum of a ray-traced pixel's channels under which it counts as dark: in shadow, or facing away from the lights. */
    static final double DARK = 0.3;

    private static boolean nearSilhouette(int[] ids, int x, int y) {
        int id = ids[y * WIDTH + x];
        for (int dy = -1; dy <= 1; dy++) {
            for (int dx = -1; dx <= 1; dx++) {
                if (ids[(y + dy) * WIDTH + x + dx] != id) return true;
            }
        }
        return false;
    }
}
