package dev.crt.studio;

import static dev.crt.studio.GuiTestSupport.onEdt;
import static dev.crt.studio.GuiTestSupport.waitFor;
import static org.assertj.core.api.Assertions.assertThat;

import bibliothek.gui.dock.common.mode.ExtendedMode;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.event.KeyEvent;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.swing.JButton;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import org.assertj.swing.core.MouseButton;
import org.assertj.swing.core.Robot;
import org.assertj.swing.fixture.FrameFixture;
import org.fife.ui.rsyntaxtextarea.RSyntaxTextArea;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The editor's and the window's everyday actions driven with real keys and clicks: find and
 * replace, toggle comment, go to definition (F3 and Ctrl+click), undo back to the saved text,
 * dropping a file, the recent-files menu, and the studio's keys in a floated panel.
 */
@Tag("gui")
class EditorGuiTest {
    private static EdtWatchdog watchdog;

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

    private void open(Path... files) throws IOException {
        studio = GuiTestSupport.openStudio(temp.resolve("home"), List.of(files));
        window = new FrameFixture(robot, studio.frame());
        awaitSteadyFocus();
    }

    private void awaitSteadyFocus() {
        int[] steady = {0};
        waitFor("the editor to hold the focus for half a second", 10, () -> {
            ScriptEditor e = studio.currentEditor();
            steady[0] = e != null && e.area().isFocusOwner() ? steady[0] + 1 : 0;
            return steady[0] >= 25;
        });
        watchdog.reset();
    }

    private RSyntaxTextArea area() { return onEdt(() -> studio.currentEditor().area()); }

    private String text() { return onEdt(() -> area().getText()); }

    private int caretLine() { return onEdt(() -> area().getCaretLineNumber() + 1); }

    private void caretAt(int offset) { onEdt(() -> area().setCaretPosition(offset)); }

    @Test
    void findAndReplaceWithTheKeysAndTheBar() throws IOException {
        Path file = scene("two-spheres.crt");
        open(file);
        String original = text();
        caretAt(0);
        keys.press(KeyEvent.VK_F, KeyEvent.VK_CONTROL);
        JTextField find = robot.finder().findByName(studio.frame(), "find", JTextField.class);
        waitFor("the find field focused", 5, find::isFocusOwner);
        // "Sphere {" (without the brace "spheres" in the first line's comment would match first).
        keys.type("Sphere {\n");
        int first = original.indexOf("Sphere {");
        waitFor("the first Sphere selected", 5, () -> area().getSelectionStart() == first && "Sphere {".equals(area().getSelectedText()));
        keys.type("\n");
        int second = original.indexOf("Sphere {", first + 1);
        waitFor("the second Sphere selected", 5, () -> area().getSelectionStart() == second);
        keys.press(KeyEvent.VK_ESCAPE);
        waitFor("the bar closed and the editor focused", 5, () -> !find.isShowing() && area().isFocusOwner());

        keys.press(KeyEvent.VK_H, KeyEvent.VK_CONTROL);
        JTextField with = robot.finder().findByName(studio.frame(), "replace", JTextField.class);
        waitFor("the find field focused again", 5, () -> find.isFocusOwner() && with.isShowing());
        onEdt(() -> find.setText(""));
        keys.type("radius -> 1 ");
        robot.click(with);
        waitFor("the replace field focused", 5, with::isFocusOwner);
        keys.type("radius -> 0.5 ");
        robot.click(robot.finder().find(studio.frame(), c -> c instanceof JButton b && "Replace all".equals(b.getText()) && b.isShowing()));
        waitFor("both radii replaced; find '" + onEdt(() -> find.getText()) + "' with '" + onEdt(() -> with.getText()) + "' text " + text(), 5, () -> text().equals(original.replace("radius -> 1 ", "radius -> 0.5 ")));
        // One undo per replacement at most; two take the text back.
        onEdt(() -> studio.focusEditor());
        waitFor("the editor focused", 5, () -> area().isFocusOwner());
        keys.press(KeyEvent.VK_Z, KeyEvent.VK_CONTROL);
        keys.press(KeyEvent.VK_Z, KeyEvent.VK_CONTROL);
        waitFor("the original text after undo", 5, () -> text().equals(original));
    }

