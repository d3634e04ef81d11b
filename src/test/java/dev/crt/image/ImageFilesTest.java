package dev.crt.image;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.metadata.IIOMetadata;
import javax.imageio.stream.ImageInputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.w3c.dom.Node;

class ImageFilesTest {
    @TempDir
    Path dir;

    /** 3×2 pixels: a ramp, an over-bright and a negative value to exercise clamping. */
    private static FrameBuffer sample() {
        FrameBuffer fb = new FrameBuffer(3, 2);
        fb.set(0, 0, 0, 0.25, 0.5);
        fb.set(1, 0, 1, 2.5, -0.5);
        fb.set(2, 0, 0.2, 0.4, 0.6);
        fb.set(0, 1, 0.01, 0.99, 0.5);
        fb.set(1, 1, 1, 1, 1);
        fb.set(2, 1, 0, 0, 0);
        return fb;
    }

    private static int expected(double c, double gamma) {
        double v = Math.max(0, Math.min(1, c));
        return (int) Math.round(Math.pow(v, 1 / gamma) * 255);
    }

    @Test
    void eightBitValueIsRoundedGammaEncodedClampedLinear() {
        for (double c : new double[] {-1, 0, 0.001, 0.2, 0.5, 0.73, 1, 7}) {
            assertThat(ImageFiles.toByte(c, 1)).isEqualTo(expected(c, 1));
            assertThat(ImageFiles.toByte(c, 2.2)).isEqualTo(expected(c, 2.2));
        }
        assertThat(ImageFiles.toByte(0.5, 2.2)).isEqualTo(186);
    }

    @Test
    void pngRoundTripsPixelsAndTextChunks() throws IOException {
        Path out = dir.resolve("a.png");
        Map<String, String> text = new LinkedHashMap<>();
        text.put("Title", "Spheres at dusk");
        text.put("Author", "Ada");
        text.put("Description", "a test");
        FrameBuffer fb = sample();
        ImageFiles.write(fb, out, 2.2, text);
        BufferedImage img = ImageIO.read(out.toFile());
        assertThat(img.getWidth()).isEqualTo(3);
        assertThat(img.getHeight()).isEqualTo(2);
        for (int y = 0; y < 2; y++) {
            for (int x = 0; x < 3; x++) {
                int rgb = img.getRGB(x, y);
                assertThat((rgb >> 16) & 0xff).isEqualTo(expected(fb.get(x, y, 0), 2.2));
                assertThat((rgb >> 8) & 0xff).isEqualTo(expected(fb.get(x, y, 1), 2.2));
                assertThat(rgb & 0xff).isEqualTo(expected(fb.get(x, y, 2), 2.2));
            }
        }
        assertThat(readText(out)).containsEntry("Title", "Spheres at dusk").containsEntry("Author", "Ada")
                .containsEntry("Description", "a test");
    }

    private static Map<String, String> readText(Path png) throws IOException {
        Map<String, String> found = new HashMap<>();
        try (ImageInputStream in = ImageIO.createImageInputStream(png.toFile())) {
            ImageReader reader = ImageIO.getImageReaders(in).next();
            reader.setInput(in);
            IIOMetadata meta = reader.getImageMetadata(0);
            Node root = meta.getAsTree("javax_imageio_png_1.0");
            for (Node n = root.getFirstChild(); n != null; n = n.getNextSibling()) {
                if (!n.getNodeName().equals("tEXt")) continue;
                for (Node e = n.getFirstChild(); e != null; e = e.getNextSibling()) {
                    found.put(e.getAttributes().getNamedItem("keyword").getNodeValue(),
                            e.getAttributes().getNamedItem("value").getNodeValue());
                }
            }
            reader.dispose();
        }
        return found;
    }

    @Test
    void ppmIsBinaryP6WithMaxval255() throws IOException {
        Path out = dir.resolve("a.ppm");
        FrameBuffer fb = sample();
        ImageFiles.write(fb, out, 1, Map.of("Title", "ignored"));
        byte[] bytes = Files.readAllBytes(out);
        byte[] header = "P6\n3 2\n255\n".getBytes(StandardCharsets.US_ASCII);
        assertThat(bytes).hasSize(header.length + 18);
        for (int i = 0; i < header.length; i++) assertThat(bytes[i]).isEqualTo(header[i]);
        for (int i = 0; i < 18; i++) {
            assertThat(bytes[header.length + i] & 0xff).isEqualTo(expected(fb.data()[i], 1));
        }
    }

    @Test
    void pfmIsLittleEndianLinearUnclampedBottomRowFirst() throws IOException {
        Path out = dir.resolve("a.PFM");
        FrameBuffer fb = sample();
        ImageFiles.write(fb, out, 2.2, Map.of());
        byte[] bytes = Files.readAllBytes(out);
        byte[] header = "PF\n3 2\n-1.0\n".getBytes(StandardCharsets.US_ASCII);
        for (int i = 0; i < header.length; i++) assertThat(bytes[i]).isEqualTo(header[i]);
        ByteBuffer b = ByteBuffer.wrap(bytes, header.length, bytes.length - header.length).order(ByteOrder.LITTLE_ENDIAN);
        assertThat(bytes.length - header.length).isEqualTo(3 * 2 * 3 * 4);
        for (int y = 1; y >= 0; y--) {
            for (int x = 0; x < 3; x++) {
                for (int c = 0; c < 3; c++) assertThat(b.getFloat()).isEqualTo(fb.get(x, y, c));
            }
        }
        assertThat(fb.get(1, 0, 1)).isEqualTo(2.5f);
    }

