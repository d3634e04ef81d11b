package dev.crt.image;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Map;

/** Reading and writing image files; the format follows the file name's extension. */
public final class ImageFiles {
    private ImageFiles() {}

    /**
     * Writes {@code image} to {@code out} (.png, .ppm or .pfm) through a temporary file in the same
     * folder that is renamed into place, so a failure never leaves a half-written file.
     * PNG and PPM are encoded as clamp(c,0,1)^(1/gamma) rounded to 8 bits; PFM stores linear floats.
     * {@code text} becomes PNG text chunks (Title, Author, …) and is ignored by the other formats.
     */
    public static void write(FrameBuffer image, Path out, double gamma, Map<String, String> text) throws IOException {
        ImageWriter writer = writerFor(out);
        writeAtomically(out, stream -> writer.write(image, gamma, text, stream));
    }

    /**
     * Writes a one-channel map (a depth pass: distances, +∞ where nothing was hit) as a greyscale
     * PFM ("Pf", little-endian floats, rows bottom to top), atomically like {@link #write}.
     * {@code values} holds {@code width × height} values, rows top to bottom.
     */
    public static void writeGreyPfm(float[] values, int width, int height, Path out) throws IOException {
        if (values.length != width * height) throw new IllegalArgumentException("expected " + width * height + " values");
        writeAtomically(out, stream -> PfmWriter.writeGrey(values, width, height, stream));
    }

    /** Writes through {@link AtomicFile}, after checking the folder, with the image writers' messages. */
    private static void writeAtomically(Path out, AtomicFile.Body body) throws IOException {
        Path target = out.toAbsolutePath();
        Path folder = target.getParent();
        if (folder == null || !Files.exists(folder)) {
            throw new IOException("cannot write " + out + ": the folder " + folder + " does not exist");
        }
        if (!Files.isDirectory(folder)) {
            throw new IOException("cannot write " + out + ": " + folder + " is a file, not a folder");
        }
        try {
            AtomicFile.write(target, body);
        } catch (IOException e) {
            throw new IOException("cannot write " + out + ": " + describe(e), e);
        }
    }

    private static String describe(IOException e) {
        if (e instanceof java.nio.file.AccessDeniedException) return "permission denied";
        if (e instanceof java.nio.file.NoSuchFileException) return "the folder does not exist";
        return e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
    }

    /**
     * Whether the file {@code out} names stores each channel clamped to [0, 1] (.png, .ppm; not .pfm,
     * which holds linear light); false for a name no writer takes.
     */
    public static boolean clampsColours(Path out) {
        try {
            return writerFor(out).clamps();
        } catch (IOException e) {
            return false;
        }
    }

    private static ImageWriter writerFor(Path out) throws IOException {
        String name = out.getFileName() == null ? "" : out.getFileName().toString();
        int dot = name.lastIndexOf('.');
        String ext = dot < 0 ? "" : name.substring(dot).toLowerCase(Locale.ROOT);
        return switch (ext) {
            case ".png" -> PngWriter.INSTANCE;
            case ".ppm" -> PpmWriter.INSTANCE;
            case ".pfm" -> PfmWriter.INSTANCE;
            default -> throw new IOException(ext.isEmpty()
                    ? "the image file name '" + name + "' has no extension: use .png, .ppm or .pfm"
                    : "unsupported image type '" + ext + "': use .png, .ppm or .pfm");
        };
    }

    /** The 8-bit value of a linear channel: round(clamp(c, 0, 1)^(1/gamma)·255). */
    public static int toByte(double c, double gamma) {
        double v = c > 0 ? Math.min(c, 1) : 0;
        if (gamma != 1 && v > 0 && v < 1) v = Math.pow(v, 1 / gamma);
        return (int) Math.round(v * 255);
    }

    /**
     * Row {@code y} of the image as gamma-encoded bytes, r, g, b per pixel, into {@code row}: the
     * writers encode row by row, so writing needs no second full-size copy of the image.
     */
    static void encodeRow(FrameBuffer image, int y, GammaEncoder encoder, byte[] row) {
        encoder.encode(image.data(), y * image.width() * 3, row);
    }
}
