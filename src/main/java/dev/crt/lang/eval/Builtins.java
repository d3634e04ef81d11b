package dev.crt.lang.eval;

import dev.crt.geom.Vec3;
import dev.crt.lang.value.ColorValue;
import dev.crt.lang.value.ListValue;
import dev.crt.lang.value.NumberValue;
import dev.crt.lang.value.StringValue;
import dev.crt.lang.value.Value;
import dev.crt.lang.value.VectorValue;
import dev.crt.scene.Rgb;
import java.util.HashMap;
import java.util.Map;
import java.util.Set;
import java.util.function.DoubleUnaryOperator;

/** The built-in functions of section 10, with their argument checks and domain checks. */
final class Builtins {
    /** What a built-in needs from the call site: its arguments, checked, and a way to complain. */
    interface Call {
        double number(int i);

        Vec3 vector(int i);

        Value arg(int i);

        ScriptError error(String message);

        ScriptError wrongArguments();

        void warn(String message);

        ScriptRandom random();
    }

    /** What a built-in computes from its checked call. */
    interface Body {
        Value apply(Call call);
    }

    private record Builtin(String signature, int arity, Body body) {}

    private static final Map<String, Builtin> ALL = new HashMap<>();

    static {
        define("vec3(number, number, number)", c -> new VectorValue(new Vec3(c.number(0), c.number(1), c.number(2))));
        define("rgb(number, number, number)", c -> new ColorValue(new Rgb(c.number(0), c.number(1), c.number(2))));
        define("rgba(number, number, number, number)", c -> {
            c.number(3);
            c.warn("rgba: the alpha component is accepted and ignored");
            return new ColorValue(new Rgb(c.number(0), c.number(1), c.number(2)));
        });
        unary("sin", Math::sin);
        unary("cos", Math::cos);
        unary("tan", Math::tan);
        define("asin(number)", c -> NumberValue.ofFloat(Math.asin(inUnitRange(c, "asin"))));
        define("acos(number)", c -> NumberValue.ofFloat(Math.acos(inUnitRange(c, "acos"))));
        unary("atan", Math::atan);
        define("atan2(number, number)", c -> NumberValue.ofFloat(Math.atan2(c.number(0), c.number(1))));
        define("sqrt(number)", c -> {
            double x = c.number(0);
            if (x < 0) throw c.error("sqrt of a negative number (" + NumberValue.format(x) + ")");
            return NumberValue.ofFloat(Math.sqrt(x));
        });
        define("pow(number, number)", c -> {
            double r = Math.pow(c.number(0), c.number(1));
            if (!Double.isFinite(r)) {
                throw c.error("pow(" + NumberValue.format(c.number(0)) + ", " + NumberValue.format(c.number(1))
                        + ") has no finite value");
            }
            return number(r, integral(c.arg(0)) && integral(c.arg(1)) && c.number(1) >= 0);
        });
        define("exp(number)", c -> {
            double r = Math.exp(c.number(0));
            if (!Double.isFinite(r)) throw c.error("exp(" + NumberValue.format(c.number(0)) + ") is too large");
            return NumberValue.ofFloat(r);
        });
        define("log(number)", c -> {
            double x = c.number(0);
            if (x <= 0) throw c.error("log of a number that is not positive (" + NumberValue.format(x) + ")");
            return NumberValue.ofFloat(Math.log(x));
        });
        define("abs(number)", c -> number(Math.abs(c.number(0)), integral(c.arg(0))));
        define("floor(number)", c -> NumberValue.ofInt(Math.floor(c.number(0))));
        define("ceil(number)", c -> NumberValue.ofInt(Math.ceil(c.number(0))));
        define("round(number)", c -> NumberValue.ofInt(Math.floor(c.number(0) + 0.5)));
        define("min(number, number)", c -> number(Math.min(c.number(0), c.number(1)), integral(c.arg(0)) && integral(c.arg(1))));
        define("max(number, number)", c -> number(Math.max(c.number(0), c.number(1)), integral(c.arg(0)) && integral(c.arg(1))));
        define("clamp(number, number, number)", c -> {
            double x = c.number(0), lo = c.number(1), hi = c.number(2);
            if (lo > hi) throw c.error("clamp: the lower bound " + NumberValue.format(lo) + " is above the upper bound " + NumberValue.format(hi));
            return number(Math.min(Math.max(x, lo), hi), integral(c.arg(0)) && integral(c.arg(1)) && integral(c.arg(2)));
        });
        define("mix(a, b, number) with a and b both numbers, vec3s or rgbs", Builtins::mix, 3);
        define("dot(vec3, vec3)", c -> NumberValue.ofFloat(c.vector(0).dot(c.vector(1))));
        define("cross(vec3, vec3)", c -> new VectorValue(c.vector(0).cross(c.vector(1))));
        define("length(vec3)", c -> {
            Vec3 v = c.vector(0);
            // hypot, as the plain square root of the sum of squares overflows for components near 1e155.
            return NumberValue.ofFloat(Math.hypot(Math.hypot(v.x(), v.y()), v.z()));
        });
        define("normalize(vec3)", c -> {
            Vec3 unit = unit(c.vector(0));
            if (unit == null) throw c.error("normalize of a zero vector");
            return new VectorValue(unit);
        });
        define("len(list or string)", c -> {
            Value v = c.arg(0);
            if (v instanceof ListValue list) return NumberValue.ofInt(list.items().size());
            if (v instanceof StringValue s) return NumberValue.ofInt(s.value().length());
            throw c.wrongArguments();
        });
        define("radians(number)", c -> NumberValue.ofFloat(Math.toRadians(c.number(0))));
        define("degrees(number)", c -> NumberValue.ofFloat(Math.toDegrees(c.number(0))));
        define("rand(number, number)", c -> {
            double a = c.number(0), b = c.number(1);
            double lo = Math.min(a, b), hi = Math.max(a, b);
            return NumberValue.ofFloat(lo + c.random().nextDouble() * (hi - lo));
        });
    }

