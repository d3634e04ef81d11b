package dev.crt.animation;

/** A frame that cannot be made, said in one plain sentence, and whose fault it is. */
public final class FrameFailure extends Exception {
    /** Whose fault: the script, the heap filled while compiling it, the settings asked of the render, or the file system. */
    public enum Kind { SCRIPT, MEMORY, SETTINGS, FILE }

    private final Kind kind;

    public FrameFailure(Kind kind, String message) {
        super(message, null, false, false);
        this.kind = kind;
    }

    public Kind kind() { return kind; }
}
