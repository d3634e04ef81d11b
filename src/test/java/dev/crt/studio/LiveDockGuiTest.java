package dev.crt.studio;

import static dev.crt.studio.GuiTestSupport.onEdt;
import static dev.crt.studio.GuiTestSupport.waitFor;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.fail;

import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import dev.crt.live.LiveViewPanel;
import dev.crt.render.Renderer;
import dev.crt.scene.Camera;
import dev.crt.scene.Scene;
import java.awt.Color;
import java.awt.Point;
import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import javax.swing.JButton;
import javax.swing.SwingUtilities;
import org.assertj.swing.core.MouseButton;
import org.assertj.swing.core.Robot;
import org.assertj.swing.fixture.FrameFixture;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The live view docked in the studio, in a real window under Xvfb, drawing with the headless EGL
 * context the live view's own tests use: it shows the compiled scene, follows edits, shares the
 * selection with the code and the render view, writes the Camera block as one undoable edit, and
 * without OpenGL the studio opens all the same.
 */
@Tag("gui")
class LiveDockGuiTest {
    private static EdtWatchdog watchdog;

    @TempDir
    Path temp;

    private Robot robot;
    private final Keyboard keys = new Keyboard();
    private StudioWindow studio;

    @BeforeAll
    static void display() {
        GuiTestSupport.requireDisplay();
        watchdog = new EdtWatchdog();
    }

    @AfterAll
    static void stopWatchdog() {
        if (watchdog != null) watchdog.close();
    }

    @BeforeEach
    void robot() {
        robot = GuiTestSupport.robot();
    }

    @AfterEach
    void closeStudio(org.junit.jupiter.api.TestInfo test) {
        watchdog.report(test.getDisplayName());
        GuiTestSupport.close(studio, robot);
    }

    private Path scene(String name) throws IOException {
        Path file = temp.resolve(name);
        try (InputStream in = getClass().getResourceAsStream(name)) {
            Files.write(file, in.readAllBytes());
        }
        return file;
    }

    /** Opens the studio on {@code file}, brings the live view to the front and waits for its first frame. */
    private LiveViewPanel openWithLiveView(Path file) throws IOException {
        studio = GuiTestSupport.openStudio(temp.resolve("home"), List.of(file));
        // Without a window manager the X server's focus settles a moment after the window maps.
        int[] steady = {0};
        waitFor("the editor to hold the focus for half a second", 10, () -> {
            ScriptEditor e = studio.currentEditor();
            steady[0] = e != null && e.area().isFocusOwner() ? steady[0] + 1 : 0;
            return steady[0] >= 25;
        });
        onEdt(() -> studio.action("showLive").actionPerformed(null));
        waitFor("the live view to start", 20, () -> studio.live().state() != LiveDock.State.STARTING
                && studio.live().state() != LiveDock.State.NOT_STARTED);
        LiveDock.State state = onEdt(() -> studio.live().state());
        if (state != LiveDock.State.READY) {
            String why = onEdt(() -> studio.live().message());
            if ("true".equalsIgnoreCase(System.getenv("CI"))) fail("CI must be able to draw with OpenGL: " + why);
            org.junit.jupiter.api.Assumptions.abort(why);
        }
        LiveViewPanel view = onEdt(() -> studio.live().view());
        waitFor("a frame of the panel's size", 20, () -> view.isShowing() && view.lastImage() != null
                && view.lastImage().getWidth() == view.getWidth() && view.lastImage().getHeight() == view.getHeight());
        watchdog.reset();
        return view;
    }

    private static CompileResult compile(String text, Path file) {
        return CrtCompiler.compile(new Source(file.toString(), text, file), LiveCompiler.OPTIONS);
    }

    private static CompileResult compileAt(String text, Path file, double t) {
        return CrtCompiler.compile(new Source(file.toString(), text, file), LiveCompiler.OPTIONS.withTime(t));
    }

    /** The ray tracer's entity ids for {@code scene} seen through its own camera at the view's size. */
    private static int[] tracedIds(Scene scene, int w, int h) {
        return Renderer.prepare(scene.withSettings(scene.settings().withSize(w, h))).idPass();
    }

