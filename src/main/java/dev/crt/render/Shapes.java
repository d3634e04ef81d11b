package dev.crt.render;

import dev.crt.geom.Aabb;
import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.Box;
import dev.crt.scene.Plane;
import dev.crt.scene.Primitive;
import dev.crt.scene.Sphere;
import java.util.Arrays;

/**
 * The primitives of a prepared scene as flat arrays, with the line–solid intersection and the
 * surface point/normal of each kind. A primitive whose transform keeps its shape simple is stored
 * in world space (a sphere under translation, rotation and uniform scale stays a sphere; a box
 * under translation, scale and quarter turns stays an axis-aligned box); only general transforms
 * pay for a matrix per ray.
 */
final class Shapes {
    static final int SPHERE = 0;
    static final int BOX = 1;
    static final int PLANE = 2;
    static final int MAPPED_SPHERE = 3;
    static final int MAPPED_BOX = 4;
    static final int EMPTY = 5;

    private int count;
    int[] kind = new int[16];
    int[] offset = new int[16];
    int[] material = new int[16];
    /** A length of the order of the primitive's coordinates, for scale-aware ray offsets. */
    double[] scale = new double[16];
    double[] data = new double[64];
    private int dataSize;

    int count() { return count; }

    /** Appends {@code p} placed by {@code toWorld}, returns its index. */
    int add(Primitive p, Transform toWorld, int materialIndex) {
        int s = next();
        material[s] = materialIndex;
        offset[s] = dataSize;
        if (p instanceof Sphere sp) addSphere(s, sp, toWorld);
        else if (p instanceof Box b) addBox(s, b, toWorld);
        else addPlane(s, (Plane) p, toWorld);
        return s;
    }

    /** Appends a copy of shape {@code s} of {@code from}, its material index included; returns its index. */
    int copy(Shapes from, int s) {
        int t = next();
        kind[t] = from.kind[s];
        material[t] = from.material[s];
        scale[t] = from.scale[s];
        offset[t] = dataSize;
        int start = from.offset[s], end = s + 1 < from.count ? from.offset[s + 1] : from.dataSize;
        int length = end - start;
        if (dataSize + length > data.length) data = Arrays.copyOf(data, Math.max(data.length * 2, dataSize + length));
        System.arraycopy(from.data, start, data, dataSize, length);
        dataSize += length;
        return t;
    }

    private int next() {
        int s = count++;
        if (s == kind.length) {
            int n = s * 2;
            kind = Arrays.copyOf(kind, n);
            offset = Arrays.copyOf(offset, n);
            material = Arrays.copyOf(material, n);
            scale = Arrays.copyOf(scale, n);
        }
        return s;
    }

    private void addSphere(int s, Sphere sp, Transform t) {
        if (!(sp.radius() > 0)) {
            kind[s] = EMPTY;
            return;
        }
        if (t == Transform.IDENTITY) {
            Vec3 c = sp.center();
            double r = sp.radius();
            kind[s] = SPHERE;
            push(c.x(), c.y(), c.z(), r, r * r);
            scale[s] = maxAbs(c) + r;
            return;
        }
        double[] m = t.matrix();
        double c0 = m[0] * m[0] + m[4] * m[4] + m[8] * m[8];
        double c1 = m[1] * m[1] + m[5] * m[5] + m[9] * m[9];
        double c2 = m[2] * m[2] + m[6] * m[6] + m[10] * m[10];
        double d01 = m[0] * m[1] + m[4] * m[5] + m[8] * m[9];
        double d02 = m[0] * m[2] + m[4] * m[6] + m[8] * m[10];
        double d12 = m[1] * m[2] + m[5] * m[6] + m[9] * m[10];
        double tol = 1e-14 * c0;
        boolean similarity = Math.abs(c1 - c0) <= tol && Math.abs(c2 - c0) <= tol
                && Math.abs(d01) <= tol && Math.abs(d02) <= tol && Math.abs(d12) <= tol;
        if (similarity) {
            Vec3 c = t.applyToPoint(sp.center());
            double r = sp.radius() * Math.sqrt(c0);
            kind[s] = SPHERE;
            push(c.x(), c.y(), c.z(), r, r * r);
            scale[s] = maxAbs(c) + r;
        } else {
            // Object space is the unit ball at the origin.
            Transform unit = Transform.scaling(new Vec3(sp.radius(), sp.radius(), sp.radius()))
                    .then(Transform.translation(sp.center())).then(t);
            kind[s] = MAPPED_SPHERE;
            pushMatrices(unit);
            Aabb b = bounds(s);
            scale[s] = Math.max(maxAbs(b.min()), maxAbs(b.max()));
        }
    }

