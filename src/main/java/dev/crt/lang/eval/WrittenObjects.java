package dev.crt.lang.eval;

import dev.crt.geom.Vec3;
import dev.crt.lang.TextPositions;
import dev.crt.lang.syntax.WrittenStatement;
import dev.crt.lang.value.BooleanValue;
import dev.crt.lang.value.ColorValue;
import dev.crt.lang.value.NumberValue;
import dev.crt.lang.value.StringValue;
import dev.crt.lang.value.Value;
import dev.crt.lang.value.VectorValue;
import dev.crt.scene.Rgb;
import dev.crt.scene.SourceSpan;
import java.util.Arrays;

import static dev.crt.lang.parser.CRTParser.*;

/**
 * Builds the object literal of a {@link WrittenStatement} straight from its tokens, doing what
 * the general path does with its tree: the same values, spans, builder calls in the same order,
 * and so the same entities and builder diagnostics. A first pass reads every plain value (no
 * side effects); when one of them would make the general path report or fail anything (an
 * unknown type or attribute, one given twice, an unassigned name, a call that is not vec3 or rgb
 * of three numbers, a number too large, a string with an escape), nothing is built and the
 * statement's tree runs instead, which reports it as always.
 */
final class WrittenObjects {
    private final Evaluator evaluator;
    private final ObjectBuilder builder;
    private final TextPositions positions;
    // By token index of the statement in hand, reused from one statement to the next: the value
    // that starts at a token, the index after what starts there, an attribute's name as the type
    // table spells it, and an object's type.
    private Value[] values = new Value[64];
    private int[] ends = new int[64];
    private String[] names = new String[64];
    private ObjectBuilder.ObjectType[] types = new ObjectBuilder.ObjectType[64];
    private WrittenStatement w;

    WrittenObjects(Evaluator evaluator, ObjectBuilder builder, TextPositions positions) {
        this.evaluator = evaluator;
        this.builder = builder;
        this.positions = positions;
    }

    /** The value of the statement's object literal, or null when its tree must run instead (nothing was built). */
    Value build(WrittenStatement statement) {
        int n = statement.size();
        if (values.length < n) {
            int size = Math.max(n, 2 * values.length);
            values = new Value[size];
            ends = new int[size];
            names = new String[size];
            types = new ObjectBuilder.ObjectType[size];
        }
        w = statement;
        try {
            int at = statement.assigns() ? 2 : 0;
            if (read(at) < 0) return null;
            return object(at);
        } finally {
            Arrays.fill(values, 0, n, null);
            w = null;
        }
    }

    // ---- first pass: read and check ---------------------------------------------------------

    /** Reads the object literal at {@code i}; the index after it, or -1 when the tree must run. */
    private int read(int i) {
        ObjectBuilder.ObjectType type = ObjectBuilder.type(w.text(i));
        if (type == null) return -1;
        types[i] = type;
        int first = i + 2;
        int j = first;
        while (w.type(j) != RBRACE) {
            String name = type.canonical(w.text(j));
            if (name == null) return -1;
            // Given twice? The canonical names are the table's own strings, so == compares them.
            for (int k = first; k < j; k = ends[k + 2]) if (names[k] == name) return -1;
            names[j] = name;
            int end = value(j + 2);
            if (end < 0) return -1;
            j = end;
        }
        ends[i] = j + 1;
        return j + 1;
    }

