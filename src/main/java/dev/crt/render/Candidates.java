package dev.crt.render;

import dev.crt.geom.Aabb;
import java.util.Arrays;

/**
 * Short lists of the items a whole bundle of rays can meet, each found by one conservative walk of
 * the BVH, so that every ray of the bundle tests the list instead of walking the tree itself: per
 * {@value #BLOCK} × {@value #BLOCK} block of the image for pinhole camera rays, and per (shape, point
 * light) for the shadow rays leaving that shape's surface towards that light. One per render thread.
 *
 * <p>A list holds every item whose box (or, for a sphere, whose own box) meets the region all the
 * bundle's rays lie in, widened far beyond rounding, so a ray's hits among the listed items are
 * all its hits in the tree. Shadow lists keep the leaves' depth-first order, the order
 * {@link BvhWalker#nextAny} meets them in, so a product of transmittances is taken in the same
 * order to the bit; block lists are sorted by a lower bound of the distance to each item, so a ray
 * stops at the first item that starts beyond its nearest hit.
 */
final class Candidates {
    /** Side of a block of pixels sharing one list of primary candidates (fixed in image coordinates). */
    static final int BLOCK = 8;
    /** A block whose list would be longer is walked ray by ray. */
    static final int BLOCK_LIMIT = 128;
    /** A (shape, light) pair whose list would be longer keeps the walk. */
    static final int SHADOW_LIMIT = 48;
    /** Shadow rays a (shape, light) pair casts by the walk before its list is built: a shape lit once does not repay a list. */
    static final int SHADOW_AFTER = 4;
    /** Relative widening of every region test, far above the rounding of rays, hits and the tests themselves. */
    private static final double WIDEN = 1e-9;
    /** The record of the (shape, light) pair whose shadow ray is walking on trial, or −1. */
    private int trialKey = -1;
    /** The weight of a CSG tree or a mesh against a plain shape's test, in {@link #weight}. */
    static final int HEAVY = 8;
    /** A state of a (shape, light) pair: no list, always the walk. */
    private static final int WALK = Integer.MAX_VALUE;

    private final Bvh bvh;
    private final int[] items;
    private final Shapes shapes;
    private final Lights lights;
    private final int[] stack, stackSlot;
    /** Not a node: the walk's next step is to pop the stack. */
    private static final int POP = Integer.MAX_VALUE;
    /** The largest coordinate of the scene's bounded items, for margins relative to the scene's size. */
    private final double sceneSize;

    /** The current block (by its index in the image), or −1. */
    private int blockKey = -1;
    /** Items of the current block's list, and a lower bound of the distance from the camera to each, ascending; count −1: walk. */
    final int[] blockItems = new int[BLOCK_LIMIT];
    final double[] blockNear = new double[BLOCK_LIMIT];
    int blockCount;
    /** The frustum's five planes (four sides and the front) through the camera: normal and the margin to allow. */
    private final double[] plane = new double[5 * 4];
    /** The length of each plane's normal, for the lens's margin. */
    private final double[] normLength = new double[5];
    /** The camera's position: the pyramid's apex. */
    private double cx, cy, cz;
    /** A lens camera's radius (0 for a pinhole), its focal distance and its view axis. */
    private double lens, focal, vx, vy, vz;

