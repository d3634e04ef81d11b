package dev.crt.studio;

import static dev.crt.studio.GuiTestSupport.onEdt;
import static dev.crt.studio.GuiTestSupport.waitFor;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.image.FrameBuffer;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Source;
import dev.crt.render.RenderMonitor;
import dev.crt.render.Renderer;
import java.awt.Color;
import javax.swing.UIManager;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.event.KeyEvent;
import java.awt.event.MouseEvent;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.assertj.swing.core.MouseButton;
import org.assertj.swing.core.Robot;
import org.assertj.swing.fixture.FrameFixture;
import org.assertj.swing.fixture.JTextComponentFixture;
import org.fife.ui.rsyntaxtextarea.RSyntaxTextArea;
import org.fife.ui.rsyntaxtextarea.parser.ParserNotice;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The studio driven as a user drives it: a real window, real key presses and mouse clicks. */
@Tag("gui")
class StudioGuiTest {
    private static EdtWatchdog watchdog;
    private static long longestStall;

    @TempDir
    Path temp;

    private Robot robot;
    private final Keyboard keys = new Keyboard();
    private StudioWindow studio;
    private FrameFixture window;

    @BeforeAll
    static void display() {
        GuiTestSupport.requireDisplay();
        watchdog = new EdtWatchdog();
    }

    @AfterAll
    static void report() {
        if (watchdog == null) return;
        watchdog.close();
        System.out.println("EDT watchdog: longest Event Dispatch Thread stall in the GUI tests: " + longestStall + " ms");
    }

    @BeforeEach
    void robot() {
        robot = GuiTestSupport.robot();
    }