    /** Reads the plain value at {@code i} into {@code values[i]}; the index after it, or -1. */
    private int value(int i) {
        int end;
        switch (w.type(i)) {
            case PLUS, MINUS -> {
                NumberValue n = number(i + 1);
                if (n == null) return -1;
                values[i] = w.type(i) == MINUS ? new NumberValue(-n.value(), n.integral()) : n;
                end = i + 2;
            }
            case INT, FLOAT -> {
                NumberValue n = number(i);
                if (n == null) return -1;
                values[i] = n;
                end = i + 1;
            }
            case STRING -> {
                String text = w.text(i);
                if (text.indexOf('\\') >= 0) return -1;
                values[i] = new StringValue(text.substring(1, text.length() - 1));
                end = i + 1;
            }
            case TRUE, FALSE -> {
                values[i] = BooleanValue.of(w.type(i) == TRUE);
                end = i + 1;
            }
            case IDENT -> {
                String name = w.text(i);
                if (w.type(i + 1) == LPAREN) {
                    end = call(name, i);
                    if (end < 0) return -1;
                } else {
                    Value v = evaluator.variable(name);
                    if (v == null) return -1;
                    values[i] = v;
                    end = i + 1;
                }
            }
            case NAME -> {
                end = read(i);
                if (end < 0) return -1;
            }
            default -> {
                return -1;
            }
        }
        ends[i] = end;
        return end;
    }

    /** vec3 or rgb of three numbers, where the script binds neither name; the index after the call, or -1. */
    private int call(String name, int i) {
        boolean vector = name.equals("vec3");
        if (!vector && !name.equals("rgb")) return -1;
        // A name the script assigns is called as a macro, or reported, by the general path.
        if (evaluator.variable(name) != null || evaluator.isAssigned(name)) return -1;
        double[] xyz = new double[3];
        int j = i + 2;
        for (int k = 0; k < 3; k++) {
            int t = w.type(j);
            boolean minus = t == MINUS;
            if (t == PLUS || t == MINUS) j++;
            NumberValue n = number(j);
            if (n == null) return -1;
            xyz[k] = minus ? -n.value() : n.value();
            j++;
            if (w.type(j) != (k < 2 ? COMMA : RPAREN)) return -1;
            j++;
        }
        values[i] = vector ? new VectorValue(new Vec3(xyz[0], xyz[1], xyz[2])) : new ColorValue(new Rgb(xyz[0], xyz[1], xyz[2]));
        return j;
    }

    /** The number literal at {@code i}, as the general path reads it, or null (not a number, or too large). */
    private NumberValue number(int i) {
        int type = w.type(i);
        String script = w.script();
        int from = w.startIndex(i), to = w.stopIndex(i) + 1;
        if (type == INT) {
            if (to - from <= 15) {
                long v = 0;
                for (int k = from; k < to; k++) v = v * 10 + (script.charAt(k) - '0');
                // Below 2^53: the double is exact, as Double.parseDouble gives it.
                return NumberValue.ofInt(v);
            }
            return NumberValue.ofInt(Double.parseDouble(script.substring(from, to)));
        }
        if (type != FLOAT) return null;
        double v = Decimals.parse(script, from, to);
        return Double.isFinite(v) ? NumberValue.ofFloat(v) : null;
    }

    // ---- second pass: build ------------------------------------------------------------------

    /** Builds the object literal read at {@code i}, as {@code ObjectBuilder.build} does from its tree. */
    private Value object(int i) {
        int end = ends[i];
        Attributes a = new Attributes(evaluator, w.text(i), span(i, i), span(i, end - 1));
        for (int j = i + 2; j < end - 1; ) {
            int at = j + 2;
            int next = ends[at];
            SourceSpan span = span(j, next - 1);
            if (w.type(at) == NAME) {
                try {
                    a.put(names[j], new Attributes.Given(object(at), span));
                } catch (EvaluationStopped stop) {
                    throw stop;
                } catch (ScriptError e) {
                    a.markFailed(names[j]);
                    evaluator.report(e);
                } catch (Failed f) {
                    a.markFailed(names[j]);
                }
            } else {
                a.put(names[j], new Attributes.Given(values[at], span));
            }
            j = next;
        }
        Value value = types[i].build().apply(builder, a);
        a.finish();
        return value;
    }

    /** The span from the start of token {@code first} to the end of token {@code last}. */
    private SourceSpan span(int first, int last) {
        return positions.span(positions.charOffset(w.startIndex(first)), positions.charOffset(w.stopIndex(last) + 1));
    }
}
