package dev.crt.live;

/** The scene holds something the live view cannot draw; the message names it in the user's words. */
public final class UnsupportedSceneException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public UnsupportedSceneException(String message) {
        super(message);
    }
}
