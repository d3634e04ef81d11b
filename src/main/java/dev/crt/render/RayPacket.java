package dev.crt.render;

/**
 * Up to {@link #SIZE} rays walked through the scene's BVH together ({@link PacketWalker}), as
 * arrays per component so the walk's loop over the rays of a node reads them in a row; each ray
 * also keeps a {@link Ray} and a {@link Hit} of its own for the leaf tests, so a packet's nearest
 * hits are found by the same item tests as a lone ray's. Per-thread scratch, filled and reused.
 */
final class RayPacket {
    /** At most this many rays: a ray's place in the packet is a bit of a long. */
    static final int SIZE = 64;

    final double[] ox = new double[SIZE], oy = new double[SIZE], oz = new double[SIZE];
    final double[] dx = new double[SIZE], dy = new double[SIZE], dz = new double[SIZE];
    final double[] ix = new double[SIZE], iy = new double[SIZE], iz = new double[SIZE];
    /** Per ray, the slots in a BVH node of the left child's near and far plane of each axis (as in {@link BvhWalker}). */
    final int[] nearX = new int[SIZE], farX = new int[SIZE], nearY = new int[SIZE], farY = new int[SIZE];
    final int[] nearZ = new int[SIZE], farZ = new int[SIZE];
    /** Per ray, the far end of the search: the nearest hit so far. */
    final double[] tMax = new double[SIZE];
    final Ray[] rays = new Ray[SIZE];
    final Hit[] hits = new Hit[SIZE];
    final boolean[] found = new boolean[SIZE];
    int count;

    RayPacket() {
        for (int r = 0; r < SIZE; r++) {
            rays[r] = new Ray();
            hits[r] = new Hit();
        }
    }

    /** Puts the ray o + t·d in place {@code r}, searched over 0 &lt; t &lt; ∞, nothing found yet. */
    void set(int r, double ox, double oy, double oz, double dx, double dy, double dz) {
        Ray ray = rays[r];
        ray.set(ox, oy, oz, dx, dy, dz);
        this.ox[r] = ox;
        this.oy[r] = oy;
        this.oz[r] = oz;
        this.dx[r] = dx;
        this.dy[r] = dy;
        this.dz[r] = dz;
        ix[r] = ray.ix;
        iy[r] = ray.iy;
        iz[r] = ray.iz;
        // The same choice as BvhWalker.start: a component of −0 counts as negative.
        int nx = ray.ix >= 0 ? 0 : Bvh.MAX, ny = ray.iy >= 0 ? 0 : Bvh.MAX, nz = ray.iz >= 0 ? 0 : Bvh.MAX;
        nearX[r] = nx;
        farX[r] = nx ^ Bvh.MAX;
        nearY[r] = 2 + ny;
        farY[r] = 2 + (ny ^ Bvh.MAX);
        nearZ[r] = 4 + nz;
        farZ[r] = 4 + (nz ^ Bvh.MAX);
        tMax[r] = Double.POSITIVE_INFINITY;
        found[r] = false;
    }

    /** The mask of rays 0 … count − 1. */
    long all() {
        return count == SIZE ? -1L : (1L << count) - 1;
    }
}
