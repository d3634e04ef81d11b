package dev.crt.render;

import static dev.crt.render.Scenes.*;
import static org.assertj.core.api.Assertions.assertThat;

import dev.crt.geom.Quartic;
import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.image.FrameBuffer;
import dev.crt.scene.Background;
import dev.crt.scene.CsgOperation;
import dev.crt.scene.Entity;
import dev.crt.scene.Material;
import dev.crt.scene.Mesh;
import dev.crt.scene.MeshData;
import dev.crt.scene.Rgb;
import dev.crt.scene.Settings;
import dev.crt.scene.SolidBackground;
import dev.crt.scene.SourceSpan;
import dev.crt.scene.Sphere;
import dev.crt.scene.Torus;
import java.io.IOException;
import java.math.BigDecimal;
import java.math.MathContext;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;

/**
 * Where ray tracers fail: grazing and far-away rays, secondary rays leaving a surface, thin and
 * coincident CSG, lights on surfaces, cameras inside solids, scenes far from the origin. Each case
 * counts failures (a NaN, a hole, a wrong hit against an exact reference) for CRT's method and,
 * where there is one, for the naive method a textbook would use, so the table shows why CRT's
 * was chosen. CRT's failure rate must be 0 on every case; the naive method's must not be, which
 * shows that the case can catch a failure at all. The table goes to target/stability.md
 * (docs/accuracy.md shows it).
 */
class StabilitySuite {
    private static final Material M = matte(rgb(0.8, 0.8, 0.8));
    private static final MathContext MC = new MathContext(50);
    private static final List<String> ROWS = new ArrayList<>();

    private static void row(String area, String what, long trials, long crtFailures, String naive, long naiveFailures) {
        ROWS.add(String.format(Locale.ROOT, "| %s | %s | %,d | %s | %s | %s |", area, what, trials,
                rate(crtFailures, trials), naive, naive.isEmpty() ? "" : rate(naiveFailures, trials)));
    }

    private static String rate(long failures, long trials) {
        return failures == 0 ? "0" : String.format(Locale.ROOT, "%.3g%% (%,d)", 100.0 * failures / trials, failures);
    }

    @AfterAll
    static void writeTable() throws IOException {
        StringBuilder b = new StringBuilder("| case | what fails | trials | CRT | naive method | naive |\n|---|---|---|---|---|---|\n");
        for (String r : ROWS) b.append(r).append('\n');
        Path out = Path.of("target", "stability.md");
        Files.createDirectories(out.getParent());
        Files.writeString(out, b);
        System.out.print(b);
    }

    private static BigDecimal big(double x) { return new BigDecimal(x); }

