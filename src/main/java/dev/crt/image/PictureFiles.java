package dev.crt.image;

import dev.crt.scene.Picture;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferByte;
import java.awt.image.PixelInterleavedSampleModel;
import java.awt.image.WritableRaster;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.lang.ref.SoftReference;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Arrays;
import javax.imageio.ImageIO;

/** Reading pictures that scenes use (panoramas, later textures). */
public final class PictureFiles {
    // 64 megapixels (a 16384 x 4096 panorama) already take 256 MB as codes, 768 MB as floats.
    private static final long MAX_PIXELS = 1L << 26;

    /**
     * The last image ImageIO decoded, with the file's bytes, kept softly (the collector drops it
     * before running out of memory): an animation compiles its script again for every frame and the
     * studio on every edit, and decoding a 6000 × 3000 JPEG panorama again took 0.5–1 s each time.
     */
    private static SoftReference<Decoded> last = new SoftReference<>(null);

    private record Decoded(byte[] bytes, Picture picture) {}

    private PictureFiles() {}

    /**
     * Decodes an image file (PNG, JPEG, GIF, BMP, PPM…) into a Picture of stored values in [0, 1]:
     * its 8-bit codes, but for a PPM whose samples are not 8-bit values (maxval 1000, 100…).
     * A file with the same bytes as the last one ImageIO decoded gives the same Picture again
     * (its texels are shared: never written into).
     * @throws IOException with a plain sentence when the file cannot be read or decoded
     */
    public static Picture read(Path file) throws IOException {
        byte[] bytes;
        try {
            bytes = Files.readAllBytes(file);
        } catch (NoSuchFileException e) {
            throw new IOException("file " + file + " does not exist");
        } catch (IOException | RuntimeException e) {
            throw new IOException("cannot read " + file + " (" + e.getClass().getSimpleName() + ")");
        }
        try {
            if (bytes.length >= 2 && bytes[0] == 'P' && bytes[1] == '6') return readPpm(bytes, file);
            Picture known = cached(bytes);
            if (known != null) return known;
            BufferedImage image;
            try {
                image = ImageIO.read(new ByteArrayInputStream(bytes));
            } catch (IOException damaged) {
                // ImageIO's own words ("Error reading PNG image data") say nothing to a user.
                throw new IOException(file + " is damaged or truncated: it cannot be decoded as an image");
            }
            if (image == null) throw new IOException(file + " is not an image CRT can decode (PNG, JPEG, GIF, BMP or PPM)");
            Picture picture = fromImage(image, file);
            remember(new Decoded(bytes, picture));
            return picture;
        } catch (IOException e) {
            throw e;
        } catch (OutOfMemoryError e) {
            throw new IOException(file + " is too large to load into memory");
        } catch (RuntimeException e) {
            // Decoders throw all sorts of unchecked exceptions on damaged files.
            throw new IOException(file + " is damaged or not an image CRT can decode");
        }
    }

    /** The picture decoded last, if its file's bytes were these (whatever the file's name), else null. */
    private static synchronized Picture cached(byte[] bytes) {
        Decoded d = last.get();
        return d != null && Arrays.equals(d.bytes(), bytes) ? d.picture() : null;
    }

    private static synchronized void remember(Decoded d) {
        last = new SoftReference<>(d);
    }

    /** The image's 8-bit codes: what getRGB gives, without its alpha. */
    private static Picture fromImage(BufferedImage image, Path file) throws IOException {
        int w = image.getWidth(), h = image.getHeight();
        checkSize(w, h, file);
        int[] codes = new int[w * h];
        byte[] bgr = plainBgr(image);
        if (bgr != null) {
            // What getRGB would give, read straight from the bytes: 0.05 s instead of 0.6-0.8 s
            // for a 6000 x 3000 JPEG, where getRGB goes through the colour model texel by texel.
            for (int i = 0, j = 0; i < codes.length; i++, j += 3) {
                codes[i] = (bgr[j + 2] & 0xFF) << 16 | (bgr[j + 1] & 0xFF) << 8 | bgr[j] & 0xFF;
            }
            return Picture.ofCodes(w, h, codes);
        }
        for (int y = 0; y < h; y++) image.getRGB(0, y, w, 1, codes, y * w, w);
        for (int i = 0; i < codes.length; i++) codes[i] &= 0xFFFFFF;
        return Picture.ofCodes(w, h, codes);
    }

