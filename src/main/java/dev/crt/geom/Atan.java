package dev.crt.geom;

/**
 * atan2 in plain arithmetic, within 1e-15 radians of {@link Math#atan2} (a couple of ulps of π): on Java 17 the library
 * one is a native call that cost a sixth of a panorama scene's render time. The angle is reduced
 * to |w| ≤ tan(π/8) by octant symmetry and atan z = π/4 + atan((z − 1)/(z + 1)), one division
 * either way, and atan w = w + w³·P(w²) with P of degree 9 fitted on that interval (Chebyshev
 * nodes; its largest error there 1.1e-16; {@code PanoramaStoreTest} checks the whole): no square root, no second division.
 */
public final class Atan {
    private static final double TAN_PI_8 = 0.41421356237309503;
    private static final double PI_4 = Math.PI / 4;
    /** P's coefficients, highest degree first. */
    private static final double P9 = 0.02275052699336167, P8 = -0.04483334622272886, P7 = 0.05736332165907643,
            P6 = -0.06649613695291669, P5 = 0.0769105515839315, P4 = -0.09090852557176049, P3 = 0.11111109636534361,
            P2 = -0.1428571426609662, P1 = 0.19999999999898407, P0 = -0.3333333333333325;

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
        double p = P9;
        p = p * q + P8;
        p = p * q + P7;
        p = p * q + P6;
        p = p * q + P5;
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
