package dev.crt.image;

import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.scene.Picture;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.SplittableRandom;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Colour JPEGs and BMPs (decoded as b, g, r bytes) read to the texels getRGB gives. */
class PictureBgrTest {
    @TempDir
    Path dir;

    @Test
    void bgrImagesReadAsTheirRgbValues() throws Exception {
        SplittableRandom r = new SplittableRandom(3);
        BufferedImage src = new BufferedImage(53, 29, BufferedImage.TYPE_3BYTE_BGR);
        for (int y = 0; y < src.getHeight(); y++) {
            for (int x = 0; x < src.getWidth(); x++) src.setRGB(x, y, r.nextInt(1 << 24));
        }
        for (String format : new String[] {"jpg", "bmp"}) {
            Path file = dir.resolve("p." + format);
            assertThat(ImageIO.write(src, format, file.toFile())).isTrue();
            BufferedImage decoded = ImageIO.read(file.toFile());
            assertThat(decoded.getType()).as(format).isEqualTo(BufferedImage.TYPE_3BYTE_BGR);
            Picture pic = PictureFiles.read(file);
            assertThat(pic.width()).isEqualTo(53);
            assertThat(pic.height()).isEqualTo(29);
            for (int y = 0; y < 29; y++) {
                for (int x = 0; x < 53; x++) {
                    int p = decoded.getRGB(x, y);
                    assertThat(pic.get(x, y, 0)).isEqualTo((p >> 16 & 0xFF) / 255f);
                    assertThat(pic.get(x, y, 1)).isEqualTo((p >> 8 & 0xFF) / 255f);
                    assertThat(pic.get(x, y, 2)).isEqualTo((p & 0xFF) / 255f);
                }
            }
        }
        assertThat(Files.size(dir.resolve("p.bmp"))).isGreaterThan(53 * 29 * 3);
    }
}
