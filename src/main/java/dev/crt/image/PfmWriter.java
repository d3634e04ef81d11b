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

    @Override
    public void write(FrameBuffer image, double gamma, Map<String, String> text, OutputStream out) throws IOException {
        int w = image.width(), h = image.height();
        out.write(("PF\n" + w + " " + h + "\n-1.0\n").getBytes(StandardCharsets.US_ASCII));
        ByteBuffer row = ByteBuffer.allocate(w * 3 * 4).order(ByteOrder.LITTLE_ENDIAN);
        float[] data = image.data();
        for (int y = h - 1; y >= 0; y--) {
            row.clear();
            for (int i = y * w * 3, end = i + w * 3; i < end; i++) row.putFloat(data[i]);
            out.write(row.array(), 0, row.position());
        }
    }
}
