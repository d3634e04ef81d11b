package dev.crt.lang.eval;

import dev.crt.geom.Vec3;
import dev.crt.lang.value.BackgroundValue;
import dev.crt.lang.value.BooleanValue;
import dev.crt.lang.value.CameraValue;
import dev.crt.lang.value.ColorValue;
import dev.crt.lang.value.MaterialValue;
import dev.crt.lang.value.NumberValue;
import dev.crt.lang.value.StringValue;
import dev.crt.lang.value.TextureValue;
import dev.crt.lang.value.Value;
import dev.crt.lang.value.VectorValue;
import dev.crt.scene.Background;
import dev.crt.scene.Camera;
import dev.crt.scene.Material;
import dev.crt.scene.Rgb;
import dev.crt.scene.SourceSpan;
import dev.crt.scene.Texture;
import java.util.List;

/**
 * The evaluated attributes of one object literal, read back with type and range checks. A failed
 * check is reported at the attribute and the object fails once every attribute has been checked,
 * so that one look at the diagnostics shows all the mistakes of an object.
 */
final class Attributes {
    /** One attribute as written: its value and where it stands. */
    record Given(Value value, SourceSpan span) {}

    /** An allowed interval of numbers, with the words that explain it. */
    record Range(double low, boolean lowOpen, double high, boolean highOpen) {
        static final Range ANY = new Range(Double.NEGATIVE_INFINITY, false, Double.POSITIVE_INFINITY, false);
        static final Range NOT_NEGATIVE = new Range(0, false, Double.POSITIVE_INFINITY, false);
        static final Range POSITIVE = new Range(0, true, Double.POSITIVE_INFINITY, false);
        static final Range UNIT = new Range(0, false, 1, false);

        boolean contains(double v) {
            return (lowOpen ? v > low : v >= low) && (highOpen ? v < high : v <= high);
        }

        String describe() {
            if (high == Double.POSITIVE_INFINITY) return (lowOpen ? "> " : ">= ") + NumberValue.format(low);
            return "in " + (lowOpen ? "(" : "[") + NumberValue.format(low) + ", " + NumberValue.format(high)
                    + (highOpen ? ")" : "]");
        }
    }

    private final Evaluator evaluator;
    private final String type;
    private final SourceSpan typeSpan;
    // At most a score of attributes, written in order: parallel arrays searched from the start beat
    // a hash map on a million spheres (the names the builders ask for are the very strings the type
    // table holds when a compiled object literal put them, so most comparisons are one ==).
    private String[] names = new String[4];
    private Given[] values = new Given[4];
    private int size;
    private final SourceSpan objectSpan;
    private boolean failed;
    // Attributes written whose value failed (already reported there): not "missing" as well.
    private String[] broken;
    private int brokenCount;

    Attributes(Evaluator evaluator, String type, SourceSpan typeSpan, SourceSpan objectSpan) {
        this.evaluator = evaluator;
        this.type = type;
        this.typeSpan = typeSpan;
        this.objectSpan = objectSpan;
    }

    /** Records an attribute not given before ({@link #has} is false for it). */
    void put(String name, Given g) {
        if (size == names.length) {
            names = java.util.Arrays.copyOf(names, size * 2);
            values = java.util.Arrays.copyOf(values, size * 2);
        }
        names[size] = name;
        values[size++] = g;
    }

    private Given find(String name) {
        for (int i = 0; i < size; i++) {
            String n = names[i];
            if (n == name || n.equals(name)) return values[i];
        }
        return null;
    }

    void markFailed() { failed = true; }

    /** Marks the object failed because the value written for {@code name} failed (and was reported). */
    void markFailed(String name) {
        failed = true;
        if (broken == null) broken = new String[2];
        else if (brokenCount == broken.length) broken = java.util.Arrays.copyOf(broken, brokenCount * 2);
        broken[brokenCount++] = name;
    }

    private boolean broken(String name) {
        for (int i = 0; i < brokenCount; i++) if (broken[i].equals(name)) return true;
        return false;
    }

    /** Whether {@code name} is written at all, also when its value failed (for checks of which attributes go together). */
    boolean written(String name) { return find(name) != null || broken(name); }

    boolean has(String name) { return find(name) != null; }

    /** The names given, in the order written. */
    List<String> names() { return List.of(java.util.Arrays.copyOf(names, size)); }

    /** What was given for {@code name}, or null. */
    Given given(String name) { return find(name); }

    SourceSpan typeSpan() { return typeSpan; }

    /** The whole literal, from the type name to the closing brace. */
    SourceSpan objectSpan() { return objectSpan; }

    SourceSpan spanOf(String name) {
        Given g = find(name);
        return g != null ? g.span() : typeSpan;
    }

    /** Throws once the object has been fully checked, if anything about it was wrong. */
    void finish() {
        if (failed) throw Failed.INSTANCE;
    }

    void error(String name, String message) {
        failed = true;
        evaluator.report(evaluator.error(message, spanOf(name)));
    }

    private Value required(String name) {
        Given g = find(name);
        if (g != null) return g.value();
        failed = true;
        if (!broken(name)) evaluator.report(evaluator.error(type + " needs the attribute '" + name + "'", typeSpan));
        return null;
    }