    /**
     * Grazing rays from near and far: the hit decision and entry distance against a 50-digit
     * evaluation of the same double inputs. Rays whose exact squared miss distance lies within
     * 1e-12 of r² may go either way; a wrong entry distance is one off by more than 1e-9 of the
     * distance travelled (plus the radius). Naive: the textbook quadratic b² − 4ac.
     */
    @Test
    void grazingAndFarAwayRaysOnSpheres() {
        SplittableRandom r = new SplittableRandom(11);
        int trials = 200_000;
        long crt = 0, naive = 0;
        Shapes shapes = new Shapes();
        Ray ray = new Ray();
        LineSpan span = new LineSpan();
        for (int k = 0; k < trials; k++) {
            double scale = Math.pow(10, r.nextInt(-6, 7));
            Vec3 c = unit(r).times(scale * 3 * r.nextDouble());
            double radius = scale * (0.5 + r.nextDouble());
            double distance = radius * Math.pow(10, r.nextInt(1, 7));
            // Aim at a point whose distance from the centre is within 1e-3 of the radius.
            Vec3 n = unit(r);
            Vec3 target = c.plus(n.times(radius * (1 + (r.nextDouble() * 2 - 1) * 1e-3)));
            Vec3 tangent = n.cross(unit(r)).normalize();
            Vec3 o = target.minus(tangent.times(distance));
            Vec3 d = target.minus(o).normalize();
            // Exact: t0 = (c − o)·d, m² = |c − o|² − t0², hit when m² ≤ r²; |d| is what the double holds.
            BigDecimal dx = big(d.x()), dy = big(d.y()), dz = big(d.z());
            BigDecimal dd = dx.multiply(dx).add(dy.multiply(dy)).add(dz.multiply(dz));
            BigDecimal ex = big(c.x()).subtract(big(o.x())), ey = big(c.y()).subtract(big(o.y())), ez = big(c.z()).subtract(big(o.z()));
            BigDecimal proj = ex.multiply(dx).add(ey.multiply(dy)).add(ez.multiply(dz)).divide(dd, MC);
            BigDecimal m2 = ex.multiply(ex).add(ey.multiply(ey)).add(ez.multiply(ez)).subtract(proj.multiply(proj).multiply(dd));
            BigDecimal r2 = big(radius).multiply(big(radius));
            double margin = r2.subtract(m2).divide(r2, MC).doubleValue();
            boolean exactHit = margin >= 0;
            double exactT = exactHit ? proj.subtract(r2.subtract(m2).divide(dd, MC).sqrt(MC)).doubleValue() : Double.NaN;
            boolean decided = Math.abs(margin) > 1e-12;
            double tolerance = 1e-9 * (distance + radius);

            int s = shapes.add(new Sphere(c, radius, M, Transform.IDENTITY, SourceSpan.NONE), Transform.IDENTITY, 0);
            ray.set(o.x(), o.y(), o.z(), d.x(), d.y(), d.z());
            boolean hit = shapes.span(s, ray, span);
            if (failed(hit, hit ? span.tIn[0] : Double.NaN, exactHit, exactT, decided, tolerance)) crt++;

            // The textbook: a = d·d, b = 2(o − c)·d, c = |o − c|² − r², t = (−b − √(b² − 4ac)) / 2a.
            double ox = o.x() - c.x(), oy = o.y() - c.y(), oz = o.z() - c.z();
            double a = d.x() * d.x() + d.y() * d.y() + d.z() * d.z();
            double b = 2 * (ox * d.x() + oy * d.y() + oz * d.z());
            double cc = ox * ox + oy * oy + oz * oz - radius * radius;
            double disc = b * b - 4 * a * cc;
            boolean naiveHit = disc >= 0;
            if (failed(naiveHit, naiveHit ? (-b - Math.sqrt(disc)) / (2 * a) : Double.NaN, exactHit, exactT, decided, tolerance)) naive++;
            if (k % 1024 == 1023) shapes = new Shapes();
        }
        row("grazing rays on spheres, 10 to 1e6 radii away, scales 1e-6 to 1e6", "wrong hit or miss, entry off by > 1e-9 of the distance",
                trials, crt, "b² − 4ac quadratic", naive);
        assertThat(crt).isZero();
        assertThat(naive).isPositive();
    }

    private static boolean failed(boolean hit, double t, boolean exactHit, double exactT, boolean decided, double tolerance) {
        if (hit && !Double.isFinite(t)) return true;
        if (!decided) return false;
        if (hit != exactHit) return true;
        return hit && Math.abs(t - exactT) > tolerance;
    }

