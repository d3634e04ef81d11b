package dev.crt.image;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.awt.image.BufferedImage;
import java.io.IOException;
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

public class GifWriterTest {
    @TempDir
    Path dir;

    /** A two-way colour gradient with a square that moves one step per frame. */
    private static RgbImage frame(int index, int w, int h) {
        int[] rgb = new int[w * h];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int r = 30 + 200 * x / (w - 1);
                int g = 40 + 180 * y / (h - 1);
                int b = 250 - 100 * (x + y) / (w + h - 2);
                boolean square = x >= 4 + 3 * index && x < 14 + 3 * index && y >= 10 && y < 20;
                rgb[y * w + x] = square ? 0xff2010 : (r << 16) | (g << 8) | b;
            }
        }
        return new RgbImage(w, h, rgb);
    }

    private static GifWriter.Frames frames(int count, int w, int h) {
        return new GifWriter.Frames() {
            @Override public int count() { return count; }

            @Override public RgbImage read(int index) { return frame(index, w, h); }
        };
    }

    /** Reads a GIF back as whole frames, drawing each stored rectangle over the previous frame as a viewer does. */
    public static List<int[]> composited(Path gif, List<Integer> delays) throws IOException {
        List<int[]> frames = new ArrayList<>();
        try (ImageInputStream in = ImageIO.createImageInputStream(gif.toFile())) {
            ImageReader reader = ImageIO.getImageReadersByFormatName("gif").next();
            reader.setInput(in);
            int n = reader.getNumImages(true);
            BufferedImage first = reader.read(0);
            int w = first.getWidth();
            int h = first.getHeight();
            int[] canvas = new int[w * h];
            for (int i = 0; i < n; i++) {
                BufferedImage part = reader.read(i);
                IIOMetadataNode root = (IIOMetadataNode) reader.getImageMetadata(i).getAsTree("javax_imageio_gif_image_1.0");
                IIOMetadataNode d = (IIOMetadataNode) root.getElementsByTagName("ImageDescriptor").item(0);
                IIOMetadataNode c = (IIOMetadataNode) root.getElementsByTagName("GraphicControlExtension").item(0);
                delays.add(Integer.parseInt(c.getAttribute("delayTime")));
                int left = Integer.parseInt(d.getAttribute("imageLeftPosition"));
                int top = Integer.parseInt(d.getAttribute("imageTopPosition"));
                for (int y = 0; y < part.getHeight(); y++) {
                    for (int x = 0; x < part.getWidth(); x++) {
                        int argb = part.getRGB(x, y);
                        if ((argb >>> 24) != 0) canvas[(top + y) * w + left + x] = argb & 0xffffff;
                    }
                }
                frames.add(canvas.clone());
            }
            reader.dispose();
        }
        return frames;
    }

    @Test
    void writesOneFramePerImageWithDelaysThatAddUpToTheFrameRate() throws IOException {
        Path gif = dir.resolve("anim.gif");
        GifWriter.write(gif, frames(6, 64, 48), 30);
        List<Integer> delays = new ArrayList<>();
        assertThat(composited(gif, delays)).hasSize(6);
        // 30 fps is 3⅓ hundredths a frame: the delays alternate so 6 frames last exactly 0.2 s.
        assertThat(delays).containsExactly(3, 4, 3, 3, 4, 3);
    }

    @Test
    void loopsForever() throws IOException {
        Path gif = dir.resolve("anim.gif");
        GifWriter.write(gif, frames(2, 32, 24), 10);
        try (ImageInputStream in = ImageIO.createImageInputStream(gif.toFile())) {
            ImageReader reader = ImageIO.getImageReadersByFormatName("gif").next();
            reader.setInput(in);
            Node root = reader.getImageMetadata(0).getAsTree("javax_imageio_gif_image_1.0");
            IIOMetadataNode app = (IIOMetadataNode) ((IIOMetadataNode) root).getElementsByTagName("ApplicationExtension").item(0);
            assertThat(app.getAttribute("applicationID")).isEqualTo("NETSCAPE");
            assertThat(app.getAttribute("authenticationCode")).isEqualTo("2.0");
            assertThat((byte[]) app.getUserObject()).containsExactly(1, 0, 0);
            reader.dispose();
        }
    }

    @Test
    void framesLookLikeTheImagesWithoutBanding() throws IOException {
        int w = 96;
        int h = 72;
        Path gif = dir.resolve("anim.gif");
        GifWriter.write(gif, frames(4, w, h), 25);
        List<int[]> shown = composited(gif, new ArrayList<>());
        double worst = 0;
        double total = 0;
        int blocks = 0;
        for (int i = 0; i < shown.size(); i++) {
            int[] original = frame(i, w, h).rgb();
            // Dithering trades bands for grain: averaged over 4×4 blocks, the GIF matches the image closely.
            for (int by = 0; by < h; by += 4) {
                for (int bx = 0; bx < w; bx += 4) {
                    for (int shift = 0; shift <= 16; shift += 8) {
                        double diff = 0;
                        for (int y = by; y < by + 4; y++) {
                            for (int x = bx; x < bx + 4; x++) {
                                diff += ((shown.get(i)[y * w + x] >> shift) & 0xff) - ((original[y * w + x] >> shift) & 0xff);
                            }
                        }
                        worst = Math.max(worst, Math.abs(diff / 16));
                        total += Math.abs(diff / 16);
                        blocks++;
                    }
                }
            }
        }
        assertThat(worst).isLessThan(4.5);
        assertThat(total / blocks).isLessThan(0.75);
    }

    @Test
    void stillFramesAreStoredAsTinyPatches() throws IOException {
        GifWriter.Frames still = new GifWriter.Frames() {
            @Override public int count() { return 20; }

            @Override public RgbImage read(int index) { return frame(0, 80, 60); }
        };
        Path once = dir.resolve("once.gif");
        Path many = dir.resolve("many.gif");
        GifWriter.write(once, frames(1, 80, 60), 25);
        GifWriter.write(many, still, 25);
        assertThat(Files.size(many) - Files.size(once)).isLessThan(19 * 60);
    }

    @Test
    void framesOfDifferentSizesAreRefusedAndNothingIsLeftBehind() {
        GifWriter.Frames mixed = new GifWriter.Frames() {
            @Override public int count() { return 2; }

            @Override public RgbImage read(int index) { return frame(0, 32 + index, 24); }
        };
        Path gif = dir.resolve("mixed.gif");
        assertThatThrownBy(() -> GifWriter.write(gif, mixed, 25)).isInstanceOf(IOException.class)
                .hasMessage("frame 2 of the GIF is 33×24 but the first is 32×24");
        assertThat(dir).isEmptyDirectory();
    }
}
