package dev.crt.image;

import dev.crt.scene.Picture;
import java.io.IOException;
import java.nio.file.Path;

/** Reading pictures that scenes use (panoramas, later textures). */
public final class PictureFiles {
    private PictureFiles() {}

    /**
     * Decodes an image file (PNG, JPEG, GIF, BMP, PPM…) into a Picture of stored values in [0, 1].
     * @throws IOException with a plain sentence when the file cannot be read or decoded
     */
    public static Picture read(Path file) throws IOException {
        throw new UnsupportedOperationException("lands with issue 2");
    }
}
