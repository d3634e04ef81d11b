package dev.crt.image;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.crt.scene.Picture;
import java.awt.Transparency;
import java.awt.color.ColorSpace;
import java.awt.image.BufferedImage;
import java.awt.image.ComponentColorModel;
import java.awt.image.DataBuffer;
import java.awt.image.WritableRaster;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.SplittableRandom;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class PictureFilesTest {
    @TempDir
    Path dir;

    @Test
    void decodesPngAsStoredValues() throws IOException {
        BufferedImage image = new BufferedImage(2, 1, BufferedImage.TYPE_INT_RGB);
        image.setRGB(0, 0, 0xFF8000);
        image.setRGB(1, 0, 0x0000FF);
        Path file = dir.resolve("p.png");
        ImageIO.write(image, "png", file.toFile());
        Picture p = PictureFiles.read(file);
        assertThat(p.width()).isEqualTo(2);
        assertThat(p.height()).isEqualTo(1);
        assertThat(p.get(0, 0, 0)).isEqualTo(1f);
        assertThat(p.get(0, 0, 1)).isEqualTo(128 / 255f);
        assertThat(p.get(1, 0, 2)).isEqualTo(1f);
    }

    /**
     * Files of 8-bit samples load as their codes, 0xRRGGBB per texel as getRGB gives them (without
     * its alpha), and no floats are kept: a JPEG (read from its b, g, r bytes), a PNG, a PNG with
     * alpha, a GIF and a 16-bit PNG (which ImageIO's getRGB, and so CRT, reads to 8 bits).
     */
    @Test
    void eightBitFilesLoadAsTheirCodes() throws IOException {
        SplittableRandom r = new SplittableRandom(17);
        int w = 23, h = 11;
        BufferedImage bgr = new BufferedImage(w, h, BufferedImage.TYPE_3BYTE_BGR);
        BufferedImage argb = new BufferedImage(w, h, BufferedImage.TYPE_INT_ARGB);
        BufferedImage deep = sixteenBitRgb(w, h, r);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                bgr.setRGB(x, y, r.nextInt(1 << 24));
                argb.setRGB(x, y, r.nextInt());
            }
        }
        Object[][] cases = {{bgr, "jpg"}, {bgr, "png"}, {argb, "png"}, {bgr, "gif"}, {deep, "png"}};
        for (int n = 0; n < cases.length; n++) {
            Path file = dir.resolve("case" + n + "." + cases[n][1]);
            assertThat(ImageIO.write((BufferedImage) cases[n][0], (String) cases[n][1], file.toFile())).isTrue();
            BufferedImage decoded = ImageIO.read(file.toFile());
            Picture p = PictureFiles.read(file);
            assertThat(p.codes()).as(file.getFileName().toString()).isNotNull().hasSize(w * h);
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    int want = decoded.getRGB(x, y) & 0xFFFFFF;
                    assertThat(p.codes()[y * w + x]).as("%s (%d, %d)", file.getFileName(), x, y).isEqualTo(want);
                    assertThat(p.get(x, y, 1)).isEqualTo((want >> 8 & 0xFF) / 255f);
                }
            }
        }
        assertThat(ImageIO.read(dir.resolve("case4.png").toFile()).getRaster().getSampleModel().getSampleSize(0)).isEqualTo(16);
    }

    @Test
    void ppmOfEightBitValuesLoadsAsCodesAndOtherPpmAsFloats() throws IOException {
        // maxval 15: v/15f is the float of code 17·v; 16 is past the maximum and reads as 1.
        Picture small = PictureFiles.read(ppm("small.ppm", "15", new byte[] {0, 1, 7, 14, 15, 16}));
        assertThat(small.codes()).containsExactly(0x00_11_77, 0xEE_FF_FF);
        float[] want = {0, 1 / 15f, 7 / 15f, 14 / 15f, 1, 1};
        assertThat(small.floats()).containsExactly(want);
        // maxval 100 and 1000: values between the codes, kept as floats.
        Picture hundred = PictureFiles.read(ppm("hundred.ppm", "100", new byte[] {0, 1, 50, 99, 100, 101}));
        assertThat(hundred.codes()).isNull();
        assertThat(hundred.floats()).containsExactly(0, 1 / 100f, 50 / 100f, 99 / 100f, 1, 1);
        Picture deep = PictureFiles.read(ppm("deep.ppm", "1000", new byte[] {0, 0, 0, 1, 1, (byte) 0xF4, 3, (byte) 0xE7, 3, (byte) 0xE8, 4, 0}));
        assertThat(deep.codes()).isNull();
        assertThat(deep.floats()).containsExactly(0, 1 / 1000f, 500 / 1000f, 999 / 1000f, 1, 1);
    }

    private Path ppm(String name, String maxval, byte[] samples) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.write(("P6\n2 1\n" + maxval + "\n").getBytes(StandardCharsets.US_ASCII));
        out.write(samples);
        return Files.write(dir.resolve(name), out.toByteArray());
    }

    /** An RGB image of 16 bits per sample (the PNG writer keeps them). */
    private static BufferedImage sixteenBitRgb(int w, int h, SplittableRandom r) {
        ComponentColorModel model = new ComponentColorModel(ColorSpace.getInstance(ColorSpace.CS_sRGB), new int[] {16, 16, 16},
                false, false, Transparency.OPAQUE, DataBuffer.TYPE_USHORT);
        WritableRaster raster = model.createCompatibleWritableRaster(w, h);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                for (int c = 0; c < 3; c++) raster.setSample(x, y, c, r.nextInt(1 << 16));
            }
        }
        return new BufferedImage(model, raster, false, null);
    }

    @Test
    void theSameBytesAreDecodedOnceAndNewBytesAgain() throws IOException {
        BufferedImage image = new BufferedImage(3, 2, BufferedImage.TYPE_INT_RGB);
        image.setRGB(2, 1, 0x336699);
        Path file = dir.resolve("sky.png");
        ImageIO.write(image, "png", file.toFile());
        Picture first = PictureFiles.read(file);
        assertThat(PictureFiles.read(file)).isSameAs(first);
        Path copy = Files.copy(file, dir.resolve("copy.png"));
        assertThat(PictureFiles.read(copy)).isSameAs(first);
        // Rewritten in place, same size and name, at once (the file's time may not even change).
        image.setRGB(2, 1, 0x996633);
        ImageIO.write(image, "png", file.toFile());
        Picture changed = PictureFiles.read(file);
        assertThat(changed).isNotSameAs(first);
        assertThat(changed.get(2, 1, 0)).isEqualTo(0x99 / 255f);
        assertThat(first.get(2, 1, 0)).isEqualTo(0x33 / 255f);
        assertThat(PictureFiles.read(copy).get(2, 1, 0)).isEqualTo(0x33 / 255f);
    }

    @Test
    void decodesBinaryPpmWithComments() throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.write("P6\n# made by hand\n2 1\n255\n".getBytes(StandardCharsets.US_ASCII));
        out.write(new byte[] {(byte) 255, 0, 51, 0, (byte) 255, 0});
        Path file = dir.resolve("p.ppm");
        Files.write(file, out.toByteArray());
        Picture p = PictureFiles.read(file);
        assertThat(p.width()).isEqualTo(2);
        assertThat(p.get(0, 0, 0)).isEqualTo(1f);
        assertThat(p.get(0, 0, 2)).isEqualTo(51 / 255f);
        assertThat(p.get(1, 0, 1)).isEqualTo(1f);
    }

    @Test
    void problemsAreIOExceptionsWithASentence() throws IOException {
        assertThatThrownBy(() -> PictureFiles.read(dir.resolve("missing.png")))
                .isInstanceOf(IOException.class).hasMessageContaining("does not exist");
        Path junk = Files.writeString(dir.resolve("junk.png"), "not an image");
        assertThatThrownBy(() -> PictureFiles.read(junk))
                .isInstanceOf(IOException.class).hasMessageContaining("is not an image CRT can decode");
        Path truncated = Files.write(dir.resolve("t.ppm"), "P6 4 4 255\nabc".getBytes(StandardCharsets.US_ASCII));
        assertThatThrownBy(() -> PictureFiles.read(truncated))
                .isInstanceOf(IOException.class).hasMessageContaining("truncated PPM");
        Path header = Files.write(dir.resolve("h.ppm"), "P6 x".getBytes(StandardCharsets.US_ASCII));
        assertThatThrownBy(() -> PictureFiles.read(header))
                .isInstanceOf(IOException.class).hasMessageContaining("damaged PPM header");
        Path empty = Files.write(dir.resolve("e.ppm"), "P6 0 1 255\n".getBytes(StandardCharsets.US_ASCII));
        assertThatThrownBy(() -> PictureFiles.read(empty))
                .isInstanceOf(IOException.class).hasMessageContaining("has an unusable size 0x1");
        byte[] png = Files.readAllBytes(writeTinyPng());
        Path cut = Files.write(dir.resolve("cut.png"), java.util.Arrays.copyOf(png, png.length / 2));
        assertThatThrownBy(() -> PictureFiles.read(cut)).isInstanceOf(IOException.class);
    }

    private Path writeTinyPng() throws IOException {
        BufferedImage image = new BufferedImage(16, 16, BufferedImage.TYPE_INT_RGB);
        Path file = dir.resolve("tiny.png");
        ImageIO.write(image, "png", file.toFile());
        return file;
    }
}
