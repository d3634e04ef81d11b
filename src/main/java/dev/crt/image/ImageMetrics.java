package dev.crt.image;

/**
 * How far a picture is from a reference, as the user sees them: both are encoded to 8-bit levels
 * with the scene's gamma first (so errors count where they show), then compared by the root mean
 * square error and by the structural similarity index (SSIM) of Wang, Bovik, Sheikh and Simoncelli,
 * "Image quality assessment: from error visibility to structural similarity", IEEE TIP 13(4), 2004:
 * an 11×11 Gaussian window of σ = 1.5, K1 = 0.01, K2 = 0.03, L = 255, averaged over the pixels
 * whose window lies inside the image and over the three channels.
 */
public final class ImageMetrics {
    private static final int RADIUS = 5;
    private static final double SIGMA = 1.5;
    private static final double C1 = sq(0.01 * 255), C2 = sq(0.03 * 255);
    private static final double[] WINDOW = window();

    private ImageMetrics() {}

    /** The 8-bit levels of {@code image} written with {@code gamma}: 3 values per pixel, row by row. */
    public static double[] levels(FrameBuffer image, double gamma) {
        GammaEncoder encoder = new GammaEncoder(gamma);
        float[] rgb = image.data();
        double[] out = new double[rgb.length];
        for (int k = 0; k < rgb.length; k++) out[k] = encoder.encode(rgb[k]);
        return out;
    }

    /** The root mean square difference of two level arrays of the same size. */
    public static double rmse(double[] a, double[] b) {
        requireSameLength(a, b);
        double sum = 0;
        for (int k = 0; k < a.length; k++) sum += sq(a[k] - b[k]);
        return Math.sqrt(sum / a.length);
    }

    /**
     * The mean SSIM of two width × height RGB level arrays (3 values per pixel); 1 for equal
     * images. Images smaller than the 11 × 11 window have no SSIM.
     * @throws IllegalArgumentException for images smaller than the window or of different sizes
     */
    public static double ssim(double[] a, double[] b, int width, int height) {
        requireSameLength(a, b);
        if (a.length != 3 * width * height) throw new IllegalArgumentException("the arrays do not hold " + width + "×" + height + " RGB pixels");
        int side = 2 * RADIUS + 1;
        if (width < side || height < side) {
            throw new IllegalArgumentException("SSIM needs pictures of at least " + side + "×" + side + " pixels");
        }
        int w = width - 2 * RADIUS, h = height - 2 * RADIUS;
        double total = 0;
        double[] x = new double[width * height], y = new double[width * height];
        double[] xx = new double[width * height], yy = new double[width * height], xy = new double[width * height];
        for (int c = 0; c < 3; c++) {
            for (int p = 0; p < width * height; p++) {
                double u = a[3 * p + c], v = b[3 * p + c];
                x[p] = u;
                y[p] = v;
                xx[p] = u * u;
                yy[p] = v * v;
                xy[p] = u * v;
            }
            double[] mx = blur(x, width, height), my = blur(y, width, height);
            double[] sxx = blur(xx, width, height), syy = blur(yy, width, height), sxy = blur(xy, width, height);
            double sum = 0;
            for (int k = 0; k < w * h; k++) {
                double ux = mx[k], uy = my[k];
                double vx = sxx[k] - ux * ux, vy = syy[k] - uy * uy, cov = sxy[k] - ux * uy;
                sum += (2 * ux * uy + C1) * (2 * cov + C2) / ((ux * ux + uy * uy + C1) * (vx + vy + C2));
            }
            total += sum / (w * h);
        }
        return total / 3;
    }

    /** The Gaussian-weighted mean around every pixel whose window fits: (width − 10) × (height − 10) values. */
    private static double[] blur(double[] v, int width, int height) {
        int w = width - 2 * RADIUS, h = height - 2 * RADIUS;
        double[] rows = new double[w * height];
        for (int j = 0; j < height; j++) {
            for (int i = 0; i < w; i++) {
                double s = 0;
                for (int k = 0; k < WINDOW.length; k++) s += WINDOW[k] * v[j * width + i + k];
                rows[j * w + i] = s;
            }
        }
        double[] out = new double[w * h];
        for (int j = 0; j < h; j++) {
            for (int i = 0; i < w; i++) {
                double s = 0;
                for (int k = 0; k < WINDOW.length; k++) s += WINDOW[k] * rows[(j + k) * w + i];
                out[j * w + i] = s;
            }
        }
        return out;
    }

    private static double[] window() {
        double[] g = new double[2 * RADIUS + 1];
        double sum = 0;
        for (int k = -RADIUS; k <= RADIUS; k++) sum += g[k + RADIUS] = Math.exp(-0.5 * k * k / (SIGMA * SIGMA));
        for (int k = 0; k < g.length; k++) g[k] /= sum;
        return g;
    }

    private static void requireSameLength(double[] a, double[] b) {
        if (a.length != b.length) throw new IllegalArgumentException("the pictures differ in size");
    }

    private static double sq(double x) { return x * x; }
}