    private Builtins() {}

    private static void define(String signature, Body body) {
        int arity = signature.endsWith("()") ? 0 : signature.split(",").length;
        define(signature, body, arity);
    }

    private static void define(String signature, Body body, int arity) {
        ALL.put(signature.substring(0, signature.indexOf('(')), new Builtin(signature, arity, body));
    }

    private static void unary(String name, DoubleUnaryOperator f) {
        define(name + "(number)", c -> {
            double r = f.applyAsDouble(c.number(0));
            if (!Double.isFinite(r)) throw c.error(name + "(" + NumberValue.format(c.number(0)) + ") has no finite value");
            return NumberValue.ofFloat(r);
        });
    }

    private static double inUnitRange(Call c, String name) {
        double x = c.number(0);
        if (x < -1 || x > 1) throw c.error(name + " takes a number in [-1, 1], got " + NumberValue.format(x));
        return x;
    }

    private static Value mix(Call c) {
        double t = c.number(2);
        Value a = c.arg(0), b = c.arg(1);
        if (a instanceof NumberValue x && b instanceof NumberValue y) {
            return NumberValue.ofFloat(x.value() + (y.value() - x.value()) * t);
        }
        if (a instanceof VectorValue x && b instanceof VectorValue y) {
            return new VectorValue(x.vector().plus(y.vector().minus(x.vector()).times(t)));
        }
        if (a instanceof ColorValue x && b instanceof ColorValue y) {
            return new ColorValue(x.color().plus(y.color().minus(x.color()).times(t)));
        }
        throw c.wrongArguments();
    }

    /**
     * The vector scaled to length 1, or null for the zero vector. It is scaled by its largest
     * component first, so that vec3(1e200, 1e200, 0) does not overflow to a zero result.
     */
    static Vec3 unit(Vec3 v) {
        double largest = Math.max(Math.abs(v.x()), Math.max(Math.abs(v.y()), Math.abs(v.z())));
        if (largest == 0) return null;
        Vec3 scaled = v.div(largest);
        return scaled.div(scaled.length());
    }

    private static boolean integral(Value v) { return v instanceof NumberValue n && n.integral(); }

    private static NumberValue number(double v, boolean integral) {
        return integral ? NumberValue.ofInt(v) : NumberValue.ofFloat(v);
    }

    static boolean exists(String name) { return ALL.containsKey(name); }

    static Set<String> names() { return ALL.keySet(); }

    static String signature(String name) { return ALL.get(name).signature(); }

    static int arity(String name) { return ALL.get(name).arity(); }

    /** The body of the built-in {@code name}, or null: looked up once where a call runs many times. */
    static Body body(String name) {
        Builtin b = ALL.get(name);
        return b == null ? null : b.body();
    }
}
