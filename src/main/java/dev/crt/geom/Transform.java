package dev.crt.geom;

import java.util.Arrays;

/**
 * An immutable affine transform of points, directions and normals, kept with its inverse.
 * The 3x4 matrix acts on column vectors: p' = M·p + t.
 */
public final class Transform {
    public static final Transform IDENTITY = new Transform(
            new double[] {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0},
            new double[] {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0});

    // Row-major: m[0..3] is row 0 (m00 m01 m02 tx), m[4..7] row 1, m[8..11] row 2.
    private final double[] m;
    private final double[] inv;

    private Transform(double[] m, double[] inv) {
        this.m = m;
        this.inv = inv;
    }

    public static Transform translation(Vec3 v) {
        return new Transform(
                new double[] {1, 0, 0, v.x(), 0, 1, 0, v.y(), 0, 0, 1, v.z()},
                new double[] {1, 0, 0, -v.x(), 0, 1, 0, -v.y(), 0, 0, 1, -v.z()});
    }

    /** Scale by the components of {@code s}; each must be non-zero. */
    public static Transform scaling(Vec3 s) {
        if (s.x() == 0 || s.y() == 0 || s.z() == 0) {
            throw new IllegalArgumentException("scale component is zero: " + s);
        }
        return new Transform(
                new double[] {s.x(), 0, 0, 0, 0, s.y(), 0, 0, 0, 0, s.z(), 0},
                new double[] {1 / s.x(), 0, 0, 0, 0, 1 / s.y(), 0, 0, 0, 0, 1 / s.z(), 0});
    }

    /**
     * Rotation by the given angles in degrees about x, then y, then z, each the standard
     * rotation matrix for column vectors (about y by θ: x' = x cosθ + z sinθ, z' = −x sinθ + z cosθ).
     */
    public static Transform rotation(Vec3 degrees) {
        return rotationX(degrees.x()).then(rotationY(degrees.y())).then(rotationZ(degrees.z()));
    }

    private static Transform rotationX(double deg) {
        double c = cosDeg(deg), s = sinDeg(deg);
        return orthonormal(new double[] {1, 0, 0, 0, 0, c, -s, 0, 0, s, c, 0});
    }

    private static Transform rotationY(double deg) {
        double c = cosDeg(deg), s = sinDeg(deg);
        return orthonormal(new double[] {c, 0, s, 0, 0, 1, 0, 0, -s, 0, c, 0});
    }

    private static Transform rotationZ(double deg) {
        double c = cosDeg(deg), s = sinDeg(deg);
        return orthonormal(new double[] {c, -s, 0, 0, s, c, 0, 0, 0, 0, 1, 0});
    }

    /** Exact values at multiples of 90 degrees, so that quarter turns leave no rounding residue. */
    static double sinDeg(double deg) {
        double r = deg % 360;
        if (r < 0) r += 360;
        if (r == 0 || r == 180) return 0;
        if (r == 90) return 1;
        if (r == 270) return -1;
        return Math.sin(Math.toRadians(deg));
    }

    static double cosDeg(double deg) {
        return sinDeg(deg + 90);
    }

    private static Transform orthonormal(double[] m) {
        double[] inv = {m[0], m[4], m[8], 0, m[1], m[5], m[9], 0, m[2], m[6], m[10], 0};
        return new Transform(m, inv);
    }

    /**
     * The map p ↦ p.x·cx + p.y·cy + p.z·cz + t, for columns that span space (a shape's own frame);
     * its inverse by cross products.
     */
    public static Transform frame(Vec3 cx, Vec3 cy, Vec3 cz, Vec3 t) {
        double det = cx.dot(cy.cross(cz));
        if (!(det != 0) || !Double.isFinite(det)) throw new IllegalArgumentException("the columns of a frame must span space");
        Vec3 r0 = cy.cross(cz).div(det), r1 = cz.cross(cx).div(det), r2 = cx.cross(cy).div(det);
        double[] m = {cx.x(), cy.x(), cz.x(), t.x(), cx.y(), cy.y(), cz.y(), t.y(), cx.z(), cy.z(), cz.z(), t.z()};
        double[] inv = {r0.x(), r0.y(), r0.z(), -r0.dot(t), r1.x(), r1.y(), r1.z(), -r1.dot(t),
                r2.x(), r2.y(), r2.z(), -r2.dot(t)};
        return new Transform(m, inv);
    }

