package dev.crt.render;

/** Thrown by a render that its monitor cancelled; no image results. */
public final class RenderCancelledException extends RuntimeException {
    public RenderCancelledException() {
        super("render cancelled");
    }
}