    /**
     * More (shape, light) pairs than this keep the walk: their table would take more than 16 MB a
     * thread (a million spheres under four lights still fit).
     */
    private static final long MAX_PAIRS = 1L << 22;
    /** At most this many records a thread (72 bytes each); pairs and faces beyond keep the walk. */
    static final int MAX_RECORDS = 1 << 18;
    /** At most this many ints of lists a thread (16 MB); once full, no more lists are built. */
    static final int MAX_POOL = 1 << 22;
    /** A listed pair's region grows to take in an origin outside it at most this many times. */
    static final int MAX_GROWTHS = 8;
    /** Whether the scene has few enough pairs for shadow lists. */
    private final boolean shadowLists;
    /** Per shape × light: 0 unseen, {@link #WALK}, or 1 + the pair's first record. */
    private int[] state;
    /**
     * Per record, {@value #RECORD} ints: the walks taken on trial, their cost (see {@link #walked}), 1 + its
     * list's index in {@link #pool} (0: none yet, −1: walk), the growths left, the face (of a box;
     * else 0), 1 + the next record of the same pair (0: none); and six doubles in
     * {@link #regions}: the box of the origins seen (on trial) or covered by the list.
     */
    private int[] records = new int[RECORD * 64];
    /** Ints per record. */
    private static final int RECORD = 6;
    /** A record's list field (less 1) when its rays walk. */
    private static final int WALKS = -2;
    private int recordCount;
    /** The lists, each: its length, its record, then its items in depth-first leaf order. */
    int[] pool = new int[1024];
    private int poolSize;
    /** Per record: min x, y, z, max x, y, z. */
    private double[] regions = new double[6 * 64];
    /** The region box and the far box of the shadow list being built. */
    private final double[] hull = new double[12];

    Candidates(Bvh bvh, int[] items, Shapes shapes, Lights lights) {
        this.bvh = bvh;
        this.items = items;
        this.shapes = shapes;
        this.lights = lights;
        stack = new int[bvh.depth + 2];
        stackSlot = new int[bvh.depth + 2];
        double size = 0;
        for (double v : bvh.root) size = Math.max(size, Math.abs(v));
        sceneSize = size;
        shadowLists = (long) shapes.count() * lights.count <= MAX_PAIRS;
    }

    /**
     * Makes the current block list the one of the block holding pixel (i, j) of a camera whose
     * {@link CameraRays#framed} holds; returns false when that block's rays are to walk the tree (its list would be too long).
     */
    boolean block(CameraRays camera, int i, int j) {
        int width = (int) camera.width, height = (int) camera.height;
        int bx = i / BLOCK, by = j / BLOCK;
        int key = by * ((width + BLOCK - 1) / BLOCK) + bx;
        if (key != blockKey) {
            blockKey = key;
            buildBlock(camera, bx * BLOCK, Math.min(bx * BLOCK + BLOCK, width), by * BLOCK, Math.min(by * BLOCK + BLOCK, height));
        }
        return blockCount >= 0;
    }