    /**
     * Secondary rays leave a surface from the point the primary ray found, pushed off along the
     * normal; a ray going out must not meet its own convex surface again, a ray going in must
     * cross the solid rather than its own entry face. CRT's offset is 2^-36 of the larger of the
     * point's coordinates and the object's size; the naive one a fixed 1e-7.
     */
    @Test
    void secondaryRaysDoNotHitTheSurfaceTheyLeave() {
        long trials = 0, crt = 0, naive = 0;
        SplittableRandom r = new SplittableRandom(5);
        for (double scale : new double[] {1e-7, 1, 1e7}) {
            for (double away : new double[] {0, 1e9}) {
                // An object 1e-7 across at 1e9 is smaller than the spacing of doubles there (1.2e-7).
                if (away / scale > 1e12) continue;
                for (int shape = 0; shape < 3; shape++) {
                    Vec3 centre = new Vec3(away, away * 0.5, -away * 0.25);
                    Entity e = switch (shape) {
                        case 0 -> sphere(centre, scale, M);
                        case 1 -> box(centre.minus(new Vec3(scale, scale * 0.7, scale * 1.3)), centre.plus(new Vec3(scale, scale * 0.7, scale * 1.3)), M);
                        default -> plane(new Vec3(0.3, 1, 0.2), centre, M);
                    };
                    double size = switch (shape) {
                        case 0 -> maxAbs(centre) + scale;
                        case 1 -> maxAbs(centre) + 1.3 * scale;
                        default -> Math.abs(new Vec3(0.3, 1, 0.2).normalize().dot(centre));
                    };
                    Tracer tracer = new Tracer(new SceneGeometry(List.of(e)), new Lights(List.of()), new BackgroundShader(Background.BLACK, 1));
                    for (int k = 0; k < 2000; k++) {
                        // A primary ray from 10 sizes away towards a point of the object.
                        Vec3 aim = centre.plus(unit(r).times(scale * 0.5));
                        Vec3 o = aim.plus(unit(r).times(scale * 10));
                        Vec3 d = aim.minus(o).normalize();
                        if (!tracer.closestHit(o.x(), o.y(), o.z(), d.x(), d.y(), d.z(), Double.POSITIVE_INFINITY)) continue;
                        Vec3 p = o.plus(d.times(tracer.hit.t));
                        Vec3 n = normal(shape, e, p, centre, scale);
                        if (n.dot(d) > 0) n = n.times(-1);
                        boolean outward = r.nextBoolean();
                        Vec3 w = unit(r);
                        if ((w.dot(n) > 0) != outward) w = w.times(-1);
                        if (Math.abs(w.dot(n)) < 1e-3) continue;
                        if (!outward && shape == 2) continue;
                        trials++;
                        double crtDelta = Tracer.OFFSET * Math.max(maxAbs(p), size);
                        if (selfHit(tracer, p, n, w, outward, crtDelta, scale)) crt++;
                        if (selfHit(tracer, p, n, w, outward, 1e-7, scale)) naive++;
                    }
                }
            }
        }
        row("secondary rays leaving spheres, boxes, planes; scales 1e-7 to 1e7 at the origin, 1 and 1e7 at 1e9 from it",
                "the ray meets the surface it leaves", trials, crt, "fixed offset 1e-7", naive);
        assertThat(crt).isZero();
        assertThat(naive).isPositive();
    }

    private static boolean selfHit(Tracer tracer, Vec3 p, Vec3 n, Vec3 w, boolean outward, double delta, double scale) {
        Vec3 s = outward ? p.plus(n.times(delta)) : p.minus(n.times(delta));
        boolean hit = tracer.closestHit(s.x(), s.y(), s.z(), w.x(), w.y(), w.z(), Double.POSITIVE_INFINITY);
        if (outward) return hit;
        // Going in, the ray must cross the solid: a hit within a thousandth of its size is its own entry face.
        return !hit || tracer.hit.t < 1e-3 * scale;
    }

    private static Vec3 normal(int shape, Entity e, Vec3 p, Vec3 centre, double scale) {
        if (shape == 0) return p.minus(centre).normalize();
        if (shape == 2) return new Vec3(0.3, 1, 0.2).normalize();
        Vec3 q = p.minus(centre);
        double[] half = {scale, scale * 0.7, scale * 1.3};
        double[] v = {q.x() / half[0], q.y() / half[1], q.z() / half[2]};
        int axis = 0;
        for (int i = 1; i < 3; i++) if (Math.abs(v[i]) > Math.abs(v[axis])) axis = i;
        double sign = Math.signum(v[axis]);
        return axis == 0 ? new Vec3(sign, 0, 0) : axis == 1 ? new Vec3(0, sign, 0) : new Vec3(0, 0, sign);
    }

    private static double maxAbs(Vec3 v) {
        return Math.max(Math.abs(v.x()), Math.max(Math.abs(v.y()), Math.abs(v.z())));
    }