    private void addBox(int s, Box b, Transform t) {
        double[] m = t.matrix();
        if (isScaledPermutation(m)) {
            Aabb w = new Aabb(b.min(), b.max()).transformed(t);
            kind[s] = BOX;
            push(w.min().x(), w.min().y(), w.min().z(), w.max().x(), w.max().y(), w.max().z());
        } else {
            kind[s] = MAPPED_BOX;
            pushMatrices(t);
            push(b.min().x(), b.min().y(), b.min().z(), b.max().x(), b.max().y(), b.max().z());
        }
        Aabb w = bounds(s);
        scale[s] = Math.max(maxAbs(w.min()), maxAbs(w.max()));
    }

    /** True when every row and column of the linear part has exactly one non-zero entry. */
    private static boolean isScaledPermutation(double[] m) {
        for (int i = 0; i < 3; i++) {
            int row = 0, col = 0;
            for (int j = 0; j < 3; j++) {
                if (m[i * 4 + j] != 0) row++;
                if (m[j * 4 + i] != 0) col++;
            }
            if (row != 1 || col != 1) return false;
        }
        return true;
    }

    private void addPlane(int s, Plane p, Transform t) {
        Vec3 n = t.applyToNormal(p.normal()).normalize();
        Vec3 q = t.applyToPoint(p.position());
        double h = n.dot(q);
        kind[s] = PLANE;
        push(n.x(), n.y(), n.z(), h);
        scale[s] = Math.abs(h);
    }

    private void pushMatrices(Transform t) {
        double[] inv = t.inverseMatrix();
        double[] m = t.matrix();
        for (double v : inv) push(v);
        for (double v : m) push(v);
    }

    private void push(double... values) {
        if (dataSize + values.length > data.length) {
            data = Arrays.copyOf(data, Math.max(data.length * 2, dataSize + values.length));
        }
        System.arraycopy(values, 0, data, dataSize, values.length);
        dataSize += values.length;
    }

    private static double maxAbs(Vec3 v) {
        return Math.max(Math.abs(v.x()), Math.max(Math.abs(v.y()), Math.abs(v.z())));
    }

    /** Whether shape {@code s} is a plane (one-sided in the 2015 shading model). */
    boolean isPlane(int s) { return kind[s] == PLANE; }

    /** World bounds of shape {@code s}; infinite for planes, empty for invisible shapes. */
    Aabb bounds(int s) {
        int o = offset[s];
        switch (kind[s]) {
            case SPHERE -> {
                double r = data[o + 3];
                return new Aabb(new Vec3(data[o] - r, data[o + 1] - r, data[o + 2] - r),
                        new Vec3(data[o] + r, data[o + 1] + r, data[o + 2] + r));
            }
            case BOX -> {
                return new Aabb(new Vec3(data[o], data[o + 1], data[o + 2]),
                        new Vec3(data[o + 3], data[o + 4], data[o + 5]));
            }
            case MAPPED_SPHERE -> {
                // The ellipsoid M·(unit ball) + t reaches |row i of M| along world axis i.
                int m = o + 12;
                double[] lo = new double[3], hi = new double[3];
                for (int i = 0; i < 3; i++) {
                    double a = data[m + i * 4], b = data[m + i * 4 + 1], c = data[m + i * 4 + 2];
                    double e = Math.sqrt(a * a + b * b + c * c);
                    lo[i] = data[m + i * 4 + 3] - e;
                    hi[i] = data[m + i * 4 + 3] + e;
                }
                return new Aabb(new Vec3(lo[0], lo[1], lo[2]), new Vec3(hi[0], hi[1], hi[2]));
            }
            case MAPPED_BOX -> {
                Aabb local = new Aabb(new Vec3(data[o + 24], data[o + 25], data[o + 26]),
                        new Vec3(data[o + 27], data[o + 28], data[o + 29]));
                double[] m = Arrays.copyOfRange(data, o + 12, o + 24);
                Aabb r = Aabb.EMPTY;
                for (int i = 0; i < 8; i++) {
                    double x = (i & 1) == 0 ? local.min().x() : local.max().x();
                    double y = (i & 2) == 0 ? local.min().y() : local.max().y();
                    double z = (i & 4) == 0 ? local.min().z() : local.max().z();
                    Vec3 p = new Vec3(m[0] * x + m[1] * y + m[2] * z + m[3],
                            m[4] * x + m[5] * y + m[6] * z + m[7], m[8] * x + m[9] * y + m[10] * z + m[11]);
                    r = new Aabb(r.min().min(p), r.max().max(p));
                }
                return r;
            }
            case PLANE -> {
                return Aabb.INFINITE;
            }
            default -> {
                return Aabb.EMPTY;
            }
        }
    }

