package dev.crt.render;

import java.util.SplittableRandom;

/** A fixed set of rays (origins, unit directions, lengths) that benchmarks cycle through. */
final class RayBatch {
    static final int SIZE = 1024;
    final double[] o = new double[3 * SIZE], d = new double[3 * SIZE], tMax = new double[SIZE];
    private int next;

    /** Rays from the point {@code from} to random points of the box [lo, hi]. */
    static RayBatch fromPoint(double[] from, double[] lo, double[] hi, long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        RayBatch b = new RayBatch();
        for (int i = 0; i < SIZE; i++) {
            double[] to = new double[3];
            for (int a = 0; a < 3; a++) to[a] = lo[a] + (hi[a] - lo[a]) * r.nextDouble();
            b.set(i, from, to, Double.POSITIVE_INFINITY);
        }
        return b;
    }

    /** Segments from random points of the box [lo, hi] to the point {@code to} (shadow rays towards a light). */
    static RayBatch toPoint(double[] lo, double[] hi, double[] to, long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        RayBatch b = new RayBatch();
        for (int i = 0; i < SIZE; i++) {
            double[] from = new double[3];
            for (int a = 0; a < 3; a++) from[a] = lo[a] + (hi[a] - lo[a]) * r.nextDouble();
            b.set(i, from, to, -1);
        }
        return b;
    }

    /** tMax < 0: the segment's length. */
    private void set(int i, double[] from, double[] to, double t) {
        double dx = to[0] - from[0], dy = to[1] - from[1], dz = to[2] - from[2];
        double length = Math.sqrt(dx * dx + dy * dy + dz * dz);
        for (int a = 0; a < 3; a++) o[3 * i + a] = from[a];
        d[3 * i] = dx / length;
        d[3 * i + 1] = dy / length;
        d[3 * i + 2] = dz / length;
        tMax[i] = t < 0 ? length : t;
    }

    /** The index of the next ray, cycling. */
    int next() {
        int i = next;
        next = (i + 1) & (SIZE - 1);
        return i;
    }

    /** The nearest hit distance of ray i, or −1. */
    double closest(Tracer t, int i) {
        return t.closestHit(o[3 * i], o[3 * i + 1], o[3 * i + 2], d[3 * i], d[3 * i + 1], d[3 * i + 2], tMax[i]) ? t.hit.t : -1;
    }

    /** The shadow factor of ray i towards light 0. */
    double transmittance(Tracer t, int i) {
        return t.transmittance(o[3 * i], o[3 * i + 1], o[3 * i + 2], d[3 * i], d[3 * i + 1], d[3 * i + 2], tMax[i], 0, -1);
    }

    /** How many of the rays hit something: to check in set-up that a batch does what its benchmark says. */
    int hits(Tracer t) {
        int n = 0;
        for (int i = 0; i < SIZE; i++) if (closest(t, i) >= 0) n++;
        return n;
    }
}