    /** Renders a 64 × 48 picture lit from the eye, so every surface shows and no shadow falls. */
    private static FrameBuffer render(Vec3 eye, Vec3 at, Rgb background, Entity... entities) {
        Settings s = settings(camera(eye, at, 50), List.of(point(eye, Rgb.WHITE, 0, 0)), new SolidBackground(background), 64, 48);
        return Renderer.prepare(scene(s, entities)).render(2, RenderMonitor.NONE);
    }

    private static long nans(FrameBuffer fb) {
        long n = 0;
        for (float f : fb.data()) if (!Float.isFinite(f)) n++;
        return n;
    }

    /**
     * A slab 1e-9 thick, the intersection of two boxes that overlap by that much, seen face-on:
     * every pixel inside its outline must show it (at the entry distance of the exact slab).
     */
    @Test
    void thinCsgSlabsAreHitWhereTheyAre() {
        long trials = 0, crt = 0;
        for (double thickness : new double[] {1e-6, 1e-9, 1e-12}) {
            Entity slab = csg(CsgOperation.INTERSECTION, box(v(-1, -1, -1), v(1, 1, thickness), M), box(v(-1, -1, 0), v(1, 1, 1), M));
            Settings s = settings(camera(v(0.1, 0.2, -4), v(0.1, 0.2, 0), 30), List.of(), Background.BLACK, 64, 48);
            Renderer renderer = Renderer.prepare(scene(s, slab));
            double[] depth = renderer.depthPass();
            int[] ids = renderer.idPass();
            for (int j = 0; j < 48; j++) {
                for (int i = 0; i < 64; i++) {
                    Vec3 d = Reference.center(s, i, j);
                    double t = 4 / d.z();
                    Vec3 p = v(0.1, 0.2, -4).plus(d.times(t));
                    if (Math.abs(p.x()) > 0.99 || Math.abs(p.y()) > 0.99) continue;
                    trials++;
                    if (ids[j * 64 + i] != 0 || Math.abs(depth[j * 64 + i] - t) > 1e-9 * t) crt++;
                }
            }
        }
        row("CSG slab 1e-6, 1e-9 and 1e-12 thick (intersection of two boxes), face-on", "a pixel inside it misses it or hits at the wrong depth",
                trials, crt, "", 0);
        assertThat(crt).isZero();
    }

    /**
     * A − B where B's top face lies exactly in A's top face (a notch cut from the top), seen from
     * above and lit from the eye: outside the notch the pixel is A's top, inside it B's floor;
     * no pixel may show anything else (a speckle of the removed face, or a hole to the background).
     */
    @Test
    void coincidentCsgFacesShowOneSurfaceWithoutSpeckle() {
        Rgb red = rgb(0.9, 0.1, 0.1), blue = rgb(0.1, 0.2, 0.9);
        long trials = 0, crt = 0;
        for (double scale : new double[] {1e-4, 1, 1e4}) {
            Entity a = box(v(-1, -1, -1).times(scale), v(1, 0, 1).times(scale), matte(red));
            Entity b = box(v(-0.5, -0.5, -0.5).times(scale), v(0.5, 0, 0.5).times(scale), matte(blue));
            Vec3 eye = v(0.05, 3, 0.03).times(scale);
            Settings s = settings(camera(eye, v(0, 0, 0), 40), List.of(point(eye, Rgb.WHITE, 0, 0)), new SolidBackground(Rgb.BLACK), 64, 48);
            FrameBuffer fb = Renderer.prepare(scene(s, csg(CsgOperation.DIFFERENCE, a, b))).render(2, RenderMonitor.NONE);
            for (int j = 0; j < 48; j++) {
                for (int i = 0; i < 64; i++) {
                    Vec3 d = Reference.center(s, i, j);
                    double t = eye.y() / -d.y();
                    Vec3 p = eye.plus(d.times(t));
                    double x = Math.abs(p.x() / scale), z = Math.abs(p.z() / scale);
                    // Skip pixels near the notch's rim and the block's edge, where both answers are fair.
                    if (Math.abs(x - 0.5) < 0.05 || Math.abs(z - 0.5) < 0.05 || x > 0.95 || z > 0.95) continue;
                    trials++;
                    boolean inNotch = x < 0.5 && z < 0.5;
                    boolean blueShown = fb.get(i, j, 2) > fb.get(i, j, 0);
                    boolean black = fb.get(i, j, 0) + fb.get(i, j, 2) < 0.05;
                    if (black || blueShown != inNotch || !Float.isFinite(fb.get(i, j, 0))) crt++;
                }
            }
        }
        row("A − B with coincident top faces, scales 1e-4 to 1e4", "a pixel shows the removed face or a hole", trials, crt, "", 0);
        assertThat(crt).isZero();
    }