    /** The list of the block of pixels i0 ≤ i < i1, j0 ≤ j < j1: every sub-pixel position of them included. */
    private void buildBlock(CameraRays c, int i0, int i1, int j0, int j1) {
        // CameraRays.direction: d ∝ f + a·r + b·u, a = (2(i + sx)/W − 1)·h·aspect, b = (1 − 2(j + sy)/H)·h.
        double ha = c.halfHeight * c.aspect;
        double a0 = (2.0 * i0 / c.width - 1) * ha, a1 = (2.0 * i1 / c.width - 1) * ha;
        double b0 = (1 - 2.0 * j1 / c.height) * c.halfHeight, b1 = (1 - 2.0 * j0 / c.height) * c.halfHeight;
        double wa = WIDEN * (1 + Math.abs(a0) + Math.abs(a1)), wb = WIDEN * (1 + Math.abs(b0) + Math.abs(b1));
        a0 -= wa;
        a1 += wa;
        b0 -= wb;
        b1 += wb;
        double am = (a0 + a1) / 2, bm = (b0 + b1) / 2;
        double mx = c.fx + am * c.rx + bm * c.ux, my = c.fy + am * c.ry + bm * c.uy, mz = c.fz + am * c.rz + bm * c.uz;
        cx = c.px;
        cy = c.py;
        cz = c.pz;
        // A lens ray meets the pinhole ray through the same point in focus there, and leaves the
        // lens at most R from the camera: at depth z along the view axis the two are at most
        // R·|1 − z/F| apart, so the sides are moved out by that much at the box's depths.
        lens = c.hasLens() ? c.lensRadius * (1 + 1e-6) : 0;
        focal = c.focalDistance;
        vx = c.fx;
        vy = c.fy;
        vz = c.fz;
        // Each side is spanned by one edge direction of the rectangle and the other axis of the image.
        side(0, c.fx + a0 * c.rx, c.fy + a0 * c.ry, c.fz + a0 * c.rz, c.ux, c.uy, c.uz, mx, my, mz);
        side(1, c.fx + a1 * c.rx, c.fy + a1 * c.ry, c.fz + a1 * c.rz, c.ux, c.uy, c.uz, mx, my, mz);
        side(2, c.fx + b0 * c.ux, c.fy + b0 * c.uy, c.fz + b0 * c.uz, c.rx, c.ry, c.rz, mx, my, mz);
        side(3, c.fx + b1 * c.ux, c.fy + b1 * c.uy, c.fz + b1 * c.uz, c.rx, c.ry, c.rz, mx, my, mz);
        setPlane(4, c.fx, c.fy, c.fz);
        blockCount = collect(true, blockItems, BLOCK_LIMIT);
        if (blockCount < 0) return;
        // Insertion sort by the lower bound (lists are short); ties keep the leaves' order.
        for (int k = 1; k < blockCount; k++) {
            double t = blockNear[k];
            int item = blockItems[k];
            int m = k - 1;
            while (m >= 0 && blockNear[m] > t) {
                blockNear[m + 1] = blockNear[m];
                blockItems[m + 1] = blockItems[m];
                m--;
            }
            blockNear[m + 1] = t;
            blockItems[m + 1] = item;
        }
    }

    /** Plane k through the camera containing directions e and g, its normal turned towards the direction m inside. */
    private void side(int k, double ex, double ey, double ez, double gx, double gy, double gz, double mx, double my, double mz) {
        double nx = ey * gz - ez * gy, ny = ez * gx - ex * gz, nz = ex * gy - ey * gx;
        if (nx * mx + ny * my + nz * mz < 0) {
            nx = -nx;
            ny = -ny;
            nz = -nz;
        }
        setPlane(k, nx, ny, nz);
    }

    private void setPlane(int k, double nx, double ny, double nz) {
        double[] p = plane;
        p[4 * k] = nx;
        p[4 * k + 1] = ny;
        p[4 * k + 2] = nz;
        normLength[k] = Math.sqrt(nx * nx + ny * ny + nz * nz);
        double camera = Math.max(Math.abs(cx), Math.max(Math.abs(cy), Math.abs(cz)));
        p[4 * k + 3] = WIDEN * (Math.abs(nx) + Math.abs(ny) + Math.abs(nz)) * (camera + sceneSize);
    }

    /** Whether the box may meet the frustum: no plane has the whole box outside it. */
    private boolean inFrustum(double x0, double y0, double z0, double x1, double y1, double z1) {
        double[] p = plane;
        double lx = x0 - cx, ly = y0 - cy, lz = z0 - cz, hx = x1 - cx, hy = y1 - cy, hz = z1 - cz;
        double spread = 0;
        if (lens > 0) {
            // R·|1 − z/F| is convex in z: its largest value over the box's depths is at one end.
            double mid = (lx + hx) / 2 * vx + (ly + hy) / 2 * vy + (lz + hz) / 2 * vz;
            double half = (hx - lx) / 2 * Math.abs(vx) + (hy - ly) / 2 * Math.abs(vy) + (hz - lz) / 2 * Math.abs(vz);
            spread = lens * Math.max(Math.abs(1 - (mid - half) / focal), Math.abs(1 - (mid + half) / focal)) * (1 + 1e-6);
        }
        for (int k = 0; k < 20; k += 4) {
            double nx = p[k], ny = p[k + 1], nz = p[k + 2];
            double far = (nx >= 0 ? nx * hx : nx * lx) + (ny >= 0 ? ny * hy : ny * ly) + (nz >= 0 ? nz * hz : nz * lz);
            // The front plane needs no margin: every lens ray leaves the lens plane forwards.
            double margin = k < 16 ? p[k + 3] + spread * normLength[k / 4] : p[k + 3];
            if (far < -margin) return false;
        }
        return true;
    }

