package dev.crt.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** crt render --pass id|depth: the id colours and the one-channel PFM of distances, computed by hand. */
class RenderPassTest {
    @TempDir
    Path dir;

    /** Camera at the origin looking along +z; entity 1 a sphere of radius 1 at z = 5; entity 2 a box far right. */
    private Path scene() throws Exception {
        Path f = dir.resolve("s.crt");
        Files.writeString(f, """
                Settings { camera -> Camera { position -> vec3(0, 0, 0) pointing -> vec3(0, 0, 1) fov -> 60 } width -> 9 height -> 9 }
                Scene {
                  Sphere { center -> vec3(0, 0, 5) radius -> 1 }
                  Box { cornerA -> vec3(2.2, -1, 5) cornerB -> vec3(4, 1, 6) }
                }
                """);
        return f;
    }

    @Test
    void theIdPassColoursEachTopLevelEntityByItsOneBasedIndex() throws Exception {
        Path out = dir.resolve("ids.png");
        CliRun r = CliRun.of("render", scene().toString(), "-o", out.toString(), "--pass", "id", "-q");
        assertThat(r.exitCode()).as(r.err()).isZero();
        BufferedImage image = ImageIO.read(out.toFile());
        assertThat(image.getRGB(4, 4) & 0xFFFFFF).as("centre: the sphere, k = 1").isEqualTo(0x010000);
        assertThat(image.getRGB(8, 4) & 0xFFFFFF).as("right edge: the box, k = 2").isEqualTo(0x020000);
        assertThat(image.getRGB(0, 0) & 0xFFFFFF).as("corner: background").isZero();
    }

    @Test
    void theDepthPassIsTheDistanceAlongTheRayAsOneChannelPfm() throws Exception {
        Path out = dir.resolve("depth.pfm");
        CliRun r = CliRun.of("render", scene().toString(), "-o", out.toString(), "--pass", "depth", "-q");
        assertThat(r.exitCode()).as(r.err()).isZero();
        byte[] bytes = Files.readAllBytes(out);
        String header = "Pf\n9 9\n-1.0\n";
        assertThat(new String(bytes, 0, header.length(), StandardCharsets.US_ASCII)).isEqualTo(header);
        ByteBuffer b = ByteBuffer.wrap(bytes, header.length(), 81 * 4).order(ByteOrder.LITTLE_ENDIAN);
        float[] rows = new float[81];
        for (int i = 0; i < 81; i++) rows[i] = b.getFloat();
        // Rows are stored bottom to top; the centre row is row 4 either way. The centre ray meets the sphere at z = 4.
        assertThat(rows[4 * 9 + 4]).isEqualTo(4f);
        assertThat(rows[0]).isEqualTo(Float.POSITIVE_INFINITY);
    }

    @Test
    void aPassThatDoesNotFitTheFileTypeIsAUsageError() throws Exception {
        CliRun depth = CliRun.of("render", scene().toString(), "-o", dir.resolve("d.png").toString(), "--pass", "depth");
        assertThat(depth.exitCode()).isEqualTo(ExitCode.USAGE);
        assertThat(depth.err()).contains("--pass depth writes a .pfm file");
        CliRun unknown = CliRun.of("render", scene().toString(), "--pass", "normals");
        assertThat(unknown.exitCode()).isEqualTo(ExitCode.USAGE);
        assertThat(unknown.err()).contains("--pass must be color, id or depth, got 'normals'");
        assertThat(dir.toFile().list()).containsExactly("s.crt");
    }
}
