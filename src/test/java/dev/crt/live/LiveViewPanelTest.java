package dev.crt.live;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.scene.Entity;
import dev.crt.scene.Scene;
import dev.crt.scene.Sphere;
import java.awt.event.KeyEvent;
import java.awt.event.MouseEvent;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** The Swing live view driven headless through its real event handlers (no window needed: it draws offscreen). */
class LiveViewPanelTest {
    private LiveViewPanel panel;

    @BeforeEach
    void open() throws Exception {
        GlAvailability.open().close();
        panel = LiveViewPanel.open();
        SwingUtilities.invokeAndWait(() -> panel.setSize(320, 240));
    }

    @AfterEach
    void close() {
        if (panel != null) panel.close();
    }

    private void onEdt(Runnable r) throws Exception {
        SwingUtilities.invokeAndWait(r);
        panel.awaitIdle();
    }

    @Test
    void showsTheSceneThroughItsCameraAndPicksWhatIsClicked() throws Exception {
        Scene scene = AlignmentTest.compile(Path.of("scenes/csg-sculpture.crt"));
        onEdt(() -> panel.setScene(scene));
        BufferedImage image = panel.lastImage();
        assertThat(image).isNotNull();
        assertThat(image.getWidth()).isEqualTo(320);

        // The free camera starts at the scene camera: the panel's ids are the ray tracer's at the same size.
        Scene small = scene.withSettings(scene.settings().withSize(320, 240));
        int[] traced = dev.crt.render.Renderer.prepare(small).idPass();
        int agree = 0, n = 0;
        for (int y = 10; y < 240; y += 23) {
            for (int x = 10; x < 320; x += 29) {
                n++;
                if (panel.entityAt(x, y) == traced[y * 320 + x]) agree++;
            }
        }
        assertThat(agree).isGreaterThanOrEqualTo(n - 2);

        List<Integer> picked = new ArrayList<>();
        List<Entity> entities = new ArrayList<>();
        panel.addSelectionListener((i, e) -> {
            picked.add(i);
            entities.add(e);
        });
        int cx = 160, cy = 120;
        int expected = traced[cy * 320 + cx];
        assertThat(expected).isNotNegative();
        onEdt(() -> {
            panel.dispatchEvent(new MouseEvent(panel, MouseEvent.MOUSE_PRESSED, 0, MouseEvent.BUTTON1_DOWN_MASK, cx, cy, 1, false, MouseEvent.BUTTON1));
            panel.dispatchEvent(new MouseEvent(panel, MouseEvent.MOUSE_RELEASED, 0, 0, cx, cy, 1, false, MouseEvent.BUTTON1));
        });
        assertThat(picked).containsExactly(expected);
        assertThat(entities.get(0)).isSameAs(scene.entities().get(expected));
        assertThat(panel.selected()).isEqualTo(expected);
    }

    @Test
    void aNewSceneIsDrawnAtHalfSizeFirstAndACameraMoveAtFullSizeOnly() throws Exception {
        Scene scene = AlignmentTest.compile(Path.of("scenes/dice.crt"));
        onEdt(() -> panel.setSize(640, 480));
        List<BufferedImage> drawn = new java.util.concurrent.CopyOnWriteArrayList<>();
        panel.addFrameListener(drawn::add);
        onEdt(() -> panel.setScene(scene));
        assertThat(drawn).extracting(BufferedImage::getWidth).containsExactly(320, 640);
        assertThat(panel.firstFrameNanos()).isPositive();
        // The coarse picture is the sharp one at half the resolution: the same colours nearly everywhere.
        BufferedImage coarse = drawn.get(0), sharp = drawn.get(1);
        int close = 0;
        for (int y = 0; y < 240; y++) {
            for (int x = 0; x < 320; x++) {
                int a = coarse.getRGB(x, y), b = sharp.getRGB(2 * x, 2 * y);
                int d = Math.abs((a >> 16 & 255) - (b >> 16 & 255)) + Math.abs((a >> 8 & 255) - (b >> 8 & 255)) + Math.abs((a & 255) - (b & 255));
                if (d < 30) close++;
            }
        }
        assertThat(close).isGreaterThan(320 * 240 * 9 / 10);
        assertThat(panel.entityAt(320, 240)).isEqualTo(dev.crt.render.Renderer.prepare(
                scene.withSettings(scene.settings().withSize(640, 480))).idPass()[240 * 640 + 320]);

        drawn.clear();
        onEdt(() -> panel.key(KeyEvent.VK_LEFT, false));
        assertThat(drawn).extracting(BufferedImage::getWidth).containsExactly(640);
    }