    /** The middle pixel of the pixels showing entity {@code id}. */
    private static Point centreOf(int[] ids, int w, int id) {
        long sx = 0, sy = 0, n = 0;
        for (int i = 0; i < ids.length; i++) {
            if (ids[i] != id) continue;
            sx += i % w;
            sy += i / w;
            n++;
        }
        assertThat(n).as("pixels of entity %d", id).isPositive();
        return new Point((int) (sx / n), (int) (sy / n));
    }

    private static Color screenPixel(java.awt.Component c, Point p) {
        Point s = onEdt(() -> {
            Point q = new Point(p);
            SwingUtilities.convertPointToScreen(q, c);
            return q;
        });
        try {
            return new java.awt.Robot().getPixelColor(s.x, s.y);
        } catch (java.awt.AWTException e) {
            throw new IllegalStateException(e);
        }
    }

    @Test
    void showsTheCompiledSceneFollowsAnEditAndSharesTheSelection() throws Exception {
        Path file = scene("two-spheres.crt");
        LiveViewPanel view = openWithLiveView(file);
        int w = onEdt(view::getWidth), h = onEdt(view::getHeight);
        Scene compiled = compile(Files.readString(file), file).scene();
        int[] traced = tracedIds(compiled, w, h);

        // The panel shows the compiled scene: its ids are the ray tracer's through the same camera ...
        int agree = 0, n = 0;
        for (int y = 5; y < h; y += 17) {
            for (int x = 5; x < w; x += 19) {
                n++;
                if (view.entityAt(x, y) == traced[y * w + x]) agree++;
            }
        }
        assertThat(agree).as("sample points where the live view and the ray tracer see the same entity").isGreaterThanOrEqualTo(n * 98 / 100);
        // ... in the script's colours (red left, blue right), and that is what is on the screen.
        Point red = centreOf(traced, w, 0), blue = centreOf(traced, w, 1);
        BufferedImage image = view.lastImage();
        Color r = new Color(image.getRGB(red.x, red.y)), b = new Color(image.getRGB(blue.x, blue.y));
        assertThat(r.getRed()).isGreaterThan(r.getBlue() + 60);
        assertThat(b.getBlue()).isGreaterThan(b.getRed() + 60);
        assertThat(screenPixel(view, red)).isEqualTo(r);
        assertThat(screenPixel(view, blue)).isEqualTo(b);

        // An edit (the blue sphere's radius 1 -> 1.6, typed) reaches the view after its compile.
        String text = Files.readString(file);
        int at = text.indexOf("radius -> 1 material -> blue") + "radius -> 1".length();
        Scene grown = compile(text.substring(0, at) + ".6" + text.substring(at), file).scene();
        Point outside = firstPointOnlyIn(traced, tracedIds(grown, w, h), w, h, 1);
        assertThat(view.entityAt(outside.x, outside.y)).isEqualTo(-1);
        onEdt(() -> studio.currentEditor().area().setCaretPosition(at));
        onEdt(() -> studio.focusEditor());
        waitFor("the editor focused", 10, () -> studio.currentEditor().area().isFocusOwner());
        keys.type(".6");
        Point p = outside;
        waitFor("the grown sphere in the live view", 10, () -> studio.model().current().resultIsCurrent()
                && view.entityAt(p.x, p.y) == 1);
        waitFor("the follow time measured", 5, () -> studio.live().lastFollowNanos() > 0);
        System.out.println("live view: compile result to first (coarse) frame drawn " + studio.live().lastFirstFrameNanos() / 1_000_000
                + " ms, to full frame " + studio.live().lastFollowNanos() / 1_000_000 + " ms; panel " + w + "x" + h + "; scene upload " + view.lastUpdateNanos() / 1_000_000 + " ms; EDT stall " + watchdog.longestMillis() + " ms");

        // Repainting the same frame (a menu or window uncovering the view) copies the picture kept in
        // the X server; beside it, what sending the picture again costs.
        long[] kept = new long[7], sent = new long[7];
        for (int i = 0; i < kept.length; i++) {
            kept[i] = onEdt(() -> {
                long t0 = System.nanoTime();
                view.paintImmediately(0, 0, w, h);
                java.awt.Toolkit.getDefaultToolkit().sync();
                return System.nanoTime() - t0;
            });
            sent[i] = onEdt(() -> {
                long t0 = System.nanoTime();
                java.awt.Graphics g = view.getGraphics();
                g.drawImage(new BufferedImage(view.lastImage().getColorModel(), view.lastImage().copyData(null), false, null), 0, 0, null);
                g.dispose();
                java.awt.Toolkit.getDefaultToolkit().sync();
                return System.nanoTime() - t0;
            });
        }
        java.util.Arrays.sort(kept);
        java.util.Arrays.sort(sent);
        System.out.printf(java.util.Locale.ROOT, "live view: repaint of the same frame %.2f ms (median of 7); sending the picture again %.2f ms%n",
                kept[3] / 1e6, sent[3] / 1e6);
        assertThat(screenPixel(view, red)).isEqualTo(r);

        // A click on the red sphere in the live view selects it for the studio and shows its code.
        robot.click(view, red, MouseButton.LEFT_BUTTON, 1);
        waitFor("the red sphere selected", 10, () -> studio.model().selectedIndex() == 0 && view.selected() == 0);
        assertThat(onEdt(() -> studio.currentEditor().area().getSelectedText())).startsWith("Sphere { center -> vec3(-1.5");
        assertThat(onEdt(() -> studio.currentEditor().area().getCaretLineNumber() + 1)).isEqualTo(11);

        // The render view outlines what the live view selected ...
        keys.press(KeyEvent.VK_F5);
        waitFor("the render to finish", 30, () -> studio.lastRender() != null);
        int[] renderedIds = Renderer.prepare(compile(onEdt(() -> studio.currentEditor().area().getText()), file).scene()).idPass();
        waitFor("the red sphere outlined in the render view", 10, () -> studio.renderView().outline() != null);
        assertOutlines(onEdt(() -> studio.renderView().outline()), renderedIds, 0);
        // ... and a pick there selects the same entity in the live view.
        Point bluePicture = onEdt(() -> studio.renderView().fromPicture(120, 60));
        robot.click(studio.renderView(), bluePicture, MouseButton.LEFT_BUTTON, 1);
        waitFor("the blue sphere selected in the live view", 10, () -> view.selected() == 1 && studio.model().selectedIndex() == 1);
        waitFor("the blue sphere outlined", 10, () -> {
            BufferedImage o = studio.renderView().outline();
            return o != null && (o.getRGB(120, 60) >>> 24) == 0 && opaque(o) > 0 && renderedIds[firstOpaque(o)] == 1;
        });
        assertOutlines(onEdt(() -> studio.renderView().outline()), renderedIds, 1);
    }