    @Test
    void ctrlSlashTogglesTheCommentOfTheSelectedLines() throws IOException {
        open(scene("two-spheres.crt"));
        String original = text();
        int line11 = original.indexOf("  Sphere { center -> vec3(-1.5");
        int line12 = original.indexOf("  Sphere { center -> vec3(1.5");
        onEdt(() -> area().select(line11 + 4, line12 + 4));
        keys.press(KeyEvent.VK_SLASH, KeyEvent.VK_CONTROL);
        waitFor("lines 11 and 12 commented; text: " + text(), 5, () -> text().lines().skip(10).limit(2).allMatch(l -> l.startsWith("--")));
        assertThat(text().lines().skip(9).findFirst().orElseThrow()).isEqualTo("Scene {");
        // Both spheres are gone from the compiled scene, so the comment is the language's.
        waitFor("the commented script compiled", 10, () -> studio.model().current().resultIsCurrent());
        assertThat(onEdt(() -> studio.model().current().result().scene().entities())).isEmpty();
        keys.press(KeyEvent.VK_SLASH, KeyEvent.VK_CONTROL);
        waitFor("the comment taken off", 5, () -> text().equals(original));
    }

    @Test
    void f3AndCtrlClickGoToTheDefinition() throws Exception {
        open(scene("two-spheres.crt"));
        String original = text();
        // F3 on "red" in "material -> red" (line 11) goes to "red = Material" (line 8).
        caretAt(original.indexOf("material -> red") + "material -> r".length());
        keys.press(KeyEvent.VK_F3);
        waitFor("the caret on line 8", 5, () -> caretLine() == 8);
        assertThat(onEdt(() -> area().getCaretPosition())).isEqualTo(original.indexOf("red = Material"));

        // Ctrl+click on "blue" in line 12 goes to line 9.
        int use = original.indexOf("material -> blue") + "material -> bl".length();
        // The word is scrolled into view first (a narrow Script panel may hide it), and the gesture
        // is made again when the loaded machine lost part of it (the link shows on a move with Ctrl held).
        for (int attempt = 0; attempt < 3 && onEdt(() -> caretLine()) != 9; attempt++) {
            Point at = onEdt(() -> {
                try {
                    Rectangle r = area().modelToView2D(use).getBounds();
                    area().scrollRectToVisible(new Rectangle(r.x - 40, r.y - 20, 80, r.height + 40));
                    r = area().modelToView2D(use).getBounds();
                    return new Point(r.x, r.y + r.height / 2);
                } catch (javax.swing.text.BadLocationException e) {
                    throw new IllegalStateException(e);
                }
            });
            robot.pressKey(KeyEvent.VK_CONTROL);
            try {
                robot.moveMouse(area(), new Point(at.x + 3, at.y));
                robot.moveMouse(area(), at);
                robot.click(area(), at, MouseButton.LEFT_BUTTON, 1);
            } finally {
                robot.releaseKey(KeyEvent.VK_CONTROL);
            }
            long until = System.nanoTime() + 3_000_000_000L;
            while (System.nanoTime() < until && onEdt(() -> caretLine()) != 9) Thread.sleep(20);
        }
        waitFor("the caret on line 9", 5, () -> caretLine() == 9);
        assertThat(onEdt(() -> area().getCaretPosition())).isEqualTo(original.indexOf("blue = Material"));
    }

    @Test
    void undoingBackToTheSavedTextClearsTheModifiedMark() throws IOException {
        open(scene("two-spheres.crt"));
        caretAt(onEdt(() -> area().getDocument().getLength()));
        keys.type("x");
        waitFor("the mark", 5, () -> studio.frame().getTitle().startsWith("*two-spheres.crt"));
        assertThat(onEdt(() -> studio.model().current().isModified())).isTrue();
        keys.press(KeyEvent.VK_Z, KeyEvent.VK_CONTROL);
        waitFor("the mark gone", 5, () -> studio.frame().getTitle().startsWith("two-spheres.crt")
                && !studio.model().current().isModified());
        // Redo makes it modified again; saving then undoing makes it modified (the file has the x).
        keys.press(KeyEvent.VK_Y, KeyEvent.VK_CONTROL);
        waitFor("the mark back", 5, () -> studio.frame().getTitle().startsWith("*two-spheres.crt"));
        keys.press(KeyEvent.VK_S, KeyEvent.VK_CONTROL);
        waitFor("saved", 5, () -> !studio.model().current().isModified());
        keys.press(KeyEvent.VK_Z, KeyEvent.VK_CONTROL);
        waitFor("modified against the saved text", 5, () -> studio.model().current().isModified());
    }

