package dev.crt.image;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferByte;
import java.awt.image.IndexColorModel;
import java.awt.image.Raster;
import java.awt.image.WritableRaster;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.Iterator;
import java.util.concurrent.ThreadLocalRandom;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageTypeSpecifier;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.metadata.IIOMetadata;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;

/**
 * Writes an animated GIF that loops forever (or plays once). All frames share one palette chosen by median cut over
 * every frame and are dithered with Floyd–Steinberg; each frame after the first stores only the
 * rectangle that changed, with unchanged pixels transparent, which keeps the file small.
 */
public final class GifWriter {
    /** Palette entries for colours; the last of the 256 slots marks pixels that did not change. */
    private static final int COLOURS = 255;
    private static final int UNCHANGED = 255;

    /** An animation's frames, in order; each is read twice (once to choose the palette, once to encode). */
    public interface Frames {
        int count();

        RgbImage read(int index) throws IOException;
    }

    private GifWriter() {}

    /**
     * Writes {@code frames} to {@code out} at {@code fps} frames per second, through a temporary file
     * in the same folder that is renamed into place, so a failure leaves no half-written GIF.
     * @throws IOException when a frame cannot be read, frames differ in size, or {@code out} cannot be written
     */
    public static void write(Path out, Frames frames, double fps) throws IOException {
        write(out, frames, fps, true);
    }

