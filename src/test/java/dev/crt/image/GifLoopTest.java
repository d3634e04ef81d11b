package dev.crt.image;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageInputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.w3c.dom.Node;

/** A GIF loops forever through the NETSCAPE2.0 extension, or plays once without it. */
public class GifLoopTest {
    @TempDir
    Path dir;

    private static GifWriter.Frames frames(int count) {
        return new GifWriter.Frames() {
            @Override public int count() { return count; }

            @Override public RgbImage read(int index) {
                int[] rgb = new int[16 * 12];
                for (int i = 0; i < rgb.length; i++) rgb[i] = i % 16 == index ? 0xff0000 : 0x2040a0;
                return new RgbImage(16, 12, rgb);
            }
        };
    }

    /**
     * The NETSCAPE2.0 application extensions of every frame, as the JDK's GIF reader gives them:
     * each as "frame:ID AUTH:loop count" (the count from its sub-block, 0 meaning forever).
     */
    public static List<String> loopExtensions(Path gif) throws IOException {
        List<String> found = new ArrayList<>();
        try (ImageInputStream in = ImageIO.createImageInputStream(gif.toFile())) {
            ImageReader reader = ImageIO.getImageReadersByFormatName("gif").next();
            reader.setInput(in);
            int n = reader.getNumImages(true);
            for (int i = 0; i < n; i++) {
                IIOMetadataNode root = (IIOMetadataNode) reader.getImageMetadata(i).getAsTree("javax_imageio_gif_image_1.0");
                for (Node c = root.getFirstChild(); c != null; c = c.getNextSibling()) {
                    if (!c.getNodeName().equals("ApplicationExtensions")) continue;
                    for (Node e = c.getFirstChild(); e != null; e = e.getNextSibling()) {
                        IIOMetadataNode ext = (IIOMetadataNode) e;
                        byte[] data = (byte[]) ext.getUserObject();
                        int count = data.length >= 3 && data[0] == 1 ? (data[1] & 0xff) | (data[2] & 0xff) << 8 : -1;
                        found.add(i + ":" + ext.getAttribute("applicationID") + " " + ext.getAttribute("authenticationCode") + ":" + count);
                    }
                }
            }
            reader.dispose();
        }
        return found;
    }

    public static int frameCount(Path gif) throws IOException {
        try (ImageInputStream in = ImageIO.createImageInputStream(gif.toFile())) {
            ImageReader reader = ImageIO.getImageReadersByFormatName("gif").next();
            reader.setInput(in);
            int n = reader.getNumImages(true);
            reader.dispose();
            return n;
        }
    }

    @Test
    void aLoopingGifCarriesTheNetscapeExtensionWithCountZeroAndAOnceGifNone() throws IOException {
        Path looping = dir.resolve("loop.gif");
        Path once = dir.resolve("once.gif");
        GifWriter.write(looping, frames(4), 10, true);
        GifWriter.write(once, frames(4), 10, false);
        assertThat(loopExtensions(looping)).containsExactly("0:NETSCAPE 2.0:0");
        assertThat(loopExtensions(once)).isEmpty();
        assertThat(frameCount(looping)).isEqualTo(4);
        assertThat(frameCount(once)).isEqualTo(4);
        // The bytes agree: the extension's identifier is in the one file and not in the other.
        assertThat(new String(Files.readAllBytes(looping), StandardCharsets.ISO_8859_1)).contains("NETSCAPE2.0");
        assertThat(new String(Files.readAllBytes(once), StandardCharsets.ISO_8859_1)).doesNotContain("NETSCAPE2.0");
        // Without the option a GIF loops, as crt animate --gif always wrote it.
        Path plain = dir.resolve("plain.gif");
        GifWriter.write(plain, frames(2), 10);
        assertThat(loopExtensions(plain)).containsExactly("0:NETSCAPE 2.0:0");
    }
}
