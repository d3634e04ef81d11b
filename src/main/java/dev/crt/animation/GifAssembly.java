package dev.crt.animation;

import dev.crt.image.GifWriter;
import dev.crt.image.PictureFiles;
import dev.crt.image.RgbImage;
import dev.crt.scene.Picture;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

/** Puts the frame files of an animation into one GIF, looping or played once. */
public final class GifAssembly {
    private GifAssembly() {}

    /** Writes {@code frames} (8-bit .png or .ppm files, in order) to {@code gif}, atomically, looping at {@code fps}. */
    public static void write(Path gif, List<Path> frames, double fps) throws IOException {
        write(gif, frames, fps, true);
    }

    /** As {@link #write(Path, List, double)}; {@code loop} false writes a GIF that plays once. */
    public static void write(Path gif, List<Path> frames, double fps, boolean loop) throws IOException {
        GifWriter.Frames source = new GifWriter.Frames() {
            @Override
            public int count() { return frames.size(); }

            @Override
            public RgbImage read(int index) throws IOException { return rgb(PictureFiles.read(frames.get(index))); }
        };
        GifWriter.write(gif, source, fps, loop);
    }

    private static RgbImage rgb(Picture picture) {
        // A frame of 8-bit codes is already what the GIF writer reads (byte8 of k/255f is k).
        if (picture.codes() != null) return new RgbImage(picture.width(), picture.height(), picture.codes());
        float[] v = picture.floats();
        int[] packed = new int[picture.width() * picture.height()];
        for (int i = 0; i < packed.length; i++) {
            packed[i] = (byte8(v[3 * i]) << 16) | (byte8(v[3 * i + 1]) << 8) | byte8(v[3 * i + 2]);
        }
        return new RgbImage(picture.width(), picture.height(), packed);
    }

    private static int byte8(float stored) { return Math.max(0, Math.min(255, Math.round(stored * 255))); }
}
