package dev.crt.image;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.Map;
import org.junit.jupiter.api.Test;

class PfmWriterTest {
    @Test
    void rowsLongerThanOneWriteKeepEveryFloatInPlace() throws IOException {
        int w = 70_001, h = 2;
        FrameBuffer fb = new FrameBuffer(w, h);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) fb.set(x, y, x + 0.25, -y - 0.5, x * 1e3 + y);
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        PfmWriter.INSTANCE.write(fb, 2.2, Map.of(), out);
        byte[] bytes = out.toByteArray();
        int header = ("PF\n" + w + " " + h + "\n-1.0\n").getBytes(StandardCharsets.US_ASCII).length;
        assertThat(bytes.length - header).isEqualTo(w * h * 3 * 4);
        ByteBuffer b = ByteBuffer.wrap(bytes, header, bytes.length - header).order(ByteOrder.LITTLE_ENDIAN);
        for (int y = h - 1; y >= 0; y--) {
            for (int x = 0; x < w; x++) {
                for (int c = 0; c < 3; c++) assertThat(b.getFloat()).isEqualTo(fb.get(x, y, c));
            }
        }
    }

    /** A row of more than 2^31 bytes (the widest images CRT renders have 2^28 pixels in one row); the test JVM has a 4 GiB heap (pom.xml). */
    @Test
    void aRowTooLongForOneArrayIsWritten() throws IOException {
        int w = 178_956_971;
        FrameBuffer fb = new FrameBuffer(w, 1);
        fb.set(w - 1, 0, 1, 2, 3);
        long[] written = {0};
        byte[] last = new byte[12];
        OutputStream counter = new OutputStream() {
            @Override
            public void write(int b) {
                System.arraycopy(last, 1, last, 0, 11);
                last[11] = (byte) b;
                written[0]++;
            }

            @Override
            public void write(byte[] b, int off, int len) {
                for (int i = Math.max(0, len - 12); i < len; i++) write(b[off + i]);
                written[0] += Math.max(0, len - 12);
            }
        };
        PfmWriter.INSTANCE.write(fb, 1, Map.of(), counter);
        long header = ("PF\n" + w + " 1\n-1.0\n").length();
        assertThat(written[0]).isEqualTo(header + 12L * w);
        ByteBuffer tail = ByteBuffer.wrap(last).order(ByteOrder.LITTLE_ENDIAN);
        assertThat(new float[] {tail.getFloat(), tail.getFloat(), tail.getFloat()}).containsExactly(1f, 2f, 3f);
    }
}
