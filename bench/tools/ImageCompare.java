import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.util.Locale;
import javax.imageio.ImageIO;

/**
 * Compares two images of the same size, or prints one pixel.
 *
 * <pre>
 *   java bench/tools/ImageCompare.java A.png B.png        # difference statistics
 *   java bench/tools/ImageCompare.java A.png X Y          # the pixel (X, Y) of A.png
 * </pre>
 * Run as a single-file source program: no build step, no dependency beyond the JDK.
 */
public final class ImageCompare {
    public static void main(String[] args) throws IOException {
        if (args.length == 3) {
            BufferedImage a = read(args[0]);
            int rgb = a.getRGB(Integer.parseInt(args[1]), Integer.parseInt(args[2]));
            System.out.printf("%d %d %d%n", (rgb >> 16) & 255, (rgb >> 8) & 255, rgb & 255);
            return;
        }
        if (args.length != 2) {
            System.err.println("usage: ImageCompare A.png B.png | ImageCompare A.png X Y");
            System.exit(2);
        }
        BufferedImage a = read(args[0]);
        BufferedImage b = read(args[1]);
        if (a.getWidth() != b.getWidth() || a.getHeight() != b.getHeight()) {
            System.err.printf("sizes differ: %dx%d and %dx%d%n", a.getWidth(), a.getHeight(), b.getWidth(), b.getHeight());
            System.exit(1);
        }
        long sum = 0;
        long differing = 0;
        int max = 0;
        long over8 = 0;
        long over32 = 0;
        long pixels = (long) a.getWidth() * a.getHeight();
        for (int y = 0; y < a.getHeight(); y++) {
            for (int x = 0; x < a.getWidth(); x++) {
                int p = a.getRGB(x, y);
                int q = b.getRGB(x, y);
                int worst = 0;
                for (int shift = 0; shift <= 16; shift += 8) {
                    int d = Math.abs(((p >> shift) & 255) - ((q >> shift) & 255));
                    sum += d;
                    worst = Math.max(worst, d);
                }
                max = Math.max(max, worst);
                if (worst > 0) differing++;
                if (worst > 8) over8++;
                if (worst > 32) over32++;
            }
        }
        System.out.printf(Locale.ROOT,
                "mean |difference| per channel %.4f of 255, largest %d; pixels that differ at all: %.3f%%,"
                        + " by more than 8: %.3f%%, by more than 32: %.3f%%%n",
                sum / (3.0 * pixels), max, 100.0 * differing / pixels, 100.0 * over8 / pixels, 100.0 * over32 / pixels);
    }

    private static BufferedImage read(String path) throws IOException {
        BufferedImage image = ImageIO.read(new File(path));
        if (image == null) {
            throw new IOException("not a readable image: " + path);
        }
        return image;
    }
}
