package dev.crt.geom;

/**
 * atan2 in plain arithmetic for the panorama's texel coordinates, within 4e-11 radians of
 * {@link Math#atan2} (a 6000-texel-wide panorama's texel is 1e-3 radians, so a lookup moves by less
 * than 1e-7 texel): on Java 17 the library one is a native call that cost a sixth of a panorama
 * scene's render time. The angle is reduced to |w| ≤ tan(π/8) by octant symmetry and
 * atan z = π/4 + atan((z − 1)/(z + 1)), one division either way, and atan w = w + w³·P(w²) with P of
 * degree 5 fitted on that interval (Chebyshev nodes; its largest error there 3.4e-11; degree 9 gave
 * 1e-16 and cost a fifth more per lookup for no change in any picture; {@code PanoramaStoreTest}
 * checks the whole): no square root, no second division.
 */
public final class Atan {
    private static final double TAN_PI_8 = 0.41421356237309503;
    private static final double PI_4 = Math.PI / 4;
    /** P's coefficients, highest degree first. */
    private static final double P5 = 0.050481378629274716, P4 = -0.08624675822412099, P3 = 0.11071364962298416,
            P2 = -0.14284151188664146, P1 = 0.19999977258511556, P0 = -0.3333333327925298;

    private Atan() {}

    /** The angle of (x, y) from the +x axis in [−π, π], for finite x and y; ±0 or ±π for (±0, ±0), like {@link Math#atan2}. */
    public static double atan2(double y, double x) {
        double ax = Math.abs(x), ay = Math.abs(y);
        if (!(ax + ay > 0)) return Math.atan2(y, x);
        // ax and ay are not NaN here: a comparison orders them (Math.min and max also sort out NaN and −0).
        boolean steep = ay > ax;
        double lo = steep ? ax : ay, hi = steep ? ay : ax;
        boolean far = lo > TAN_PI_8 * hi;
        // (z − 1)/(z + 1) with z = lo/hi is (lo − hi)/(lo + hi).
        double w = far ? (lo - hi) / (lo + hi) : lo / hi;
        double q = w * w;
        double p = P5;
        p = p * q + P4;
        p = p * q + P3;
        p = p * q + P2;
        p = p * q + P1;
        p = p * q + P0;
        double r = w + w * q * p;
        if (far) r += PI_4;
        if (steep) r = Math.PI / 2 - r;
        if (x < 0) r = Math.PI - r;
        return Math.copySign(r, y);
    }
}
