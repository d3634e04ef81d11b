package dev.crt.scene;

/** A linear RGB colour; components are usually in [0, 1] but may exceed 1 (emission, bright lights). */
public record Rgb(double r, double g, double b) {
    public static final Rgb BLACK = new Rgb(0, 0, 0);
    public static final Rgb WHITE = new Rgb(1, 1, 1);
    public static final Rgb GREY = new Rgb(0.5, 0.5, 0.5);

    public Rgb plus(Rgb o) { return new Rgb(r + o.r, g + o.g, b + o.b); }
    public Rgb minus(Rgb o) { return new Rgb(r - o.r, g - o.g, b - o.b); }
    public Rgb times(double s) { return new Rgb(r * s, g * s, b * s); }
    public Rgb times(Rgb o) { return new Rgb(r * o.r, g * o.g, b * o.b); }
    public Rgb div(double s) { return new Rgb(r / s, g / s, b / s); }

    /** Component by index: 0 is red, 1 green, 2 blue. */
    public double get(int i) {
        return switch (i) {
            case 0 -> r;
            case 1 -> g;
            case 2 -> b;
            default -> throw new IndexOutOfBoundsException(i);
        };
    }

    public boolean isBlack() { return r == 0 && g == 0 && b == 0; }

    @Override
    public String toString() { return "rgb(" + r + ", " + g + ", " + b + ")"; }
}