    @Test
    void droppingACrtFileOnTheWindowOpensIt() throws Exception {
        Path first = scene("two-spheres.crt");
        Path dropped = temp.resolve("dropped.crt");
        Files.writeString(dropped, "-- dropped onto the studio\nScene { Sphere { } }\n");
        open(first);
        // A real drag and drop: from a list of files in a window of its own onto the studio's editor.
        javax.swing.JFrame source = onEdt(() -> {
            javax.swing.JFrame f = new javax.swing.JFrame("files");
            javax.swing.JList<java.io.File> list = new javax.swing.JList<>(new java.io.File[] {dropped.toFile()});
            list.setName("files");
            list.setDragEnabled(true);
            list.setTransferHandler(new javax.swing.TransferHandler() {
                @Override public int getSourceActions(javax.swing.JComponent c) { return COPY; }

                @Override protected java.awt.datatransfer.Transferable createTransferable(javax.swing.JComponent c) {
                    return new FileList(List.of(dropped.toFile()));
                }
            });
            f.add(list);
            f.setBounds(studio.frame().getX() + 40, studio.frame().getY() + studio.frame().getHeight() - 120, 200, 80);
            f.setVisible(true);
            return f;
        });
        try {
            javax.swing.JList<?> list = robot.finder().findByName(source, "files", javax.swing.JList.class);
            waitFor("the file list shown", 5, list::isShowing);
            Point from = onEdt(() -> list.indexToLocation(0));
            from.translate(10, 5);
            org.assertj.swing.core.ComponentDragAndDrop dnd = new org.assertj.swing.core.ComponentDragAndDrop(robot);
            dnd.drag(list, from);
            RSyntaxTextArea target = area();
            dnd.drop(target, new Point(200, 100));
            waitFor("the dropped script open and current", 10, () -> studio.model().find(dropped).isPresent()
                    && studio.model().current() == studio.model().find(dropped).get());
            assertThat(text()).isEqualTo(Files.readString(dropped));
            assertThat(onEdt(() -> studio.model().documents().size())).isEqualTo(2);
        } finally {
            onEdt(source::dispose);
        }
    }

    /** The file-list flavour a file manager offers. */
    private record FileList(List<java.io.File> files) implements java.awt.datatransfer.Transferable {
        @Override public java.awt.datatransfer.DataFlavor[] getTransferDataFlavors() {
            return new java.awt.datatransfer.DataFlavor[] {java.awt.datatransfer.DataFlavor.javaFileListFlavor};
        }

        @Override public boolean isDataFlavorSupported(java.awt.datatransfer.DataFlavor f) {
            return java.awt.datatransfer.DataFlavor.javaFileListFlavor.equals(f);
        }

        @Override public Object getTransferData(java.awt.datatransfer.DataFlavor f) { return files; }
    }

    @Test
    void theRecentFilesMenuReopensAScriptAlsoAfterARestart() throws IOException {
        Path a = scene("two-spheres.crt");
        Path b = temp.resolve("other.crt");
        Files.writeString(b, "Scene { Box { } }\n");
        open(a, b);
        keys.press(KeyEvent.VK_W, KeyEvent.VK_CONTROL);
        waitFor("other.crt closed", 5, () -> studio.model().find(b).isEmpty());
        // The last opened is first: "1  other.crt — folder".
        clickRecent("1  other.crt");
        waitFor("other.crt open again", 5, () -> studio.model().find(b).isPresent() && text().equals("Scene { Box { } }\n"));

        // The list survives a restart, in the same order.
        onEdt(() -> studio.quit());
        studio = GuiTestSupport.openStudio(temp.resolve("home"), List.of());
        window = new FrameFixture(robot, studio.frame());
        awaitSteadyFocus();
        clickRecent("2  two-spheres.crt");
        waitFor("two-spheres.crt open", 5, () -> studio.model().find(a).isPresent());
    }