    /**
     * Intersects the line of {@code ray} with the solid {@code s}; on success writes the parameter
     * interval inside the solid (±∞ where it never leaves) and the faces crossed into {@code out}.
     */
    boolean span(int s, Ray ray, LineSpan out) {
        int o = offset[s];
        double[] a = data;
        switch (kind[s]) {
            case SPHERE:
                return sphereSpan(ray.ox - a[o], ray.oy - a[o + 1], ray.oz - a[o + 2], ray.dx, ray.dy, ray.dz,
                        a[o + 4], out);
            case BOX:
                return slabs(ray.ox, ray.oy, ray.oz, ray.dx, ray.dy, ray.dz, ray.ix, ray.iy, ray.iz,
                        a[o], a[o + 1], a[o + 2], a[o + 3], a[o + 4], a[o + 5], out);
            case PLANE: {
                double dn = a[o] * ray.dx + a[o + 1] * ray.dy + a[o + 2] * ray.dz;
                double on = a[o] * ray.ox + a[o + 1] * ray.oy + a[o + 2] * ray.oz;
                double h = a[o + 3];
                out.faceIn = 0;
                out.faceOut = 0;
                if (dn == 0) {
                    out.tIn = Double.NEGATIVE_INFINITY;
                    out.tOut = Double.POSITIVE_INFINITY;
                    return on <= h;
                }
                double t = (h - on) / dn;
                if (dn < 0) {
                    out.tIn = t;
                    out.tOut = Double.POSITIVE_INFINITY;
                } else {
                    out.tIn = Double.NEGATIVE_INFINITY;
                    out.tOut = t;
                }
                return true;
            }
            case MAPPED_SPHERE: {
                double ox = a[o] * ray.ox + a[o + 1] * ray.oy + a[o + 2] * ray.oz + a[o + 3];
                double oy = a[o + 4] * ray.ox + a[o + 5] * ray.oy + a[o + 6] * ray.oz + a[o + 7];
                double oz = a[o + 8] * ray.ox + a[o + 9] * ray.oy + a[o + 10] * ray.oz + a[o + 11];
                double dx = a[o] * ray.dx + a[o + 1] * ray.dy + a[o + 2] * ray.dz;
                double dy = a[o + 4] * ray.dx + a[o + 5] * ray.dy + a[o + 6] * ray.dz;
                double dz = a[o + 8] * ray.dx + a[o + 9] * ray.dy + a[o + 10] * ray.dz;
                return sphereSpan(ox, oy, oz, dx, dy, dz, 1, out);
            }
            case MAPPED_BOX: {
                double ox = a[o] * ray.ox + a[o + 1] * ray.oy + a[o + 2] * ray.oz + a[o + 3];
                double oy = a[o + 4] * ray.ox + a[o + 5] * ray.oy + a[o + 6] * ray.oz + a[o + 7];
                double oz = a[o + 8] * ray.ox + a[o + 9] * ray.oy + a[o + 10] * ray.oz + a[o + 11];
                double dx = a[o] * ray.dx + a[o + 1] * ray.dy + a[o + 2] * ray.dz;
                double dy = a[o + 4] * ray.dx + a[o + 5] * ray.dy + a[o + 6] * ray.dz;
                double dz = a[o + 8] * ray.dx + a[o + 9] * ray.dy + a[o + 10] * ray.dz;
                int b = o + 24;
                return slabs(ox, oy, oz, dx, dy, dz, 1 / dx, 1 / dy, 1 / dz,
                        a[b], a[b + 1], a[b + 2], a[b + 3], a[b + 4], a[b + 5], out);
            }
            default:
                return false;
        }
    }

