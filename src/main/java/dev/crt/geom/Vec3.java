package dev.crt.geom;

/** An immutable 3-component vector of doubles: points, directions and offsets. */
public record Vec3(double x, double y, double z) {
    public static final Vec3 ZERO = new Vec3(0, 0, 0);
    public static final Vec3 X = new Vec3(1, 0, 0);
    public static final Vec3 Y = new Vec3(0, 1, 0);
    public static final Vec3 Z = new Vec3(0, 0, 1);

    public Vec3 plus(Vec3 o) { return new Vec3(x + o.x, y + o.y, z + o.z); }
    public Vec3 minus(Vec3 o) { return new Vec3(x - o.x, y - o.y, z - o.z); }
    public Vec3 times(double s) { return new Vec3(x * s, y * s, z * s); }
    public Vec3 times(Vec3 o) { return new Vec3(x * o.x, y * o.y, z * o.z); }
    public Vec3 div(double s) { return new Vec3(x / s, y / s, z / s); }
    public Vec3 negate() { return new Vec3(-x, -y, -z); }
    public double dot(Vec3 o) { return x * o.x + y * o.y + z * o.z; }
    public Vec3 cross(Vec3 o) { return new Vec3(y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x); }
    public double length() { return Math.sqrt(dot(this)); }
    public Vec3 normalize() { return div(length()); }
    public Vec3 min(Vec3 o) { return new Vec3(Math.min(x, o.x), Math.min(y, o.y), Math.min(z, o.z)); }
    public Vec3 max(Vec3 o) { return new Vec3(Math.max(x, o.x), Math.max(y, o.y), Math.max(z, o.z)); }

    /** Component by index: 0 is x, 1 is y, 2 is z. */
    public double get(int i) {
        return switch (i) {
            case 0 -> x;
            case 1 -> y;
            case 2 -> z;
            default -> throw new IndexOutOfBoundsException(i);
        };
    }

    public boolean isFinite() { return Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z); }

    @Override
    public String toString() { return "vec3(" + fmt(x) + ", " + fmt(y) + ", " + fmt(z) + ")"; }

    static String fmt(double d) {
        return d == Math.rint(d) && Math.abs(d) < 1e15 ? Long.toString((long) d) : Double.toString(d);
    }
}
