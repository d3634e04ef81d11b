package dev.crt.lang.value;

/** A number; {@code integral} marks an integer, which is accepted wherever a float is. */
public record NumberValue(double value, boolean integral) implements Value {
    private static final NumberValue[] SMALL_INTS = new NumberValue[256];

    static {
        for (int i = 0; i < SMALL_INTS.length; i++) SMALL_INTS[i] = new NumberValue(i, true);
    }

    public static NumberValue ofInt(double value) {
        if (value >= 0 && value < SMALL_INTS.length && value == (int) value) return SMALL_INTS[(int) value];
        return new NumberValue(value, true);
    }

    public static NumberValue ofFloat(double value) { return new NumberValue(value, false); }

    @Override
    public String typeName() { return "number"; }

    @Override
    public String toString() { return format(value); }

    /** A number as a person writes it: 3, 1.5, -0.25. */
    public static String format(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) return Long.toString((long) v);
        // Java's 1.0E22 in the script's own notation: 1e22.
        return Double.toString(v).replace(".0E", "E").replace('E', 'e');
    }

    /** A float as a person writes one, with its point even when whole (2.0), so it never reads as an integer. */
    public static String formatFloat(double v) {
        String s = format(v);
        return s.matches("-?\\d+") ? s + ".0" : s;
    }
}
