package dev.crt.studio;

import java.nio.file.Files;
import java.nio.file.Path;
import javax.swing.SwingUtilities;

/**
 * A studio in a process of its own whose OpenGL cannot start (the test points LWJGL at an EGL
 * library that does not exist): brings the live view to the front, waits for it to give up, and
 * prints what a user would see, then quits. Arguments: the home folder, the script.
 */
public final class LiveDockWithoutGl {
    private LiveDockWithoutGl() {}

    public static void main(String[] args) throws Exception {
        StudioWindow[] studio = {GuiTestSupport.openSettled(Path.of(args[0]), Path.of(args[1]))};
        SwingUtilities.invokeAndWait(() -> studio[0].action("showLive").actionPerformed(null));
        long end = System.nanoTime() + 30_000_000_000L;
        LiveDock.State[] state = new LiveDock.State[1];
        do {
            Thread.sleep(20);
            SwingUtilities.invokeAndWait(() -> state[0] = studio[0].live().state());
        } while ((state[0] == LiveDock.State.STARTING || state[0] == LiveDock.State.NOT_STARTED) && System.nanoTime() < end);
        String text = Files.readString(Path.of(args[1]));
        SwingUtilities.invokeAndWait(() -> {
            System.out.println("state: " + state[0]);
            System.out.println("panel showing: " + studio[0].live().isShowing());
            System.out.println("message: " + studio[0].live().message());
            System.out.println("window showing: " + studio[0].frame().isShowing());
            System.out.println("editor text intact: " + studio[0].currentEditor().area().getText().equals(text));
            studio[0].onExit(code -> System.exit(code));
            studio[0].quit();
        });
    }
}
