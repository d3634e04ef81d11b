package dev.crt.render;

import dev.crt.geom.Quartic;
import java.io.IOException;
import java.math.BigDecimal;
import java.math.MathContext;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;

/**
 * How often each quartic method of {@link Quartic} gets a torus ray wrong, and what it costs.
 * For each ray the reference roots of the exact quartic in t (coefficients formed exactly from the
 * ray's doubles, evaluated with 60 significant digits) are isolated level by level through the
 * derivatives and bisected down to adjacent doubles. A method fails on a ray when it misses a
 * reference root (one not within the tolerance of another, i.e. not half of a tangent pair too
 * close to matter) or returns a root with no reference root within the tolerance, 1e-7 of the
 * torus's size. A last row measures the closest-hit path tori ship (only the first root with
 * t &gt; 0 that bounds the solid is refined): it fails when that root is missed or another is
 * given. Cost: nanoseconds per ray of the production path (move to the closest approach, bound
 * the stretch of the line near the torus, form the quartic, solve), the best of nine passes over
 * the same rays, the methods taking turns.
 *
 * <pre>mvn -B -q -o test-compile && java -cp target/classes:target/test-classes dev.crt.render.TorusRootsBench [rays per family] [csv]</pre>
 */
public final class TorusRootsBench {
    private static final MathContext MC = new MathContext(60);
    /** The rows of the study: the three methods on every root, then the closest-hit path tori ship. */
    private static final String[] NAMES = {Quartic.NAMES[0], Quartic.NAMES[1], Quartic.NAMES[2],
        "first root only (closest hit: isolating intervals)"};
    /** The index in {@link #NAMES} of the closest-hit path. */
    private static final int FIRST = 3;
    private static final String[] FAMILIES = {"random", "grazing (1e-9 to 1e-5 of r)", "along the axis", "far away (1e4 radii)", "spindle"};

    /** A ray in the torus's own frame (centre at the origin, axis z) and the torus. */
    record Case(double ox, double oy, double oz, double dx, double dy, double dz, double big, double small) {}

    public static void main(String[] args) throws IOException {
        int n = args.length > 0 ? Integer.parseInt(args[0]) : 20000;
        Path csv = Path.of(args.length > 1 ? args[1] : "bench/results/torus-roots.csv");
        List<String> lines = new ArrayList<>();
        lines.add("method,family,rays,failed_rays,missed_roots,spurious_roots,failure_rate,ns_per_ray");
        for (int f = 0; f < FAMILIES.length; f++) {
            List<Case> cases = cases(f, n, new SplittableRandom(1234 + f));
            List<double[]> reference = new ArrayList<>();
            for (Case c : cases) reference.add(reference(c));
            double[] ns = costs(cases);
            for (int m = 0; m < NAMES.length; m++) {
                int failed = 0, missed = 0, spurious = 0;
                double[] out = new double[8];
                for (int i = 0; i < cases.size(); i++) {
                    Case c = cases.get(i);
                    double tol = 1e-7 * (c.big + c.small);
                    double[] ref = reference.get(i);
                    int miss = 0, extra = 0;
                    if (m == FIRST) {
                        int verdict = firstFailure(c, ref, solve(m, c, out) > 0 ? out[0] : Double.NaN, tol);
                        miss = verdict == 1 ? 1 : 0;
                        extra = verdict == 2 ? 1 : 0;
                    } else {
                        int k = solve(m, c, out);
                        for (int a = 0; a < ref.length; a++) {
                            if (!near(ref[a], out, k, tol) && !tangentHalf(ref, a, tol)) miss++;
                        }
                        for (int b = 0; b < k; b++) if (!near(out[b], ref, ref.length, tol)) extra++;
                    }
                    if (miss + extra > 0) failed++;
                    missed += miss;
                    spurious += extra;
                }
                String line = String.format(Locale.ROOT, "%s,%s,%d,%d,%d,%d,%.3e,%.1f", NAMES[m], FAMILIES[f],
                        cases.size(), failed, missed, spurious, failed / (double) cases.size(), ns[m]);
                System.out.println(line);
                lines.add(line);
            }
        }
        Files.createDirectories(csv.getParent() == null ? Path.of(".") : csv.getParent());
        Path tmp = csv.resolveSibling(csv.getFileName() + ".tmp");
        Files.write(tmp, lines);
        Files.move(tmp, csv, java.nio.file.StandardCopyOption.REPLACE_EXISTING, java.nio.file.StandardCopyOption.ATOMIC_MOVE);
    }

