package dev.crt.studio;

import static dev.crt.studio.GuiTestSupport.onEdt;
import static dev.crt.studio.GuiTestSupport.waitFor;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.studio.SceneOutline.Node;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.beans.FeatureDescriptor;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.swing.JTable;
import javax.swing.text.Element;
import org.assertj.swing.core.GenericTypeMatcher;
import org.assertj.swing.core.MouseButton;
import org.assertj.swing.core.Robot;
import org.assertj.swing.fixture.FrameFixture;
import org.fife.ui.rsyntaxtextarea.RSyntaxTextArea;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The Navigator and Properties panels and the Insert menu, driven with real clicks and key presses. */
@Tag("gui")
class NavigatorGuiTest {
    @TempDir
    Path temp;

    private Robot robot;
    private final Keyboard keys = new Keyboard();
    private StudioWindow studio;
    private FrameFixture window;
    private String original;

    @BeforeAll
    static void display() { GuiTestSupport.requireDisplay(); }

    @BeforeEach
    void open() throws IOException {
        robot = GuiTestSupport.robot();
        Path file = temp.resolve("objects.crt");
        try (InputStream in = getClass().getResourceAsStream("objects.crt")) {
            Files.write(file, in.readAllBytes());
        }
        original = Files.readString(file);
        studio = GuiTestSupport.openStudio(temp.resolve("home"), List.of(file));
        window = new FrameFixture(robot, studio.frame());
        waitFor("the navigator to show the scene", 20, () -> outline() != null && window().isShowing());
        int[] steady = {0};
        waitFor("the editor to hold the focus for half a second", 10, () -> {
            steady[0] = area().isFocusOwner() ? steady[0] + 1 : 0;
            return steady[0] >= 25;
        });
    }

    @AfterEach
    void close() {
        GuiTestSupport.close(studio, robot);
    }

    private javax.swing.JFrame window() { return studio.frame(); }

    private Node outline() { return studio.objects().navigator().outline(); }

    private RSyntaxTextArea area() { return studio.currentEditor().area(); }

    private String text() { return onEdt(() -> area().getText()); }

    private int caretLine() {
        return onEdt(() -> area().getDocument().getDefaultRootElement().getElementIndex(area().getCaretPosition()) + 1);
    }

    private String selectedKey() {
        return onEdt(() -> {
            Node n = studio.objects().navigator().selected();
            return n == null ? null : n.key();
        });
    }

    private void compiled() {
        waitFor("the script to compile", 15, () -> studio.model().current().resultIsCurrent());
        waitFor("the compile to reach the navigator", 5, () -> outline() != null);
    }

    private void clickNode(String path) {
        window.tree("navigatorTree").clickPath(path);
    }

    /** The row of the property sheet whose name is {@code name}, scrolled into view; -1 when it is not there. */
    private int row(JTable table, String name) {
        return onEdt(() -> {
            for (int r = 0; r < table.getRowCount(); r++) {
                if (table.getValueAt(r, 0) instanceof FeatureDescriptor f && f.getDisplayName().equals(name)) {
                    table.scrollRectToVisible(table.getCellRect(r, 1, true));
                    return r;
                }
            }
            return -1;
        });
    }

    private JTable sheetTable() {
        return window.robot().finder().find(studio.objects().properties(), new GenericTypeMatcher<>(JTable.class, true) {
            @Override protected boolean isMatching(JTable t) { return true; }
        });
    }

    /** Edits a property as a user does in a NetBeans sheet: click its row, F2, select all, type, Enter. */
    private void edit(String property, String value) throws InterruptedException {
        JTable table = sheetTable();
        waitFor("the property " + property + " in the sheet", 10, () -> row(table, property) >= 0);
        // On a loaded machine the sheet can be rebuilt (after the compile of the last edit) between
        // the click and F2, which then go to the old rows: click and press F2 again until it edits.
        long end = System.nanoTime() + 20_000_000_000L;
        while (true) {
            int r = row(table, property);
            // The name, not the value: a narrow value column puts a colour's "…" button at its centre.
            Rectangle cell = onEdt(() -> table.getCellRect(r, 0, true));
            robot.click(table, new Point(cell.x + cell.width / 2, cell.y + cell.height / 2), MouseButton.LEFT_BUTTON, 1);
            waitFor("the sheet to select the row", 5, () -> table.getSelectedRow() == row(table, property));
            if (!onEdt(table::isEditing)) keys.press(KeyEvent.VK_F2);
            if (poll(3, table::isEditing)) break;
            if (System.nanoTime() > end) throw new AssertionError("waited 20 s for the sheet to edit " + property);
        }
        keys.press(KeyEvent.VK_A, KeyEvent.VK_CONTROL);
        keys.type(value);
        keys.press(KeyEvent.VK_ENTER);
    }

    private boolean canWrite(String property) {
        JTable table = sheetTable();
        waitFor("the property " + property + " in the sheet", 10, () -> row(table, property) >= 0);
        return onEdt(() -> ((org.openide.nodes.Node.Property<?>) table.getValueAt(row(table, property), 0)).canWrite());
    }