    /**
     * A lower bound of the parameter t at which a camera ray (unit direction) meets anything inside
     * the box; a lens ray starts at most R from the camera.
     */
    private double nearest(double x0, double y0, double z0, double x1, double y1, double z1) {
        double dx = Math.max(0, Math.max(x0 - cx, cx - x1));
        double dy = Math.max(0, Math.max(y0 - cy, cy - y1));
        double dz = Math.max(0, Math.max(z0 - cz, cz - z1));
        double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
        // Hits of grazing rays are rounded by up to about √ε of their distance.
        return d - 1e-6 * d - lens - WIDEN * (sceneSize + Math.max(Math.abs(cx), Math.max(Math.abs(cy), Math.abs(cz))));
    }

    /**
     * The index in {@link #pool} of the shadow list of {@code shape} (a box: its face {@code face})
     * towards {@code light}, valid for a shadow ray from o; −1 when the ray is to walk the tree.
     *
     * <p>A list covers the region its pair's shadow rays came from, not the shape's whole box: the
     * box of the origins of its first {@value #SHADOW_AFTER} rays (which walk on trial), widened by
     * its own extent on each axis. A later origin outside it grows the region (the union, widened
     * again) and builds the list again, {@value #MAX_GROWTHS} times at most; after that such rays walk.
     */
    int shadow(int shape, int face, int light, double ox, double oy, double oz) {
        trialKey = -1;
        if (!shadowLists) return -1;
        int[] st = state;
        if (st == null) st = state = new int[shapes.count() * lights.count];
        int key = shape * lights.count + light;
        // A box's faces keep records of their own: the origins on one face lie in one plane.
        if (shapes.kind[shape] != Shapes.BOX) face = 0;
        int s = st[key];
        if (s == WALK) return -1;
        int[] rc = records;
        int rec;
        if (s == 0) {
            if (recordCount == MAX_RECORDS) {
                st[key] = WALK;
                return -1;
            }
            rec = newRecord(face);
            st[key] = 1 + rec;
            rc = records;
        } else {
            rec = s - 1;
            while (rc[RECORD * rec + 4] != face) {
                int next = rc[RECORD * rec + 5];
                if (next == 0) {
                    if (recordCount == MAX_RECORDS) return -1;
                    int added = newRecord(face);
                    rc = records;
                    rc[RECORD * rec + 5] = 1 + added;
                    next = 1 + added;
                }
                rec = next - 1;
            }
        }
        int ri = RECORD * rec, k = 6 * rec;
        double[] r = regions;
        int list = rc[ri + 2] - 1;
        if (list == WALKS) return -1;
        boolean inside = ox >= r[k] && oy >= r[k + 1] && oz >= r[k + 2] && ox <= r[k + 3] && oy <= r[k + 4] && oz <= r[k + 5];
        if (list >= 0) {
            if (inside) return list;
            if (rc[ri + 3] == 0) return -1;
            rc[ri + 3]--;
            int grown = grow(shape, light, rec, ox, oy, oz);
            if (grown < 0) rc[ri + 3] = 0;
            return grown;
        }
        if (rc[ri] < SHADOW_AFTER) {
            if (!inside) {
                r[k] = Math.min(r[k], ox);
                r[k + 1] = Math.min(r[k + 1], oy);
                r[k + 2] = Math.min(r[k + 2], oz);
                r[k + 3] = Math.max(r[k + 3], ox);
                r[k + 4] = Math.max(r[k + 4], oy);
                r[k + 5] = Math.max(r[k + 5], oz);
            }
            trialKey = rec;
            return -1;
        }
        int grown = grow(shape, light, rec, ox, oy, oz);
        if (grown < 0) rc[ri + 2] = WALKS + 1;
        return grown;
    }

