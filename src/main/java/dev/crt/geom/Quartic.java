package dev.crt.geom;

/**
 * Real roots of the depressed monic quartic x⁴ + c2·x² + c1·x + c0 within [−bound, bound], by three
 * methods compared in docs/benchmarks.md: the closed form ({@link #FERRARI}), isolating intervals
 * from the derivative's roots refined by safeguarded Newton steps ({@link #ISOLATE}, the default:
 * it never lost a root in the measurements), and Newton from the bound with deflation
 * ({@link #NEWTON}). Each writes the roots in increasing order into {@code out[0…]} and returns
 * their count; {@code out} must hold 8 doubles (the upper half is scratch). No allocation.
 */
public final class Quartic {
    public static final int FERRARI = 0;
    public static final int ISOLATE = 1;
    public static final int NEWTON = 2;
    public static final String[] NAMES = {"closed form (Ferrari)", "isolating intervals + safeguarded Newton",
        "Newton from a bound"};

    private Quartic() {}

    public static int solve(int method, double c2, double c1, double c0, double bound, double[] out) {
        return switch (method) {
            case FERRARI -> ferrari(c2, c1, c0, bound, out);
            case ISOLATE -> isolate(c2, c1, c0, bound, out);
            case NEWTON -> newton(c2, c1, c0, bound, out);
            default -> throw new IllegalArgumentException("no quartic method " + method);
        };
    }

    static double quartic(double c2, double c1, double c0, double x) {
        double x2 = x * x;
        return (x2 + c2) * x2 + c1 * x + c0;
    }

    // ---- closed form ---------------------------------------------------------------------------

    /**
     * Ferrari: with m > 0 a root of the resolvent cubic 8m³ + 8c2·m² + (2c2² − 8c0)m − c1² = 0,
     * the quartic is the product of x² ∓ √(2m)·x + c2/2 + m ± c1/(2√(2m)).
     */
    public static int ferrari(double c2, double c1, double c0, double bound, double[] out) {
        int n = 0;
        if (c1 == 0) {
            // Biquadratic: y = x² solves y² + c2·y + c0 = 0.
            n = quadratic(1, c2, c0, out, 4);
            int k = 0;
            for (int i = 0; i < n; i++) {
                double y = out[4 + i];
                if (y >= 0) {
                    double s = Math.sqrt(y);
                    out[k++] = -s;
                    out[k++] = s;
                }
            }
            return keep(out, k, bound);
        }
        double m = largestCubicRoot(c2, c2 * c2 / 4 - c0, -c1 * c1 / 8);
        if (!(m > 0)) return 0;
        double s = Math.sqrt(2 * m);
        double h = c1 / (2 * s);
        n = quadratic(1, -s, c2 / 2 + m + h, out, 4);
        n += quadratic(1, s, c2 / 2 + m - h, out, 4 + n);
        for (int i = 0; i < n; i++) out[i] = out[4 + i];
        return keep(out, n, bound);
    }

    /** Real roots of a·x² + b·x + c (a ≠ 0) without cancellation, into out[at…]; returns 0, 1 or 2. */
    private static int quadratic(double a, double b, double c, double[] out, int at) {
        double disc = b * b - 4 * a * c;
        if (disc < 0) return 0;
        double q = -0.5 * (b + Math.copySign(Math.sqrt(disc), b));
        if (q == 0) {
            out[at] = 0;
            return 1;
        }
        out[at] = q / a;
        out[at + 1] = c / q;
        return 2;
    }

    /** The largest real root of x³ + a·x² + b·x + c by the trigonometric or Cardano formula. */
    static double largestCubicRoot(double a, double b, double c) {
        double q = (a * a - 3 * b) / 9;
        double r = (2 * a * a * a - 9 * a * b + 27 * c) / 54;
        double q3 = q * q * q;
        if (r * r < q3) {
            double theta = Math.acos(Math.max(-1, Math.min(1, r / Math.sqrt(q3))));
            return -2 * Math.sqrt(q) * Math.cos((theta - 2 * Math.PI) / 3) - a / 3;
        }
        double big = -Math.copySign(Math.cbrt(Math.abs(r) + Math.sqrt(r * r - q3)), r);
        double small = big == 0 ? 0 : q / big;
        return big + small - a / 3;
    }