    private static boolean near(double x, double[] set, int count, double tol) {
        for (int i = 0; i < count; i++) if (Math.abs(set[i] - x) <= tol) return true;
        return false;
    }

    /** Whether reference root a is half of a tangent pair closer than the tolerance, which no picture can show. */
    private static boolean tangentHalf(double[] ref, int a, double tol) {
        return (a > 0 && ref[a] - ref[a - 1] <= tol) || (a + 1 < ref.length && ref[a + 1] - ref[a] <= tol);
    }

    /**
     * How the closest-hit path did on a ray, against the reference roots with t &gt; 0 that bound the
     * solid (off a spindle torus's inner sheet): 0 right, 1 a missed first crossing, 2 a crossing
     * where there is none or beyond the first. Skipping a tangent pair closer than the tolerance
     * is right, as in the all-roots rows.
     */
    static int firstFailure(Case c, double[] ref, double found, double tol) {
        double inner = (c.small - c.big) * (c.small + c.big);
        for (int a = 0; a < ref.length; a++) {
            double t = ref[a];
            double px = c.ox + t * c.dx, py = c.oy + t * c.dy, pz = c.oz + t * c.dz;
            if (t <= 0 || px * px + py * py + pz * pz < inner) continue;
            if (found == found && Math.abs(found - t) <= tol) return 0;
            if (!tangentHalf(ref, a, tol)) return found == found && found < t ? 2 : 1;
        }
        return found == found ? 2 : 0;
    }

    /**
     * The production path: the roots in t of the ray as TorusShape.span finds them (both sheets of
     * the quartic), or for {@link #FIRST} the one root TorusShape.firstHit refines (t &gt; 0).
     */
    static int solve(int method, Case c, double[] out) {
        double length = Math.sqrt(c.dx * c.dx + c.dy * c.dy + c.dz * c.dz);
        double dx = c.dx / length, dy = c.dy / length, dz = c.dz / length;
        double s0 = -(c.ox * dx + c.oy * dy + c.oz * dz);
        double ox = c.ox + s0 * dx, oy = c.oy + s0 * dy, oz = c.oz + s0 * dz;
        boolean first = method == FIRST;
        int k = TorusShape.roots(first ? Quartic.ISOLATE : method, ox, oy, oz, dx, dy, dz, c.big, c.small,
                first ? -s0 : Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY, first ? TorusShape.FIRST : TorusShape.ALL,
                out);
        for (int i = 0; i < k; i++) out[i] = (out[i] + s0) / length;
        return k;
    }

    /**
     * Nanoseconds per ray of each method: passes over the same rays taken in turn (one method,
     * then the next, and again), the best pass of each, so that a busy moment of the machine
     * does not land on one method only.
     */
    private static double[] costs(List<Case> cases) {
        int methods = NAMES.length;
        double[] best = new double[methods];
        java.util.Arrays.fill(best, Double.POSITIVE_INFINITY);
        double[] out = new double[8];
        double sink = 0;
        for (int pass = 0; pass < 9; pass++) {
            for (int m = 0; m < methods; m++) {
                long t0 = System.nanoTime();
                for (Case c : cases) sink += solve(m, c, out);
                best[m] = Math.min(best[m], (System.nanoTime() - t0) / (double) cases.size());
            }
        }
        if (sink < 0) System.out.println(sink);
        return best;
    }

