package dev.crt.studio;

import java.awt.KeyboardFocusManager;
import java.nio.file.Path;
import java.util.List;
import javax.swing.SwingUtilities;

/**
 * A studio in a process of its own for the crash test: opens the script given, types the text
 * given with real key presses, says TYPED on stdout, then waits to be killed.
 * Arguments: the home folder for settings and recovery, the script, the text to type.
 */
public final class RecoveryVictim {
    private RecoveryVictim() {}

    public static void main(String[] args) throws Exception {
        StudioPaths paths = GuiTestSupport.paths(Path.of(args[0]));
        StudioWindow[] studio = new StudioWindow[1];
        SwingUtilities.invokeAndWait(() -> {
            studio[0] = new StudioWindow(paths);
            studio[0].show(List.of(Path.of(args[1])));
        });
        int steady = 0;
        for (int i = 0; i < 500 && steady < 25; i++) {
            Thread.sleep(20);
            boolean focused = KeyboardFocusManager.getCurrentKeyboardFocusManager().getFocusOwner() == studio[0].currentEditor().area();
            steady = focused ? steady + 1 : 0;
        }
        SwingUtilities.invokeAndWait(() -> {
            var area = studio[0].currentEditor().area();
            area.setCaretPosition(area.getDocument().getLength());
        });
        new Keyboard().type(args[2]);
        System.out.println("TYPED");
        System.out.flush();
        Thread.sleep(Long.MAX_VALUE);
    }
}
