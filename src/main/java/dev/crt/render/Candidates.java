package dev.crt.render;

import dev.crt.geom.Aabb;
import java.util.Arrays;

/**
 * Short lists of the items a whole bundle of rays can meet, each found by one conservative walk of
 * the BVH, so that every ray of the bundle tests the list instead of walking the tree itself: per
 * {@value #BLOCK} × {@value #BLOCK} block of the image for camera rays, per (shape, light) (a box:
 * per face) for the shadow rays leaving that surface towards that light, and per (shape, face) for
 * the mirror-reflected rays leaving it. One per render thread.
 *
 * <p>A list holds every item whose box (or, for a sphere or a box, whose own box) meets the region
 * all the bundle's rays lie in, widened far beyond rounding, so a ray's hits among the listed items
 * are all its hits in the tree. Shadow lists keep the leaves' depth-first order, the order
 * {@link BvhWalker#nextAny} meets them in, so a product of transmittances is taken in the same
 * order to the bit; block and reflected-ray lists are sorted by a lower bound of the ray parameter
 * at each item, so a ray stops at the first item that starts beyond its nearest hit.
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
    /**
     * Reflected rays a (shape, face) record walks before its list is built: their lists are dearer
     * to build (a sweep to the scene's end) and a face seen by few rays (one sample a pixel) does not
     * repay one (measured on the box field, section 28).
     */
    static final int REFLECTED_AFTER = 16;
    /** How many times its trial walks' average cost a reflected-ray list may weigh (see {@link #grow}). */
    static final double REFLECTED_WEIGHT = 1.5;
    /** Relative widening of every region test, far above the rounding of rays, hits and the tests themselves. */
    private static final double WIDEN = 1e-9;
    /** The weight of a mesh against a plain shape's test, in {@link #weight}: its own BVH is walked. */
    static final int HEAVY = 8;
    /**
     * The weight of a CSG tree, in {@link #weight}: a list tests its bounds first (a bowl cut from a
     * ball has the bowl's), which turns most rays away, and a walk reaches it only through a box
     * around it. Weighed as a mesh (8), drops.crt's bowls kept most mirror rays off lists (section 44).
     */
    static final int CSG_WEIGHT = 2;

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
    /** At most this many records a thread (120 bytes each); rays they would cover keep the walk. */
    static final int MAX_RECORDS = 1 << 17;
    /** At most this many ints (and as many bounds) of lists a thread (48 MB); once full, no more lists are built. */
    static final int MAX_POOL = 1 << 22;
    /** Records a key keeps per face of a box: regions apart on one face (a list that could not grow) get records of their own. */
    static final int MAX_SIBLINGS = 4;
    /** A record's region grows to take in a ray outside it at most this many times. */
    static final int MAX_GROWTHS = 4;
    /** Whether the scene has few enough pairs for lists. */
    private final boolean lists;
    /**
     * Per key, 0 unseen or 1 + the index of its heads in {@link #faceHeads}: key shape × lights +
     * light for the shadow rays of (shape, light), shapes × lights + shape for the mirror-reflected
     * rays leaving the shape.
     */
    private int[] state;
    /**
     * Per key and face (six for a box, one for other shapes): 0 or 1 + the first of its records; at
     * most {@link #MAX_RECORDS}; {@link #ALL_WALK} once the face has all the records it may have and
     * every one walks (found by one search, and no longer searched for every ray).
     */
    private int[] faceHeads = new int[256];
    private static final int ALL_WALK = -1;
    private int headCount;
    /**
     * Per record, {@value #RECORD} ints: the walks taken on trial, their cost (see {@link #walked}),
     * 1 + its list's index in {@link #pool} (0: none yet, −1: walk), the growths left, the face (of
     * a box; else 0), 1 + the next record of the key and face (0: none); and 12 doubles in {@link #regions}.
     */
    private int[] records = new int[RECORD * 64];
    /** Ints per record. */
    private static final int RECORD = 6;
    /** A record's list field (less 1) when its rays walk. */
    private static final int WALKS = -2;
    private int recordCount;
    /**
     * Per record: the box its rays' origins lie in (min x, y, z, max x, y, z), then the box their
     * directions lie in (reflected rays; ±∞ for shadow rays, whose direction the light fixes).
     */
    private double[] regions = new double[12 * 64];
    /**
     * The lists, each: its length, then its items: a shadow list in depth-first leaf order, a
     * reflected-ray list by ascending lower bound of the ray parameter, held at the same index in
     * {@link #near}.
     */
    int[] pool = new int[1024];
    double[] near = new double[1024];
    private int poolSize;
    /**
     * Per light (and one more for reflected rays), {@link #WAYS} entries, a shape's face hashed to
     * one: the key and record whose list the last listed ray from there took, tested first, since
     * neighbouring rays mostly leave the same face (only records with a list are cached, so its list
     * field is one). A pixel's rays alternate between the surfaces its camera rays and their
     * reflections hit: one entry per light sent half of drops.crt's shadow rays to {@link #search}.
     */
    private final int[] cacheKey, cacheRecord;
    static final int LOG_WAYS = 3, WAYS = 1 << LOG_WAYS;
    /** Calls of {@link #search}: lookups the cache did not answer (one that makes a record counts twice). */
    long searches;

    /** The cache entry, of a light's {@link #WAYS}, of rays leaving shape's face (a multiplicative hash). */
    static int way(int shape, int face) {
        return (shape * 8 + face) * 0x9E3779B1 >>> (32 - LOG_WAYS);
    }
    /** The record whose ray is walking on trial, or −1. */
    private int trialRecord = -1;
    /** The direction box of the reflected-ray list being built, and the largest length of a direction in it. */
    private final double[] directions = new double[6];
    private double reach;
    /** Per axis, +1 when every ray of the list being built moves up along it, −1 when every one moves down, else 0. */
    private final int[] moving = new int[3];
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
        lists = (long) shapes.count() * (lights.count + 1) <= MAX_PAIRS;
        cacheKey = new int[(lights.count + 1) * WAYS];
        cacheRecord = new int[(lights.count + 1) * WAYS];
        Arrays.fill(cacheKey, -1);
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
        sortByNear(blockItems, blockNear, 0, blockCount);
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
     */
    int shadow(int shape, int face, int light, double ox, double oy, double oz) {
        return lookup(shape * lights.count + light, shape, face, light, ox, oy, oz, 0, 0, 0);
    }

    /**
     * The index in {@link #pool} of the list for a mirror-reflected ray leaving {@code shape} (a
     * box: its face {@code face}) from o along d; −1 when the ray is to walk the tree. Every ray a
     * list is for lies in its region swept along its box of directions, R + t·D for t ≥ 0: a box
     * whose faces move linearly in t, tested as the shadow rays' hulls are; its items are sorted by
     * a lower bound of the ray parameter at which a ray can reach them, so a ray stops at the first
     * item that starts beyond its nearest hit.
     */
    int reflected(int shape, int face, double ox, double oy, double oz, double dx, double dy, double dz) {
        // Shorter directions would need a longer sweep: walked (mirror directions are unit).
        if (dx * dx + dy * dy + dz * dz < 0.25) {
            trialRecord = -1;
            return -1;
        }
        return lookup(shapes.count() * lights.count + shape, shape, face, -1, ox, oy, oz, dx, dy, dz);
    }

    /**
     * The list for a ray of {@code key} from o along d (light ≥ 0: a shadow ray, d unused), or −1.
     *
     * <p>A list covers the region its rays came from, not the shape's whole box: the box of the
     * origins (and directions) of its first {@value #SHADOW_AFTER} rays, which walk on trial, widened
     * by its extent on each axis. A later ray outside it grows the region (the sides it lies beyond,
     * by the union's extent or at least a fraction of the shape's) and builds the list again,
     * {@value #MAX_GROWTHS} times at most; when a list would grow too heavy, the rays outside it
     * start a new record of the same face with a trial of its own, {@value #MAX_SIBLINGS} at most.
     */
    private int lookup(int key, int shape, int face, int light, double ox, double oy, double oz, double dx, double dy, double dz) {
        trialRecord = -1;
        if (!lists) return -1;
        int[] st = state;
        if (st == null) st = state = new int[shapes.count() * (lights.count + 1)];
        // A box's faces keep records of their own: the origins on one face lie in one plane.
        if (shapes.kind[shape] != Shapes.BOX) face = 0;
        int[] rc = records;
        double[] r = regions;
        int slot = (light < 0 ? lights.count : light) * WAYS + way(shape, face);
        int cached = cacheRecord[slot];
        if (cacheKey[slot] == key && rc[RECORD * cached + 4] == face) {
            int k = 12 * cached;
            if (ox >= r[k] && oy >= r[k + 1] && oz >= r[k + 2] && ox <= r[k + 3] && oy <= r[k + 4] && oz <= r[k + 5]
                    && dx >= r[k + 6] && dy >= r[k + 7] && dz >= r[k + 8] && dx <= r[k + 9] && dy <= r[k + 10] && dz <= r[k + 11]) {
                return rc[RECORD * cached + 2] - 1;
            }
        }
        return search(key, shape, face, light, slot, ox, oy, oz, dx, dy, dz);
    }

    /** {@link #lookup} past the cached record: the key's records of that face, a trial, a growth or a new record. */
    private int search(int key, int shape, int face, int light, int slot, double ox, double oy, double oz, double dx, double dy,
            double dz) {
        searches++;
        int[] st = state, rc = records;
        double[] r = regions;
        int heads = st[key] - 1;
        if (heads < 0) {
            // The heads of the key's lists of records, one per face of a box.
            heads = headCount;
            int n = shapes.kind[shape] == Shapes.BOX ? 6 : 1;
            if (heads + n > MAX_RECORDS) return -1;
            if (faceHeads.length < heads + n) faceHeads = Arrays.copyOf(faceHeads, 2 * faceHeads.length);
            Arrays.fill(faceHeads, heads, heads + n, 0);
            headCount += n;
            st[key] = 1 + heads;
        }
        int head = faceHeads[heads + face];
        if (head == ALL_WALK) return -1;
        int trial = -1, growing = -1, siblings = 0, walking = 0, last = -1;
        for (int s = head; s != 0; s = rc[RECORD * last + 5]) {
            last = s - 1;
            int ri = RECORD * last;
            siblings++;
            int list = rc[ri + 2] - 1;
            if (list == WALKS) {
                walking++;
                continue;
            }
            if (list < 0) {
                trial = last;
                continue;
            }
            int k = 12 * last;
            if (ox >= r[k] && oy >= r[k + 1] && oz >= r[k + 2] && ox <= r[k + 3] && oy <= r[k + 4] && oz <= r[k + 5]
                    && dx >= r[k + 6] && dy >= r[k + 7] && dz >= r[k + 8] && dx <= r[k + 9] && dy <= r[k + 10] && dz <= r[k + 11]) {
                cacheKey[slot] = key;
                cacheRecord[slot] = last;
                return list;
            }
            if (growing < 0 && rc[ri + 3] > 0) growing = last;
        }
        if (trial >= 0) {
            int ri = RECORD * trial;
            if (rc[ri] < (light < 0 ? REFLECTED_AFTER : SHADOW_AFTER)) {
                int k = 12 * trial;
                for (int a = 0; a < 3; a++) {
                    double o = a == 0 ? ox : a == 1 ? oy : oz, d = a == 0 ? dx : a == 1 ? dy : dz;
                    r[k + a] = Math.min(r[k + a], o);
                    r[k + 3 + a] = Math.max(r[k + 3 + a], o);
                    r[k + 6 + a] = Math.min(r[k + 6 + a], d);
                    r[k + 9 + a] = Math.max(r[k + 9 + a], d);
                }
                trialRecord = trial;
                return -1;
            }
            int built = grow(shape, light, trial, ox, oy, oz, dx, dy, dz);
            if (built < 0) rc[ri + 2] = WALKS + 1;
            return built;
        }
        if (growing >= 0) {
            int ri = RECORD * growing;
            rc[ri + 3]--;
            int grown = grow(shape, light, growing, ox, oy, oz, dx, dy, dz);
            if (grown >= 0) {
                cacheKey[slot] = key;
                cacheRecord[slot] = growing;
                return grown;
            }
            rc[ri + 3] = 0;
        }
        // A list of another shape covers its whole box: a second record would be the same.
        if (siblings >= (shapes.kind[shape] == Shapes.BOX ? MAX_SIBLINGS : 1)) {
            // Every record of the face walks, and no other can be made: its rays walk from now on.
            if (walking == siblings) faceHeads[heads + face] = ALL_WALK;
            return -1;
        }
        if (recordCount == MAX_RECORDS) return -1;
        int added = newRecord(face);
        if (last < 0) faceHeads[heads + face] = 1 + added;
        else records[RECORD * last + 5] = 1 + added;
        return search(key, shape, face, light, slot, ox, oy, oz, dx, dy, dz);
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
        int k = 12 * rec;
        for (int a = 0; a < 3; a++) {
            regions[k + a] = regions[k + 6 + a] = Double.POSITIVE_INFINITY;
            regions[k + 3 + a] = regions[k + 9 + a] = Double.NEGATIVE_INFINITY;
        }
        return rec;
    }

    /**
     * Widens record {@code rec}'s region to take in o (and d), never past the shape's box widened by
     * the tracer's offset (no origin lies outside it), and builds its list for that region; the new
     * list, or −1 when the ray is to walk (its list would be too long, cost more than its trial
     * walks did on average, or the pool is full), the region and list then staying as they were.
     */
    private int grow(int shape, int light, int rec, double ox, double oy, double oz, double dx, double dy, double dz) {
        Aabb b = shapes.bounds(shape);
        if (b.isEmpty() || !b.isFinite()) return -1;
        int ri = RECORD * rec, walks = records[ri];
        if (walks == 0) return -1;
        double walkedCost = (double) records[ri + 1] / walks;
        double x0 = b.min().x(), y0 = b.min().y(), z0 = b.min().z(), x1 = b.max().x(), y1 = b.max().y(), z1 = b.max().z();
        // A ray leaves the hit point by Tracer's offset, at most OFFSET × max(|p|, scale).
        double big = Math.max(Math.max(Math.max(Math.abs(x0), Math.abs(x1)), Math.max(Math.abs(y0), Math.abs(y1))),
                Math.max(Math.max(Math.abs(z0), Math.abs(z1)), shapes.scale[shape]));
        double w = 4 * Tracer.OFFSET * big;
        double[] r = regions, h = hull;
        int k = 12 * rec;
        boolean first = records[ri + 2] == 0;
        // A box's face is flat: its rays' origins fill a small part of the box. Other shapes' lists
        // cover their whole box, which one build does (their trial regions gained nothing on
        // the 10,000 spheres and cost their growths, section 28).
        boolean flat = shapes.kind[shape] == Shapes.BOX;
        // Each axis by a call rather than a loop over the axes: a list is built a few thousand
        // times a render, and the loop (its bounds chosen by index, its tests the same every turn)
        // made the JIT's optimising compiler spend 60-160 ms on this method, two or three times
        // over after its loop guesses failed (docs/benchmarks.md, section 47).
        regionAxis(0, x0 - w, x1 + w, ox, dx, k, flat, light < 0, first);
        regionAxis(1, y0 - w, y1 + w, oy, dy, k, flat, light < 0, first);
        regionAxis(2, z0 - w, z1 + w, oz, dz, k, flat, light < 0, first);
        double sweep = 4 * Math.sqrt(3) * (sceneSize + big) + 1;
        if (light < 0) {
            // Beyond twice the diameter of the box around every item a ray at least ½ long (as
            // reflected() takes them) has left it: the far box is the region moved that far.
            // A ray's parameter t covers at least the distance travelled over the longest
            // direction's length.
            double far = 2 * sweep;
            double m = sweptAxis(0, far);
            m += sweptAxis(1, far);
            m += sweptAxis(2, far);
            reach = Math.sqrt(m) * (1 + 1e-9);
        } else if (lights.kind[light] == Lights.PARALLEL) {
            // Every shadow ray runs along the light's direction w to infinity: the region box swept
            // along w. Swept by more than the diameter of the box around every item, nothing lies
            // beyond, so its far end may be a box moved that far.
            double wx = lights.x[light], wy = lights.y[light], wz = lights.z[light];
            double far = sweep / Math.sqrt(wx * wx + wy * wy + wz * wz);
            h[6] = h[0] + far * wx;
            h[9] = h[3] + far * wx;
            h[7] = h[1] + far * wy;
            h[10] = h[4] + far * wy;
            h[8] = h[2] + far * wz;
            h[11] = h[5] + far * wz;
        } else {
            h[6] = h[9] = lights.x[light];
            h[7] = h[10] = lights.y[light];
            h[8] = h[11] = lights.z[light];
        }
        // Per axis, whether every ray of the region moves up along it (+1) or down (−1).
        if (light < 0) {
            double[] dir = directions;
            moving[0] = sign(dir[0], dir[3]);
            moving[1] = sign(dir[1], dir[4]);
            moving[2] = sign(dir[2], dir[5]);
        } else if (lights.kind[light] == Lights.PARALLEL) {
            moving[0] = sign(lights.x[light], lights.x[light]);
            moving[1] = sign(lights.y[light], lights.y[light]);
            moving[2] = sign(lights.z[light], lights.z[light]);
        } else {
            // Towards the light's point q: q − o over o in the region.
            moving[0] = sign(lights.x[light] - h[3], lights.x[light] - h[0]);
            moving[1] = sign(lights.y[light] - h[4], lights.y[light] - h[1]);
            moving[2] = sign(lights.z[light] - h[5], lights.z[light] - h[2]);
        }
        int at = poolSize;
        if (at + 1 + SHADOW_LIMIT > MAX_POOL) return -1;
        if (pool.length < at + 1 + SHADOW_LIMIT) {
            int size = Math.max(2 * pool.length, at + 1 + SHADOW_LIMIT);
            pool = Arrays.copyOf(pool, size);
            near = Arrays.copyOf(near, size);
        }
        // A reflected-ray list may weigh one and a half times its trial walks: a step of the walk
        // tests two boxes, but its branches go each way at random from ray to ray, while a list's
        // box test of an item is one; on drops.crt a step costs at least 1.25 list items' tests
        // (section 44; the box field, for which section 28 chose half, is no slower).
        double bound = light < 0 ? walkedCost * REFLECTED_WEIGHT : walkedCost;
        // Every item weighs at least 1: the walk stops as soon as the list is too heavy.
        int n = collectInto(false, pool, at + 1, (int) Math.min(SHADOW_LIMIT, bound), light < 0 ? near : null);
        if (n < 0) return -1;
        double cost = 0;
        for (int i = at + 1; i < at + 1 + n; i++) cost += weight(pool[i]);
        if (cost > bound) return -1;
        if (light < 0) sortByNear(pool, near, at + 1, n);
        pool[at] = n;
        System.arraycopy(h, 0, r, k, 6);
        System.arraycopy(directions, 0, r, k + 6, 6);
        poolSize = at + 1 + n;
        records[ri + 2] = at + 1;
        return at;
    }

    /**
     * Axis a of a list's region ({@link #hull}'s near box) and of its directions, for a ray from
     * o along d: the shape's box [bl, bh] on that axis (widened by the rays' offset) or, on a box's
     * face, the record's trial box widened; directions only for reflected rays. The first region
     * is the trial's box widened by its extent on every side; a growth widens only the sides the
     * ray lies beyond, by the union's extent or at least 1/32 of the shape's (directions: 1/8), so
     * that a few growths cover what the rays come from.
     */
    private void regionAxis(int a, double bl, double bh, double o, double d, int k, boolean flat, boolean reflected, boolean first) {
        double[] r = regions, h = hull, dir = directions;
        if (flat) {
            h[a] = widen(first, r[k + a], r[k + 3 + a], o, (bh - bl) / 32, bl, false);
            h[3 + a] = widen(first, r[k + a], r[k + 3 + a], o, (bh - bl) / 32, bh, true);
        } else {
            h[a] = Math.min(bl, o);
            h[3 + a] = Math.max(bh, o);
        }
        if (reflected) {
            // Unit directions have no component beyond ±1.
            dir[a] = widen(first, r[k + 6 + a], r[k + 9 + a], d, 0.125, -1, false);
            dir[3 + a] = widen(first, r[k + 6 + a], r[k + 9 + a], d, 0.125, 1, true);
        } else {
            dir[a] = Double.NEGATIVE_INFINITY;
            dir[3 + a] = Double.POSITIVE_INFINITY;
        }
    }

    /** Axis a of a reflected-ray region's far box, its near box moved by {@code s} times its directions; returns the square of the largest direction component on the axis. */
    private double sweptAxis(int a, double s) {
        double[] h = hull, dir = directions;
        h[6 + a] = h[a] + s * dir[a];
        h[9 + a] = h[3 + a] + s * dir[3 + a];
        double c = Math.max(Math.abs(dir[a]), Math.abs(dir[3 + a]));
        return c * c;
    }

    /** +1 when every value of [lo, hi] is positive, −1 when every one is negative, else 0. */
    private static int sign(double lo, double hi) {
        return lo > 0 ? 1 : hi < 0 ? -1 : 0;
    }

    /**
     * One side of a widened interval: the trial's [lo, hi] widened by its extent on both sides when
     * {@code first}, else by at least {@code least} on the side v lies beyond; clipped to
     * {@code bound}, but always holding v (a region must hold the ray it is built for).
     */
    private static double widen(boolean first, double lo, double hi, double v, double least, double bound, boolean upper) {
        double extent = Math.max(hi, v) - Math.min(lo, v), step = Math.max(extent, least);
        if (upper) return Math.max(Math.min(first ? Math.max(hi, v) + extent : v > hi ? v + step : hi, bound), v);
        return Math.min(Math.max(first ? Math.min(lo, v) - extent : v < lo ? v - step : lo, bound), v);
    }

    /** Whether the ray the last {@link #shadow} or {@link #reflected} call turned down walks on trial (its cost is wanted). */
    boolean onTrial() {
        return trialRecord >= 0;
    }

    /**
     * Records what the walk of the ray the last {@link #shadow} or {@link #reflected} call turned
     * down cost, while its record is on trial: the walks it took (0 or 1), and their nodes opened plus
     * their items tested, weighed by {@link #weight} (a node's two box tests cost about a sphere's test).
     */
    void walked(int walks, int cost) {
        if (trialRecord < 0 || walks == 0) return;
        int ri = RECORD * trialRecord;
        records[ri] += walks;
        records[ri + 1] = (int) Math.min((long) records[ri + 1] + cost, Integer.MAX_VALUE);
        trialRecord = -1;
    }

    /**
     * What testing an item costs, in tests of a plain shape: a CSG tree or a mesh gathers or walks
     * its own parts. {@link Tracer}'s walk counts its CSG trees the same way.
     */
    int weight(int item) {
        return item < 0 ? CSG_WEIGHT : shapes.kind[item] == Shapes.MESH ? HEAVY : 1;
    }

    /** Sorts {@code count} items from {@code at} by their lower bounds (lists are short); ties keep the leaves' order. */
    private static void sortByNear(int[] items, double[] near, int at, int count) {
        for (int k = at + 1; k < at + count; k++) {
            double t = near[k];
            int item = items[k];
            // The place m is found moving down while the one below is larger: a loop on m > at
            // rather than on m ≥ at, which the JIT's guess about its bound (a "loop limit
            // check") failed on and compiled the list builder again (section 47).
            int m = k;
            while (m > at && near[m - 1] > t) {
                near[m] = near[m - 1];
                items[m] = items[m - 1];
                m--;
            }
            near[m] = t;
            items[m] = item;
        }
    }

    /**
     * A lower bound of the parameter t at which a ray of the swept region being built (origin in
     * the region box of {@link #hull}, direction at most {@link #reach} long) reaches the box.
     */
    private double reached(double x0, double y0, double z0, double x1, double y1, double z1) {
        double[] h = hull;
        double dx = Math.max(0, Math.max(x0 - h[3], h[0] - x1));
        double dy = Math.max(0, Math.max(y0 - h[4], h[1] - y1));
        double dz = Math.max(0, Math.max(z0 - h[5], h[2] - z1));
        double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
        // Hits of grazing rays are rounded by up to about √ε of their distance.
        return (d - 1e-6 * d - WIDEN * sceneSize) / reach;
    }

    /**
     * Whether every ray of the list being built starts beyond the box on some axis (the region box
     * of {@link #hull} wholly past it) and moves away from it along that axis. Such a ray's slab
     * distances to that axis's two planes are both negative (their signs are exact), so the box's
     * own test (a slab test) finds no crossing at t > 0: its factor is 1 and it is never the
     * nearest hit. It tells apart what the widened hull test cannot: a box the region touches,
     * such as the shape's own box under the face the rays leave, or its neighbours' of the same height.
     */
    private boolean receding(double x0, double y0, double z0, double x1, double y1, double z1) {
        double[] h = hull;
        int[] m = moving;
        return m[0] > 0 && h[0] > x1 || m[0] < 0 && h[3] < x0
                || m[1] > 0 && h[1] > y1 || m[1] < 0 && h[4] < y0
                || m[2] > 0 && h[2] > z1 || m[2] < 0 && h[5] < z0;
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
                        if (!frustum && kind == Shapes.BOX && receding(x0, y0, z0, x1, y1, z1)) continue;
                    }
                    if (n == limit) return -1;
                    if (near != null) near[at + n] = frustum ? nearest(x0, y0, z0, x1, y1, z1) : reached(x0, y0, z0, x1, y1, z1);
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