    /**
     * The ball |p| ≤ √r2 about the origin against the line oc + t·d, in the numerically stable
     * form: the discriminant is taken from the closest approach oc − (b/a)d, which keeps its
     * precision for far-away origins, and the small root comes from c/q without cancellation.
     */
    private static boolean sphereSpan(double ocx, double ocy, double ocz, double dx, double dy, double dz,
            double r2, LineSpan out) {
        double a = dx * dx + dy * dy + dz * dz;
        double b = ocx * dx + ocy * dy + ocz * dz;
        double k = b / a;
        double fx = ocx - k * dx, fy = ocy - k * dy, fz = ocz - k * dz;
        double disc = r2 - (fx * fx + fy * fy + fz * fz);
        if (!(disc >= 0)) return false;
        double c = ocx * ocx + ocy * ocy + ocz * ocz - r2;
        double q = b >= 0 ? -b - Math.sqrt(a * disc) : -b + Math.sqrt(a * disc);
        double t0, t1;
        if (q == 0) {
            t0 = 0;
            t1 = 0;
        } else {
            t0 = c / q;
            t1 = q / a;
            if (t0 > t1) {
                double x = t0;
                t0 = t1;
                t1 = x;
            }
        }
        out.tIn = t0;
        out.tOut = t1;
        out.faceIn = 0;
        out.faceOut = 0;
        return true;
    }

    /** The slab test with faces numbered 2·axis (+1 on the max side); parallel axes are decided exactly. */
    private static boolean slabs(double ox, double oy, double oz, double dx, double dy, double dz,
            double ix, double iy, double iz, double x0, double y0, double z0, double x1, double y1, double z1,
            LineSpan out) {
        double tin = Double.NEGATIVE_INFINITY, tout = Double.POSITIVE_INFINITY;
        int fin = -1, fout = -1;
        if (dx == 0) {
            if (ox < x0 || ox > x1) return false;
        } else {
            double ta = (x0 - ox) * ix, tb = (x1 - ox) * ix;
            if (ta <= tb) {
                tin = ta;
                fin = 0;
                tout = tb;
                fout = 1;
            } else {
                tin = tb;
                fin = 1;
                tout = ta;
                fout = 0;
            }
        }
        if (dy == 0) {
            if (oy < y0 || oy > y1) return false;
        } else {
            double ta = (y0 - oy) * iy, tb = (y1 - oy) * iy;
            int fa = 2, fb = 3;
            if (ta > tb) {
                double x = ta;
                ta = tb;
                tb = x;
                fa = 3;
                fb = 2;
            }
            if (ta > tin) {
                tin = ta;
                fin = fa;
            }
            if (tb < tout) {
                tout = tb;
                fout = fb;
            }
        }
        if (dz == 0) {
            if (oz < z0 || oz > z1) return false;
        } else {
            double ta = (z0 - oz) * iz, tb = (z1 - oz) * iz;
            int fa = 4, fb = 5;
            if (ta > tb) {
                double x = ta;
                ta = tb;
                tb = x;
                fa = 5;
                fb = 4;
            }
            if (ta > tin) {
                tin = ta;
                fin = fa;
            }
            if (tb < tout) {
                tout = tb;
                fout = fb;
            }
        }
        if (tin > tout) return false;
        out.tIn = tin;
        out.tOut = tout;
        out.faceIn = fin;
        out.faceOut = fout;
        return true;
    }