    private int newRecord(int face) {
        int rec = recordCount++;
        if (records.length < RECORD * recordCount) {
            records = Arrays.copyOf(records, 2 * records.length);
            regions = Arrays.copyOf(regions, 2 * regions.length);
        }
        int ri = RECORD * rec;
        records[ri] = 0;
        records[ri + 1] = 0;
        records[ri + 2] = 0;
        records[ri + 3] = MAX_GROWTHS;
        records[ri + 4] = face;
        records[ri + 5] = 0;
        int k = 6 * rec;
        regions[k] = regions[k + 1] = regions[k + 2] = Double.POSITIVE_INFINITY;
        regions[k + 3] = regions[k + 4] = regions[k + 5] = Double.NEGATIVE_INFINITY;
        return rec;
    }

    /**
     * Widens record {@code rec}'s region to take in o, by the union's extent on each axis but never
     * past the shape's box widened by the tracer's offset (no origin lies outside it), and builds
     * its list for that region; the new list, or −1 when the pair is to walk (its list would be too
     * long, cost more than its trial walks did on average, or the pool is full). On −1 the region and
     * list stay as they were.
     */
    private int grow(int shape, int light, int rec, double ox, double oy, double oz) {
        Aabb b = shapes.bounds(shape);
        if (b.isEmpty() || !b.isFinite()) return -1;
        int ri = RECORD * rec, walks = records[ri];
        if (walks == 0) return -1;
        double walkedCost = (double) records[ri + 1] / walks;
        double x0 = b.min().x(), y0 = b.min().y(), z0 = b.min().z(), x1 = b.max().x(), y1 = b.max().y(), z1 = b.max().z();
        // The shadow ray leaves the hit point by Tracer's offset, at most OFFSET × max(|p|, scale).
        double big = Math.max(Math.max(Math.max(Math.abs(x0), Math.abs(x1)), Math.max(Math.abs(y0), Math.abs(y1))),
                Math.max(Math.max(Math.abs(z0), Math.abs(z1)), shapes.scale[shape]));
        double w = 4 * Tracer.OFFSET * big;
        double[] r = regions, h = hull;
        int k = 6 * rec;
        boolean first = records[ri + 2] == 0;
        for (int a = 0; a < 3; a++) {
            double o = a == 0 ? ox : a == 1 ? oy : oz, lo = r[k + a], hi = r[k + 3 + a];
            double bl = (a == 0 ? x0 : a == 1 ? y0 : z0) - w, bh = (a == 0 ? x1 : a == 1 ? y1 : z1) + w;
            // The first region is the trial origins' box widened by its extent on every side; a
            // growth widens only the sides o lies beyond, by the union's extent or at least 1/32
            // of the shape's, so that a few growths cover what the rays come from.
            double extent = Math.max(hi, o) - Math.min(lo, o), step = Math.max(extent, (bh - bl) / 32);
            double nl = first ? Math.min(lo, o) - extent : o < lo ? o - step : lo;
            double nh = first ? Math.max(hi, o) + extent : o > hi ? o + step : hi;
            // Clipped to the widened box, but always holding o (a region must hold the ray's origin).
            h[a] = Math.min(Math.max(nl, bl), o);
            h[3 + a] = Math.max(Math.min(nh, bh), o);
        }
        if (lights.kind[light] == Lights.PARALLEL) {
            // Every shadow ray runs along the light's direction w to infinity: the region box swept
            // along w. Swept by more than the diameter of the box around every item, nothing lies
            // beyond, so its far end may be a box moved that far.
            double wx = lights.x[light], wy = lights.y[light], wz = lights.z[light];
            double far = (4 * Math.sqrt(3) * (sceneSize + big) + 1) / Math.sqrt(wx * wx + wy * wy + wz * wz);
            for (int a = 0; a < 3; a++) {
                double wa = a == 0 ? wx : a == 1 ? wy : wz;
                h[6 + a] = h[a] + far * wa;
                h[9 + a] = h[3 + a] + far * wa;
            }
        } else {
            h[6] = h[9] = lights.x[light];
            h[7] = h[10] = lights.y[light];
            h[8] = h[11] = lights.z[light];
        }
        int at = poolSize;
        if (at + 2 + SHADOW_LIMIT > MAX_POOL) return -1;
        if (pool.length < at + 2 + SHADOW_LIMIT) pool = Arrays.copyOf(pool, Math.max(2 * pool.length, at + 2 + SHADOW_LIMIT));
        int n = collectInto(false, pool, at + 2, SHADOW_LIMIT, null);
        if (n < 0) return -1;
        double cost = 0;
        for (int i = at + 2; i < at + 2 + n; i++) cost += weight(pool[i]);
        if (cost > walkedCost) return -1;
        pool[at] = n;
        pool[at + 1] = rec;
        System.arraycopy(h, 0, r, k, 6);
        poolSize = at + 2 + n;
        records[ri + 2] = at + 1;
        return at;
    }

