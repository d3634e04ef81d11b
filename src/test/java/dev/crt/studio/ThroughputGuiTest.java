package dev.crt.studio;

import static dev.crt.studio.GuiTestSupport.onEdt;
import static dev.crt.studio.GuiTestSupport.waitFor;
import static org.assertj.core.api.Assertions.assertThat;

import java.awt.event.KeyEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The System panel charts a render's throughput while the render runs, not only when it is done. */
@Tag("gui")
class ThroughputGuiTest {
    /** Far more work than the test waits for: the render is cancelled once the chart has shown it. */
    private static final String SLOW = """
            Settings {
              width -> 1200 height -> 900 supersampling -> 6
              camera -> Camera { position -> vec3(0, 1, -6) pointing -> vec3(0, 0, 0) }
              lights -> [ PointLight { origin -> vec3(-3, 4, -5) }, PointLight { origin -> vec3(3, 4, -5) } ]
            }
            Scene {
              Sphere { radius -> 1 material -> Material { color -> rgb(1, 0.4, 0.1) reflectivity -> 0.4 } }
              Plane { normal -> vec3(0, 1, 0) position -> vec3(0, -1, 0) material -> Material { reflectivity -> 0.3 } }
            }
            """;

    @TempDir
    Path temp;

    private final Keyboard keys = new Keyboard();
    private StudioWindow studio;

    @BeforeAll
    static void display() { GuiTestSupport.requireDisplay(); }

    @AfterEach
    void close() {
        GuiTestSupport.close(studio, null);
    }

    @Test
    void throughputIsChartedEverySecondWhileARenderRuns() throws Exception {
        Path file = temp.resolve("slow.crt");
        Files.writeString(file, SLOW);
        studio = GuiTestSupport.openStudio(temp.resolve("home"), List.of(file));
        waitFor("the studio to show", 20, () -> studio.frame().isShowing());
        SystemPanel system = onEdt(() -> studio.system());
        waitFor("the script compiled", 15, () -> studio.model().current().resultIsCurrent());
        assertThat(onEdt(() -> studio.model().current().result().hasErrors())).isFalse();
        int[] steady = {0};
        waitFor("the editor to hold the focus for half a second", 10, () -> {
            steady[0] = studio.currentEditor().area().isFocusOwner() ? steady[0] + 1 : 0;
            return steady[0] >= 25;
        });
        // A key the loaded machine lost is pressed again.
        for (int attempt = 0; attempt < 3 && !onEdt(system::isSampling); attempt++) {
            keys.press(KeyEvent.VK_8, KeyEvent.VK_ALT);
            try {
                waitFor("the System panel sampling", 5, system::isSampling);
            } catch (AssertionError lost) {
                if (attempt == 2) throw lost;
            }
        }
        assertThat(onEdt(() -> system.highest(SystemPanel.THROUGHPUT))).isZero();

        onEdt(() -> studio.render());
        waitFor("the render under way", 10, studio::isRendering);
        // Within a few samples the chart's newest point shows the rays being traced, the render still running.
        waitFor("a throughput sample while rendering", 15,
                () -> studio.isRendering() && system.latest(SystemPanel.THROUGHPUT) > 0);
        int points = onEdt(() -> system.points(SystemPanel.THROUGHPUT));
        waitFor("a second sample while rendering", 5, () -> studio.isRendering()
                && system.points(SystemPanel.THROUGHPUT) > points && system.latest(SystemPanel.THROUGHPUT) > 0);
        assertThat(onEdt(studio::isRendering)).as("the render is far from done").isTrue();

        // Cancelled, the rays stop: the newest point falls back to zero within a couple of samples.
        onEdt(() -> studio.cancelRender());
        waitFor("the render stopped", 10, () -> !studio.isRendering());
        waitFor("no more throughput", 10, () -> system.latest(SystemPanel.THROUGHPUT) == 0);
        assertThat(onEdt(() -> system.highest(SystemPanel.THROUGHPUT))).isPositive();
    }
}
