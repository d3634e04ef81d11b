package dev.crt.studio;

import java.nio.file.Path;
import javax.swing.SwingUtilities;

/**
 * A studio in a process of its own for the crash test: opens the script given, types the text
 * given with real key presses, says TYPED on stdout, then waits to be killed.
 * Arguments: the home folder for settings and recovery, the script, the text to type.
 */
public final class RecoveryVictim {
    private RecoveryVictim() {}

    public static void main(String[] args) throws Exception {
        StudioWindow[] studio = {GuiTestSupport.openSettled(Path.of(args[0]), Path.of(args[1]))};
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