    /**
     * Opens File → Open recent with the robot's clicks and clicks its entry that starts with
     * {@code prefix}. A click that does not open its menu (CI saw one on File after the restart
     * below, where AssertJ's menu path then failed on a submenu that was not showing, and one on
     * Open recent, whose list then never showed) is made again, three times at most for each; a
     * menu is clicked only while its own popup is closed, so a retry never closes it, and File
     * again only if its menu closed meanwhile.
     */
    private void clickRecent(String prefix) {
        javax.swing.JMenu file = onEdt(() -> {
            javax.swing.JMenuBar bar = studio.frame().getJMenuBar();
            for (int i = 0; i < bar.getMenuCount(); i++) if ("File".equals(bar.getMenu(i).getText())) return bar.getMenu(i);
            throw new AssertionError("no File menu");
        });
        javax.swing.JMenu recent = onEdt(() -> {
            for (java.awt.Component c : file.getMenuComponents()) {
                if (c instanceof javax.swing.JMenu m && "Open recent".equals(m.getText())) return m;
            }
            throw new AssertionError("no Open recent menu");
        });
        for (int tries = 1; !onEdt(() -> recent.getPopupMenu().isShowing()); tries++) {
            assertThat(tries).as("clicks on Open recent before its list showed").isLessThanOrEqualTo(3);
            for (int attempt = 1; !onEdt(() -> recent.isShowing()); attempt++) {
                assertThat(attempt).as("clicks on File before its menu showed").isLessThanOrEqualTo(3);
                if (!onEdt(() -> file.getPopupMenu().isShowing())) robot.click(file);
                awaitUpTo(3, () -> recent.isShowing());
            }
            if (!onEdt(() -> recent.getPopupMenu().isShowing())) robot.click(recent);
            awaitUpTo(3, () -> recent.getPopupMenu().isShowing());
        }
        robot.click(robot.finder().find(c -> c instanceof javax.swing.JMenuItem m && m.isShowing()
                && m.getText().startsWith(prefix)));
    }

    /** Waits at most {@code seconds} for {@code condition} (read on the EDT); a retry follows when it stays false. */
    private static void awaitUpTo(double seconds, java.util.function.BooleanSupplier condition) {
        long end = System.nanoTime() + (long) (seconds * 1e9);
        while (!onEdt(() -> condition.getAsBoolean()) && System.nanoTime() < end) pause(20);
    }

    private static void pause(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AssertionError(e);
        }
    }

    /** Clicks into the floated {@code c}; with no window manager, its window must be raised above the studio's first. */
    private void clickIn(java.awt.Component c) {
        onEdt(() -> SwingUtilities.getWindowAncestor(c).toFront());
        robot.click(c);
        waitFor("the floated console focused", 5, c::isFocusOwner);
    }

    @Test
    void theStudiosKeysWorkInAFloatedPanel() throws IOException {
        Path file = scene("two-spheres.crt");
        open(file);
        onEdt(() -> studio.dock().dockable("console").setExtendedMode(ExtendedMode.EXTERNALIZED));
        javax.swing.JTextPane console = onEdt(() -> studio.console().text());
        waitFor("the console in a window of its own", 10, () -> console.isShowing()
                && SwingUtilities.getWindowAncestor(console) != studio.frame());
        clickIn(console);
        int before = onEdt(() -> studio.model().documents().size());
        keys.press(KeyEvent.VK_N, KeyEvent.VK_CONTROL);
        waitFor("Ctrl+N made a new script", 5, () -> studio.model().documents().size() == before + 1);
        clickIn(console);
        keys.press(KeyEvent.VK_1, KeyEvent.VK_ALT);
        waitFor("Alt+1 put the focus in the editor", 5, () -> area().isFocusOwner());
        onEdt(() -> studio.model().setCurrent(studio.model().find(file).orElseThrow()));
        clickIn(console);
        keys.press(KeyEvent.VK_F5);
        waitFor("F5 rendered", 30, () -> studio.lastRender() != null);
    }
}