    /** Sorts the first n roots, drops those outside [−bound, bound], and returns how many are left. */
    private static int keep(double[] out, int n, double bound) {
        for (int i = 1; i < n; i++) {
            double x = out[i];
            int j = i;
            while (j > 0 && out[j - 1] > x) {
                out[j] = out[j - 1];
                j--;
            }
            out[j] = x;
        }
        int k = 0;
        for (int i = 0; i < n; i++) if (out[i] >= -bound && out[i] <= bound) out[k++] = out[i];
        return k;
    }

    // ---- isolating intervals -------------------------------------------------------------------

    /** {@link #isolate(double, double, double, double, double, double, double, int, double[])} over all of [−bound, bound]. */
    public static int isolate(double c2, double c1, double c0, double bound, double[] out) {
        return isolate(c2, c1, c0, -bound, bound, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY, 4, out);
    }

    /**
     * The roots in [lo, hi] that lie in (from, to), in increasing order, at most {@code max} of
     * them, into {@code out[0…]}; returns their count. The inflection points ±√(−c2/6) cut
     * [lo, hi] into at most three pieces where the quartic is convex or concave, so a piece holds
     * at most two roots: one when its ends differ in sign; none when the ends lie on the side its
     * curvature bends away from; otherwise its extremum (a root of the derivative
     * 4x³ + 2c2·x + c1, monotone on the piece) decides, sought only until a point of the other
     * sign splits the piece into two stretches of one root each, or a tangent shows the extremum
     * keeps the ends' sign. A pair of roots however close keeps the extremum between them, so
     * neither is lost. The brackets depend on [lo, hi] alone, never on (from, to): a root is the
     * same double whichever window asks for it; pieces wholly before {@code from} are not refined
     * and the walk stops at the first root past {@code to} or after {@code max} roots.
     */
    public static int isolate(double c2, double c1, double c0, double lo, double hi, double from, double to, int max,
            double[] out) {
        return walk(c2, c1, c0, lo, hi, from, to, max, false, out);
    }

    /**
     * Whether the quartic has a root in [lo, hi] that lies in (from, to), as {@link #isolate}
     * finds them: a bracket wholly inside the window answers without being refined.
     */
    public static boolean crosses(double c2, double c1, double c0, double lo, double hi, double from, double to,
            double[] scratch) {
        return walk(c2, c1, c0, lo, hi, from, to, 1, true, scratch) > 0;
    }

    /** {@link #isolate}; with {@code decide}, a sign change wholly inside (from, to) is written as NaN unrefined. */
    private static int walk(double c2, double c1, double c0, double lo, double hi, double from, double to, int max,
            boolean decide, double[] out) {
        if (!(lo <= hi) || max <= 0) return 0;
        int n = 0;
        double inflection = c2 < 0 ? Math.sqrt(-c2 / 6) : Double.POSITIVE_INFINITY;
        double p0 = lo, f0 = quartic(c2, c1, c0, lo);
        if (f0 == 0 && lo > from && lo < to) {
            out[n++] = lo;
            if (n == max) return n;
        }
        for (int piece = 0; piece < 3; piece++) {
            double p1 = Math.min(hi, piece == 0 ? -inflection : piece == 1 ? inflection : hi);
            if (!(p1 > p0)) continue;
            if (p0 >= to) return n;
            double f1 = quartic(c2, c1, c0, p1);
            if (p1 > from) {
                boolean convex = c2 >= 0 || piece != 1;
                if (f0 != 0 && f1 != 0 && (f0 < 0) != (f1 < 0)) {
                    double x = decide && p0 >= from && p1 <= to ? Double.NaN : refineQuartic(c2, c1, c0, p0, p1, f0, convex);
                    if (x != x) {
                        out[n++] = x;
                        return n;
                    }
                    if (x > from && x < to) {
                        out[n++] = x;
                        if (n == max) return n;
                    } else if (x >= to) {
                        return n;
                    }
                } else if (f0 != 0 && f1 != 0 && (convex ? f0 < 0 : f0 > 0)) {
                    // Both ends on the side the piece bends away from: it never reaches zero.
                } else {
                    double g0 = cubic(c2, c1, p0), g1 = cubic(c2, c1, p1);
                    double x0 = p0, fx0 = f0;
                    if (g0 != 0 && g1 != 0 && (g0 < 0) != (g1 < 0)) {
                        // Both ends of one sign: a point of the other sign, or a bound on the
                        // extremum, answers before the critical point is refined to the last bit.
                        double c = f0 != 0 && f1 != 0 ? split(c2, c1, c0, p0, p1, g0, f0) : refineCubic(c2, c1, p0, p1, g0);
                        if (c > p0 && c < p1) {
                            double fc = quartic(c2, c1, c0, c);
                            n = stretch(c2, c1, c0, x0, fx0, c, fc, convex, from, to, decide, n, out);
                            if (n == max || c >= to) return n;
                            x0 = c;
                            fx0 = fc;
                        }
                    }
                    n = stretch(c2, c1, c0, x0, fx0, p1, f1, convex, from, to, decide, n, out);
                    if (n == max) return n;
                }
            }
            p0 = p1;
            f0 = f1;
        }
        return n;
    }

