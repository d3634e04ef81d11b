package dev.crt.lang;

import static dev.crt.lang.Scripts.CAMERA;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.scene.Mesh;
import dev.crt.scene.MeshData;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Binary PLY files of the common layout (scalar vertex properties, faces of an 8-bit length and
 * 32-bit indices alone) are read by a loop of their own: it gives the very mesh, and the same
 * problems, as the value-by-value reading every other layout gets.
 */
class BinaryPlyTest {
    @TempDir
    Path dir;

    @Test
    void theCommonLayoutReadsAsAnyOther() throws IOException {
        for (boolean attributes : new boolean[] {false, true}) {
            Files.write(dir.resolve("common.ply"), ply(2000, attributes, false, 0));
            // An extra list on the vertices and an extra scalar on the faces: the general reading.
            Files.write(dir.resolve("general.ply"), ply(2000, attributes, true, 0));
            MeshData common = mesh("common.ply"), general = mesh("general.ply");
            String what = attributes ? "with normals and uv" : "positions alone";
            assertThat(common.triangleCount()).as(what).isGreaterThan(2000);
            assertThat(common.positions()).as(what).isEqualTo(general.positions());
            assertThat(common.triangles()).as(what).isEqualTo(general.triangles());
            assertThat(common.normals()).as(what).isEqualTo(general.normals());
            assertThat(common.uvs()).as(what).isEqualTo(general.uvs());
            assertThat(common.closed()).as(what).isEqualTo(general.closed());
        }
    }

    @Test
    void cutFilesAreReportedAtTheElementWhereTheyEnd() throws IOException {
        for (boolean extra : new boolean[] {false, true}) {
            byte[] whole = ply(100, true, extra, 0);
            int header = new String(whole, StandardCharsets.ISO_8859_1).indexOf("end_header\n") + 11;
            int stride = 4 * (3 + 3 + 2) + (extra ? 1 + 4 : 0);
            Files.write(dir.resolve("cut.ply"), Arrays.copyOf(whole, header + 37 * stride + 5));
            assertThat(problem("cut.ply")).as("extra %s", extra)
                    .isEqualTo("cannot use mesh 'cut.ply': the file ends at vertex 37 of 100 vertex elements (truncated?)");
            Files.write(dir.resolve("cut.ply"), Arrays.copyOf(whole, whole.length - 3));
            assertThat(problem("cut.ply")).as("extra %s", extra).startsWith("cannot use mesh 'cut.ply': the file ends at face ");
        }
    }

    @Test
    void indicesOutOfRangeAreReportedAlike() throws IOException {
        for (boolean extra : new boolean[] {false, true}) {
            Files.write(dir.resolve("far.ply"), ply(50, false, extra, 50));
            assertThat(problem("far.ply")).as("extra %s", extra)
                    .isEqualTo("cannot use mesh 'far.ply': face 0: vertex 50 does not exist (there are 50 vertices before it, numbered from 0)");
            Files.write(dir.resolve("far.ply"), ply(50, false, extra, Integer.MIN_VALUE));
            assertThat(problem("far.ply")).as("extra %s", extra)
                    .isEqualTo("cannot use mesh 'far.ply': face 0: vertex index -2.147483648E9 is not a whole number");
        }
    }

    private MeshData mesh(String file) throws IOException {
        CompileResult r = compile("Scene { Mesh { file -> \"" + file + "\" } }\n");
        assertThat(r.hasErrors()).as(() -> r.diagnostics().toString()).isFalse();
        return ((Mesh) r.scene().entities().get(0)).data();
    }

    private String problem(String file) throws IOException {
        CompileResult r = compile("m = Mesh { file -> \"" + file + "\" }\n");
        return r.diagnostics().stream().filter(Diagnostic::isError).findFirst().orElseThrow().message();
    }

    private CompileResult compile(String text) throws IOException {
        Path script = dir.resolve("scene.crt");
        Files.writeString(script, CAMERA + text);
        return CrtCompiler.compile(new Source(script.toString(), CAMERA + text, script), CompileOptions.DEFAULT);
    }

    /**
     * A random binary PLY of {@code n} vertices and polygons of 3 to 5 corners, with normals and uv
     * when asked, and with an extra vertex list and face scalar when asked; the first face's first
     * index is {@code firstIndex} when that is not 0.
     */
    private static byte[] ply(int n, boolean attributes, boolean extra, int firstIndex) {
        SplittableRandom r = new SplittableRandom(n);
        StringBuilder h = new StringBuilder("ply\nformat binary_little_endian 1.0\nelement vertex " + n + "\n");
        h.append("property float x\nproperty float y\nproperty float z\n");
        if (attributes) h.append("property float nx\nproperty float ny\nproperty float nz\nproperty float u\nproperty float v\n");
        if (extra) h.append("property list uchar int extra\n");
        h.append("element face ").append(n).append("\nproperty list uchar int vertex_indices\n");
        if (extra) h.append("property uchar flags\n");
        h.append("end_header\n");
        ByteBuffer b = ByteBuffer.allocate(h.length() + n * (4 * 8 + 5) + n * (1 + 4 * 5 + 1)).order(ByteOrder.LITTLE_ENDIAN);
        b.put(h.toString().getBytes(StandardCharsets.US_ASCII));
        for (int i = 0; i < n; i++) {
            for (int k = 0; k < (attributes ? 8 : 3); k++) b.putFloat((float) r.nextDouble(-1, 1));
            if (extra) {
                b.put((byte) 1);
                b.putInt(i);
            }
        }
        for (int i = 0; i < n; i++) {
            int corners = 3 + r.nextInt(3);
            b.put((byte) corners);
            for (int c = 0; c < corners; c++) b.putInt(i == 0 && c == 0 && firstIndex != 0 ? firstIndex : r.nextInt(n));
            if (extra) b.put((byte) 7);
        }
        return Arrays.copyOf(b.array(), b.position());
    }
}
