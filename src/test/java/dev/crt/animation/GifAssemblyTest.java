package dev.crt.animation;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.image.GifWriter;
import dev.crt.image.RgbImage;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Frame files read to the pixels they store: PNG frames (loaded as 8-bit codes) and 16-bit PPM
 * frames of the same values (loaded as floats) give the GIF of those pixels written directly.
 */
class GifAssemblyTest {
    @TempDir
    Path dir;

    @Test
    void pngAndSixteenBitPpmFramesGiveTheGifOfTheirPixels() throws IOException {
        int w = 24, h = 16, count = 3;
        SplittableRandom r = new SplittableRandom(29);
        List<RgbImage> images = new ArrayList<>();
        List<Path> png = new ArrayList<>(), ppm = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            int[] rgb = new int[w * h];
            for (int k = 0; k < rgb.length; k++) rgb[k] = r.nextInt(1 << 24);
            images.add(new RgbImage(w, h, rgb));
            BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
            image.setRGB(0, 0, w, h, rgb, 0, w);
            Path p = dir.resolve("f" + i + ".png");
            assertThat(ImageIO.write(image, "png", p.toFile())).isTrue();
            png.add(p);
            // Sample k·257 of 65535 is exactly k/255.
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            out.write(("P6\n" + w + " " + h + "\n65535\n").getBytes(StandardCharsets.US_ASCII));
            for (int c : rgb) {
                for (int shift = 16; shift >= 0; shift -= 8) {
                    int v = (c >> shift & 0xFF) * 257;
                    out.write(v >> 8);
                    out.write(v & 0xFF);
                }
            }
            ppm.add(Files.write(dir.resolve("f" + i + ".ppm"), out.toByteArray()));
        }
        Path direct = dir.resolve("direct.gif"), fromPng = dir.resolve("png.gif"), fromPpm = dir.resolve("ppm.gif");
        GifWriter.write(direct, new GifWriter.Frames() {
            @Override public int count() { return count; }

            @Override public RgbImage read(int index) { return images.get(index); }
        }, 10, true);
        GifAssembly.write(fromPng, png, 10);
        GifAssembly.write(fromPpm, ppm, 10);
        assertThat(Files.readAllBytes(fromPng)).isEqualTo(Files.readAllBytes(direct));
        assertThat(Files.readAllBytes(fromPpm)).isEqualTo(Files.readAllBytes(direct));
    }
}