    private void render() {
        onEdt(() -> studio.render());
        waitFor("the render to finish", 30, () -> !studio.isRendering() && studio.lastRender() != null
                && studio.lastRender().scene().entities().size() == studio.model().current().result().scene().entities().size());
    }

    @Test
    void aSelectedNodePutsTheCaretOnItsCodeAndOutlinesItAndTheCaretSelectsNodes() throws Exception {
        render();
        clickNode("Entities/Sphere ball");
        waitFor("the caret on line 16", 5, () -> caretLine() == 16);
        assertThat(onEdt(() -> studio.objects().properties().shown().label())).isEqualTo("Sphere ball");
        // The render view outlines the ball: its pixels (from the renderer's id pass) in the overlay, nothing else.
        waitFor("the outline of the ball", 15, () -> studio.renderView().overlay() != null);
        BufferedImage overlay = onEdt(() -> studio.renderView().overlay());
        int[] ids = studio.lastRender().renderer().idPass();
        int inside = 0;
        for (int y = 0; y < overlay.getHeight(); y++) {
            for (int x = 0; x < overlay.getWidth(); x++) {
                boolean marked = (overlay.getRGB(x, y) >>> 24) != 0;
                assertThat(marked).as("pixel %d,%d", x, y).isEqualTo(ids[y * overlay.getWidth() + x] == 0);
                if (marked) inside++;
            }
        }
        assertThat(inside).isGreaterThan(100);

        // The caret moves into the Plane (line 22) by keys: the tree follows, and so does the sheet.
        onEdt(() -> area().requestFocusInWindow());
        waitFor("the editor focused", 5, () -> area().isFocusOwner());
        keys.press(KeyEvent.VK_HOME, KeyEvent.VK_CONTROL);
        for (int i = 0; i < 21; i++) keys.press(KeyEvent.VK_DOWN);
        keys.press(KeyEvent.VK_END);
        keys.press(KeyEvent.VK_LEFT);
        waitFor("the tree to select the Plane", 5, () -> "Entities/Plane".equals(selectedKey()));
        // Into the cut's sphere (line 17, after the '-'): the CSG operand, not the operation.
        Element line17 = onEdt(() -> area().getDocument().getDefaultRootElement().getElement(16));
        int sphere = original.indexOf("Sphere { center -> vec3(1.5");
        onEdt(() -> area().setCaretPosition(sphere + 3));
        assertThat(line17.getStartOffset()).isLessThan(sphere);
        waitFor("the tree to select the cut's sphere", 5, () -> "Entities/Difference cut/Sphere".equals(selectedKey()));
        assertThat(onEdt(() -> studio.renderView().overlay())).as("the whole CSG object is outlined").isNotNull();
    }

    @Test
    void sheetEditsWriteLiteralsThatCompileRenderAndUndoExactly() throws Exception {
        clickNode("Entities/Sphere ball");
        waitFor("the ball's properties", 5, () -> studio.objects().properties().shown() != null);
        edit("radius", "1.1");
        waitFor("the new radius in the script", 5, () -> text().contains("radius -> 1.1 material -> red"));
        String afterRadius = text();
        assertThat(afterRadius).isEqualTo(original.replace("radius -> 0.8", "radius -> 1.1"));
        compiled();
        assertThat(onEdt(() -> studio.model().current().result().hasErrors())).isFalse();
        // The round trip (sheet, text, compile, tree) keeps the selection.
        assertThat(selectedKey()).isEqualTo("Entities/Sphere ball");
        assertThat(onEdt(() -> ((dev.crt.scene.Sphere) studio.model().current().result().scene().entities().get(0)).radius()))
                .isEqualTo(1.1);

        // The material is the variable red: its colour is edited where red is written (line 2).
        render();
        BufferedImage before = onEdt(() -> studio.lastRender().picture());
        int centre = before.getRGB(80, 50);
        assertThat((centre >> 16) & 0xFF).as("red before").isGreaterThan(centre & 0xFF);
        edit("color", "0.1, 0.2, 0.9");
        waitFor("the new colour in the script", 5, () -> text().contains("red = Material { color -> rgb(0.1, 0.2, 0.9)"));
        compiled();
        assertThat(selectedKey()).isEqualTo("Entities/Sphere ball");
        render();
        int after = onEdt(() -> studio.lastRender().picture().getRGB(80, 50));
        assertThat(after & 0xFF).as("blue after").isGreaterThan((after >> 16) & 0xFF);

        // Each sheet edit is one undo step, and undoing restores the text exactly.
        onEdt(() -> area().requestFocusInWindow());
        waitFor("the editor focused", 5, () -> area().isFocusOwner());
        keys.press(KeyEvent.VK_Z, KeyEvent.VK_CONTROL);
        waitFor("the colour undone", 5, () -> text().equals(afterRadius));
        keys.press(KeyEvent.VK_Z, KeyEvent.VK_CONTROL);
        waitFor("the radius undone", 5, () -> text().equals(original));
    }