    static List<Case> cases(int family, int n, SplittableRandom r) {
        List<Case> list = new ArrayList<>(n);
        while (list.size() < n) {
            double big = 1;
            double small = family == 4 ? 1.05 + r.nextDouble() : 0.05 + 0.9 * r.nextDouble();
            double[] o = new double[3], d = new double[3];
            switch (family) {
                case 1 -> {
                    // A point on the surface and a direction in its tangent plane, the line moved along the normal.
                    double phi = 2 * Math.PI * r.nextDouble(), psi = 2 * Math.PI * r.nextDouble();
                    double[] n3 = {Math.cos(psi) * Math.cos(phi), Math.cos(psi) * Math.sin(phi), Math.sin(psi)};
                    double rho = big + small * Math.cos(psi);
                    double[] p = {rho * Math.cos(phi), rho * Math.sin(phi), small * Math.sin(psi)};
                    double[] t = unit(r);
                    double dot = t[0] * n3[0] + t[1] * n3[1] + t[2] * n3[2];
                    for (int i = 0; i < 3; i++) d[i] = t[i] - dot * n3[i];
                    // Mostly inward, by 1e-9 … 1e-5 of r: the two roots are then apart by more than
                    // the tolerance, a pair a method must not lose; outward the line misses.
                    double nudge = small * Math.pow(10, -9 + 4 * r.nextDouble()) * (r.nextInt(4) == 0 ? 1 : -1);
                    double back = 2 + 3 * r.nextDouble();
                    double len = Math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                    for (int i = 0; i < 3; i++) {
                        d[i] /= len;
                        o[i] = p[i] + nudge * n3[i] - back * d[i];
                    }
                }
                case 2 -> {
                    double off = big * Math.pow(10, -2 - 4 * r.nextDouble());
                    double a = 2 * Math.PI * r.nextDouble(), tilt = r.nextDouble() * 1e-3;
                    o[0] = off * Math.cos(a);
                    o[1] = off * Math.sin(a);
                    o[2] = -(3 + 1e3 * r.nextDouble());
                    d[0] = tilt * Math.cos(a + 1);
                    d[1] = tilt * Math.sin(a + 1);
                    d[2] = 1;
                }
                case 3 -> {
                    double[] u = unit(r);
                    double far = 1e4 * (big + small);
                    double[] target = {(2 * r.nextDouble() - 1) * (big + small), (2 * r.nextDouble() - 1) * (big + small),
                        (2 * r.nextDouble() - 1) * small};
                    for (int i = 0; i < 3; i++) o[i] = u[i] * far;
                    for (int i = 0; i < 3; i++) d[i] = target[i] - o[i];
                }
                default -> {
                    double[] u = unit(r);
                    double[] target = {(2 * r.nextDouble() - 1) * (big + small), (2 * r.nextDouble() - 1) * (big + small),
                        (2 * r.nextDouble() - 1) * small};
                    double dist = 3 * r.nextDouble();
                    for (int i = 0; i < 3; i++) o[i] = u[i] * dist;
                    for (int i = 0; i < 3; i++) d[i] = target[i] - o[i];
                }
            }
            double len = Math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            if (!(len > 0)) continue;
            list.add(new Case(o[0], o[1], o[2], d[0] / len, d[1] / len, d[2] / len, big, small));
        }
        return list;
    }

    private static double[] unit(SplittableRandom r) {
        while (true) {
            double x = 2 * r.nextDouble() - 1, y = 2 * r.nextDouble() - 1, z = 2 * r.nextDouble() - 1;
            double l = Math.sqrt(x * x + y * y + z * z);
            if (l > 0.1 && l <= 1) return new double[] {x / l, y / l, z / l};
        }
    }

    // ---- the 60-digit reference ----------------------------------------------------------------

