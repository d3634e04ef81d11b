package dev.crt.studio;

import java.awt.AWTException;
import java.awt.Robot;
import java.awt.event.KeyEvent;

/** Types text with real key presses (US layout), as a person at the keyboard would. */
final class Keyboard {
    private static final String SHIFTED = "~!@#$%^&*()_+{}|:\"<>?";
    private static final String UNSHIFTED = "`1234567890-=[]\\;',./";

    private final Robot robot;

    Keyboard() {
        try {
            robot = new Robot();
        } catch (AWTException e) {
            throw new IllegalStateException(e);
        }
        robot.setAutoDelay(4);
    }

    void type(String text) {
        for (char c : text.toCharArray()) type(c);
        robot.waitForIdle();
    }

    private void type(char c) {
        boolean shift = Character.isUpperCase(c) || SHIFTED.indexOf(c) >= 0;
        char base = SHIFTED.indexOf(c) >= 0 ? UNSHIFTED.charAt(SHIFTED.indexOf(c)) : Character.toLowerCase(c);
        int code = switch (base) {
            case '\n' -> KeyEvent.VK_ENTER;
            case '\t' -> KeyEvent.VK_TAB;
            default -> KeyEvent.getExtendedKeyCodeForChar(base);
        };
        if (code == KeyEvent.VK_UNDEFINED) throw new IllegalArgumentException("cannot type " + c);
        if (shift) robot.keyPress(KeyEvent.VK_SHIFT);
        robot.keyPress(code);
        robot.keyRelease(code);
        if (shift) robot.keyRelease(KeyEvent.VK_SHIFT);
    }

    /** Presses {@code key} with the modifier keys held down, in order. */
    void press(int key, int... modifiers) {
        for (int m : modifiers) robot.keyPress(m);
        robot.keyPress(key);
        robot.keyRelease(key);
        for (int i = modifiers.length - 1; i >= 0; i--) robot.keyRelease(modifiers[i]);
        robot.waitForIdle();
    }
}