    /**
     * As {@link #write(Path, Frames, double)}; {@code loop} false leaves out the NETSCAPE2.0
     * application extension, so viewers play the animation once and stop on its last frame.
     */
    public static void write(Path out, Frames frames, double fps, boolean loop) throws IOException {
        if (frames.count() < 1) throw new IllegalArgumentException("a GIF needs at least one frame");
        if (!(fps > 0)) throw new IllegalArgumentException("frames per second must be positive, got " + fps);
        Palette palette = choosePalette(frames);
        Path dir = out.toAbsolutePath().getParent();
        // Named like ImageFiles' temporary files, so one rule finds what a killed run left behind.
        Path temp = dir.resolve("." + out.getFileName() + ".tmp-"
                + Long.toHexString(ThreadLocalRandom.current().nextLong() & Long.MAX_VALUE));
        try {
            encode(temp, frames, palette, fps, loop);
            try {
                Files.move(temp, out, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(temp, out, StandardCopyOption.REPLACE_EXISTING);
            }
        } finally {
            Files.deleteIfExists(temp);
        }
    }

    /** The delay before frame {@code index} advances, in hundredths of a second, rounded so the total stays exact. */
    static int delayCentiseconds(int index, double fps) {
        return (int) (Math.round(100 * (index + 1) / fps) - Math.round(100 * index / fps));
    }

    private static Palette choosePalette(Frames frames) throws IOException {
        MedianCutQuantizer quantizer = new MedianCutQuantizer();
        for (int i = 0; i < frames.count(); i++) quantizer.add(frames.read(i).rgb());
        return quantizer.palette(COLOURS);
    }

    private static void encode(Path temp, Frames frames, Palette palette, double fps, boolean loop) throws IOException {
        Iterator<ImageWriter> writers = ImageIO.getImageWritersByFormatName("gif");
        if (!writers.hasNext()) throw new IOException("this Java runtime has no GIF writer");
        ImageWriter writer = writers.next();
        IndexColorModel opaque = colourModel(palette, -1);
        // The writer sets the transparency flag from the colour model, not from the metadata alone.
        IndexColorModel withUnchanged = colourModel(palette, UNCHANGED);
        try (OutputStream file = new BufferedOutputStream(
                     Files.newOutputStream(temp, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE), 1 << 16);
             ImageOutputStream stream = new MemoryCacheImageOutputStream(file)) {
            writer.setOutput(stream);
            RgbImage first = frames.read(0);
            writer.prepareWriteSequence(streamMetadata(writer, palette, first.width(), first.height()));
            byte[] shown = null;
            for (int i = 0; i < frames.count(); i++) {
                RgbImage frame = i == 0 ? first : frames.read(i);
                if (frame.width() != first.width() || frame.height() != first.height()) {
                    throw new IOException("frame " + (i + 1) + " of the GIF is " + frame.width() + "×" + frame.height()
                            + " but the first is " + first.width() + "×" + first.height());
                }
                byte[] indices = FloydSteinberg.dither(frame.rgb(), frame.width(), frame.height(), palette);
                Patch patch = shown == null ? Patch.whole(indices, frame.width(), frame.height())
                        : Patch.changes(shown, indices, frame.width(), frame.height());
                BufferedImage image = patch.image(i == 0 ? opaque : withUnchanged);
                writer.writeToSequence(new IIOImage(image, null,
                        frameMetadata(writer, image, patch, i == 0, loop, delayCentiseconds(i, fps))), null);
                shown = indices;
            }
            writer.endWriteSequence();
        } finally {
            writer.dispose();
        }
    }

    private static IndexColorModel colourModel(Palette palette, int transparent) {
        byte[] r = new byte[256];
        byte[] g = new byte[256];
        byte[] b = new byte[256];
        for (int i = 0; i < palette.size(); i++) {
            int c = palette.colour(i);
            r[i] = (byte) Palette.red(c);
            g[i] = (byte) Palette.green(c);
            b[i] = (byte) Palette.blue(c);
        }
        return new IndexColorModel(8, 256, r, g, b, transparent);
    }

    /** The logical screen and the one global colour table, so frames need no colour table of their own. */
    private static IIOMetadata streamMetadata(ImageWriter writer, Palette palette, int width, int height) throws IOException {
        IIOMetadata metadata = writer.getDefaultStreamMetadata(writer.getDefaultWriteParam());
        String format = metadata.getNativeMetadataFormatName();
        IIOMetadataNode root = (IIOMetadataNode) metadata.getAsTree(format);
        IIOMetadataNode screen = child(root, "LogicalScreenDescriptor");
        screen.setAttribute("logicalScreenWidth", Integer.toString(width));
        screen.setAttribute("logicalScreenHeight", Integer.toString(height));
        screen.setAttribute("colorResolution", "8");
        screen.setAttribute("pixelAspectRatio", "0");
        IIOMetadataNode table = child(root, "GlobalColorTable");
        while (table.getFirstChild() != null) table.removeChild(table.getFirstChild());
        table.setAttribute("sizeOfGlobalColorTable", "256");
        table.setAttribute("backgroundColorIndex", "0");
        table.setAttribute("sortFlag", "FALSE");
        for (int i = 0; i < 256; i++) {
            int c = i < palette.size() ? palette.colour(i) : 0;
            IIOMetadataNode entry = new IIOMetadataNode("ColorTableEntry");
            entry.setAttribute("index", Integer.toString(i));
            entry.setAttribute("red", Integer.toString(Palette.red(c)));
            entry.setAttribute("green", Integer.toString(Palette.green(c)));
            entry.setAttribute("blue", Integer.toString(Palette.blue(c)));
            table.appendChild(entry);
        }
        metadata.setFromTree(format, root);
        return metadata;
    }

    private static IIOMetadata frameMetadata(ImageWriter writer, BufferedImage image, Patch patch, boolean first,
            boolean loop, int delay) throws IOException {
        ImageWriteParam param = writer.getDefaultWriteParam();
        IIOMetadata metadata = writer.getDefaultImageMetadata(ImageTypeSpecifier.createFromRenderedImage(image), param);
        String format = metadata.getNativeMetadataFormatName();
        IIOMetadataNode root = (IIOMetadataNode) metadata.getAsTree(format);

        // The default metadata carries a generic local colour table; without it frames use the global one.
        IIOMetadataNode local = child(root, "LocalColorTable");
        root.removeChild(local);

        IIOMetadataNode control = child(root, "GraphicControlExtension");
        // Each frame draws over the last, so only changed pixels need storing.
        control.setAttribute("disposalMethod", "doNotDispose");
        control.setAttribute("userInputFlag", "FALSE");
        control.setAttribute("transparentColorFlag", first ? "FALSE" : "TRUE");
        control.setAttribute("transparentColorIndex", Integer.toString(first ? 0 : UNCHANGED));
        control.setAttribute("delayTime", Integer.toString(delay));

        IIOMetadataNode descriptor = child(root, "ImageDescriptor");
        descriptor.setAttribute("imageLeftPosition", Integer.toString(patch.x()));
        descriptor.setAttribute("imageTopPosition", Integer.toString(patch.y()));
        descriptor.setAttribute("imageWidth", Integer.toString(patch.width()));
        descriptor.setAttribute("imageHeight", Integer.toString(patch.height()));
        descriptor.setAttribute("interlaceFlag", "FALSE");

        if (first && loop) {
            IIOMetadataNode extensions = child(root, "ApplicationExtensions");
            IIOMetadataNode netscape = new IIOMetadataNode("ApplicationExtension");
            netscape.setAttribute("applicationID", "NETSCAPE");
            netscape.setAttribute("authenticationCode", "2.0");
            // Sub-block 1 holds the loop count, little-endian; 0 loops forever.
            netscape.setUserObject(new byte[] {1, 0, 0});
            extensions.appendChild(netscape);
        }
        metadata.setFromTree(format, root);
        return metadata;
    }

    private static IIOMetadataNode child(IIOMetadataNode parent, String name) {
        for (int i = 0; i < parent.getLength(); i++) {
            if (parent.item(i).getNodeName().equals(name)) return (IIOMetadataNode) parent.item(i);
        }
        IIOMetadataNode node = new IIOMetadataNode(name);
        parent.appendChild(node);
        return node;
    }

    /** The rectangle of a frame that is stored, as palette indices. */
    private record Patch(int x, int y, int width, int height, byte[] indices) {
        static Patch whole(byte[] indices, int width, int height) {
            return new Patch(0, 0, width, height, indices);
        }

        /** The bounding box of the pixels that differ from {@code shown}, with the unchanged ones inside it transparent. */
        static Patch changes(byte[] shown, byte[] next, int width, int height) {
            int minX = width, minY = height, maxX = -1, maxY = -1;
            for (int y = 0; y < height; y++) {
                for (int x = 0; x < width; x++) {
                    if (shown[y * width + x] != next[y * width + x]) {
                        minX = Math.min(minX, x);
                        maxX = Math.max(maxX, x);
                        minY = Math.min(minY, y);
                        maxY = Math.max(maxY, y);
                    }
                }
            }
            if (maxX < 0) return new Patch(0, 0, 1, 1, new byte[] {(byte) UNCHANGED});
            int w = maxX - minX + 1;
            int h = maxY - minY + 1;
            byte[] patch = new byte[w * h];
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    int i = (minY + y) * width + minX + x;
                    patch[y * w + x] = shown[i] == next[i] ? (byte) UNCHANGED : next[i];
                }
            }
            return new Patch(minX, minY, w, h, patch);
        }

        BufferedImage image(IndexColorModel colours) {
            WritableRaster raster = Raster.createInterleavedRaster(new DataBufferByte(indices, indices.length),
                    width, height, width, 1, new int[] {0}, null);
            return new BufferedImage(colours, raster, false, null);
        }
    }
}
