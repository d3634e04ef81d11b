package dev.crt.image;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.util.Iterator;
import java.util.Map;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageTypeSpecifier;
import javax.imageio.metadata.IIOInvalidTreeException;
import javax.imageio.metadata.IIOMetadata;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageOutputStream;

/** 8-bit RGB PNG through javax.imageio, with one tEXt chunk per entry of the text map. */
final class PngWriter implements ImageWriter {
    static final PngWriter INSTANCE = new PngWriter();
    private static final String FORMAT = "javax_imageio_png_1.0";

    @Override
    public void write(FrameBuffer image, double gamma, Map<String, String> text, OutputStream out) throws IOException {
        int w = image.width(), h = image.height();
        byte[] bytes = ImageFiles.encode8(image, gamma);
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        int[] argb = new int[w];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int i = (y * w + x) * 3;
                argb[x] = (bytes[i] & 0xff) << 16 | (bytes[i + 1] & 0xff) << 8 | (bytes[i + 2] & 0xff);
            }
            img.setRGB(0, y, w, 1, argb, 0, w);
        }
        Iterator<javax.imageio.ImageWriter> writers = ImageIO.getImageWritersByFormatName("png");
        if (!writers.hasNext()) throw new IOException("this Java runtime has no PNG writer");
        javax.imageio.ImageWriter writer = writers.next();
        try (ImageOutputStream ios = ImageIO.createImageOutputStream(out)) {
            writer.setOutput(ios);
            IIOMetadata meta = writer.getDefaultImageMetadata(ImageTypeSpecifier.createFromRenderedImage(img),
                    writer.getDefaultWriteParam());
            if (text != null && !text.isEmpty()) addText(meta, text);
            writer.write(null, new IIOImage(img, null, meta), writer.getDefaultWriteParam());
            ios.flush();
        } finally {
            writer.dispose();
        }
    }

    private static void addText(IIOMetadata meta, Map<String, String> text) throws IOException {
        IIOMetadataNode textNode = new IIOMetadataNode("tEXt");
        for (Map.Entry<String, String> e : text.entrySet()) {
            if (e.getValue() == null || e.getValue().isEmpty()) continue;
            IIOMetadataNode entry = new IIOMetadataNode("tEXtEntry");
            entry.setAttribute("keyword", e.getKey());
            entry.setAttribute("value", latin1(e.getValue()));
            textNode.appendChild(entry);
        }
        IIOMetadataNode root = new IIOMetadataNode(FORMAT);
        root.appendChild(textNode);
        try {
            meta.mergeTree(FORMAT, root);
        } catch (IIOInvalidTreeException e) {
            throw new IOException("cannot add PNG text chunks: " + e.getMessage(), e);
        }
    }

    /** tEXt chunks hold Latin-1; characters outside it become '?'. */
    private static String latin1(String s) {
        StringBuilder b = new StringBuilder(s.length());
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            b.append(c < 256 ? c : '?');
        }
        return b.toString();
    }
}