    /**
     * An orthonormal frame whose third axis is the unit vector {@code w}: the first axis is
     * perpendicular to w, built from the world axis least aligned with it.
     */
    public static Vec3[] axes(Vec3 w) {
        Vec3 a = Math.abs(w.x()) <= Math.abs(w.y()) && Math.abs(w.x()) <= Math.abs(w.z()) ? Vec3.X
                : Math.abs(w.y()) <= Math.abs(w.z()) ? Vec3.Y : Vec3.Z;
        Vec3 u = a.cross(w).normalize();
        return new Vec3[] {u, w.cross(u), w};
    }

    /** The transform that applies this one first, then {@code after}. */
    public Transform then(Transform after) {
        if (this == IDENTITY) return after;
        if (after == IDENTITY) return this;
        return new Transform(multiply(after.m, m), multiply(inv, after.inv));
    }

    private static double[] multiply(double[] a, double[] b) {
        double[] r = new double[12];
        for (int row = 0; row < 3; row++) {
            for (int col = 0; col < 4; col++) {
                double v = a[row * 4] * b[col] + a[row * 4 + 1] * b[4 + col] + a[row * 4 + 2] * b[8 + col];
                if (col == 3) v += a[row * 4 + 3];
                r[row * 4 + col] = v;
            }
        }
        return r;
    }

    public Transform inverse() { return new Transform(inv, m); }

    /** True when the matrix and its inverse hold only finite numbers, so the transform can be used and undone. */
    public boolean isFinite() {
        for (int i = 0; i < 12; i++) {
            if (!Double.isFinite(m[i]) || !Double.isFinite(inv[i])) return false;
        }
        return true;
    }

    public boolean isIdentity() { return this == IDENTITY || Arrays.equals(m, IDENTITY.m); }

    /** True when the linear part is the identity, so the transform only moves things. */
    public boolean isTranslation() {
        return m[0] == 1 && m[1] == 0 && m[2] == 0 && m[4] == 0 && m[5] == 1 && m[6] == 0
                && m[8] == 0 && m[9] == 0 && m[10] == 1;
    }

    public Vec3 translationPart() { return new Vec3(m[3], m[7], m[11]); }

    public Vec3 applyToPoint(Vec3 p) {
        return new Vec3(
                m[0] * p.x() + m[1] * p.y() + m[2] * p.z() + m[3],
                m[4] * p.x() + m[5] * p.y() + m[6] * p.z() + m[7],
                m[8] * p.x() + m[9] * p.y() + m[10] * p.z() + m[11]);
    }

    public Vec3 applyToVector(Vec3 v) {
        return new Vec3(
                m[0] * v.x() + m[1] * v.y() + m[2] * v.z(),
                m[4] * v.x() + m[5] * v.y() + m[6] * v.z(),
                m[8] * v.x() + m[9] * v.y() + m[10] * v.z());
    }

    /** Transforms a surface normal (by the inverse transpose); the result is not normalised. */
    public Vec3 applyToNormal(Vec3 n) {
        return new Vec3(
                inv[0] * n.x() + inv[4] * n.y() + inv[8] * n.z(),
                inv[1] * n.x() + inv[5] * n.y() + inv[9] * n.z(),
                inv[2] * n.x() + inv[6] * n.y() + inv[10] * n.z());
    }

    /** A copy of the forward matrix, row-major 3x4. */
    public double[] matrix() { return m.clone(); }

    /** A copy of the inverse matrix, row-major 3x4. */
    public double[] inverseMatrix() { return inv.clone(); }

    /** Writes the inverse matrix (row-major 3x4) into {@code out} from {@code at}, with no copy made on the way. */
    public void copyInverse(double[] out, int at) { System.arraycopy(inv, 0, out, at, 12); }

    @Override
    public boolean equals(Object o) {
        return o instanceof Transform t && Arrays.equals(m, t.m);
    }

    @Override
    public int hashCode() { return Arrays.hashCode(m); }

    @Override
    public String toString() { return "Transform" + Arrays.toString(m); }
}
