package dev.crt.live;

/** No OpenGL 3.3 core context could be made here; the message is one sentence a user can act on. */
public final class GlUnavailableException extends Exception {
    private static final long serialVersionUID = 1L;

    public GlUnavailableException(String message) {
        super(message);
    }

    public GlUnavailableException(String message, Throwable cause) {
        super(message, cause);
    }
}
