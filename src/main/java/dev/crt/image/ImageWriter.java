package dev.crt.image;

import java.io.IOException;
import java.io.OutputStream;
import java.util.Map;

/** Encodes a frame buffer in one file format. */
interface ImageWriter {
    void write(FrameBuffer image, double gamma, Map<String, String> text, OutputStream out) throws IOException;

    /** Whether the file stores each channel clamped to [0, 1] (8-bit formats), not the linear colour itself. */
    default boolean clamps() {
        return true;
    }
}