    @Test
    void followsTheAnimationPanelsTimeAndEditsMadeAtIt() throws Exception {
        Path file = scene("moving-sphere.crt");
        LiveViewPanel view = openWithLiveView(file);
        int w = onEdt(view::getWidth), h = onEdt(view::getHeight);
        String text = Files.readString(file);
        int[] at0 = tracedIds(compile(text, file).scene(), w, h);
        int[] at4 = tracedIds(compileAt(text, file, 4).scene(), w, h);
        // Where the sphere is at t = 4 and not at t = 0 (it moves right with t).
        Point p = firstPointOnlyIn(at0, at4, w, h, 0);
        assertThat(view.entityAt(p.x, p.y)).isEqualTo(-1);

        // Scrubbing the Animation panel to frame 4 moves the sphere in the live view.
        FrameFixture window = new FrameFixture(robot, studio.frame());
        keys.press(KeyEvent.VK_7, KeyEvent.VK_ALT);
        waitFor("the Animation panel to show", 10, () -> studio.animation().isShowing());
        window.slider("animSlider").slideTo(4);
        waitFor("the studio at t = 4", 10, () -> studio.model().time() == 4.0);
        keys.press(KeyEvent.VK_4, KeyEvent.VK_ALT);
        waitFor("the live view to show again", 10, view::isShowing);
        waitFor("the sphere of t = 4 in the live view", 10, () -> view.entityAt(p.x, p.y) == 0);
        int[] agree = agreement(view, at4, w, h);
        assertThat(agree[0]).as("sample points agreeing with the ray tracer at t = 4").isGreaterThanOrEqualTo(agree[1] * 98 / 100);

        // An edit made while at t = 4 (radius 0.8 -> 1.25) shows at t = 4, not at t = 0.
        int at = text.indexOf("radius -> 0.8") + "radius -> 0.".length();
        int[] grown = tracedIds(compileAt(text.substring(0, at - 2) + "1.25" + text.substring(at + 1), file, 4).scene(), w, h);
        Point q = firstPointOnlyIn(at4, grown, w, h, 0);
        onEdt(() -> studio.currentEditor().area().replaceRange("1.25", at - 2, at + 1));
        waitFor("the grown sphere at t = 4 in the live view", 10, () -> studio.model().current().resultIsCurrent()
                && view.entityAt(q.x, q.y) == 0);

        // Back at t = 0 the view shows the script's t = 0 scene again.
        keys.press(KeyEvent.VK_7, KeyEvent.VK_ALT);
        waitFor("the Animation panel to show", 10, () -> studio.animation().isShowing());
        window.slider("animSlider").slideTo(0);
        waitFor("the studio at t = 0", 10, () -> studio.model().time() == 0.0);
        waitFor("the sphere back at its t = 0 place", 10, () -> view.entityAt(p.x, p.y) == -1);
    }

