package dev.crt.studio;

import java.awt.AWTException;
import java.awt.Toolkit;
import java.lang.reflect.Field;
import java.lang.reflect.Method;

/**
 * A java.awt.Robot that returns from each mouse or key event only once the X server has made it
 * and the toolkit has read it back and posted it as a Java event.
 *
 * <p>AssertJ-Swing's robot waits for Java's event queue to run empty, but the events it makes travel
 * through the X server first. On a loaded machine one could still be on its way when the queue
 * looked empty; the test then went on and the click came late or, once a dialog had closed, not at
 * all ("lost" clicks in CI). The toolkit's own round trip (a window moved, its ConfigureNotify
 * awaited) puts every event made before it into Java's queue, where AssertJ's wait then finds it.
 * java.awt.Robot's auto wait for idle does the same round trip, but it also waits for the Event
 * Dispatch Thread to stay idle, which a studio with timers and a watchdog never quite is: seconds
 * per event.
 */
final class XSyncedRobot extends java.awt.Robot {
    private static final long TIMEOUT_MS = 5000;
    private final Method syncNativeQueue;

    private XSyncedRobot() throws AWTException, ReflectiveOperationException {
        syncNativeQueue = Class.forName("sun.awt.SunToolkit").getDeclaredMethod("syncNativeQueue", long.class);
        syncNativeQueue.setAccessible(true);
    }

    /** Makes {@code robot} send its events through a robot of this kind. */
    static void install(org.assertj.swing.core.Robot robot) {
        try {
            XSyncedRobot awt = new XSyncedRobot();
            Field generatorField = org.assertj.swing.core.BasicRobot.class.getDeclaredField("eventGenerator");
            generatorField.setAccessible(true);
            Object generator = generatorField.get(robot);
            Field robotField = generator.getClass().getDeclaredField("robot");
            robotField.setAccessible(true);
            robotField.set(generator, awt);
            Method attach = org.assertj.swing.core.Settings.class.getDeclaredMethod("attachTo", java.awt.Robot.class);
            attach.setAccessible(true);
            attach.invoke(robot.settings(), awt);
        } catch (AWTException | ReflectiveOperationException e) {
            throw new IllegalStateException("cannot make the GUI tests' robot wait for the X server", e);
        }
    }

    /** One round trip to the X server: every event made before it is in Java's event queue after it. */
    private void sync() {
        try {
            syncNativeQueue.invoke(Toolkit.getDefaultToolkit(), TIMEOUT_MS);
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("the toolkit's round trip to the X server failed", e);
        }
    }

    @Override
    public synchronized void mouseMove(int x, int y) {
        super.mouseMove(x, y);
        sync();
    }

    @Override
    public synchronized void mousePress(int buttons) {
        super.mousePress(buttons);
        sync();
    }

    @Override
    public synchronized void mouseRelease(int buttons) {
        super.mouseRelease(buttons);
        sync();
    }

    @Override
    public synchronized void mouseWheel(int wheelAmt) {
        super.mouseWheel(wheelAmt);
        sync();
    }

    @Override
    public synchronized void keyPress(int keycode) {
        super.keyPress(keycode);
        sync();
    }

    @Override
    public synchronized void keyRelease(int keycode) {
        super.keyRelease(keycode);
        sync();
    }
}