    /**
     * The surface point of shape {@code s} at parameter {@code t} of {@code ray} on {@code face},
     * snapped back onto the exact surface (so its error scales with its own coordinates, not with the
     * ray's length), and the primitive's outward unit normal there.
     */
    void surface(int s, int face, double t, Ray ray, SurfacePoint out) {
        int o = offset[s];
        double[] a = data;
        double px = ray.ox + t * ray.dx, py = ray.oy + t * ray.dy, pz = ray.oz + t * ray.dz;
        switch (kind[s]) {
            case SPHERE -> {
                double vx = px - a[o], vy = py - a[o + 1], vz = pz - a[o + 2];
                double inv = 1 / Math.sqrt(vx * vx + vy * vy + vz * vz);
                double nx = vx * inv, ny = vy * inv, nz = vz * inv;
                double r = a[o + 3];
                out.nx = nx;
                out.ny = ny;
                out.nz = nz;
                out.px = a[o] + nx * r;
                out.py = a[o + 1] + ny * r;
                out.pz = a[o + 2] + nz * r;
            }
            case BOX -> {
                int axis = face >> 1;
                double v = a[o + axis + ((face & 1) == 0 ? 0 : 3)];
                double sign = (face & 1) == 0 ? -1 : 1;
                out.px = axis == 0 ? v : px;
                out.py = axis == 1 ? v : py;
                out.pz = axis == 2 ? v : pz;
                out.nx = axis == 0 ? sign : 0;
                out.ny = axis == 1 ? sign : 0;
                out.nz = axis == 2 ? sign : 0;
            }
            case PLANE -> {
                double nx = a[o], ny = a[o + 1], nz = a[o + 2];
                double e = nx * px + ny * py + nz * pz - a[o + 3];
                out.px = px - e * nx;
                out.py = py - e * ny;
                out.pz = pz - e * nz;
                out.nx = nx;
                out.ny = ny;
                out.nz = nz;
            }
            case MAPPED_SPHERE -> {
                double lx = a[o] * px + a[o + 1] * py + a[o + 2] * pz + a[o + 3];
                double ly = a[o + 4] * px + a[o + 5] * py + a[o + 6] * pz + a[o + 7];
                double lz = a[o + 8] * px + a[o + 9] * py + a[o + 10] * pz + a[o + 11];
                double inv = 1 / Math.sqrt(lx * lx + ly * ly + lz * lz);
                lx *= inv;
                ly *= inv;
                lz *= inv;
                toWorld(a, o, lx, ly, lz, out);
                normalToWorld(a, o, lx, ly, lz, out);
            }
            case MAPPED_BOX -> {
                double lx = a[o] * px + a[o + 1] * py + a[o + 2] * pz + a[o + 3];
                double ly = a[o + 4] * px + a[o + 5] * py + a[o + 6] * pz + a[o + 7];
                double lz = a[o + 8] * px + a[o + 9] * py + a[o + 10] * pz + a[o + 11];
                int axis = face >> 1;
                double v = a[o + 24 + axis + ((face & 1) == 0 ? 0 : 3)];
                double sign = (face & 1) == 0 ? -1 : 1;
                if (axis == 0) lx = v;
                else if (axis == 1) ly = v;
                else lz = v;
                toWorld(a, o, lx, ly, lz, out);
                normalToWorld(a, o, axis == 0 ? sign : 0, axis == 1 ? sign : 0, axis == 2 ? sign : 0, out);
            }
            default -> throw new IllegalStateException("no surface on shape kind " + kind[s]);
        }
    }

    private static void toWorld(double[] a, int o, double x, double y, double z, SurfacePoint out) {
        int m = o + 12;
        out.px = a[m] * x + a[m + 1] * y + a[m + 2] * z + a[m + 3];
        out.py = a[m + 4] * x + a[m + 5] * y + a[m + 6] * z + a[m + 7];
        out.pz = a[m + 8] * x + a[m + 9] * y + a[m + 10] * z + a[m + 11];
    }

    /** Normals map by the inverse transpose: the world normal's i-th component is Σj inv[j][i]·n[j]. */
    private static void normalToWorld(double[] a, int o, double x, double y, double z, SurfacePoint out) {
        double nx = a[o] * x + a[o + 4] * y + a[o + 8] * z;
        double ny = a[o + 1] * x + a[o + 5] * y + a[o + 9] * z;
        double nz = a[o + 2] * x + a[o + 6] * y + a[o + 10] * z;
        double inv = 1 / Math.sqrt(nx * nx + ny * ny + nz * nz);
        out.nx = nx * inv;
        out.ny = ny * inv;
        out.nz = nz * inv;
    }
}