    /** Sample points of the view where the live view and {@code traced} see the same entity, and how many were sampled. */
    private static int[] agreement(LiveViewPanel view, int[] traced, int w, int h) {
        int agree = 0, n = 0;
        for (int y = 5; y < h; y += 17) {
            for (int x = 5; x < w; x += 19) {
                n++;
                if (view.entityAt(x, y) == traced[y * w + x]) agree++;
            }
        }
        return new int[] {agree, n};
    }

    private static int opaque(BufferedImage o) {
        int n = 0;
        for (int y = 0; y < o.getHeight(); y++) for (int x = 0; x < o.getWidth(); x++) if ((o.getRGB(x, y) >>> 24) != 0) n++;
        return n;
    }

    private static int firstOpaque(BufferedImage o) {
        for (int i = 0; i < o.getWidth() * o.getHeight(); i++) if ((o.getRGB(i % o.getWidth(), i / o.getWidth()) >>> 24) != 0) return i;
        return -1;
    }

    /** The outline covers only pixels of entity {@code id}, and every one of its pixels next to another id. */
    private static void assertOutlines(BufferedImage o, int[] ids, int id) {
        int w = o.getWidth(), h = o.getHeight(), edges = 0;
        for (int y = 1; y < h - 1; y++) {
            for (int x = 1; x < w - 1; x++) {
                int i = y * w + x;
                boolean drawn = (o.getRGB(x, y) >>> 24) != 0;
                boolean edge = ids[i] == id && (ids[i - 1] != id || ids[i + 1] != id || ids[i - w] != id || ids[i + w] != id);
                assertThat(drawn).as("outline at %d,%d", x, y).isEqualTo(edge);
                if (edge) edges++;
            }
        }
        assertThat(edges).isGreaterThan(20);
    }

    /** A pixel that shows entity {@code id} in {@code after} and nothing in {@code before}, away from any edge. */
    private static Point firstPointOnlyIn(int[] before, int[] after, int w, int h, int id) {
        for (int y = 2; y < h - 2; y++) {
            for (int x = 2; x < w - 2; x++) {
                boolean inside = true;
                for (int dy = -2; dy <= 2 && inside; dy++) {
                    for (int dx = -2; dx <= 2 && inside; dx++) {
                        int i = (y + dy) * w + x + dx;
                        inside = before[i] == -1 && after[i] == id;
                    }
                }
                if (inside) return new Point(x, y);
            }
        }
        throw new AssertionError("the edit changes no pixel");
    }