    /** The real roots in t of (|o + t·d|² + R² − r²)² − 4R²((ox + t·dx)² + (oy + t·dy)²), in order. */
    static double[] reference(Case c) {
        BigDecimal ox = bd(c.ox), oy = bd(c.oy), oz = bd(c.oz), dx = bd(c.dx), dy = bd(c.dy), dz = bd(c.dz);
        BigDecimal big2 = bd(c.big).multiply(bd(c.big)), small2 = bd(c.small).multiply(bd(c.small));
        BigDecimal a = dx.multiply(dx).add(dy.multiply(dy)).add(dz.multiply(dz));
        BigDecimal b = two(ox.multiply(dx).add(oy.multiply(dy)).add(oz.multiply(dz)));
        BigDecimal cc = ox.multiply(ox).add(oy.multiply(oy)).add(oz.multiply(oz)).add(big2).subtract(small2);
        BigDecimal e2 = dx.multiply(dx).add(dy.multiply(dy));
        BigDecimal e1 = two(ox.multiply(dx).add(oy.multiply(dy)));
        BigDecimal e0 = ox.multiply(ox).add(oy.multiply(oy));
        BigDecimal k = big2.multiply(BigDecimal.valueOf(4));
        // Coefficients from t⁰ up.
        BigDecimal[] p = {
            cc.multiply(cc).subtract(k.multiply(e0)),
            two(b.multiply(cc)).subtract(k.multiply(e1)),
            b.multiply(b).add(two(a.multiply(cc))).subtract(k.multiply(e2)),
            two(a.multiply(b)),
            a.multiply(a)};
        double speed = Math.sqrt(c.dx * c.dx + c.dy * c.dy + c.dz * c.dz);
        double centre = -(c.ox * c.dx + c.oy * c.dy + c.oz * c.dz) / (speed * speed);
        double reach = (c.big + c.small) * 1.01 / speed;
        return roots(p, centre - reach, centre + reach);
    }

    private static BigDecimal bd(double x) { return new BigDecimal(x); }

    private static BigDecimal two(BigDecimal x) { return x.add(x); }

    /** Roots in [lo, hi] of the polynomial with coefficients p (from x⁰ up), isolated by those of its derivative. */
    private static double[] roots(BigDecimal[] p, double lo, double hi) {
        int degree = p.length - 1;
        if (degree == 1) {
            if (p[1].signum() == 0) return new double[0];
            double x = p[0].negate().divide(p[1], MC).doubleValue();
            return x >= lo && x <= hi ? new double[] {x} : new double[0];
        }
        BigDecimal[] d = new BigDecimal[degree];
        for (int i = 1; i <= degree; i++) d[i - 1] = p[i].multiply(BigDecimal.valueOf(i));
        double[] crit = roots(d, lo, hi);
        double[] edges = new double[crit.length + 2];
        edges[0] = lo;
        System.arraycopy(crit, 0, edges, 1, crit.length);
        edges[edges.length - 1] = hi;
        List<Double> found = new ArrayList<>();
        for (int i = 0; i + 1 < edges.length; i++) {
            double a = edges[i], b = edges[i + 1];
            int sa = sign(p, a), sb = sign(p, b);
            if (sa == 0) {
                if (found.isEmpty() || found.get(found.size() - 1) != a) found.add(a);
                continue;
            }
            if (sb == 0 || sa == sb) continue;
            while (true) {
                double m = 0.5 * (a + b);
                if (m <= a || m >= b) break;
                int sm = sign(p, m);
                if (sm == 0) {
                    a = m;
                    b = m;
                    break;
                }
                if (sm == sa) a = m;
                else b = m;
            }
            found.add(0.5 * (a + b));
        }
        int sh = sign(p, hi);
        if (sh == 0 && (found.isEmpty() || found.get(found.size() - 1) != hi)) found.add(hi);
        double[] out = new double[found.size()];
        for (int i = 0; i < out.length; i++) out[i] = found.get(i);
        return out;
    }

    private static int sign(BigDecimal[] p, double x) {
        BigDecimal bx = new BigDecimal(x), acc = BigDecimal.ZERO;
        for (int i = p.length - 1; i >= 0; i--) acc = acc.multiply(bx, MC).add(p[i], MC);
        return acc.signum();
    }
}
