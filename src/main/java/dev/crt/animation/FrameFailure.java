package dev.crt.animation;

/** A frame that cannot be made, said in one plain sentence, and whose fault it is. */
public final class FrameFailure extends Exception {
    /** Whose fault: the script, the settings asked of the render, the file system, or a full Java heap. */
    public enum Kind { SCRIPT, SETTINGS, FILE, MEMORY }

    private final Kind kind;

    public FrameFailure(Kind kind, String message) {
        super(message, null, false, false);
        this.kind = kind;
    }

    public Kind kind() { return kind; }
}
