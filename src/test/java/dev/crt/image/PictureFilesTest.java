package dev.crt.image;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.crt.scene.Picture;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
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
