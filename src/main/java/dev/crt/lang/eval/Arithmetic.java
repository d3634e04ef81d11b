package dev.crt.lang.eval;

import dev.crt.lang.value.ColorValue;
import dev.crt.lang.value.ListValue;
import dev.crt.lang.value.NumberValue;
import dev.crt.lang.value.Value;
import dev.crt.lang.value.VectorValue;
import dev.crt.scene.Rgb;
import dev.crt.scene.SourceSpan;
import java.util.ArrayList;
import java.util.List;
import org.antlr.v4.runtime.ParserRuleContext;

/** The arithmetic operators on numbers, vectors, colours and lists (CSG is the evaluator's). */
final class Arithmetic {
    // Doubling a list in a loop would exhaust the heap long before the loop budget stops it.
    static final int MAX_LIST_SIZE = 10_000_000;

    private Arithmetic() {}

    static Value multiplicative(String op, Value a, Value b, ParserRuleContext where, Evaluator ev) {
        if (a instanceof NumberValue x && b instanceof NumberValue y) {
            double p = x.value(), q = y.value();
            return switch (op.charAt(0)) {
                case '*' -> number(p * q, x.integral() && y.integral(), op, where, ev);
                case '/' -> {
                    if (q == 0) throw ev.error("division by zero", ev.span(where));
                    yield number(p / q, false, op, where, ev);
                }
                default -> {
                    if (q == 0) throw ev.error("remainder of a division by zero ('%' by 0)", ev.span(where));
                    yield number(p % q, x.integral() && y.integral(), op, where, ev);
                }
            };
        }
        if (op.charAt(0) == '*') {
            if (a instanceof VectorValue v && b instanceof NumberValue s) return vector(v.vector().times(s.value()), where, ev);
            if (a instanceof NumberValue s && b instanceof VectorValue v) return vector(v.vector().times(s.value()), where, ev);
            if (a instanceof ColorValue c && b instanceof ColorValue d) return color(c.color().times(d.color()), where, ev);
            if (a instanceof ColorValue c && b instanceof NumberValue s) return color(c.color().times(s.value()), where, ev);
            if (a instanceof NumberValue s && b instanceof ColorValue c) return color(c.color().times(s.value()), where, ev);
        }
        if (op.charAt(0) == '/' && b instanceof NumberValue s && (a instanceof VectorValue || a instanceof ColorValue)) {
            if (s.value() == 0) throw ev.error("division by zero", ev.span(where));
            if (a instanceof VectorValue v) return vector(v.vector().div(s.value()), where, ev);
            return color(((ColorValue) a).color().div(s.value()), where, ev);
        }
        throw badOperands(op, a, b, ev.span(where), ev);
    }

    static Value additive(String op, Value a, Value b, ParserRuleContext where, Evaluator ev) {
        if (op.charAt(0) != '^') {
            boolean plus = op.charAt(0) == '+';
            if (a instanceof NumberValue x && b instanceof NumberValue y) {
                double r = plus ? x.value() + y.value() : x.value() - y.value();
                return number(r, x.integral() && y.integral(), op, where, ev);
            }
            if (a instanceof VectorValue v && b instanceof VectorValue w) {
                return vector(plus ? v.vector().plus(w.vector()) : v.vector().minus(w.vector()), where, ev);
            }
            if (a instanceof ColorValue c && b instanceof ColorValue d) {
                return color(plus ? c.color().plus(d.color()) : c.color().minus(d.color()), where, ev);
            }
            if (plus && a instanceof ListValue xs && b instanceof ListValue ys) {
                long size = (long) xs.items().size() + ys.items().size();
                if (size > MAX_LIST_SIZE) {
                    throw ev.error(String.format("a list of %,d items is too long (at most %,d)", size, MAX_LIST_SIZE), ev.span(where));
                }
                List<Value> all = new ArrayList<>(xs.items().size() + ys.items().size());
                all.addAll(xs.items());
                all.addAll(ys.items());
                return new ListValue(all);
            }
        }
        throw ev.error(badOperandsMessage(op, a, b) + Evaluator.continuation(where), ev.span(where));
    }

    static ScriptError badOperands(String op, Value a, Value b, SourceSpan at, Evaluator ev) {
        return ev.error(badOperandsMessage(op, a, b), at);
    }

    private static String badOperandsMessage(String op, Value a, Value b) {
        String hint = op.equals("^") && a instanceof NumberValue && b instanceof NumberValue
                ? " (for powers, use pow(a, b))" : "";
        return "operator '" + op + "' cannot apply to " + a.typeName() + " and " + b.typeName() + hint;
    }

    private static NumberValue number(double r, boolean integral, String op, ParserRuleContext where, Evaluator ev) {
        if (!Double.isFinite(r)) throw ev.error("the result of '" + op + "' is too large", ev.span(where));
        return integral ? NumberValue.ofInt(r) : NumberValue.ofFloat(r);
    }

    private static VectorValue vector(dev.crt.geom.Vec3 v, ParserRuleContext where, Evaluator ev) {
        if (!v.isFinite()) throw ev.error("a vector component is too large", ev.span(where));
        return new VectorValue(v);
    }

    private static ColorValue color(Rgb c, ParserRuleContext where, Evaluator ev) {
        if (!Double.isFinite(c.r()) || !Double.isFinite(c.g()) || !Double.isFinite(c.b())) {
            throw ev.error("a colour component is too large", ev.span(where));
        }
        return new ColorValue(c);
    }
}