    @Test
    void expressionsAreReadOnlyAndMacroMadeEntitiesEditTheArgumentOrSayWhyNot() throws Exception {
        clickNode("Entities/Difference cut/Sphere");
        waitFor("the cut sphere's properties", 5, () -> studio.objects().properties().shown() != null
                && studio.objects().properties().shown().key().equals("Entities/Difference cut/Sphere"));
        assertThat(canWrite("radius")).as("radius -> r * 1.2 is an expression").isFalse();
        // Trying to edit it anyway changes nothing.
        JTable table = sheetTable();
        int r = row(table, "radius");
        assertThat(onEdt(() -> table.getValueAt(r, 1).toString())).isNotNull();
        Rectangle cell = onEdt(() -> table.getCellRect(r, 1, true));
        robot.click(table, new Point(cell.x + cell.width / 2, cell.y + cell.height / 2), MouseButton.LEFT_BUTTON, 1);
        keys.press(KeyEvent.VK_F2);
        keys.type("9");
        keys.press(KeyEvent.VK_ENTER);
        assertThat(text()).isEqualTo(original);

        // A sphere made by row(3, 0.3): its radius is the argument size, so the edit goes to the call.
        clickNode("Entities/row(3, 0.3)/Sphere");
        waitFor("the macro sphere's properties", 5, () -> studio.objects().properties().shown() != null
                && studio.objects().properties().shown().key().equals("Entities/row(3, 0.3)/Sphere"));
        edit("radius (= size)", "0.2");
        waitFor("the argument rewritten", 5, () -> text().contains("row(3, 0.2)"));
        assertThat(text()).isEqualTo(original.replace("row(3, 0.3)", "row(3, 0.2)"));
        compiled();
        // Its colour is a literal inside the macro, shared by every call: refused, with the reason.
        clickNode("Entities/row(3, 0.2)/Sphere");
        waitFor("the macro sphere's properties", 5, () -> studio.objects().properties().shown() != null
                && studio.objects().properties().shown().key().equals("Entities/row(3, 0.2)/Sphere"));
        String beforeRefusal = text();
        edit("color", "1, 1, 0");
        waitFor("the refusal", 5, () -> studio.objects().properties().message().getText().contains("inside a macro"));
        assertThat(onEdt(() -> studio.objects().properties().message().getAccessibleContext().getAccessibleName()))
                .isEqualTo("Properties message");
        assertThat(text()).isEqualTo(beforeRefusal);

        // The call's own node edits its literal arguments.
        clickNode("Entities/row(3, 0.2)");
        waitFor("the call's properties", 5, () -> studio.objects().properties().shown() != null
                && studio.objects().properties().shown().key().equals("Entities/row(3, 0.2)"));
        edit("n", "2");
        waitFor("the count rewritten", 5, () -> text().contains("row(2, 0.2)"));
        compiled();
        assertThat(onEdt(() -> studio.model().current().result().scene().entities())).hasSize(5);
    }

    @Test
    void theInsertMenuAddsABoxThatCompilesAndShowsInTheTree() throws Exception {
        onEdt(() -> area().setCaretPosition(original.indexOf("  cut\n")));
        window.menuItemWithPath("Insert", "Box").click();
        waitFor("a Box in the script", 5, () -> text().length() > original.length());
        String added = text().substring(original.indexOf("  cut\n"));
        assertThat(added).startsWith("  cut\n  Box { cornerA -> vec3(-0.5, -0.5, -0.5) cornerB -> vec3(0.5, 0.5, 0.5)");
        compiled();
        assertThat(onEdt(() -> studio.model().current().result().hasErrors())).isFalse();
        assertThat(onEdt(() -> studio.model().current().result().scene().entities())).hasSize(7);
        waitFor("the Box in the tree", 5, () -> SceneOutline.find(outline(), "Entities/Box") != null);

        // A light goes into the existing lights list, so that both lights shine.
        window.menuItemWithPath("Insert", "Point light").click();
        waitFor("a second light in the script", 5, () -> text().indexOf("PointLight {", text().indexOf("PointLight {") + 1) >= 0);
        compiled();
        assertThat(text()).contains("lights -> [PointLight { origin -> vec3(3, 5, -4) }, PointLight {");
        assertThat(onEdt(() -> studio.model().current().result().scene().settings().lights())).hasSize(2);
    }

    /** Whether {@code condition} (checked on the EDT) comes to hold within {@code seconds}. */
    private static boolean poll(double seconds, java.util.function.BooleanSupplier condition) throws InterruptedException {
        long end = System.nanoTime() + (long) (seconds * 1e9);
        while (System.nanoTime() < end) {
            if (onEdt(condition::getAsBoolean)) return true;
            Thread.sleep(20);
        }
        return onEdt(condition::getAsBoolean);
    }
}
