package dev.crt.geom;

/**
 * atan2 in plain arithmetic, within 1e-15 radians of {@link Math#atan2}: on Java 17 the library
 * one is a native call that cost a sixth of a panorama scene's render time. The angle is reduced
 * to |z| ≤ tan(π/8) by octant symmetry and atan z = π/4 + atan((z − 1)/(z + 1)), halved once more
 * by atan w = 2·atan(w/(1 + √(1 + w²))), and the rest (|w| ≤ 0.1) is a Taylor polynomial to w¹⁷.
 */
public final class Atan {
    private static final double TAN_PI_8 = 0.41421356237309503;
    private static final double PI_4 = Math.PI / 4;

    private Atan() {}

    /** The angle of (x, y) from the +x axis in [−π, π], for finite x and y; ±0 or ±π for (±0, ±0), like {@link Math#atan2}. */
    public static double atan2(double y, double x) {
        double ax = Math.abs(x), ay = Math.abs(y);
        if (!(ax + ay > 0)) return Math.atan2(y, x);
        boolean swap = ay > ax;
        double lo = swap ? ax : ay, hi = swap ? ay : ax;
        // One division either way: (z − 1)/(z + 1) with z = lo/hi is (lo − hi)/(lo + hi).
        double r = lo > TAN_PI_8 * hi ? PI_4 + small((lo - hi) / (lo + hi)) : small(lo / hi);
        if (swap) r = Math.PI / 2 - r;
        if (x < 0) r = Math.PI - r;
        return y < 0 || y == 0 && 1 / y < 0 ? -r : r;
    }

    /** asin(s) as atan2(s, √(1 − s²)), s clamped to [−1, 1]. */
    public static double asin(double s) {
        s = Math.max(-1, Math.min(1, s));
        return atan2(s, Math.sqrt((1 - s) * (1 + s)));
    }

    /** atan w for |w| ≤ tan(π/8). */
    private static double small(double w) {
        double h = w / (1 + Math.sqrt(1 + w * w));
        double q = h * h;
        double p = 1.0 / 17;
        p = p * q - 1.0 / 15;
        p = p * q + 1.0 / 13;
        p = p * q - 1.0 / 11;
        p = p * q + 1.0 / 9;
        p = p * q - 1.0 / 7;
        p = p * q + 1.0 / 5;
        p = p * q - 1.0 / 3;
        p = p * q + 1;
        return 2 * h * p;
    }
}