    /**
     * The root of a stretch [x0, x1] of the quartic (values f0, f1) that holds at most one, if it
     * lies in (from, to), appended at out[n]; returns the new count.
     */
    private static int stretch(double c2, double c1, double c0, double x0, double f0, double x1, double f1,
            boolean convex, double from, double to, boolean decide, int n, double[] out) {
        if (!(x1 > from)) return n;
        double x;
        if (f1 == 0) {
            if (n > 0 && out[n - 1] == x1) return n;
            x = x1;
        } else if (f0 != 0 && (f0 < 0) != (f1 < 0)) {
            if (decide && x0 >= from && x1 <= to) {
                out[n] = Double.NaN;
                return n + 1;
            }
            x = refineQuartic(c2, c1, c0, x0, x1, f0, convex);
        } else {
            return n;
        }
        if (x > from && x < to) out[n++] = x;
        return n;
    }

    /**
     * Within a piece [a, b] where the quartic bends one way and is f0 (≠ 0) at both ends, and its
     * derivative changes sign (ga at a): Newton steps towards the extremum as {@link #refine} takes
     * them on the derivative, stopping at the first point where the quartic has the other sign
     * (it splits the piece into two stretches of one root each), or with NaN as soon as the
     * tangent at a step shows that the extremum keeps f0's sign (the quartic lies beyond its
     * tangent, and the extremum lies within the bracket); otherwise the extremum itself.
     */
    private static double split(double c2, double c1, double c0, double a, double b, double ga, double f0) {
        double x = 0.5 * (a + b);
        for (int i = 0; i < 200; i++) {
            double g = cubic(c2, c1, x);
            if (g == 0) return x;
            if ((g < 0) == (ga < 0)) a = x;
            else b = x;
            double x2 = x * x;
            double f = (x2 + c2) * x2 + c1 * x + c0;
            if (f != 0 && (f < 0) != (f0 < 0)) return x;
            double reach = Math.abs(g) * (b - a) + 0x1p-40 * (x2 * x2 + Math.abs(c2) * x2 + Math.abs(c1 * x) + Math.abs(c0));
            if (f0 > 0 ? f > reach : f < -reach) return Double.NaN;
            double next = x - g / (12 * x2 + 2 * c2);
            if (Math.abs(next - x) <= 2 * Math.ulp(x)) return x;
            if (!(next > a && next < b) || Math.abs(next - x) > 0.5 * (b - a)) next = 0.5 * (a + b);
            if (b - a <= 2 * Math.ulp(Math.max(Math.abs(a), Math.abs(b)))) return next;
            x = next;
        }
        return x;
    }

    private static double cubic(double c2, double c1, double x) {
        return (4 * x * x + 2 * c2) * x + c1;
    }

    /** The root of the cubic in [a, b], where it changes sign (fa = its value at a), to full precision. */
    private static double refineCubic(double c2, double c1, double a, double b, double fa) {
        return refine(c2, c1, 0, a, b, fa, false, 0.5 * (a + b));
    }

    /**
     * The root of the quartic in [a, b], where it changes sign (fa = its value at a) and bends
     * one way ({@code convex}: upwards), to full precision. Newton starts from the end where the
     * quartic has the sign of its curvature: from there it never overshoots the root.
     */
    private static double refineQuartic(double c2, double c1, double c0, double a, double b, double fa, boolean convex) {
        return refine(c2, c1, c0, a, b, fa, true, (fa > 0) == convex ? a : b);
    }