    /**
     * Rays tangent to a torus at a random point of its surface, the line moved 1e-9 to 1e-5 of r
     * along the normal (three times in four inwards, where the two roots are apart by more than the
     * tolerance): the first entry against the 60-digit roots of {@link TorusRootsBench}, through
     * the whole shape path (Shapes.span, and Shapes.firstHit and anyHit, which refine the first
     * root only). A ray fails when it misses a root pair that is farther apart than the tolerance
     * (1e-7 of R + r), or enters where there is no root. Naive: the closed form (Ferrari) on the
     * same quartic.
     */
    @Test
    void raysTangentToATorus() {
        List<TorusRootsBench.Case> cases = TorusRootsBench.cases(1, 3000, new SplittableRandom(99));
        long crt = 0, naive = 0;
        Shapes shapes = new Shapes();
        Ray ray = new Ray();
        LineSpan span = new LineSpan();
        Hit nearest = new Hit();
        double[] roots = new double[8];
        for (TorusRootsBench.Case c : cases) {
            double[] ref = TorusRootsBench.reference(c);
            double tol = 1e-7 * (c.big() + c.small());
            // A tangent pair closer than the tolerance may be found or not: no picture can show it.
            boolean mustHit = ref.length >= 2 && ref[1] - ref[0] > tol;
            int s = shapes.add(new Torus(v(0, 0, 0), v(0, 0, 1), c.big(), c.small(), M, Transform.IDENTITY, SourceSpan.NONE),
                    Transform.IDENTITY, 0);
            ray.set(c.ox(), c.oy(), c.oz(), c.dx(), c.dy(), c.dz());
            boolean hit = shapes.span(s, ray, span);
            boolean failed = torusFailed(hit, hit ? span.tIn[0] : Double.NaN, ref, mustHit, tol);
            // The closest-hit and shadow paths, which refine only the first root, must agree.
            ray.set(c.ox(), c.oy(), c.oz(), c.dx(), c.dy(), c.dz());
            boolean first = shapes.firstHit(s, ray, Double.POSITIVE_INFINITY, span, nearest);
            failed |= torusFailed(first, first ? nearest.t : Double.NaN, ref, mustHit, tol);
            ray.set(c.ox(), c.oy(), c.oz(), c.dx(), c.dy(), c.dz());
            failed |= shapes.anyHit(s, ray, Double.POSITIVE_INFINITY, span) != first;
            if (failed) crt++;
            int k = TorusRootsBench.solve(Quartic.FERRARI, c, roots);
            if (torusFailed(k > 0, k > 0 ? roots[0] : Double.NaN, ref, mustHit, tol)) naive++;
        }
        row("rays tangent to tori (r from 0.05 to 0.95 R), moved 1e-9 to 1e-5 of r off the surface",
                "a root pair lost, or an entry where there is no root (60-digit reference)", cases.size(), crt,
                "closed form (Ferrari)", naive);
        assertThat(crt).isZero();
        assertThat(naive).isPositive();
    }

    private static boolean torusFailed(boolean hit, double first, double[] ref, boolean mustHit, double tol) {
        if (hit && !Double.isFinite(first)) return true;
        if (!hit) return mustHit;
        for (double r : ref) if (Math.abs(r - first) <= tol) return false;
        return true;
    }

