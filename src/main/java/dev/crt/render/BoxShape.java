package dev.crt.render;

import dev.crt.geom.Aabb;
import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.Box;
import java.util.Arrays;

/**
 * The box: stored in world space as its corners when its transform keeps it axis-aligned
 * (translation, scale, quarter turns), else as its local corners under an {@link Affine}
 * placement (kind MAPPED_BOX). Faces are numbered 2·axis, +1 on the max side. Each face's uv run
 * from 0 to 1 across it, u along the next axis and v along the one after (x → y, z; y → z, x; z → x, y).
 */
final class BoxShape {
    private BoxShape() {}

    static void add(Shapes out, int s, Box b, Transform t) {
        double[] m = t.matrix();
        if (isScaledPermutation(m)) {
            Aabb w = new Aabb(b.min(), b.max()).transformed(t);
            out.kind[s] = Shapes.BOX;
            out.push(w.min().x(), w.min().y(), w.min().z(), w.max().x(), w.max().y(), w.max().z());
        } else {
            out.kind[s] = Shapes.MAPPED_BOX;
            out.pushMatrices(t);
            out.push(b.min().x(), b.min().y(), b.min().z(), b.max().x(), b.max().y(), b.max().z());
        }
        Aabb w = out.bounds(s);
        out.scale[s] = Math.max(Shapes.maxAbs(w.min()), Shapes.maxAbs(w.max()));
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

    static Aabb bounds(double[] a, int o) {
        return new Aabb(new Vec3(a[o], a[o + 1], a[o + 2]), new Vec3(a[o + 3], a[o + 4], a[o + 5]));
    }

    static Aabb mappedBounds(double[] a, int o) {
        Aabb local = new Aabb(new Vec3(a[o + 24], a[o + 25], a[o + 26]), new Vec3(a[o + 27], a[o + 28], a[o + 29]));
        double[] m = Arrays.copyOfRange(a, o + 12, o + 24);
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

    static boolean span(double[] a, int o, Ray ray, LineSpan out) {
        return slabs(ray.ox, ray.oy, ray.oz, ray.dx, ray.dy, ray.dz, ray.ix, ray.iy, ray.iz,
                a[o], a[o + 1], a[o + 2], a[o + 3], a[o + 4], a[o + 5], out);
    }

    static boolean mappedSpan(double[] a, int o, Ray ray, LineSpan out) {
        ray.toLocal(a, o);
        int b = o + 24;
        return slabs(ray.lox, ray.loy, ray.loz, ray.ldx, ray.ldy, ray.ldz, 1 / ray.ldx, 1 / ray.ldy, 1 / ray.ldz,
                a[b], a[b + 1], a[b + 2], a[b + 3], a[b + 4], a[b + 5], out);
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
        out.one(tin, tout, fin, fout);
        return true;
    }

    static void surface(double[] a, int o, int face, double px, double py, double pz, SurfacePoint out) {
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

    static void mappedSurface(double[] a, int o, int face, double px, double py, double pz, SurfacePoint out) {
        double lx = a[o] * px + a[o + 1] * py + a[o + 2] * pz + a[o + 3];
        double ly = a[o + 4] * px + a[o + 5] * py + a[o + 6] * pz + a[o + 7];
        double lz = a[o + 8] * px + a[o + 9] * py + a[o + 10] * pz + a[o + 11];
        int axis = face >> 1;
        double v = a[o + 24 + axis + ((face & 1) == 0 ? 0 : 3)];
        double sign = (face & 1) == 0 ? -1 : 1;
        if (axis == 0) lx = v;
        else if (axis == 1) ly = v;
        else lz = v;
        Affine.pointToWorld(a, o, lx, ly, lz, out);
        Affine.normalToWorld(a, o, axis == 0 ? sign : 0, axis == 1 ? sign : 0, axis == 2 ? sign : 0, out);
    }

    /** uv of the local point p on {@code face} of the box [lo, hi] at {@code b} in {@code a}, with its tangents. */
    private static void frame(double[] a, int b, int face, double x, double y, double z, SurfacePoint out) {
        int axis = face >> 1, ua = (axis + 1) % 3, va = (axis + 2) % 3;
        double ul = a[b + 3 + ua] - a[b + ua], vl = a[b + 3 + va] - a[b + va];
        out.u = ul > 0 ? (pick(ua, x, y, z) - a[b + ua]) / ul : 0;
        out.v = vl > 0 ? (pick(va, x, y, z) - a[b + va]) / vl : 0;
        out.tangents(ua == 0 ? ul : 0, ua == 1 ? ul : 0, ua == 2 ? ul : 0, va == 0 ? vl : 0, va == 1 ? vl : 0,
                va == 2 ? vl : 0);
    }

    private static double pick(int axis, double x, double y, double z) {
        return axis == 0 ? x : axis == 1 ? y : z;
    }

    static void frame(double[] a, int o, int face, SurfacePoint out) {
        frame(a, o, face, out.px, out.py, out.pz, out);
    }

    static void mappedFrame(double[] a, int o, int face, SurfacePoint out) {
        double px = out.px, py = out.py, pz = out.pz;
        double lx = a[o] * px + a[o + 1] * py + a[o + 2] * pz + a[o + 3];
        double ly = a[o + 4] * px + a[o + 5] * py + a[o + 6] * pz + a[o + 7];
        double lz = a[o + 8] * px + a[o + 9] * py + a[o + 10] * pz + a[o + 11];
        frame(a, o + 24, face, lx, ly, lz, out);
        Affine.tangentsToWorld(a, o, out.dpdux, out.dpduy, out.dpduz, out.dpdvx, out.dpdvy, out.dpdvz, out);
    }
}
