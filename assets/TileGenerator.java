import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import javax.imageio.ImageIO;

/**
 * Draws assets/tiles.png: 4 × 4 glazed tiles with light grout and a faint speckle, seamless when
 * repeated, for CRT's {@code ImageTexture { file -> "/tiles.png" }}.
 *
 * <pre>
 *   java assets/TileGenerator.java assets/tiles.png [SIZE]     # default 256 x 256
 * </pre>
 * Deterministic: the same command draws the same picture.
 */
public final class TileGenerator {
    public static void main(String[] args) throws IOException {
        if (args.length < 1 || args.length > 2) {
            System.err.println("usage: java TileGenerator.java OUT.png [SIZE]");
            System.exit(2);
        }
        int n = args.length == 2 ? Integer.parseInt(args[1]) : 256;
        int cell = n / 4;
        BufferedImage image = new BufferedImage(n, n, BufferedImage.TYPE_INT_RGB);
        long state = 12345;
        for (int y = 0; y < n; y++) {
            for (int x = 0; x < n; x++) {
                int cx = x / cell, cy = y / cell;
                int ex = Math.min(x % cell, cell - 1 - x % cell), ey = Math.min(y % cell, cell - 1 - y % cell);
                state = state * 6364136223846793005L + 1442695040888963407L;
                double speckle = ((state >>> 40) & 0xFF) / 255.0 * 0.06;
                double r, g, b;
                if (Math.min(ex, ey) < Math.max(1, cell / 24)) {
                    r = g = b = 0.82 - speckle;
                } else {
                    boolean dark = ((cx + cy) & 1) == 0;
                    double edge = Math.min(1, Math.min(ex, ey) / (cell / 8.0));
                    double shade = 0.85 + 0.15 * edge;
                    r = (dark ? 0.55 : 0.9) * shade - speckle;
                    g = (dark ? 0.22 : 0.75) * shade - speckle;
                    b = (dark ? 0.12 : 0.45) * shade - speckle;
                }
                image.setRGB(x, y, (byte8(r) << 16) | (byte8(g) << 8) | byte8(b));
            }
        }
        if (!ImageIO.write(image, "png", new File(args[0]))) throw new IOException("no PNG writer");
    }

    private static int byte8(double v) { return (int) Math.round(Math.max(0, Math.min(1, v)) * 255); }
}