    /**
     * An open grid mesh, scaled (1e-3 to 1e3), turned and moved, and rays aimed at its vertices
     * (where six triangles meet) and at points of its shared edges, from random directions: each
     * must cross it exactly once, never zero times (a crack) or twice (counted by both neighbours).
     * With {@code degenerate}, the grid also holds a zero-area sliver along every diagonal (through
     * an extra vertex at its midpoint) and a triangle with a repeated vertex at every vertex, which
     * must add no crossing and no NaN. Naive: Möller–Trumbore with ε = 1e-7 over every triangle.
     */
    private static long[] meshEdgeTrials(boolean degenerate, long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        int n = 6;
        MeshData grid = Meshes.grid(n);
        double[] p = grid.positions();
        int[] t = grid.triangles();
        if (degenerate) {
            List<double[]> extra = new ArrayList<>();
            List<int[]> tris = new ArrayList<>();
            int next = p.length / 3;
            for (int k = 0; k < t.length; k += 6) {
                // The diagonal is the edge the cell's two triangles share.
                int a = -1, b = -1;
                for (int x = k; x < k + 3; x++) {
                    for (int y = k + 3; y < k + 6; y++) {
                        if (t[x] == t[y]) {
                            if (a < 0) a = t[x];
                            else if (t[x] != a) b = t[x];
                        }
                    }
                }
                extra.add(new double[] {(p[3 * a] + p[3 * b]) / 2, (p[3 * a + 1] + p[3 * b + 1]) / 2, 0});
                tris.add(new int[] {a, next++, b});
            }
            for (int vtx = 0; vtx < p.length / 3; vtx++) tris.add(new int[] {vtx, vtx, (vtx + 1) % (p.length / 3)});
            double[] p2 = java.util.Arrays.copyOf(p, p.length + 3 * extra.size());
            for (int i = 0; i < extra.size(); i++) System.arraycopy(extra.get(i), 0, p2, p.length + 3 * i, 3);
            int[] t2 = java.util.Arrays.copyOf(t, t.length + 3 * tris.size());
            for (int i = 0; i < tris.size(); i++) System.arraycopy(tris.get(i), 0, t2, t.length + 3 * i, 3);
            p = p2;
            t = t2;
        }
        MeshData data = new MeshData(degenerate ? "grid with degenerate triangles" : "grid", p, t, null, null, false);
        long trials = 0, crt = 0, naive = 0;
        Ray ray = new Ray();
        LineSpan span = new LineSpan();
        for (int placement = 0; placement < 40; placement++) {
            double scale = Math.pow(10, r.nextInt(-3, 4));
            Transform place = Transform.scaling(v(scale, scale, scale)).then(Transform.rotation(unit(r).times(180)))
                    .then(Transform.translation(unit(r).times(scale * 100 * r.nextDouble())));
            Shapes shapes = new Shapes();
            int s = shapes.add(new Mesh(data, false, M, Transform.IDENTITY, SourceSpan.NONE), place, 0);
            double[] world = new double[p.length];
            for (int i = 0; i < p.length; i += 3) {
                Vec3 w = place.applyToPoint(v(p[i], p[i + 1], p[i + 2]));
                world[i] = w.x();
                world[i + 1] = w.y();
                world[i + 2] = w.z();
            }
            Vec3 normal = place.applyToNormal(v(0, 0, 1)).normalize();
            for (int i = 1; i < n; i++) {
                for (int j = 1; j < n; j++) {
                    Vec3[] targets = {v(i, j, 0), v(i + 0.5, j, 0), v(i, j + 0.25, 0), v(i + 0.5, j + 0.5, 0), v(i + 0.25, j + 0.25, 0),
                        v(i + 0.75, j + 0.25, 0)};
                    for (Vec3 local : targets) {
                        Vec3 target = place.applyToPoint(local);
                        Vec3 d = unit(r);
                        if (Math.abs(d.dot(normal)) < 0.05) d = d.plus(normal).normalize();
                        Vec3 o = target.minus(d.times(3 * scale));
                        trials++;
                        ray.set(o.x(), o.y(), o.z(), d.x(), d.y(), d.z());
                        boolean hit = shapes.span(s, ray, span);
                        int crossings = hit ? span.count : 0;
                        if (crossings != 1 || !Double.isFinite(span.tIn[0])) crt++;
                        if (mollerTrumbore(world, t, o, d) != 1) naive++;
                    }
                }
            }
        }
        return new long[] {trials, crt, naive};
    }