    @Test
    void unknownExtensionIsAPlainError() {
        assertThatThrownBy(() -> ImageFiles.write(sample(), dir.resolve("a.jpg"), 1, Map.of()))
                .isInstanceOf(IOException.class)
                .hasMessage("unsupported image type '.jpg': use .png, .ppm or .pfm");
        assertThat(dir).isEmptyDirectory();
    }

    @Test
    void unwritableFolderFailsWithoutLeavingFiles() throws IOException {
        Path notAFolder = Files.writeString(dir.resolve("file"), "x");
        assertThatThrownBy(() -> ImageFiles.write(sample(), notAFolder.resolve("a.png"), 1, Map.of()))
                .isInstanceOf(IOException.class).hasMessageContaining("cannot write").hasMessageContaining("not a folder");
        assertThatThrownBy(() -> ImageFiles.write(sample(), dir.resolve("missing/a.ppm"), 1, Map.of()))
                .isInstanceOf(IOException.class).hasMessageContaining("does not exist");
        try (Stream<Path> files = Files.list(dir)) {
            assertThat(files.map(p -> p.getFileName().toString()).toList()).containsExactly("file");
        }
    }

    @Test
    void aFailedRenameLeavesNoTemporaryFile() throws IOException {
        // The target is a non-empty folder, so the final rename fails after the data was written.
        Path target = dir.resolve("busy.png");
        Files.createDirectory(target);
        Files.writeString(target.resolve("inside"), "x");
        assertThatThrownBy(() -> ImageFiles.write(sample(), target, 1, Map.of())).isInstanceOf(IOException.class);
        try (Stream<Path> files = Files.list(dir)) {
            assertThat(files.map(p -> p.getFileName().toString()).toList()).containsExactly("busy.png");
        }
    }

    @Test
    void anExistingFileIsReplacedWhole() throws IOException {
        Path out = dir.resolve("a.ppm");
        Files.write(out, new byte[100_000]);
        ImageFiles.write(sample(), out, 1, Map.of());
        assertThat(Files.size(out)).isEqualTo("P6\n3 2\n255\n".length() + 18);
        try (Stream<Path> files = Files.list(dir)) {
            assertThat(files.toList()).hasSize(1);
        }
        assertThat(List.of(Files.readAllBytes(out)[0], Files.readAllBytes(out)[1])).containsExactly((byte) 'P', (byte) '6');
    }

    @Test
    void gammaEncoderGivesExactlyTheFormulasBytes() {
        java.util.SplittableRandom r = new java.util.SplittableRandom(5);
        for (double gamma : new double[] {2.2, 1.8, 0.45, 3}) {
            GammaEncoder e = new GammaEncoder(gamma);
            for (int k = 0; k < 200_000; k++) {
                double c = k % 2 == 0 ? r.nextDouble() * 1.2 - 0.1 : r.nextDouble() * r.nextDouble() * r.nextDouble();
                assertThat(e.encode(c)).isEqualTo(ImageFiles.toByte(c, gamma));
            }
            for (int k = 1; k < 256; k++) {
                // Right at each step, where rounding decides.
                double step = Math.pow((k - 0.5) / 255, gamma);
                for (double c : new double[] {Math.nextDown(step), step, Math.nextUp(step), (float) step}) {
                    assertThat(e.encode(c)).as("gamma %s at step %d", gamma, k).isEqualTo(ImageFiles.toByte(c, gamma));
                }
            }
        }
    }

    @Test
    void rowsAtGammaOneGiveExactlyTheFormulasBytes() {
        java.util.SplittableRandom r = new java.util.SplittableRandom(11);
        FrameBuffer image = new FrameBuffer(1000, 3);
        float[] data = image.data();
        for (int i = 0; i < data.length; i++) {
            data[i] = switch (i % 7) {
                case 0 -> (float) (r.nextDouble() * 1.4 - 0.2);
                case 1 -> (float) ((r.nextInt(256) + 0.5) / 255);   // where rounding decides
                case 2 -> Math.nextDown((float) ((r.nextInt(256) + 0.5) / 255));
                case 3 -> Float.NaN;
                case 4 -> r.nextBoolean() ? Float.POSITIVE_INFINITY : Float.NEGATIVE_INFINITY;
                case 5 -> r.nextBoolean() ? 1f : -0f;
                default -> (float) r.nextDouble();
            };
        }
        byte[] row = new byte[3000];
        for (int y = 0; y < 3; y++) {
            ImageFiles.encodeRow(image, y, new GammaEncoder(1), row);
            for (int i = 0; i < row.length; i++) {
                assertThat(row[i] & 0xff).as("value %s", data[y * 3000 + i]).isEqualTo(ImageFiles.toByte(data[y * 3000 + i], 1));
            }
        }
    }
}
