package dev.crt.studio;

import static dev.crt.studio.GuiTestSupport.onEdt;
import static dev.crt.studio.GuiTestSupport.waitFor;
import static org.assertj.core.api.Assertions.assertThat;

import java.awt.Point;
import java.awt.Rectangle;
import java.awt.event.KeyEvent;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.swing.JList;
import org.assertj.swing.core.ComponentDragAndDrop;
import org.assertj.swing.core.Robot;
import org.fife.ui.rsyntaxtextarea.RSyntaxTextArea;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The palette: a shape dragged onto the editor is inserted where it is dropped; one undo takes it back. */
@Tag("gui")
class PaletteGuiTest {
    @TempDir
    Path temp;

    private Robot robot;
    private final Keyboard keys = new Keyboard();
    private StudioWindow studio;
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
        waitFor("the navigator to show the scene", 20, () -> studio.objects().navigator().outline() != null && studio.frame().isShowing());
    }

    @AfterEach
    void close() {
        GuiTestSupport.close(studio, robot);
    }

    private RSyntaxTextArea area() { return studio.currentEditor().area(); }

    private String text() { return onEdt(() -> area().getText()); }

    @Test
    void aBoxDraggedOntoTheSceneBlockIsInsertedAfterTheLineItIsDroppedOn() throws Exception {
        JList<String> items = onEdt(() -> studio.objects().palette().items());
        // The palette is a tab behind Properties; brought to the front once the window has settled.
        for (int attempt = 0; attempt < 5 && !onEdt(items::isShowing); attempt++) {
            onEdt(() -> studio.dock().dockable("palette").toFront());
            try {
                waitFor("the palette to show", 3, items::isShowing);
            } catch (AssertionError notYet) {
                if (attempt == 4) throw notYet;
            }
        }
        assertThat(onEdt(() -> items.getModel().getSize())).isEqualTo(8);
        waitFor("the script compiled", 15, () -> studio.model().current().resultIsCurrent());

        // Dropped on the line of row(3, 0.3), inside the Scene block: the Box goes on a new line after it.
        int target = original.indexOf("row(3, 0.3)") + 4;
        String expectedStart = "  row(3, 0.3)\n  Box { cornerA -> ";
        ComponentDragAndDrop dnd = new ComponentDragAndDrop(robot);
        for (int attempt = 0; attempt < 3 && !text().contains(expectedStart); attempt++) {
            Point from = onEdt(() -> items.indexToLocation(1));
            from.translate(10, 4);
            dnd.drag(items, from);
            Rectangle at = onEdt(() -> {
                try {
                    return area().modelToView2D(target).getBounds();
                } catch (javax.swing.text.BadLocationException e) {
                    throw new IllegalStateException(e);
                }
            });
            dnd.drop(area(), new Point(at.x, at.y + at.height / 2));
            try {
                waitFor("the Box in the script", 5, () -> area().getText().contains(expectedStart));
            } catch (AssertionError lost) {
                // A drag the loaded machine's X server lost is made again.
                if (attempt == 2) throw lost;
            }
        }
        String edited = text();
        int line = edited.substring(0, edited.indexOf("  Box { cornerA")).split("\n", -1).length;
        assertThat(line).as("the line after row(3, 0.3), line 21").isEqualTo(22);
        assertThat(edited.replaceFirst("\n  Box \\{[^\n]*", "")).isEqualTo(original);
        waitFor("the edit compiled", 15, () -> studio.model().current().resultIsCurrent());
        assertThat(onEdt(() -> studio.model().current().result().hasErrors())).isFalse();
        assertThat(onEdt(() -> studio.model().current().result().scene().entities().stream()
                .filter(e -> e instanceof dev.crt.scene.Box).count())).isEqualTo(1);

        // One edit: Ctrl+Z in the editor gives back the text exactly.
        onEdt(() -> area().requestFocusInWindow());
        waitFor("the editor focused", 5, () -> area().isFocusOwner());
        keys.press(KeyEvent.VK_Z, KeyEvent.VK_CONTROL);
        waitFor("the drop undone", 5, () -> text().equals(original));
    }
}
