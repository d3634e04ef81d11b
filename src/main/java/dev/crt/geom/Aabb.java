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