    /**
     * Records what the walk of the shadow ray the last {@link #shadow} call turned down cost, while
     * its pair is on trial: the walks it took (0 or 1), and their nodes opened plus their items
     * tested, weighed by {@link #weight} (a node's two box tests cost about a sphere's test).
     */
    void walked(int walks, int cost) {
        if (trialKey < 0 || walks == 0) return;
        int ri = RECORD * trialKey;
        records[ri] += walks;
        records[ri + 1] = (int) Math.min((long) records[ri + 1] + cost, Integer.MAX_VALUE);
        trialKey = -1;
    }

    /**
     * What testing an item costs, in tests of a plain shape: a CSG tree or a mesh gathers or walks
     * its own parts. {@link Tracer}'s walk counts its CSG trees the same way.
     */
    int weight(int item) {
        return item < 0 ? HEAVY : shapes.kind[item] == Shapes.MESH ? HEAVY : 1;
    }

    /**
     * Whether the box may meet the convex hull of the region box and the far box held in
     * {@link #hull} (the light's point, or the region box swept along a parallel light).
     */
    private boolean inHull(double x0, double y0, double z0, double x1, double y1, double z1) {
        double[] h = hull;
        // The hull is the union over s in [0, 1] of the region box moved s of the way to the far
        // box, a box whose faces move linearly in s: per axis two linear conditions on s, each a
        // half-line.
        double lo = 0, hi = 1;
        for (int a = 0; a < 3; a++) {
            double bl = h[a], bh = h[3 + a], ql = h[6 + a], qh = h[9 + a];
            double cl = a == 0 ? x0 : a == 1 ? y0 : z0, ch = a == 0 ? x1 : a == 1 ? y1 : z1;
            double m = WIDEN * (Math.abs(bl) + Math.abs(bh) + Math.abs(ql) + Math.abs(qh) + Math.abs(cl) + Math.abs(ch))
                    + Double.MIN_NORMAL;
            // The moving box's low face stays at or below the box's high face: bl + s(ql − bl) ≤ ch.
            double g0 = bl - ch - m, g1 = ql - ch - m;
            if (g0 > 0) {
                if (g1 > 0) return false;
                lo = Math.max(lo, g0 / (g0 - g1) - 1e-12);
            } else if (g1 > 0) {
                hi = Math.min(hi, g0 / (g0 - g1) + 1e-12);
            }
            // Its high face stays at or above the box's low face: cl − bh − s(qh − bh) ≤ 0.
            g0 = cl - bh - m;
            g1 = cl - qh - m;
            if (g0 > 0) {
                if (g1 > 0) return false;
                lo = Math.max(lo, g0 / (g0 - g1) - 1e-12);
            } else if (g1 > 0) {
                hi = Math.min(hi, g0 / (g0 - g1) + 1e-12);
            }
        }
        return lo <= hi;
    }

