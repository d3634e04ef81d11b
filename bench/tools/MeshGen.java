import java.io.BufferedOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Locale;

/**
 * Writes a closed, bumpy ball of about N triangles for the mesh benchmarks, as binary PLY (CRT)
 * and, with a .inc name, as a POV-Ray mesh2 of the same vertices and faces.
 *
 * <pre>java bench/tools/MeshGen.java TRIANGLES OUT.ply [OUT.inc]</pre>
 *
 * The ball is a latitude–longitude grid of nu × nv quads (nu = 2·nv), radius 1 with a ripple of
 * 0.03, the poles closed by fans; both files hold identical float vertices.
 */
public final class MeshGen {
    public static void main(String[] args) throws IOException {
        if (args.length < 2) {
            System.err.println("usage: java bench/tools/MeshGen.java TRIANGLES OUT.ply [OUT.inc]");
            System.exit(2);
        }
        long wanted = Long.parseLong(args[0].replace("_", ""));
        int nv = Math.max(3, (int) Math.round(Math.sqrt(wanted / 4.0)));
        int nu = 2 * nv;
        // Rows 1 … nv−1 of nu vertices each, then the two poles.
        int vertices = nu * (nv - 1) + 2;
        long triangles = 2L * nu * (nv - 2) + 2L * nu;
        float[] p = new float[3 * vertices];
        for (int j = 1; j < nv; j++) {
            double theta = Math.PI * j / nv;
            for (int i = 0; i < nu; i++) {
                double phi = 2 * Math.PI * i / nu;
                double r = 1 + 0.03 * Math.sin(17 * phi) * Math.sin(13 * theta);
                int k = 3 * ((j - 1) * nu + i);
                p[k] = (float) (r * Math.sin(theta) * Math.cos(phi));
                p[k + 1] = (float) (r * Math.cos(theta));
                p[k + 2] = (float) (r * Math.sin(theta) * Math.sin(phi));
            }
        }
        int north = vertices - 2, south = vertices - 1;
        p[3 * north + 1] = 1;
        p[3 * south + 1] = -1;
        int[] f = new int[(int) (3 * triangles)];
        int n = 0;
        for (int i = 0; i < nu; i++) {
            int a = i, b = (i + 1) % nu;
            f[n++] = north; f[n++] = b; f[n++] = a;
            int c = (nv - 2) * nu + i, d = (nv - 2) * nu + (i + 1) % nu;
            f[n++] = south; f[n++] = c; f[n++] = d;
        }
        for (int j = 1; j < nv - 1; j++) {
            for (int i = 0; i < nu; i++) {
                int a = (j - 1) * nu + i, b = (j - 1) * nu + (i + 1) % nu, c = j * nu + (i + 1) % nu, d = j * nu + i;
                f[n++] = a; f[n++] = b; f[n++] = c;
                f[n++] = a; f[n++] = c; f[n++] = d;
            }
        }
        writePly(Path.of(args[1]), p, f);
        if (args.length > 2) writeMesh2(Path.of(args[2]), p, f);
        System.out.printf(Locale.ROOT, "%d vertices, %d triangles%n", vertices, triangles);
    }

    private static void writePly(Path out, float[] p, int[] f) throws IOException {
        Path tmp = out.resolveSibling(out.getFileName() + ".tmp");
        try (OutputStream o = new BufferedOutputStream(Files.newOutputStream(tmp), 1 << 20)) {
            String header = "ply\nformat binary_little_endian 1.0\nelement vertex " + p.length / 3
                    + "\nproperty float x\nproperty float y\nproperty float z\nelement face " + f.length / 3
                    + "\nproperty list uchar int vertex_indices\nend_header\n";
            o.write(header.getBytes(java.nio.charset.StandardCharsets.US_ASCII));
            ByteBuffer b = ByteBuffer.allocate(1 << 16).order(ByteOrder.LITTLE_ENDIAN);
            for (float x : p) {
                if (b.remaining() < 4) flush(b, o);
                b.putFloat(x);
            }
            for (int i = 0; i < f.length; i += 3) {
                if (b.remaining() < 13) flush(b, o);
                b.put((byte) 3).putInt(f[i]).putInt(f[i + 1]).putInt(f[i + 2]);
            }
            flush(b, o);
        }
        Files.move(tmp, out, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
    }

    private static void flush(ByteBuffer b, OutputStream o) throws IOException {
        o.write(b.array(), 0, b.position());
        b.clear();
    }

    private static void writeMesh2(Path out, float[] p, int[] f) throws IOException {
        Path tmp = out.resolveSibling(out.getFileName() + ".tmp");
        try (DataOutputStream o = new DataOutputStream(new BufferedOutputStream(Files.newOutputStream(tmp), 1 << 20))) {
            StringBuilder s = new StringBuilder(1 << 16);
            s.append("mesh2 {\n  vertex_vectors { ").append(p.length / 3);
            for (int i = 0; i < p.length; i += 3) {
                // POV-Ray is left-handed as CRT is: the same numbers give the same ball.
                s.append(",\n<").append(p[i]).append(',').append(p[i + 1]).append(',').append(p[i + 2]).append('>');
                if (s.length() > 60_000) { o.writeBytes(s.toString()); s.setLength(0); }
            }
            s.append("\n  }\n  face_indices { ").append(f.length / 3);
            for (int i = 0; i < f.length; i += 3) {
                s.append(",\n<").append(f[i]).append(',').append(f[i + 1]).append(',').append(f[i + 2]).append('>');
                if (s.length() > 60_000) { o.writeBytes(s.toString()); s.setLength(0); }
            }
            s.append("\n  }\n");
            o.writeBytes(s.toString());
        }
        Files.move(tmp, out, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
    }
}