    @Test
    void copyCameraToScriptWritesTheCameraBlockAsOneUndoableEdit() throws Exception {
        Path file = scene("two-spheres.crt");
        String original = Files.readString(file);
        LiveViewPanel view = openWithLiveView(file);
        // Orbit the free camera with the view's own keys.
        robot.click(view, new Point(5, onEdt(view::getHeight) / 2), MouseButton.LEFT_BUTTON, 1);
        waitFor("the view focused", 10, view::isFocusOwner);
        Camera before = onEdt(view::freeCamera);
        keys.press(KeyEvent.VK_LEFT);
        keys.press(KeyEvent.VK_UP);
        waitFor("the free camera moved", 10, () -> !view.freeCamera().position().equals(before.position()));
        Camera moved = onEdt(view::freeCamera);
        String block = onEdt(view::cameraBlock);

        JButton copy = robot.finder().findByName(studio.frame(), "Copy-camera-to-script", JButton.class);
        robot.click(copy);
        waitFor("the block in the script", 10, () -> studio.currentEditor().area().getText().contains(block));
        String written = onEdt(() -> studio.currentEditor().area().getText());
        int start = original.indexOf("Camera {");
        int end = original.indexOf('}', start) + 1;
        assertThat(written).isEqualTo(original.substring(0, start) + block + original.substring(end));
        Camera compiled = compile(written, file).scene().settings().camera();
        assertThat(compiled.position().minus(moved.position()).length()).isLessThan(1e-4);
        assertThat(compiled.pointing().minus(moved.pointing()).length()).isLessThan(1e-4);
        assertThat(compiled.fov()).isCloseTo(moved.fov(), org.assertj.core.data.Offset.offset(1e-4));
        assertThat(onEdt(() -> studio.frame().getTitle())).startsWith("*two-spheres.crt");

        // One Ctrl+Z (typed in the editor) takes the whole block back, and the script is unmodified again.
        onEdt(() -> studio.focusEditor());
        waitFor("the editor focused", 10, () -> studio.currentEditor().area().isFocusOwner());
        keys.press(KeyEvent.VK_Z, KeyEvent.VK_CONTROL);
        waitFor("the original text back", 10, () -> studio.currentEditor().area().getText().equals(original));
        waitFor("the modified mark gone", 10, () -> !studio.model().current().isModified()
                && studio.frame().getTitle().startsWith("two-spheres.crt"));
    }

    @Test
    void withoutOpenGlTheStudioOpensAndThePanelSaysWhyInOneSentence() throws Exception {
        Path script = scene("two-spheres.crt");
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Process studioProcess = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"),
                "-Djava.util.prefs.userRoot=" + temp.resolve("prefs"),
                "-Dorg.lwjgl.egl.libname=" + temp.resolve("no-such-libEGL.so"),
                LiveDockWithoutGl.class.getName(), temp.resolve("home").toString(), script.toString())
                .redirectErrorStream(true).start();
        StringBuilder out = new StringBuilder();
        try (BufferedReader in = new BufferedReader(new InputStreamReader(studioProcess.getInputStream(), StandardCharsets.UTF_8))) {
            String line;
            while ((line = in.readLine()) != null) out.append(line).append('\n');
        }
        assertThat(studioProcess.waitFor(60, TimeUnit.SECONDS)).isTrue();
        assertThat(studioProcess.exitValue()).as("exit code; output:%n%s", out).isZero();
        String said = out.toString();
        assertThat(said).contains("window showing: true", "state: UNAVAILABLE", "panel showing: true", "editor text intact: true");
        String message = said.lines().filter(l -> l.startsWith("message: ")).findFirst().orElseThrow().substring(9);
        assertThat(message).startsWith("OpenGL is not available: the EGL library").doesNotContain("\n").doesNotContain("Exception");
        assertThat(said).doesNotContain("\tat ");
    }
}