    @Test
    void draggingOrbitsTheFreeCameraAndKeysSwitchViews() throws Exception {
        Scene scene = AlignmentTest.compile(Path.of("scenes/dice.crt"));
        onEdt(() -> panel.setScene(scene));
        FreeCamera before = panel.getFreeCamera();
        BufferedImage first = panel.lastImage();
        onEdt(() -> {
            panel.dispatchEvent(new MouseEvent(panel, MouseEvent.MOUSE_PRESSED, 0, MouseEvent.BUTTON1_DOWN_MASK, 100, 100, 1, false, MouseEvent.BUTTON1));
            panel.dispatchEvent(new MouseEvent(panel, MouseEvent.MOUSE_DRAGGED, 0, MouseEvent.BUTTON1_DOWN_MASK, 150, 100, 0, false, MouseEvent.BUTTON1));
            panel.dispatchEvent(new MouseEvent(panel, MouseEvent.MOUSE_RELEASED, 0, 0, 150, 100, 1, false, MouseEvent.BUTTON1));
        });
        assertThat(panel.getFreeCamera().yaw()).isCloseTo(before.yaw() + 15, org.assertj.core.data.Offset.offset(1e-9));
        assertThat(panel.getFreeCamera().distance()).isCloseTo(before.distance(), org.assertj.core.data.Offset.offset(1e-9));
        assertThat(panel.selected()).as("a drag is not a click").isEqualTo(-1);
        assertThat(differingPixels(first, panel.lastImage())).isGreaterThan(1000);

        onEdt(() -> panel.key(KeyEvent.VK_V, false));
        assertThat(panel.isQuad()).isTrue();
        onEdt(() -> panel.key(KeyEvent.VK_3, false));
        assertThat(panel.isQuad()).isFalse();
        assertThat(panel.singleViewport()).isEqualTo(Viewport.TOP);
        // Top view: orthographic, looking down; the grid shows around the dice.
        assertThat(panel.viewOf(Viewport.TOP).orthographic()).isTrue();
        assertThat(panel.viewOf(Viewport.TOP).forward().y()).isEqualTo(-1);
    }

    @Test
    void thePreviewRayTracesTheFreeViewAtHalfSize() throws Exception {
        Scene scene = AlignmentTest.compile(Path.of("scenes/dice.crt"));
        onEdt(() -> panel.setScene(scene));
        BufferedImage traced = panel.rayTracePreview().get();
        assertThat(traced.getWidth()).isEqualTo(160);
        assertThat(traced.getHeight()).isEqualTo(120);
        // The free camera starts at the scene camera: the preview is the ray tracer's picture at that size.
        Scene small = scene.withSettings(scene.settings().withSize(160, 120).withSampling(1, 1));
        dev.crt.image.FrameBuffer expected = dev.crt.render.Renderer.prepare(small).render(1, dev.crt.render.RenderMonitor.NONE);
        int rgb = traced.getRGB(80, 60) & 0xFFFFFF;
        assertThat(rgb >> 16).isEqualTo(dev.crt.image.ImageFiles.toByte(expected.get(80, 60, 0), scene.settings().gamma()));
    }

    @Test
    void aNewCompileUploadsOnlyWhatChanged() throws Exception {
        Scene scene = AlignmentTest.compile(Path.of("scenes/box-field.crt"));
        onEdt(() -> panel.setScene(scene));
        List<Entity> moved = new ArrayList<>(scene.entities());
        int last = moved.size() - 1;
        Sphere s = null;
        for (int i = last; i >= 0 && s == null; i--) {
            if (moved.get(i) instanceof Sphere sp) {
                s = sp;
                last = i;
            }
        }
        assertThat(s).as("box-field has a sphere").isNotNull();
        Sphere bigger = new Sphere(s.center(), s.radius() * 1.5, s.material(), s.transform(), s.span());
        moved.set(last, bigger);
        Scene next = new Scene(scene.sourceName(), scene.settings(), moved);
        GpuScene before = SceneConverter.convert(scene);
        onEdt(() -> panel.setScene(next));
        assertThat(panel.lastUpdateNanos()).isPositive();
        LiveRenderer r = rendererOf(panel);
        assertThat(r.lastUploadFloats()).isPositive().isLessThan(before.texels * 4L / 10);
        onEdt(() -> panel.setScene(next));
        assertThat(r.lastUploadFloats()).isZero();
    }

    private static LiveRenderer rendererOf(LiveViewPanel p) throws Exception {
        var f = LiveViewPanel.class.getDeclaredField("renderer");
        f.setAccessible(true);
        return (LiveRenderer) f.get(p);
    }

    private static int differingPixels(BufferedImage a, BufferedImage b) {
        int n = 0;
        for (int y = 0; y < a.getHeight(); y++) {
            for (int x = 0; x < a.getWidth(); x++) if (a.getRGB(x, y) != b.getRGB(x, y)) n++;
        }
        return n;
    }
}
