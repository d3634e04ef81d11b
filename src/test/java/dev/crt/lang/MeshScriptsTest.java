package dev.crt.lang;

import static dev.crt.lang.Scripts.CAMERA;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.scene.Mesh;
import dev.crt.scene.MeshData;
import dev.crt.scene.Scene;
import java.io.IOException;
import java.io.RandomAccessFile;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Meshes in scripts: each file format, inline meshes, sharing, and each bad file's diagnostic at its attribute. */
class MeshScriptsTest {
    @TempDir
    Path dir;

    private CompileResult compile(String text) throws IOException {
        Path script = dir.resolve("scene.crt");
        Files.writeString(script, text);
        return CrtCompiler.compile(new Source(script.toString(), text, script), CompileOptions.DEFAULT);
    }

    private Scene scene(String text) throws IOException {
        CompileResult r = compile(text);
        assertThat(r.hasErrors()).as(() -> r.diagnostics().toString()).isFalse();
        return r.scene();
    }

    private Diagnostic error(String text) throws IOException {
        CompileResult r = compile(text);
        List<Diagnostic> errors = r.diagnostics().stream().filter(Diagnostic::isError).toList();
        assertThat(errors).as(errors.toString()).hasSize(1);
        return errors.get(0);
    }

    private static final String CUBE_OBJ = """
            # a unit cube, quads, with normals and uvs
            v 0 0 0
            v 1 0 0
            v 1 1 0
            v 0 1 0
            v 0 0 1
            v 1 0 1
            v 1 1 1
            v 0 1 1
            vt 0 0
            vt 1 0
            vt 1 1
            vt 0 1
            vn 0 0 -1
            g cube
            f 1/1/1 4/4/1 3/3/1 2/2/1
            f 5/1 6/2 7/3 8/4
            f 1 2 6 5
            f 2 3 7 6
            f -5 -1 -2 -6
            f 4 1 5 8
            """;

    @Test
    void anObjFileIsFannedIntoAClosedSolidWithItsUvs() throws IOException {
        Files.writeString(dir.resolve("cube.obj"), CUBE_OBJ);
        Scene s = scene(CAMERA + "Scene { Mesh { file -> \"cube.obj\" } }\n");
        MeshData m = ((Mesh) s.entities().get(0)).data();
        assertThat(m.triangleCount()).isEqualTo(12);
        assertThat(m.closed()).isTrue();
        assertThat(m.uvs()).isNotNull();
    }

    @Test
    void instancesOfOneFileShareTheirData() throws IOException {
        Files.writeString(dir.resolve("cube.obj"), CUBE_OBJ);
        Scene s = scene(CAMERA + "c = Mesh { file -> \"cube.obj\" }\nScene { c c <translate vec3(2, 0, 0)> Mesh { file -> \"cube.obj\" smooth -> false } }\n");
        assertThat(((Mesh) s.entities().get(0)).data()).isSameAs(((Mesh) s.entities().get(2)).data());
        assertThat(((Mesh) s.entities().get(2)).smooth()).isFalse();
    }

    @Test
    void rawAndAsciiAndBinaryPlyFilesLoad() throws IOException {
        Files.writeString(dir.resolve("tri.raw"), "0 0 0 1 0 0 0 1 0\n0 0 0 0 1 0 0 0 1\n");
        Files.writeString(dir.resolve("quad.ply"), """
                ply
                format ascii 1.0
                comment a square
                element vertex 4
                property float x
                property float y
                property float z
                property float nx
                property float ny
                property float nz
                element face 1
                property list uchar int vertex_indices
                end_header
                0 0 0 0 0 1
                1 0 0 0 0 1
                1 1 0 0 0 1
                0 1 0 0 0 1
                4 0 1 2 3
                """);
        Files.write(dir.resolve("tet.ply"), binaryTetrahedron(false));
        Scene s = scene(CAMERA + "Scene { Mesh { file -> \"tri.raw\" } Mesh { file -> \"quad.ply\" } Mesh { file -> \"tet.ply\" } }\n");
        assertThat(((Mesh) s.entities().get(0)).data().triangleCount()).isEqualTo(2);
        MeshData quad = ((Mesh) s.entities().get(1)).data();
        assertThat(quad.triangleCount()).isEqualTo(2);
        assertThat(quad.closed()).isFalse();
        MeshData tet = ((Mesh) s.entities().get(2)).data();
        assertThat(tet.triangleCount()).isEqualTo(4);
        assertThat(tet.closed()).isTrue();
    }

