import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import javax.imageio.ImageIO;

/**
 * Draws assets/sky.png: an equirectangular panorama (sky gradient, sun with glow, clouds,
 * distant hills and a ground plain) for CRT's {@code Background { image -> ... }}.
 *
 * <pre>
 *   java assets/SkyGenerator.java assets/sky.png [WIDTH]     # default 1024 x 512
 * </pre>
 * Deterministic: the same command draws the same picture. The mapping is the one of CRT's
 * rendering model with angle 0: column u looks along azimuth atan2(x, z) = 2π(u − 0.5), so the
 * middle column faces +z (into the screen), and row v looks at elevation π(0.5 − v).
 * Clouds and ground detail come from 3D noise on the view direction, so the left and right edges
 * meet without a seam.
 */
public final class SkyGenerator {
    private static final double[] SUN = direction(Math.toRadians(-35), Math.toRadians(24));

    public static void main(String[] args) throws IOException {
        if (args.length < 1 || args.length > 2) {
            System.err.println("usage: java SkyGenerator.java OUT.png [WIDTH]");
            System.exit(2);
        }
        int width = args.length == 2 ? Integer.parseInt(args[1]) : 1024;
        int height = width / 2;
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        for (int row = 0; row < height; row++) {
            double elevation = Math.PI * (0.5 - (row + 0.5) / height);
            for (int col = 0; col < width; col++) {
                double azimuth = 2 * Math.PI * ((col + 0.5) / width - 0.5);
                double[] c = shade(azimuth, elevation);
                image.setRGB(col, row, (byte8(c[0]) << 16) | (byte8(c[1]) << 8) | byte8(c[2]));
            }
        }
        File out = new File(args[0]);
        if (!ImageIO.write(image, "png", out)) {
            throw new IOException("no PNG writer");
        }
        System.out.printf("wrote %s (%d x %d)%n", out, width, height);
    }

    /** The colour seen along one direction, in display values 0..1. */
    private static double[] shade(double azimuth, double elevation) {
        double[] d = direction(azimuth, elevation);
        double hills = 0.035 + 0.025 * Math.sin(3 * azimuth + 1.0) + 0.015 * Math.sin(7 * azimuth + 0.3)
                + 0.012 * (fbm(d[0] * 6, 0.5, d[2] * 6, 4) - 0.5);
        if (elevation < 0) {
            return ground(d, elevation);
        }
        if (elevation < hills) {
            // far hills: bluish with haze, a little darker towards their foot
            double haze = 0.55 + 0.3 * elevation / hills;
            double n = fbm(d[0] * 40, d[1] * 40, d[2] * 40, 3);
            return mix(new double[] {0.28 + 0.08 * n, 0.36 + 0.08 * n, 0.32 + 0.05 * n},
                    new double[] {0.72, 0.78, 0.86}, haze * 0.6);
        }
        double e = elevation / (Math.PI / 2);
        double[] horizon = {0.86, 0.89, 0.95};
        double[] zenith = {0.16, 0.32, 0.72};
        double[] sky = mix(horizon, zenith, Math.pow(e, 0.55));
        double cosSun = dot(d, SUN);
        double angle = Math.acos(Math.max(-1, Math.min(1, cosSun)));
        double glow = 0.55 * Math.exp(-angle / 0.12) + 0.18 * Math.exp(-angle / 0.5);
        sky = add(sky, new double[] {glow, glow * 0.9, glow * 0.7});
        // clouds on a flat layer above the viewer
        double y = Math.max(d[1], 0.02);
        double cx = d[0] / y * 0.6;
        double cz = d[2] / y * 0.6;
        double density = fbm(cx + 11.3, 0.0, cz - 4.1, 5);
        double cover = smooth(0.54, 0.76, density) * smooth(0.0, 0.25, elevation);
        double lit = 0.82 + 0.18 * smooth(0.4, 1.0, cosSun) + 0.12 * (density - 0.5);
        double[] cloud = {lit, lit * 0.98, lit * 0.95};
        sky = mix(sky, cloud, cover * 0.85);
        if (angle < 0.03) {
            sky = mix(sky, new double[] {1.0, 0.98, 0.9}, smooth(0.03, 0.022, angle));
        }
        return sky;
    }

    private static double[] ground(double[] d, double elevation) {
        double depth = -elevation / (Math.PI / 2);
        double y = Math.min(d[1], -0.02);
        double gx = d[0] / -y;
        double gz = d[2] / -y;
        double n = fbm(gx * 2.5, 3.7, gz * 2.5, 5);
        double[] grass = {0.22 + 0.12 * n, 0.34 + 0.14 * n, 0.14 + 0.06 * n};
        double[] haze = {0.62, 0.68, 0.72};
        return mix(haze, grass, smooth(0.0, 0.18, depth));
    }

    private static double[] direction(double azimuth, double elevation) {
        double c = Math.cos(elevation);
        return new double[] {c * Math.sin(azimuth), Math.sin(elevation), c * Math.cos(azimuth)};
    }

    /** Fractal sum of value noise, about 0..1. */
    private static double fbm(double x, double y, double z, int octaves) {
        double sum = 0;
        double amplitude = 0.5;
        double total = 0;
        for (int i = 0; i < octaves; i++) {
            sum += amplitude * noise(x, y, z);
            total += amplitude;
            x *= 2.03;
            y *= 2.03;
            z *= 2.03;
            amplitude *= 0.5;
        }
        return sum / total;
    }

    private static double noise(double x, double y, double z) {
        int xi = (int) Math.floor(x);
        int yi = (int) Math.floor(y);
        int zi = (int) Math.floor(z);
        double fx = fade(x - xi);
        double fy = fade(y - yi);
        double fz = fade(z - zi);
        double result = 0;
        for (int k = 0; k < 8; k++) {
            int dx = k & 1;
            int dy = (k >> 1) & 1;
            int dz = (k >> 2) & 1;
            double w = (dx == 1 ? fx : 1 - fx) * (dy == 1 ? fy : 1 - fy) * (dz == 1 ? fz : 1 - fz);
            result += w * hash(xi + dx, yi + dy, zi + dz);
        }
        return result;
    }

    private static double hash(int x, int y, int z) {
        long h = x * 374761393L + y * 668265263L + z * 2147483647L + 1013904223L;
        h = (h ^ (h >>> 13)) * 1274126177L;
        h ^= h >>> 16;
        return (h & 0xFFFFFF) / (double) 0xFFFFFF;
    }

    private static double fade(double t) { return t * t * (3 - 2 * t); }

    private static double smooth(double a, double b, double x) {
        double t = Math.max(0, Math.min(1, (x - a) / (b - a)));
        return t * t * (3 - 2 * t);
    }

    private static double dot(double[] a, double[] b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

    private static double[] add(double[] a, double[] b) { return new double[] {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }

    private static double[] mix(double[] a, double[] b, double t) {
        return new double[] {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
    }

    private static int byte8(double v) { return (int) Math.round(Math.max(0, Math.min(1, v)) * 255); }
}