    private int collect(boolean frustum, int[] out, int limit) {
        return collectInto(frustum, out, 0, limit, blockNear);
    }

    /** Whether the box of child slot {@code k} (a node's offset in the box array plus 0 or 1) may meet the region. */
    private boolean meets(boolean frustum, double[] b, int k) {
        double x0 = b[k], y0 = b[k + 2], z0 = b[k + 4], x1 = b[k + Bvh.MAX], y1 = b[k + Bvh.MAX + 2], z1 = b[k + Bvh.MAX + 4];
        return frustum ? inFrustum(x0, y0, z0, x1, y1, z1) : inHull(x0, y0, z0, x1, y1, z1);
    }

    /**
     * Walks the tree depth first, left child first (the order of {@link BvhWalker#nextAny}), into
     * {@code out} from {@code at}: every item of every leaf whose boxes all meet the region, less
     * the spheres whose own box does not; with {@code near}, each item's lower bound of distance
     * (from the sphere's own box, else the leaf's). Returns the count, or −1 when it would pass
     * {@code limit}.
     */
    private int collectInto(boolean frustum, int[] out, int at, int limit, double[] near) {
        double[] b = bvh.box;
        int[] children = bvh.children, st = stack, slots = stackSlot;
        double[] root = bvh.root;
        if (!(frustum ? inFrustum(root[0], root[1], root[2], root[3], root[4], root[5])
                : inHull(root[0], root[1], root[2], root[3], root[4], root[5]))) return 0;
        int top = 0, n = 0, node = 0, slot = 0;
        while (true) {
            if (Bvh.isLeaf(node)) {
                for (int i = Bvh.leafFirst(node), end = i + Bvh.leafCount(node); i < end; i++) {
                    int item = items[i];
                    double x0 = b[slot], y0 = b[slot + 2], z0 = b[slot + 4];
                    double x1 = b[slot + Bvh.MAX], y1 = b[slot + Bvh.MAX + 2], z1 = b[slot + Bvh.MAX + 4];
                    int kind = item >= 0 ? shapes.kind[item] : -1;
                    if (kind == Shapes.SPHERE || kind == Shapes.BOX) {
                        double[] d = shapes.data;
                        int o = shapes.offset[item];
                        if (kind == Shapes.SPHERE) {
                            double r = d[o + 3];
                            x0 = d[o] - r;
                            y0 = d[o + 1] - r;
                            z0 = d[o + 2] - r;
                            x1 = d[o] + r;
                            y1 = d[o + 1] + r;
                            z1 = d[o + 2] + r;
                        } else {
                            x0 = d[o];
                            y0 = d[o + 1];
                            z0 = d[o + 2];
                            x1 = d[o + 3];
                            y1 = d[o + 4];
                            z1 = d[o + 5];
                        }
                        if (!(frustum ? inFrustum(x0, y0, z0, x1, y1, z1) : inHull(x0, y0, z0, x1, y1, z1))) continue;
                    }
                    if (n == limit) return -1;
                    if (near != null) near[at + n] = nearest(x0, y0, z0, x1, y1, z1);
                    out[at + n++] = item;
                }
                node = POP;
            } else {
                int k = Bvh.NODE * node;
                boolean left = meets(frustum, b, k), right = meets(frustum, b, k + 1);
                if (left) {
                    if (right) {
                        st[top] = children[2 * node + 1];
                        slots[top++] = k + 1;
                    }
                    node = children[2 * node];
                    slot = k;
                } else if (right) {
                    node = children[2 * node + 1];
                    slot = k + 1;
                } else {
                    node = POP;
                }
            }
            if (node == POP) {
                if (top == 0) return n;
                node = st[--top];
                slot = slots[top];
            }
        }
    }
}