    /** Crossings of the line with every triangle by the textbook test, inclusive edges, ε = 1e-7. */
    private static int mollerTrumbore(double[] p, int[] t, Vec3 o, Vec3 d) {
        int count = 0;
        for (int k = 0; k < t.length; k += 3) {
            Vec3 a = v(p[3 * t[k]], p[3 * t[k] + 1], p[3 * t[k] + 2]);
            Vec3 e1 = v(p[3 * t[k + 1]], p[3 * t[k + 1] + 1], p[3 * t[k + 1] + 2]).minus(a);
            Vec3 e2 = v(p[3 * t[k + 2]], p[3 * t[k + 2] + 1], p[3 * t[k + 2] + 2]).minus(a);
            Vec3 h = d.cross(e2);
            double det = e1.dot(h);
            if (Math.abs(det) < 1e-7) continue;
            double f = 1 / det;
            Vec3 sv = o.minus(a);
            double u = f * sv.dot(h);
            if (u < 0 || u > 1) continue;
            Vec3 q = sv.cross(e1);
            double w = f * d.dot(q);
            if (w < 0 || u + w > 1) continue;
            if (f * e2.dot(q) > 1e-7) count++;
        }
        return count;
    }

    @Test
    void raysThroughSharedMeshEdgesAndVertices() {
        long[] f = meshEdgeTrials(false, 21);
        row("rays through the shared edges and vertices of a grid mesh, scaled 1e-3 to 1e3, turned and moved",
                "a crack (no crossing) or a double crossing", f[0], f[1], "Möller–Trumbore, ε = 1e-7", f[2]);
        assertThat(f[1]).isZero();
        assertThat(f[2]).isPositive();
    }

    @Test
    void degenerateTrianglesAddNoCrossing() {
        long[] f = meshEdgeTrials(true, 22);
        row("the same grid with a zero-area sliver along every diagonal and a repeated-vertex triangle at every vertex",
                "a NaN, a crack or an extra crossing", f[0], f[1], "Möller–Trumbore, ε = 1e-7", f[2]);
        assertThat(f[1]).isZero();
        assertThat(f[2]).isPositive();
    }

    /** Point lights lying exactly on a plane and on a sphere, and cameras inside solids. */
    @Test
    void lightsOnSurfacesAndCamerasInsideSolids() {
        Rgb sky = rgb(0, 1, 0);
        long pixels = 0, nanOrHole = 0;
        // A light on the floor and on a ball's surface: no NaN, and the floor is lit smoothly.
        for (Vec3 light : new Vec3[] {v(0, 0, 2), v(0, 1, 0)}) {
            Settings s = settings(camera(v(0, 2, -4), v(0, 0, 2), 50), List.of(point(light, Rgb.WHITE, 0, 0.1)),
                    new SolidBackground(sky), 64, 48);
            FrameBuffer fb = Renderer.prepare(scene(s, plane(v(0, 1, 0), v(0, 0, 0), M), sphere(v(0, 1.5, 0), 0.5, M))).render(2, RenderMonitor.NONE);
            pixels += 64 * 48;
            nanOrHole += nans(fb);
        }
        // Cameras inside a ball, a box and a CSG difference see their inside at every pixel.
        Entity[] solids = {sphere(v(0, 0, 0), 2, M), box(v(-2, -2, -2), v(2, 2, 2), M),
                csg(CsgOperation.DIFFERENCE, sphere(v(0, 0, 0), 3, M), sphere(v(0, 0, 5), 1, M))};
        for (Entity e : solids) {
            FrameBuffer fb = render(v(0.1, 0.2, 0.3), v(1, 0.5, 2), sky, e);
            for (int j = 0; j < 48; j++) {
                for (int i = 0; i < 64; i++) {
                    pixels++;
                    boolean background = fb.get(i, j, 1) == 1 && fb.get(i, j, 0) == 0;
                    if (background || !Float.isFinite(fb.get(i, j, 0))) nanOrHole++;
                }
            }
        }
        row("point lights on a plane and on a ball; cameras inside a ball, a box and a CSG solid", "a NaN, or a pixel that sees out of the solid",
                pixels, nanOrHole, "", 0);
        assertThat(nanOrHole).isZero();
    }