    /** A tetrahedron as binary little-endian PLY; cut short when asked. */
    private static byte[] binaryTetrahedron(boolean truncated) {
        String header = "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                + "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n";
        ByteBuffer b = ByteBuffer.allocate(header.length() + 4 * 12 + 4 * 13).order(ByteOrder.LITTLE_ENDIAN);
        b.put(header.getBytes(StandardCharsets.US_ASCII));
        float[][] v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        for (float[] p : v) for (float c : p) b.putFloat(c);
        int[][] f = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
        for (int[] face : f) {
            b.put((byte) 3);
            for (int i : face) b.putInt(i);
        }
        byte[] all = b.array();
        return truncated ? java.util.Arrays.copyOf(all, all.length - 7) : all;
    }

    @Test
    void inlineVerticesAndFacesMakeAMesh() throws IOException {
        Scene s = scene(CAMERA + "Scene { Mesh { vertices -> [vec3(0,0,0), vec3(1,0,0), vec3(0,1,0), vec3(0,0,1)]\n"
                + "faces -> [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]] } }\n");
        MeshData m = ((Mesh) s.entities().get(0)).data();
        assertThat(m.triangleCount()).isEqualTo(4);
        assertThat(m.closed()).isTrue();
    }

    private static void at(Diagnostic d, int line, int column, String message) {
        assertThat(d.message()).isEqualTo(message);
        assertThat(d.span().line()).isEqualTo(line);
        assertThat(d.span().column()).isEqualTo(column);
    }

    @Test
    void badFilesAreReportedAtTheFileAttribute() throws IOException {
        Files.writeString(dir.resolve("far.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
        at(error("m = Mesh {\n  file -> \"far.obj\" }\n"), 2, 3,
                "cannot use mesh 'far.obj': line 4: vertex 6 does not exist (there are 3 vertices before it, numbered from 0)");
        Files.writeString(dir.resolve("nan.obj"), "v 0 0 0\nv NaN 0 0\nv 0 1 0\nf 1 2 3\n");
        at(error("m = Mesh { file -> \"nan.obj\" }\n"), 1, 12,
                "cannot use mesh 'nan.obj': line 2: vertex 1 is not a finite point (NaN, 0.0, 0.0)");
        Files.writeString(dir.resolve("none.obj"), "v 0 0 0\n# nothing else\n");
        at(error("m = Mesh { file -> \"none.obj\" }\n"), 1, 12, "cannot use mesh 'none.obj': the mesh has no faces");
        Files.write(dir.resolve("cut.ply"), binaryTetrahedron(true));
        at(error("m = Mesh { file -> \"cut.ply\" }\n"), 1, 12,
                "cannot use mesh 'cut.ply': the file ends at face 3 of 4 face elements (truncated?)");
        Files.writeString(dir.resolve("odd.raw"), "0 0 0 1 0 0 0 1\n");
        at(error("m = Mesh { file -> \"odd.raw\" }\n"), 1, 12,
                "cannot use mesh 'odd.raw': the file ends in the middle of a triangle: 8 numbers left over (RAW has 9 per triangle)");
        Files.writeString(dir.resolve("words.obj"), "v 0 zero 0\n");
        at(error("m = Mesh { file -> \"words.obj\" }\n"), 1, 12, "cannot use mesh 'words.obj': line 1: 'zero' is not a number");
    }

    @Test
    void aHugeFileIsRefusedBeforeItIsRead() throws IOException {
        Path big = dir.resolve("huge.obj");
        try (RandomAccessFile f = new RandomAccessFile(big.toFile(), "rw")) {
            f.setLength(2L << 30);
        }
        at(error("m = Mesh { file -> \"huge.obj\" }\n"), 1, 12,
                "cannot use mesh 'huge.obj': the file is 2048 MiB; meshes up to 1024 MiB are read");
    }

    @Test
    void inlineMistakesAndOpenMeshesInCsgAreReported() throws IOException {
        at(error("m = Mesh { vertices -> [vec3(0,0,0), vec3(1,0,0), vec3(0,1,0)]\n  faces -> [[0, 1, 3]] }\n"), 2, 3,
                "faces[0]: vertex 3 does not exist (there are 3 vertices before it, numbered from 0)");
        at(error("m = Mesh { vertices -> [vec3(0,0,0)] }\n"), 1, 12, "an inline Mesh needs both vertices and faces");
        at(error("m = Mesh { smooth -> false }\n"), 1, 5, "a Mesh takes either file, or vertices with faces");
        at(error("m = Mesh { vertices -> [vec3(0,0,0), vec3(1,0,0), vec3(0,1,0)] faces -> [[0, 1, 2]] }\nu = m + Sphere { }\n"),
                2, 5, "an open Mesh (not watertight) is a surface, not a solid, so it cannot be used in CSG");
    }
}
