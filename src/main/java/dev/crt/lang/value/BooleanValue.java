package dev.crt.lang.value;

/** true or false; only conditions and the logical operators take them. */
public record BooleanValue(boolean value) implements Value {
    public static final BooleanValue TRUE = new BooleanValue(true);
    public static final BooleanValue FALSE = new BooleanValue(false);

    public static BooleanValue of(boolean b) { return b ? TRUE : FALSE; }

    @Override
    public String typeName() { return "boolean"; }

    @Override
    public String toString() { return Boolean.toString(value); }
}
