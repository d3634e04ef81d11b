package dev.crt.image;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.Map;

/** Portable float map: "PF", little-endian (scale −1.0) linear floats, unclamped, rows bottom to top. */
final class PfmWriter implements ImageWriter {
    static final PfmWriter INSTANCE = new PfmWriter();
    /** Floats per write. */
    private static final int PIECE = 1 << 16;

    /** PFM holds the linear colours as they are. */
    @Override
    public boolean clamps() {
        return false;
    }

    @Override
    public void write(FrameBuffer image, double gamma, Map<String, String> text, OutputStream out) throws IOException {
        int w = image.width(), h = image.height();
        out.write(("PF\n" + w + " " + h + "\n-1.0\n").getBytes(StandardCharsets.US_ASCII));
        // A row of a very wide image can hold more bytes than an array: write it in pieces.
        ByteBuffer piece = ByteBuffer.allocate(4 * Math.min(w * 3, PIECE)).order(ByteOrder.LITTLE_ENDIAN);
        float[] data = image.data();
        for (int y = h - 1; y >= 0; y--) {
            for (int i = y * w * 3, end = i + w * 3; i < end; ) {
                piece.clear();
                while (i < end && piece.hasRemaining()) piece.putFloat(data[i++]);
                out.write(piece.array(), 0, piece.position());
            }
        }
    }

    /** A one-channel map as "Pf": little-endian floats, rows bottom to top; {@code values} rows top to bottom. */
    static void writeGrey(float[] values, int w, int h, OutputStream out) throws IOException {
        out.write(("Pf\n" + w + " " + h + "\n-1.0\n").getBytes(StandardCharsets.US_ASCII));
        ByteBuffer row = ByteBuffer.allocate(4 * w).order(ByteOrder.LITTLE_ENDIAN);
        for (int y = h - 1; y >= 0; y--) {
            row.clear();
            for (int x = 0; x < w; x++) row.putFloat(values[y * w + x]);
            out.write(row.array(), 0, row.position());
        }
    }
}
