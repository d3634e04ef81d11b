package dev.crt.geom;

/** An axis-aligned bounding box; an empty box has min > max. */
public record Aabb(Vec3 min, Vec3 max) {
    public static final Aabb EMPTY = new Aabb(
            new Vec3(Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY),
            new Vec3(Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY));
    public static final Aabb INFINITE = new Aabb(
            new Vec3(Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY),
            new Vec3(Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY));

    public boolean isEmpty() { return min.x() > max.x() || min.y() > max.y() || min.z() > max.z(); }

    public boolean isFinite() { return min.isFinite() && max.isFinite(); }

    public Aabb union(Aabb o) { return new Aabb(min.min(o.min), max.max(o.max)); }

    public Aabb intersection(Aabb o) { return new Aabb(min.max(o.min), max.min(o.max)); }

    /**
     * A box holding every point of this box that the solid box {@code cut} leaves: where {@code cut}
     * spans this box on two axes, what is left lies beyond its faces on the third, and the side
     * {@code cut} reaches over is moved in to its face, then back out by {@code margin}. Otherwise
     * (and when {@code cut} spans all three) this box.
     */
    public Aabb less(Aabb cut, double margin) {
        double[] lo = {min.x(), min.y(), min.z()}, hi = {max.x(), max.y(), max.z()};
        double[] cl = {cut.min.x(), cut.min.y(), cut.min.z()}, ch = {cut.max.x(), cut.max.y(), cut.max.z()};
        int open = -1, spanned = 0;
        for (int a = 0; a < 3; a++) {
            if (cl[a] <= lo[a] && ch[a] >= hi[a]) spanned++;
            else open = a;
        }
        if (spanned != 2) return this;
        if (cl[open] <= lo[open] && ch[open] >= lo[open]) lo[open] = Math.max(lo[open], ch[open] - margin);
        else if (ch[open] >= hi[open] && cl[open] <= hi[open]) hi[open] = Math.min(hi[open], cl[open] + margin);
        else return this;
        return new Aabb(new Vec3(lo[0], lo[1], lo[2]), new Vec3(hi[0], hi[1], hi[2]));
    }

    public Vec3 center() { return min.plus(max).times(0.5); }

    /** The box that bounds this one after an affine transform (its eight corners transformed). */
    public Aabb transformed(Transform t) {
        if (isEmpty() || !isFinite()) return isEmpty() ? this : INFINITE;
        Aabb r = EMPTY;
        for (int i = 0; i < 8; i++) {
            Vec3 c = new Vec3((i & 1) == 0 ? min.x() : max.x(), (i & 2) == 0 ? min.y() : max.y(),
                    (i & 4) == 0 ? min.z() : max.z());
            Vec3 p = t.applyToPoint(c);
            r = new Aabb(r.min.min(p), r.max.max(p));
        }
        return r;
    }
}
