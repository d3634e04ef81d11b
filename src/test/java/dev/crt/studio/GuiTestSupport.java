package dev.crt.studio;

import static org.assertj.core.api.Assertions.fail;

import java.awt.GraphicsEnvironment;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;
import org.assertj.swing.edt.GuiActionRunner;
import org.junit.jupiter.api.Assumptions;

/** What the studio's GUI tests share: the display check, a studio on temporary folders, waiting. */
final class GuiTestSupport {
    private GuiTestSupport() {}

    /** Fails under CI without a display (GUI tests must run there); elsewhere skips with the reason. */
    static void requireDisplay() {
        if (!GraphicsEnvironment.isHeadless()) return;
        String why = "the GUI tests need a display: run them under Xvfb (DISPLAY=:N), as .ci/run does";
        if (System.getenv("CI") != null && !System.getenv("CI").isEmpty()) fail(why);
        Assumptions.abort(why);
    }

    /** A studio whose settings and recovery folders are fresh temporary ones. */
    static StudioWindow openStudio(Path home, java.util.List<Path> files) throws IOException {
        StudioPaths paths = paths(home);
        return GuiActionRunner.execute(() -> {
            StudioWindow w = new StudioWindow(paths);
            w.show(files);
            return w;
        });
    }

    /**
     * The robot of every GUI test: over the current AWT hierarchy, paced for a loaded machine, each
     * of its events waited for until it has come back from the X server ({@link XSyncedRobot}).
     */
    static org.assertj.swing.core.Robot robot() {
        org.assertj.swing.core.Robot robot = org.assertj.swing.core.BasicRobot.robotWithCurrentAwtHierarchy();
        XSyncedRobot.install(robot);
        robot.settings().delayBetweenEvents(15);
        robot.settings().eventPostingDelay(20);
        return robot;
    }

    /**
     * Ends a test: its studio (if it opened one) quits without asking about unsaved text, which is
     * marked saved first, and its robot (if any) lets go of the keys, buttons and windows.
     */
    static void close(StudioWindow studio, org.assertj.swing.core.Robot robot) {
        if (studio != null) {
            onEdt(() -> {
                for (ScriptDocument d : studio.model().documents()) if (d.isModified()) d.saved(d.file(), d.diskTime());
                studio.quit();
            });
        }
        if (robot != null) robot.cleanUp();
    }

    static StudioPaths paths(Path home) throws IOException {
        Files.createDirectories(home);
        return new StudioPaths(home.resolve("config").resolve("crt"), home.resolve("state").resolve("crt").resolve("recovery"));
    }

    static <T> T onEdt(Supplier<T> s) {
        return GuiActionRunner.execute(s::get);
    }

    static void onEdt(Runnable r) {
        GuiActionRunner.execute(r::run);
    }

    /** Waits until {@code condition} (checked on the EDT) holds, or fails after {@code seconds}. */
    static void waitFor(String what, double seconds, BooleanSupplier condition) {
        long end = System.nanoTime() + (long) (seconds * 1e9);
        while (true) {
            boolean ok = GuiActionRunner.execute(condition::getAsBoolean);
            if (ok) return;
            if (System.nanoTime() > end) fail("waited " + seconds + " s for " + what);
            try {
                TimeUnit.MILLISECONDS.sleep(20);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                fail("interrupted while waiting for " + what);
            }
        }
    }

    /**
     * For the studios the GUI tests start in a process of their own: opens {@code script} in a studio
     * on {@code home}'s folders and returns once the window has settled (the editor holding the focus
     * for half a second, or ten seconds at most).
     */
    static StudioWindow openSettled(Path home, Path script) throws Exception {
        StudioPaths paths = paths(home);
        StudioWindow[] studio = new StudioWindow[1];
        javax.swing.SwingUtilities.invokeAndWait(() -> {
            studio[0] = new StudioWindow(paths);
            studio[0].show(java.util.List.of(script));
        });
        int steady = 0;
        for (int i = 0; i < 500 && steady < 25; i++) {
            Thread.sleep(20);
            boolean focused = java.awt.KeyboardFocusManager.getCurrentKeyboardFocusManager().getFocusOwner()
                    == studio[0].currentEditor().area();
            steady = focused ? steady + 1 : 0;
        }
        return studio[0];
    }
}
