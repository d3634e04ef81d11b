package dev.crt.render;

/** Watches a render: receives progress and can ask it to stop. Called from render threads. */
public interface RenderMonitor {
    RenderMonitor NONE = new RenderMonitor() {};

    /** {@code done} of {@code total} pixels are finished. */
    default void progress(long done, long total) {}

    /** Polled often; a render that sees true stops within a fraction of a second. */
    default boolean isCancelled() { return false; }
}
