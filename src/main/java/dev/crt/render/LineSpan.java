package dev.crt.render;

import java.util.Arrays;

/**
 * Where a line o + t·d is inside one primitive solid: {@link #count} disjoint intervals in
 * increasing order, interval i from {@code tIn[i]} to {@code tOut[i]} (infinite for half-spaces),
 * with the face crossed at each end. A convex solid gives one interval, a torus up to two, a mesh
 * as many as it has pairs of crossings. Per-thread scratch: it grows when a shape needs more room
 * and is reused for every query after that.
 *
 * <p>An open surface (an uncapped tube) has no inside: {@link #surface} is then true and each
 * interval is one crossing, tIn = tOut.
 */
final class LineSpan {
    int count;
    boolean surface;
    double[] tIn = new double[2], tOut = new double[2];
    int[] faceIn = new int[2], faceOut = new int[2];
    /** Room for a shape's polynomial roots while it builds the intervals. */
    final double[] roots = new double[8];

    /** Sets the one interval of a convex solid. */
    void one(double in, double out, int fIn, int fOut) {
        tIn[0] = in;
        tOut[0] = out;
        faceIn[0] = fIn;
        faceOut[0] = fOut;
        count = 1;
        surface = false;
    }

    /** Appends an interval after the ones already there. */
    void add(double in, double out, int fIn, int fOut) {
        int i = count++;
        if (i == tIn.length) {
            int n = 2 * i;
            tIn = Arrays.copyOf(tIn, n);
            tOut = Arrays.copyOf(tOut, n);
            faceIn = Arrays.copyOf(faceIn, n);
            faceOut = Arrays.copyOf(faceOut, n);
        }
        tIn[i] = in;
        tOut[i] = out;
        faceIn[i] = fIn;
        faceOut[i] = fOut;
    }

    private Crossings crossings;

    /** This thread's scratch for collecting a mesh's crossings, made on first use. */
    Crossings crossings() {
        if (crossings == null) crossings = new Crossings();
        return crossings;
    }

    /** The crossings of one line with one mesh, with the sheared ray of the watertight test. */
    static final class Crossings {
        final double[] o = new double[3];
        double dx, dy, dz;
        int kx, ky, kz;
        double sx, sy, sz;
        int count;
        double[] t = new double[8];
        int[] triangle = new int[8];
        /** The sign of d·n for the triangle's winding normal n. */
        double[] facing = new double[8];
        final Ray localRay = new Ray();
        /** The nearest crossing found so far by a first-hit walk: its t, triangle and facing. */
        double nearT;
        int nearTriangle;
        double nearFacing;
        private BvhWalker walker;
        private int walkerDepth;

        void set(double ox, double oy, double oz, double dx, double dy, double dz, int kx, int ky, int kz, double sx,
                double sy, double sz) {
            o[0] = ox;
            o[1] = oy;
            o[2] = oz;
            this.dx = dx;
            this.dy = dy;
            this.dz = dz;
            this.kx = kx;
            this.ky = ky;
            this.kz = kz;
            this.sx = sx;
            this.sy = sy;
            this.sz = sz;
        }

        BvhWalker walker(int depth) {
            if (walker == null || depth > walkerDepth) {
                walker = new BvhWalker(depth);
                walkerDepth = depth;
            }
            return walker;
        }

        void add(double at, int tri, double side) {
            if (count == t.length) {
                t = Arrays.copyOf(t, 2 * count);
                triangle = Arrays.copyOf(triangle, 2 * count);
                facing = Arrays.copyOf(facing, 2 * count);
            }
            t[count] = at;
            triangle[count] = tri;
            facing[count] = side;
            count++;
        }

        /** Orders the crossings by distance (insertion: a line crosses few triangles of a mesh). */
        void sort() {
            for (int i = 1; i < count; i++) {
                double x = t[i], f = facing[i];
                int tri = triangle[i];
                int j = i;
                while (j > 0 && t[j - 1] > x) {
                    t[j] = t[j - 1];
                    triangle[j] = triangle[j - 1];
                    facing[j] = facing[j - 1];
                    j--;
                }
                t[j] = x;
                triangle[j] = tri;
                facing[j] = f;
            }
        }
    }
}