    /**
     * The bytes of an sRGB image stored as b, g, r per texel, row after row with no gaps (how
     * ImageIO decodes colour JPEGs), or null for any other layout.
     */
    private static byte[] plainBgr(BufferedImage image) {
        if (image.getType() != BufferedImage.TYPE_3BYTE_BGR || !image.getColorModel().getColorSpace().isCS_sRGB()) return null;
        WritableRaster raster = image.getRaster();
        if (raster.getSampleModelTranslateX() != 0 || raster.getSampleModelTranslateY() != 0) return null;
        if (!(raster.getDataBuffer() instanceof DataBufferByte buffer) || buffer.getNumBanks() != 1 || buffer.getOffset() != 0) return null;
        if (!(raster.getSampleModel() instanceof PixelInterleavedSampleModel sm) || sm.getPixelStride() != 3
                || sm.getScanlineStride() != 3 * image.getWidth() || !Arrays.equals(sm.getBandOffsets(), new int[] {2, 1, 0})) {
            return null;
        }
        byte[] data = buffer.getData();
        return data.length == 3 * image.getWidth() * image.getHeight() ? data : null;
    }

    /** Binary PPM (P6): header "P6 width height maxval", comments with '#', 1 or 2 bytes per sample. */
    private static Picture readPpm(byte[] bytes, Path file) throws IOException {
        int[] pos = {2};
        int w = headerNumber(bytes, pos, file), h = headerNumber(bytes, pos, file), max = headerNumber(bytes, pos, file);
        if (max < 1 || max > 65535) throw new IOException(file + " is a PPM with a bad maximum value " + max);
        checkSize(w, h, file);
        int start = pos[0] + 1;
        int bytesPerSample = max < 256 ? 1 : 2;
        long needed = (long) w * h * 3 * bytesPerSample;
        if (start > bytes.length || bytes.length - start < needed) throw new IOException(file + " is a truncated PPM file");
        if (bytesPerSample == 1 && 255 % max == 0) {
            // Samples of 8 bits or fewer whose values v/max are 8-bit codes (maxval 255, 15, 1…):
            // v/max and (v·255/max)/255 round to the same float.
            int[] codes = new int[w * h];
            int step = 255 / max;
            for (int i = 0, j = start; i < codes.length; i++, j += 3) {
                codes[i] = code(bytes[j], step) << 16 | code(bytes[j + 1], step) << 8 | code(bytes[j + 2], step);
            }
            return Picture.ofCodes(w, h, codes);
        }
        float[] rgb = new float[w * h * 3];
        for (int i = 0; i < rgb.length; i++) {
            int v = bytesPerSample == 1 ? bytes[start + i] & 0xFF
                    : ((bytes[start + 2 * i] & 0xFF) << 8) | (bytes[start + 2 * i + 1] & 0xFF);
            rgb[i] = Math.min(1f, v / (float) max);
        }
        return new Picture(w, h, rgb);
    }

    /** The 8-bit code of a PPM sample of {@code 255 / step} levels; a value past the maximum reads as 1. */
    private static int code(byte sample, int step) {
        return Math.min(255, (sample & 0xFF) * step);
    }

    private static int headerNumber(byte[] bytes, int[] pos, Path file) throws IOException {
        int i = pos[0];
        while (i < bytes.length) {
            if (bytes[i] == '#') {
                while (i < bytes.length && bytes[i] != '\n') i++;
            } else if (Character.isWhitespace(bytes[i])) {
                i++;
            } else {
                break;
            }
        }
        int startDigits = i;
        long value = 0;
        while (i < bytes.length && bytes[i] >= '0' && bytes[i] <= '9' && i - startDigits < 10) value = value * 10 + (bytes[i++] - '0');
        if (i == startDigits || value > Integer.MAX_VALUE) {
            throw new IOException(file + " has a damaged PPM header near byte " + i + " ("
                    + new String(bytes, startDigits, Math.min(8, bytes.length - startDigits), StandardCharsets.US_ASCII).strip() + ")");
        }
        pos[0] = i;
        return (int) value;
    }

    private static void checkSize(int w, int h, Path file) throws IOException {
        if (w < 1 || h < 1 || (long) w * h > MAX_PIXELS) throw new IOException(file + " has an unusable size " + w + "x" + h);
    }
}