    /**
     * The same scene at 1e-7 and 1e7 times its size and 1e9 from the origin renders the same
     * picture: every channel within 1 level of the unit scene's, except at pixels whose rays pass
     * within about 1e-6 (relative) of a silhouette or shadow boundary, which the rendering model
     * lets go either way: those are found as the pixels that change when the unit scene's camera
     * and ball move by 1e-6 of the scene's size.
     *
     * <p>1e9 from the origin is a known limitation: secondary rays start 2^-36 of the point's largest
     * coordinate off the surface, 0.015 there, so shadow rays start that much higher and shadow
     * edges on the floor move by as much; a few pixels along them change. The test bounds it.
     */
    @Test
    void scaledAndFarScenesRenderTheSamePicture() {
        long[] floating = compareToUnit(0.2), resting = compareToUnit(0);
        row("a ball above a box, and resting on it, under two lights at 1e-7 and 1e7 scale",
                "a channel more than 1 level from the unit scene's", floating[0] + resting[0], floating[1] + resting[1], "", 0);
        row("the same two scenes 1e9 from the origin: known limitation (shadow edges move by the 0.015 offset)",
                "as above", floating[2] + resting[2], floating[3] + resting[3], "", 0);
        assertThat(floating[1] + resting[1]).isZero();
        assertThat(floating[3] + resting[3]).as("1e9 from the origin, pixels on shadow edges").isLessThanOrEqualTo(12);
    }

    /** {trials, failures} at 1e-7 and 1e7 scale, then {trials, failures} 1e9 from the origin. */
    private static long[] compareToUnit(double lift) {
        FrameBuffer unit = placed(1, v(0, 0, 0), v(0, lift, 0));
        boolean[] sensitive = new boolean[unit.data().length];
        for (Vec3 nudge : new Vec3[] {v(1e-6, 0, 0), v(0, -1e-6, 0), v(0, 0, 1e-6), v(-1e-6, 1e-6, 0)}) {
            float[] moved = placed(1, v(0, 0, 0), nudge.plus(v(0, lift, 0))).data();
            for (int k = 0; k < moved.length; k++) sensitive[k] |= Math.abs(moved[k] - unit.data()[k]) > 1 / 255.0;
        }
        long[] out = new long[4];
        Object[][] cases = {{1e-7, v(0, 0, 0)}, {1e7, v(0, 0, 0)}, {1.0, v(1e9, -1e9, 1e9)}};
        for (int c = 0; c < cases.length; c++) {
            FrameBuffer fb = placed((double) cases[c][0], (Vec3) cases[c][1], v(0, lift, 0));
            int slot = c < 2 ? 0 : 2;
            for (int k = 0; k < fb.data().length; k++) {
                if (sensitive[k]) continue;
                out[slot]++;
                if (!(Math.abs(fb.data()[k] - unit.data()[k]) <= 1 / 255.0)) out[slot + 1]++;
            }
        }
        return out;
    }

    private static FrameBuffer placed(double scale, Vec3 shift, Vec3 nudge) {
        Vec3 eye = v(1, 2, -5).plus(nudge).times(scale).plus(shift), at = v(0, 0.5, 0).times(scale).plus(shift);
        Settings s = settings(camera(eye, at, 45), List.of(point(v(-3, 4, -2).times(scale).plus(shift), Rgb.WHITE, 0, 0.1),
                point(v(3, 3, -3).times(scale).plus(shift), rgb(0.5, 0.5, 0.4), 0, 0)), new SolidBackground(rgb(0.1, 0.1, 0.2)), 48, 36);
        return Renderer.prepare(scene(s, sphere(v(0, 1, 0).plus(nudge).times(scale).plus(shift), scale, matte(rgb(0.9, 0.5, 0.2))),
                box(v(-2, -0.5, -2).times(scale).plus(shift), v(2, 0, 2).times(scale).plus(shift), M))).render(2, RenderMonitor.NONE);
    }
}
