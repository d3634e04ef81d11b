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
}
