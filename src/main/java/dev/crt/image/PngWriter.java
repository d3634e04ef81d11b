package dev.crt.image;

import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.Map;
import java.util.zip.CRC32;
import java.util.zip.Deflater;
import java.util.zip.DeflaterOutputStream;

/**
 * 8-bit RGB PNG with one tEXt chunk per entry of the text map, encoded directly (IHDR, tEXt, IDAT
 * with the Up filter, IEND). The format is small enough that writing it by hand is simpler than
 * javax.imageio and avoids ImageIO's start-up cost, which dominated writing a 1280×720 image in a
 * fresh process (about 0.6 s through ImageIO, about 0.1 s this way). Any PNG reader, ImageIO
 * included, reads the result back.
 */
final class PngWriter implements ImageWriter {
    static final PngWriter INSTANCE = new PngWriter();
    private static final byte[] SIGNATURE = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    private static final int FILTER_UP = 2;

    @Override
    public void write(FrameBuffer image, double gamma, Map<String, String> text, OutputStream out) throws IOException {
        int w = image.width(), h = image.height();
        out.write(SIGNATURE);
        ByteArrayOutputStream header = new ByteArrayOutputStream(13);
        DataOutputStream d = new DataOutputStream(header);
        d.writeInt(w);
        d.writeInt(h);
        d.writeByte(8);
        d.writeByte(2);
        d.writeByte(0);
        d.writeByte(0);
        d.writeByte(0);
        chunk(out, "IHDR", header.toByteArray());
        if (text != null) {
            for (Map.Entry<String, String> e : text.entrySet()) {
                if (e.getValue() == null || e.getValue().isEmpty()) continue;
                String keyword = e.getKey().length() > 79 ? e.getKey().substring(0, 79) : e.getKey();
                byte[] key = latin1(keyword), value = latin1(e.getValue());
                byte[] data = new byte[key.length + 1 + value.length];
                System.arraycopy(key, 0, data, 0, key.length);
                System.arraycopy(value, 0, data, key.length + 1, value.length);
                chunk(out, "tEXt", data);
            }
        }
        compress(image, gamma, out);
        chunk(out, "IEND", new byte[0]);
    }

    /**
     * Scanlines filtered with Up (each byte minus the one above), deflated fast and written as
     * IDAT chunks of at most 64 KiB as they fill: two rows and one chunk are all the memory it
     * needs, whatever the size of the image.
     */
    private static void compress(FrameBuffer image, double gamma, OutputStream out) throws IOException {
        int stride = image.width() * 3;
        GammaEncoder encoder = new GammaEncoder(gamma);
        Deflater deflater = new Deflater(Deflater.BEST_SPEED);
        try (DeflaterOutputStream z = new DeflaterOutputStream(new IdatChunks(out), deflater, 1 << 16)) {
            byte[] above = new byte[stride];
            byte[] row = new byte[stride];
            byte[] line = new byte[stride + 1];
            line[0] = FILTER_UP;
            for (int y = 0; y < image.height(); y++) {
                ImageFiles.encodeRow(image, y, encoder, row);
                for (int i = 0; i < stride; i++) line[i + 1] = (byte) (row[i] - above[i]);
                z.write(line);
                byte[] swap = above;
                above = row;
                row = swap;
            }
        } finally {
            deflater.end();
        }
    }

    /** Collects the compressed stream into IDAT chunks of up to 64 KiB. */
    private static final class IdatChunks extends OutputStream {
        private final OutputStream out;
        private final byte[] buffer = new byte[1 << 16];
        private int used;

        IdatChunks(OutputStream out) { this.out = out; }

        @Override
        public void write(int b) throws IOException {
            if (used == buffer.length) emit();
            buffer[used++] = (byte) b;
        }

        @Override
        public void write(byte[] b, int off, int len) throws IOException {
            while (len > 0) {
                if (used == buffer.length) emit();
                int n = Math.min(len, buffer.length - used);
                System.arraycopy(b, off, buffer, used, n);
                used += n;
                off += n;
                len -= n;
            }
        }

        private void emit() throws IOException {
            byte[] data = java.util.Arrays.copyOf(buffer, used);
            chunk(out, "IDAT", data);
            used = 0;
        }

        /** Writes the last chunk but leaves {@code out} open for IEND. */
        @Override
        public void close() throws IOException {
            if (used > 0) emit();
        }
    }

    private static void chunk(OutputStream out, String type, byte[] data) throws IOException {
        byte[] t = type.getBytes(StandardCharsets.US_ASCII);
        CRC32 crc = new CRC32();
        crc.update(t);
        crc.update(data);
        DataOutputStream d = new DataOutputStream(out);
        d.writeInt(data.length);
        d.write(t);
        d.write(data);
        d.writeInt((int) crc.getValue());
    }

    /** tEXt chunks hold Latin-1; characters outside it become '?'. Keywords are 1–79 characters. */
    private static byte[] latin1(String s) {
        byte[] b = new byte[s.length()];
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            b[i] = (byte) (c < 256 && c != 0 ? c : '?');
        }
        return b;
    }
}
