package dev.crt.image;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.Map;

/** Binary PPM (P6, maxval 255), gamma-encoded 8-bit RGB, rows top to bottom. */
final class PpmWriter implements ImageWriter {
    static final PpmWriter INSTANCE = new PpmWriter();

    @Override
    public void write(FrameBuffer image, double gamma, Map<String, String> text, OutputStream out) throws IOException {
        out.write(("P6\n" + image.width() + " " + image.height() + "\n255\n").getBytes(StandardCharsets.US_ASCII));
        GammaEncoder encoder = new GammaEncoder(gamma);
        byte[] row = new byte[image.width() * 3];
        for (int y = 0; y < image.height(); y++) {
            ImageFiles.encodeRow(image, y, encoder, row);
            out.write(row);
        }
    }
}