    @AfterEach
    void closeStudio(org.junit.jupiter.api.TestInfo test) {
        longestStall = Math.max(longestStall, watchdog.longestMillis());
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

    private void open(Path... files) throws IOException {
        studio = GuiTestSupport.openStudio(temp.resolve("home"), List.of(files));
        window = new FrameFixture(robot, studio.frame());
        // Without a window manager the X server's focus settles a moment after the window maps;
        // keys typed before that are lost, as they would be for a person typing that fast.
        int[] steady = {0};
        waitFor("the editor to hold the focus for half a second", 10, () -> {
            ScriptEditor e = studio.currentEditor();
            steady[0] = e != null && e.area().isFocusOwner() ? steady[0] + 1 : 0;
            return steady[0] >= 25;
        });
        // Building the window is start-up, measured apart; the watchdog measures what follows.
        watchdog.reset();
    }

    /** Ctrl+key as a user presses it: Ctrl down, the key, Ctrl up. */
    private void ctrl(int key) {
        keys.press(key, KeyEvent.VK_CONTROL);
    }

    private RSyntaxTextArea area() { return onEdt(() -> studio.currentEditor().area()); }

    private JTextComponentFixture editor() { return new JTextComponentFixture(robot, area()); }

    private ScriptDocument document() { return onEdt(() -> studio.model().current()); }

    private void caretAtEnd() {
        onEdt(() -> area().setCaretPosition(area().getDocument().getLength()));
    }

    @Test
    void opensAScriptWithTheFocusInTheEditorAndItsNameInTheTitle() throws IOException {
        Path file = scene("two-spheres.crt");
        open(file);
        assertThat(onEdt(() -> studio.frame().getTitle())).startsWith("two-spheres.crt");
        assertThat(onEdt(() -> area().getText())).isEqualTo(Files.readString(file));
        assertThat(onEdt(() -> area().getAccessibleContext().getAccessibleName())).startsWith("Script editor");
        assertThat(onEdt(() -> studio.renderView().getAccessibleContext().getAccessibleName())).isEqualTo("Render view");
        // The docking library knows the Script panel holds the focus, so it asks for none itself:
        // while it thought another panel focused, it took the focus from the editor, which took it
        // back, a dozen times in the first seconds of typing (docs/studio.md, "EDT stalls while typing").
        assertThat(onEdt(() -> studio.dock().control().getController().getFocusedDockable()))
                .isSameAs(onEdt(() -> studio.dock().dockable("script").intern()));
        int[] focusChanges = {0};
        java.beans.PropertyChangeListener count = e -> focusChanges[0]++;
        onEdt(() -> java.awt.KeyboardFocusManager.getCurrentKeyboardFocusManager().addPropertyChangeListener("focusOwner", count));
        caretAtEnd();
        keys.type("x = 1");
        assertThat(onEdt(() -> studio.frame().getTitle())).startsWith("*two-spheres.crt");
        onEdt(() -> java.awt.KeyboardFocusManager.getCurrentKeyboardFocusManager().removePropertyChangeListener("focusOwner", count));
        assertThat(onEdt(() -> focusChanges[0])).as("focus changes while typing").isZero();
    }

    @Test
    void aTypedErrorIsSquiggledWithItsMessageAndGoesAwayWhenFixed() throws IOException {
        open(scene("two-spheres.crt"));
        caretAtEnd();
        watchdog.reset();
        keys.type("\nk = 2 * nothing");
        try {
            waitFor("a diagnostic about 'nothing'", 10, () -> area().getParserNotices().stream()
                    .anyMatch(n -> n.getMessage().contains("nothing")));
        } catch (AssertionError e) {
            throw new AssertionError(e.getMessage() + "; text: " + onEdt(() -> area().getText()) + "; result: "
                    + onEdt(() -> document().result() == null ? null : document().result().diagnostics()) + " current "
                    + onEdt(() -> document().resultIsCurrent()) + " notices " + onEdt(() -> area().getParserNotices()));
        }
        ParserNotice notice = onEdt(() -> area().getParserNotices().stream()
                .filter(n -> n.getMessage().contains("nothing")).findFirst().orElseThrow());
        assertThat(notice.getLevel()).isEqualTo(ParserNotice.Level.ERROR);
        int offset = notice.getOffset();
        assertThat(onEdt(() -> area().getText().substring(offset, offset + notice.getLength()))).isEqualTo("nothing");
        // The tooltip where the squiggle is carries the message.
        String tip = onEdt(() -> {
            try {
                Rectangle r = area().modelToView2D(offset + 2).getBounds();
                MouseEvent at = new MouseEvent(area(), MouseEvent.MOUSE_MOVED, System.currentTimeMillis(), 0,
                        r.x, r.y + r.height / 2, 0, false);
                return area().getToolTipText(at);
            } catch (javax.swing.text.BadLocationException e) {
                throw new IllegalStateException(e);
            }
        });
        assertThat(tip).contains("nothing");
        // Fix it: replace the unknown name by a number.
        for (int i = 0; i < "nothing".length(); i++) keys.press(KeyEvent.VK_BACK_SPACE);
        keys.type("3");
        waitFor("the diagnostic to go", 10, () -> document().resultIsCurrent() && area().getParserNotices().isEmpty());
        System.out.println("keystroke to squiggle (last compile): " + onEdt(() -> studio.compiler().lastLatencyNanos()) / 1_000_000 + " ms");
    }

    @Test
    void theLookOfCrt2015RendersWithTheOriginalShadingModel() throws IOException {
        Path file = scene("two-spheres.crt");
        open(file);
        keys.press(KeyEvent.VK_O, KeyEvent.VK_CONTROL, KeyEvent.VK_SHIFT);
        keys.press(KeyEvent.VK_F5);
        waitFor("the render to finish", 30, () -> studio.lastRender() != null);
        CompileResult compiled = CrtCompiler.compile(new Source(file.toString(), Files.readString(file), file),
                LiveCompiler.OPTIONS);
        dev.crt.scene.Scene original = compiled.scene().withSettings(
                compiled.scene().settings().withShading(dev.crt.scene.Shading.ORIGINAL));
        FrameBuffer expected = Renderer.prepare(original).render(1, RenderMonitor.NONE);
        FrameBuffer crt = Renderer.prepare(compiled.scene()).render(1, RenderMonitor.NONE);
        BufferedImage shown = onEdt(() -> studio.renderView().picture());
        int differ = 0;
        for (int y = 0; y < 120; y += 7) {
            for (int x = 0; x < 160; x += 7) {
                assertThat(shown.getRGB(x, y) & 0xFFFFFF).as("pixel %d,%d", x, y).isEqualTo(RenderJob.rgb(expected, x, y, 1));
                if (RenderJob.rgb(expected, x, y, 1) != RenderJob.rgb(crt, x, y, compiled.scene().settings().outputGamma())) differ++;
            }
        }
        // The two models differ on this scene, so the check above could tell them apart.
        assertThat(differ).isPositive();
    }

    @Test
    void f5RendersThePictureOfTheSameRendererAndAClickedPixelPutsTheCaretOnItsCode() throws IOException {
        Path file = scene("two-spheres.crt");
        open(file);
        watchdog.reset();
        keys.press(KeyEvent.VK_F5);
        waitFor("the render to finish", 30, () -> studio.lastRender() != null);
        System.out.println("EDT watchdog during the render: " + watchdog.longestMillis() + " ms");

        CompileResult compiled = CrtCompiler.compile(new Source(file.toString(), Files.readString(file), file),
                LiveCompiler.OPTIONS);
        FrameBuffer expected = Renderer.prepare(compiled.scene()).render(1, RenderMonitor.NONE);
        double gamma = compiled.scene().settings().outputGamma();
        BufferedImage shown = onEdt(() -> studio.renderView().picture());
        assertThat(shown.getWidth()).isEqualTo(160);
        for (int y = 0; y < 120; y += 7) {
            for (int x = 0; x < 160; x += 7) {
                assertThat(shown.getRGB(x, y) & 0xFFFFFF).as("pixel %d,%d", x, y).isEqualTo(RenderJob.rgb(expected, x, y, gamma));
            }
        }
        // What is on the screen, at 1:1, is that picture too.
        ctrl(KeyEvent.VK_1);
        robot.waitForIdle();
        for (Point p : new Point[] {new Point(40, 60), new Point(120, 60), new Point(5, 5)}) {
            Point screen = onEdt(() -> {
                Point c = studio.renderView().fromPicture(p.x, p.y);
                javax.swing.SwingUtilities.convertPointToScreen(c, studio.renderView());
                return c;
            });
            Color c = screenPixel(screen);
            assertThat(c.getRGB() & 0xFFFFFF).as("screen pixel of %s", p).isEqualTo(RenderJob.rgb(expected, p.x, p.y, gamma));
        }

        // Click the blue sphere, then the red one: the caret lands on the line that wrote each.
        ctrl(KeyEvent.VK_0);
        robot.waitForIdle();
        clickPicture(120, 60);
        waitFor("the caret on line 12", 5, () -> lineOfCaret() == 12);
        clickPicture(40, 60);
        waitFor("the caret on line 11", 5, () -> lineOfCaret() == 11);
        assertThat(onEdt(() -> area().getSelectedText())).startsWith("Sphere { center -> vec3(-1.5");
    }

    private static Color screenPixel(Point p) {
        try {
            return new java.awt.Robot().getPixelColor(p.x, p.y);
        } catch (java.awt.AWTException e) {
            throw new IllegalStateException(e);
        }
    }

    private void clickPicture(int px, int py) {
        Point at = onEdt(() -> studio.renderView().fromPicture(px, py));
        robot.click(studio.renderView(), at, MouseButton.LEFT_BUTTON, 1);
    }

    private int lineOfCaret() {
        return area().getCaretLineNumber() + 1;
    }

    @Test
    void ctrlSpaceCompletesAnAttributeOfTheTypeBeingWritten() throws IOException {
        open(scene("two-spheres.crt"));
        caretAtEnd();
        keys.type("\nScene { Sphere { radius -> 1 cen");
        ctrl(KeyEvent.VK_SPACE);
        waitFor("center completed", 5, () -> area().getText().endsWith("Sphere { radius -> 1 center -> "));
    }

    @Test
    void savingWritesTheFileAtomicallyAndReopeningGivesTheSameText() throws IOException {
        Path file = scene("two-spheres.crt");
        open(file);
        caretAtEnd();
        keys.type("\n-- saved by the test");
        ctrl(KeyEvent.VK_S);
        waitFor("the document saved", 5, () -> !document().isModified());
        String text = onEdt(() -> area().getText());
        assertThat(Files.readString(file, StandardCharsets.UTF_8)).isEqualTo(text).endsWith("-- saved by the test");
        try (Stream<Path> files = Files.list(temp)) {
            assertThat(files.map(p -> p.getFileName().toString())).containsExactlyInAnyOrder("two-spheres.crt", "home");
        }
        ctrl(KeyEvent.VK_W);
        waitFor("the tab closed", 5, () -> studio.model().find(file).isEmpty());
        onEdt(() -> studio.open(file));
        assertThat(onEdt(() -> area().getText())).isEqualTo(text);
    }

    @Test
    void aRunawayLoopWhileTypingLeavesTheEditorResponsive() throws IOException {
        open(scene("two-spheres.crt"));
        caretAtEnd();
        keys.type("\ni = 0 while (true) { i = i + 1 }");
        watchdog.reset();
        long start = System.nanoTime();
        keys.type(" -- still typing while it loops");
        long typing = System.nanoTime() - start;
        long stall = watchdog.longestMillis();
        assertThat(onEdt(() -> area().getText())).endsWith("i = i + 1 } -- still typing while it loops");
        System.out.println("typing 31 keys during a runaway loop: " + typing / 1_000_000 + " ms, longest EDT stall " + stall + " ms");
        assertThat(stall).as("longest EDT stall while a runaway loop compiles").isLessThan(1000);
        waitFor("the loop budget to end the compile with a diagnostic", 30, () -> document().resultIsCurrent()
                && document().result().hasErrors());
    }

    @Test
    void renderingAScriptWithAnErrorListsItInTheConsoleAndAClickThereGoesToIt() throws IOException {
        Path file = temp.resolve("broken.crt");
        Files.writeString(file, "a = 1\nb = a + \"text\" * 2\nScene { Sphere { } }\n");
        open(file);
        onEdt(() -> area().setCaretPosition(0));
        keys.press(KeyEvent.VK_F5);
        String place = file.toAbsolutePath() + ":2:";
        waitFor("the error in the console", 10, () -> studio.console().text().getText().contains(place));
        String consoleText = onEdt(() -> studio.console().text().getText());
        int at = consoleText.indexOf(place);
        assertThat(onEdt(() -> studio.console().attributesAt(at)))
                .satisfies(a -> assertThat(javax.swing.text.StyleConstants.getForeground(a)).isEqualTo(new Color(0xE53935)));
        Point p = onEdt(() -> {
            try {
                Rectangle r = studio.console().text().modelToView2D(at + 3).getBounds();
                return new Point(r.x, r.y + r.height / 2);
            } catch (javax.swing.text.BadLocationException e) {
                throw new IllegalStateException(e);
            }
        });
        robot.click(studio.console().text(), p, MouseButton.LEFT_BUTTON, 1);
        waitFor("the caret on line 2", 5, () -> lineOfCaret() == 2 && area().isFocusOwner());
    }

    @Test
    void aFileChangedByAnotherProgramIsOfferedForReload() throws Exception {
        Path file = scene("two-spheres.crt");
        open(file);
        String changed = Files.readString(file) + "-- changed elsewhere\n";
        // Written whole and moved in place, as careful programs write: a write in place could be
        // seen half done (the studio then reloads that half and asks again about the rest).
        Path written = file.resolveSibling("two-spheres.crt.new");
        Files.writeString(written, changed);
        Files.setLastModifiedTime(written, java.nio.file.attribute.FileTime.fromMillis(System.currentTimeMillis() + 5000));
        Files.move(written, file, java.nio.file.StandardCopyOption.REPLACE_EXISTING, java.nio.file.StandardCopyOption.ATOMIC_MOVE);
        org.assertj.swing.fixture.JOptionPaneFixture question = org.assertj.swing.finder.JOptionPaneFinder.findOptionPane()
                .withTimeout(10_000).using(robot);
        question.requireMessage(java.util.regex.Pattern.compile("(?s).*two-spheres\\.crt was changed by another program.*"));
        // Yes to whichever reload question is up, again while one is: a click the loaded machine
        // lost is not the test's point.
        long end = System.nanoTime() + 20_000_000_000L;
        javax.swing.JOptionPane clicked = null;
        while (!onEdt(() -> area().getText().equals(changed)) && System.nanoTime() < end) {
            javax.swing.JOptionPane up = onEdt(StudioGuiTest::reloadQuestion);
            if (up != null && up == clicked) {
                // Still up after a real click: with no window manager the frame can cover the dialog
                // and take the click; press Yes as a program would (the reload is what is tested).
                onEdt(() -> yesButton(up).doClick());
            } else if (up != null) {
                try {
                    new org.assertj.swing.fixture.JOptionPaneFixture(robot, up).yesButton().click();
                } catch (RuntimeException closed) {
                    if (onEdt(up::isShowing)) throw closed;
                }
                clicked = up;
            }
            Thread.sleep(500);
        }
        waitFor("the new text in the editor (it holds " + onEdt(() -> area().getText().length()) + " characters, "
                + changed.length() + " expected; a reload question is " + (onEdt(StudioGuiTest::reloadQuestion) != null ? "" : "not ")
                + "showing)", 1, () -> area().getText().equals(changed));
        assertThat(onEdt(() -> document().isModified())).isFalse();
    }

    /** The Yes button of an option pane. */
    private static javax.swing.JButton yesButton(java.awt.Container c) {
        for (java.awt.Component k : c.getComponents()) {
            if (k instanceof javax.swing.JButton b && UIManager.getString("OptionPane.yesButtonText").equals(b.getText())) return b;
            if (k instanceof java.awt.Container inner) {
                javax.swing.JButton b = yesButton(inner);
                if (b != null) return b;
            }
        }
        return null;
    }

    /** The studio's reload question, when one is showing. */
    private static javax.swing.JOptionPane reloadQuestion() {
        for (java.awt.Window w : java.awt.Window.getWindows()) {
            if (!w.isShowing() || !(w instanceof javax.swing.JDialog dialog)) continue;
            for (java.awt.Component c : dialog.getContentPane().getComponents()) {
                if (c instanceof javax.swing.JOptionPane pane && String.valueOf(pane.getMessage()).contains("was changed by another program")) {
                    return pane;
                }
            }
        }
        return null;
    }

    @Test
    void quitSavesThemeAndLayoutAndTheyComeBack() throws IOException {
        open(scene("two-spheres.crt"));
        keys.press(KeyEvent.VK_D, KeyEvent.VK_CONTROL, KeyEvent.VK_SHIFT);
        waitFor("the dark theme", 5, () -> studio.isDark());
        assertThat(onEdt(() -> javax.swing.UIManager.getLookAndFeel().getName())).containsIgnoringCase("dark");
        onEdt(() -> studio.frame().setSize(1100, 700));
        int[] exit = {-1};
        onEdt(() -> studio.onExit(c -> exit[0] = c));
        ctrl(KeyEvent.VK_Q);
        waitFor("the studio to close", 5, () -> exit[0] == 0);
        studio = null;
        StudioPaths paths = GuiTestSupport.paths(temp.resolve("home"));
        assertThat(paths.settingsFile()).exists();
        assertThat(paths.layoutFile()).exists();
        studio = GuiTestSupport.openStudio(temp.resolve("home"), List.of());
        watchdog.reset();
        assertThat(onEdt(() -> studio.isDark())).isTrue();
        assertThat(onEdt(() -> studio.frame().getSize())).isEqualTo(new java.awt.Dimension(1100, 700));
        onEdt(() -> studio.action("light").actionPerformed(null));
    }
}