    /**
     * Safeguarded Newton on the depressed quartic ({@code quartic}) or on its derivative, the cubic
     * 4x³ + 2c2·x + c1: Newton steps while they stay inside the shrinking sign-change bracket
     * [a, b] and halve it at least, bisection otherwise; from x.
     */
    private static double refine(double c2, double c1, double c0, double a, double b, double fa, boolean quartic,
            double x) {
        for (int i = 0; i < 200; i++) {
            double f = quartic ? quartic(c2, c1, c0, x) : cubic(c2, c1, x);
            if (f == 0) return x;
            if ((f < 0) == (fa < 0)) a = x;
            else b = x;
            double d = quartic ? cubic(c2, c1, x) : 12 * x * x + 2 * c2;
            double next = x - f / d;
            // Newton closes on a root from one side, so the bracket alone shrinks slowly: a
            // step of an ulp or two is convergence, whether or not it lands inside the bracket
            // (x itself is then one of its ends).
            if (Math.abs(next - x) <= 2 * Math.ulp(x)) return x;
            if (!(next > a && next < b) || Math.abs(next - x) > 0.5 * (b - a)) next = 0.5 * (a + b);
            if (b - a <= 2 * Math.ulp(Math.max(Math.abs(a), Math.abs(b)))) return next;
            x = next;
        }
        return x;
    }

    // ---- Newton from a bound -------------------------------------------------------------------

    /**
     * Newton's method started left of every root converges to the smallest one when nothing
     * bends in between; the root is divided out and the search starts again from the left on
     * the cubic, and so on. Each root is then polished once on the full quartic. It loses roots
     * behind a dip of the quartic that does not reach zero, where Newton stalls.
     */
    public static int newton(double c2, double c1, double c0, double bound, double[] out) {
        // Coefficients of the current polynomial, highest first: x⁴ + 0x³ + c2x² + c1x + c0.
        double p4 = 1, p3 = 0, p2 = c2, p1 = c1, p0 = c0;
        int degree = 4, n = 0;
        while (degree > 0) {
            double x = -bound;
            boolean found = false;
            for (int i = 0; i < 60; i++) {
                double f, d;
                if (degree == 4) {
                    f = (((p4 * x + p3) * x + p2) * x + p1) * x + p0;
                    d = ((4 * p4 * x + 3 * p3) * x + 2 * p2) * x + p1;
                } else if (degree == 3) {
                    f = ((p3 * x + p2) * x + p1) * x + p0;
                    d = (3 * p3 * x + 2 * p2) * x + p1;
                } else if (degree == 2) {
                    f = (p2 * x + p1) * x + p0;
                    d = 2 * p2 * x + p1;
                } else {
                    f = p1 * x + p0;
                    d = p1;
                }
                if (f == 0) {
                    found = true;
                    break;
                }
                if (d == 0) break;
                double next = x - f / d;
                if (!(next <= bound) || next < x - bound) break;
                if (Math.abs(next - x) <= 4 * Math.ulp(Math.abs(next) + bound * 1e-16)) {
                    x = next;
                    found = true;
                    break;
                }
                x = next;
            }
            if (!found) break;
            out[n++] = x;
            // Synthetic division by (x − root).
            if (degree == 4) {
                double q3 = p4, q2 = p3 + x * q3, q1 = p2 + x * q2, q0 = p1 + x * q1;
                p3 = q3;
                p2 = q2;
                p1 = q1;
                p0 = q0;
            } else if (degree == 3) {
                double q2 = p3, q1 = p2 + x * q2, q0 = p1 + x * q1;
                p2 = q2;
                p1 = q1;
                p0 = q0;
            } else if (degree == 2) {
                double q1 = p2, q0 = p1 + x * q1;
                p1 = q1;
                p0 = q0;
            }
            degree--;
        }
        for (int i = 0; i < n; i++) {
            double x = out[i], d = cubic(c2, c1, x);
            if (d != 0) out[i] = x - quartic(c2, c1, c0, x) / d;
        }
        return keep(out, n, bound);
    }
}
