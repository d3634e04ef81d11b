package dev.crt.studio;

import static dev.crt.studio.GuiTestSupport.onEdt;
import static dev.crt.studio.GuiTestSupport.waitFor;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.image.GifLoopTest;
import java.awt.event.KeyEvent;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.assertj.swing.core.Robot;
import org.assertj.swing.fixture.FrameFixture;
import org.assertj.swing.fixture.JFileChooserFixture;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The Animation panel's "Loop GIF" check box decides whether the exported GIF loops. */
@Tag("gui")
class GifLoopGuiTest {
    @TempDir
    Path temp;

    private Robot robot;
    private final Keyboard keys = new Keyboard();
    private StudioWindow studio;
    private FrameFixture window;

    @BeforeAll
    static void display() { GuiTestSupport.requireDisplay(); }

    @AfterEach
    void close() {
        GuiTestSupport.close(studio, robot);
    }

    private void export(Path gif) {
        String before = onEdt(() -> window.label("animStatus").target().getText());
        window.button("animExportGif").click();
        JFileChooserFixture chooser = window.fileChooser();
        chooser.fileNameTextBox().setText(gif.toString());
        chooser.approve();
        // A click the machine lost leaves the chooser up (seen in CI, with no window manager):
        // approve again, and after a second lost click approve as a program would, saying so, as
        // the other dialog tests do; the GIF written is what the test checks.
        for (int i = 0; ; i++) {
            try {
                waitFor("the chooser to close", 5, () -> !chooser.target().isShowing());
                break;
            } catch (AssertionError lost) {
                if (i == 2) throw lost;
                if (i == 0) {
                    chooser.approve();
                } else {
                    System.out.println("GifLoopGuiTest: two clicks on the chooser's approve button lost; approved as a program would");
                    javax.swing.SwingUtilities.invokeLater(() -> {
                        chooser.target().setSelectedFile(gif.toFile());
                        chooser.target().approveSelection();
                    });
                }
            }
        }
        waitFor("the GIF to be written", 20, () -> {
            String now = window.label("animStatus").target().getText();
            return now.startsWith("wrote " + gif) && !now.equals(before);
        });
    }

    @Test
    void theExportedGifLoopsOnlyWithTheBoxChecked() throws IOException {
        robot = GuiTestSupport.robot();
        Path file = temp.resolve("moving-sphere.crt");
        try (InputStream in = getClass().getResourceAsStream("moving-sphere.crt")) {
            Files.write(file, in.readAllBytes());
        }
        studio = GuiTestSupport.openStudio(temp.resolve("home"), List.of(file));
        window = new FrameFixture(robot, studio.frame());
        int[] steady = {0};
        waitFor("the editor to hold the focus for half a second", 10, () -> {
            ScriptEditor e = studio.currentEditor();
            steady[0] = e != null && e.area().isFocusOwner() ? steady[0] + 1 : 0;
            return steady[0] >= 25;
        });
        AnimationPanel panel = onEdt(() -> studio.animation());
        for (int attempt = 0; attempt < 3 && !onEdt(panel::isShowing); attempt++) {
            keys.press(KeyEvent.VK_7, KeyEvent.VK_ALT);
            try {
                waitFor("the Animation panel to show", 5, panel::isShowing);
            } catch (AssertionError lost) {
                if (attempt == 2) throw lost;
            }
        }
        // A key the loaded machine lost is typed again.
        for (int attempt = 0; attempt < 3 && !Integer.valueOf(2).equals(onEdt(() -> window.spinner("animLast").target().getValue())); attempt++) {
            window.spinner("animLast").enterTextAndCommit("2");
        }
        waitFor("the range 0..2", 5, () -> window.slider("animSlider").target().getMaximum() == 2);
        window.button("animRender").click();
        waitFor("frames 0..2 rendered", 20, () -> !panel.isRendering() && panel.renderedFrames().size() == 3);

        Files.createDirectories(temp.resolve("out"));
        window.checkBox("animGifLoop").requireSelected();
        window.checkBox("animGifLoop").click();
        window.checkBox("animGifLoop").requireNotSelected();
        Path once = temp.resolve("out").resolve("once.gif");
        export(once);
        assertThat(window.label("animStatus").target().getText()).endsWith("played once)");
        assertThat(GifLoopTest.frameCount(once)).isEqualTo(3);
        assertThat(GifLoopTest.loopExtensions(once)).isEmpty();

        window.checkBox("animGifLoop").click();
        window.checkBox("animGifLoop").requireSelected();
        Path looping = temp.resolve("out").resolve("loop.gif");
        export(looping);
        assertThat(window.label("animStatus").target().getText()).endsWith("looping)");
        assertThat(GifLoopTest.frameCount(looping)).isEqualTo(3);
        assertThat(GifLoopTest.loopExtensions(looping)).containsExactly("0:NETSCAPE 2.0:0");
    }
}
