package dev.crt.studio;

import static dev.crt.studio.GuiTestSupport.onEdt;
import static dev.crt.studio.GuiTestSupport.waitFor;
import static org.assertj.core.api.Assertions.assertThat;

import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.assertj.swing.core.Robot;
import org.assertj.swing.fixture.FrameFixture;
import org.fife.ui.rsyntaxtextarea.RSyntaxTextArea;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The render view's selection outline shows only over a render of the script's text as it is. */
@Tag("gui")
class RenderOutlineGuiTest {
    /** The opaque edge colours of the two outlines (the navigator's and the shared selection's). */
    private static final int[] EDGES = {0xFF8C00, 0xFF9800};

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
        waitFor("the navigator to show the scene", 20, () -> studio.objects().navigator().outline() != null && studio.frame().isShowing());
    }

    @AfterEach
    void close() {
        GuiTestSupport.close(studio, robot);
    }

    private RSyntaxTextArea area() { return studio.currentEditor().area(); }

    private String text() { return onEdt(() -> area().getText()); }

    /** How many pixels of the render view, painted as it is now, have an outline's edge colour. */
    private int outlinePixels() {
        return onEdt(() -> {
            RenderView view = studio.renderView();
            BufferedImage shot = new BufferedImage(view.getWidth(), view.getHeight(), BufferedImage.TYPE_INT_RGB);
            java.awt.Graphics2D g = shot.createGraphics();
            view.paint(g);
            g.dispose();
            int n = 0;
            for (int y = 0; y < shot.getHeight(); y++) {
                for (int x = 0; x < shot.getWidth(); x++) {
                    int rgb = shot.getRGB(x, y) & 0xFFFFFF;
                    if (rgb == EDGES[0] || rgb == EDGES[1]) n++;
                }
            }
            return n;
        });
    }

    private void render() {
        RenderJob.Result previous = onEdt(() -> studio.lastRender());
        onEdt(() -> studio.render());
        waitFor("the render to finish", 30, () -> !studio.isRendering() && studio.lastRender() != null && studio.lastRender() != previous);
    }

    @Test
    void theOutlineHidesAfterAnEditComesBackOnUndoAndIsRedrawnByTheNextRender() throws Exception {
        render();
        window.tree("navigatorTree").clickPath("Entities/Sphere ball");
        waitFor("the ball outlined on the picture", 15, () -> studio.renderView().showsOutline());
        int before = outlinePixels();
        assertThat(before).as("outline pixels painted over the render").isGreaterThan(20);

        // Typing into the ball's radius (0.8 becomes 0.85) makes the picture stale: no outline over it.
        int at = original.indexOf("radius -> 0.8") + "radius -> 0.8".length();
        onEdt(() -> area().requestFocusInWindow());
        waitFor("the editor focused", 5, () -> area().isFocusOwner());
        onEdt(() -> area().setCaretPosition(at));
        keys.type("5");
        waitFor("the edit in the text", 5, () -> text().contains("radius -> 0.85"));
        waitFor("the stale outline hidden", 5, () -> !studio.renderView().showsOutline());
        assertThat(outlinePixels()).isZero();
        assertThat(onEdt(() -> studio.renderView().picture())).as("the old picture itself stays").isNotNull();

        // Undo gives back the rendered text: the outline fits the picture again.
        keys.press(KeyEvent.VK_Z, KeyEvent.VK_CONTROL);
        waitFor("the text as rendered", 5, () -> text().equals(original));
        waitFor("the outline back", 5, () -> studio.renderView().showsOutline());
        assertThat(outlinePixels()).isEqualTo(before);

        // Edit again, then render: the new picture gets the selection's outline, of the bigger ball.
        keys.press(KeyEvent.VK_Y, KeyEvent.VK_CONTROL);
        waitFor("the edit redone", 5, () -> text().contains("radius -> 0.85"));
        waitFor("the stale outline hidden", 5, () -> !studio.renderView().showsOutline());
        waitFor("the edit compiled", 15, () -> studio.model().current().resultIsCurrent());
        render();
        waitFor("the outline drawn on the new render", 15, () -> studio.renderView().showsOutline());
        assertThat(onEdt(() -> studio.renderView().isPictureCurrent())).isTrue();
        BufferedImage overlay = onEdt(() -> studio.renderView().overlay());
        int[] ids = studio.lastRender().renderer().idPass();
        for (int y = 0; y < overlay.getHeight(); y++) {
            for (int x = 0; x < overlay.getWidth(); x++) {
                assertThat((overlay.getRGB(x, y) >>> 24) != 0).as("pixel %d,%d", x, y).isEqualTo(ids[y * overlay.getWidth() + x] == 0);
            }
        }
        assertThat(outlinePixels()).isGreaterThan(20);
    }
}