    private void wrongType(String name, String expected, Value got) {
        error(name, "attribute '" + name + "' of " + type + " expects " + expected + ", got " + got.typeName());
    }

    Vec3 vector(String name, Vec3 fallback) {
        Given g = fallback == null ? null : find(name);
        Value v = fallback == null ? required(name) : g != null ? g.value() : null;
        if (v == null) return fallback != null ? fallback : Vec3.ZERO;
        if (v instanceof VectorValue vec) return vec.vector();
        wrongType(name, "a vec3", v);
        return Vec3.ZERO;
    }

    /** The raw value of an optional attribute, or null when it is not given. */
    Value value(String name) {
        Given g = find(name);
        return g == null ? null : g.value();
    }

    boolean bool(String name, boolean fallback) {
        Given g = find(name);
        if (g == null) return fallback;
        if (g.value() instanceof BooleanValue b) return b.value();
        wrongType(name, "a boolean", g.value());
        return fallback;
    }

    Rgb color(String name, Rgb fallback) {
        Given g = find(name);
        if (g == null) return fallback;
        if (g.value() instanceof ColorValue c) return c.color();
        boolean texturable = (name.equals("color") || name.equals("emission")) && type.equals("Material")
                || name.startsWith("color") && type.equals("Checker");
        wrongType(name, texturable ? "an rgb colour or a texture" : "an rgb colour", g.value());
        return fallback;
    }

    double number(String name, double fallback, Range range) {
        return number(name, fallback, range, "a number");
    }

    /** A number attribute that may instead be a texture (read by {@link #texture}): then the fallback. */
    double numberOrTexture(String name, double fallback, Range range) {
        Given g = find(name);
        if (g != null && g.value() instanceof TextureValue) return fallback;
        return number(name, fallback, range, "a number or a texture");
    }

    private double number(String name, double fallback, Range range, String expected) {
        Given g = find(name);
        if (g == null) return fallback;
        if (!(g.value() instanceof NumberValue n)) {
            wrongType(name, expected, g.value());
            return fallback;
        }
        if (!range.contains(n.value())) {
            error(name, name + " must be " + range.describe() + ", got " + n);
            return fallback;
        }
        return n.value();
    }

    /** An integer attribute from {@code minimum} to {@code maximum}; out of range is an error naming both. */
    int integer(String name, int fallback, int minimum, int maximum) {
        int value = integer(name, fallback, minimum);
        if (value > maximum) {
            error(name, name + " must be an integer from " + minimum + " to " + maximum + ", got " + value);
            return fallback;
        }
        return value;
    }

    int integer(String name, int fallback, int minimum) {
        Given g = find(name);
        if (g == null) return fallback;
        if (!(g.value() instanceof NumberValue n)) {
            wrongType(name, "an integer", g.value());
            return fallback;
        }
        if (!n.integral()) {
            error(name, "attribute '" + name + "' of " + type + " expects an integer, got the float " + NumberValue.formatFloat(n.value()));
            return fallback;
        }
        if (n.value() < minimum || n.value() > Integer.MAX_VALUE) {
            error(name, name + " must be an integer >= " + minimum + ", got " + n);
            return fallback;
        }
        return (int) n.value();
    }

    String string(String name, String fallback) {
        Given g = find(name);
        if (g == null) return fallback;
        if (g.value() instanceof StringValue s) return s.value();
        wrongType(name, "a string", g.value());
        return fallback;
    }

    /** The texture given for {@code name}, or null when it is absent or not a texture (then read it as a colour). */
    Texture texture(String name) {
        Given g = find(name);
        return g != null && g.value() instanceof TextureValue t ? t.texture() : null;
    }

    /** A texture attribute that must be a texture when given (a bump map). */
    Texture requiredTexture(String name) {
        Given g = find(name);
        if (g == null) return null;
        if (g.value() instanceof TextureValue t) return t.texture();
        wrongType(name, "a texture", g.value());
        return null;
    }

    /** A number or a vec3 (a number n means vec3(n, n, n)). */
    Vec3 numberOrVector(String name, Vec3 fallback) {
        Given g = find(name);
        if (g == null) return fallback;
        if (g.value() instanceof NumberValue n) return new Vec3(n.value(), n.value(), n.value());
        if (g.value() instanceof VectorValue v) return v.vector();
        wrongType(name, "a number or a vec3", g.value());
        return fallback;
    }

    Material material(String name) {
        Given g = find(name);
        if (g == null) return Material.DEFAULT;
        if (g.value() instanceof MaterialValue m) return m.material();
        wrongType(name, "a material", g.value());
        return Material.DEFAULT;
    }

    Camera camera(String name) {
        Given g = find(name);
        if (g == null) return null;
        if (g.value() instanceof CameraValue c) return c.camera();
        wrongType(name, "a camera", g.value());
        return null;
    }

    Background background(String name) {
        Given g = find(name);
        if (g == null) return null;
        if (g.value() instanceof BackgroundValue b) return b.background();
        wrongType(name, "a background", g.value());
        return null;
    }
}
