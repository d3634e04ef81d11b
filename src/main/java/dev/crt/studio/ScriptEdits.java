package dev.crt.studio;

import dev.crt.lang.CompileOptions;
import dev.crt.lang.CompileResult;
import dev.crt.lang.CrtCompiler;
import dev.crt.lang.Diagnostic;
import dev.crt.lang.Source;
import dev.crt.lang.SourceMap;
import dev.crt.lang.SourceMap.Expr;
import dev.crt.lang.SourceMap.MacroCall;
import dev.crt.lang.SourceMap.ObjectInfo;
import dev.crt.lang.value.NumberValue;
import java.math.BigDecimal;
import java.math.MathContext;
import java.time.Duration;
import java.util.List;

/**
 * Turns a change made with the mouse into a change of the script's text: the literal of an
 * attribute rewritten in place, the variable or macro argument it comes from rewritten instead, or
 * the attribute inserted when it was defaulted. What cannot be changed that way (an expression, a
 * literal shared by every call of a macro) is refused with a sentence saying why and where to edit.
 */
final class ScriptEdits {
    /** Replace [start, end) of the text with {@code text}; {@code what} says what changes, as a sentence for the status line. */
    record Edit(int start, int end, String text, String what) {
        String applyTo(String script) { return script.substring(0, start) + text + script.substring(end); }
    }

    /** An edit that cannot be made, with the sentence that explains it. */
    static final class Refused extends Exception {
        Refused(String message) { super(message); }
    }

    private ScriptEdits() {}

    /**
     * The edit that gives {@code attribute} of {@code object} the value {@code literal} (as a script
     * writes it). {@code call} is the macro call that made the entity, or null.
     */
    static Edit setAttribute(String script, SourceMap map, ObjectInfo object, MacroCall call, String attribute, String literal)
            throws Refused {
        Expr e = object.attributes().get(attribute);
        String where = object.type() + (object.variable() != null ? " " + object.variable() : "");
        if (e == null) {
            if (object.inMacro()) {
                throw new Refused("'" + attribute + "' is not written in this " + where + ", which a macro makes for every call: "
                        + "add it inside the macro, line " + object.span().line());
            }
            return insert(script, object, attribute, literal);
        }
        int line = lineOf(script, e.start());
        switch (e.kind()) {
            case VARIABLE -> {
                Expr def = map.definitions().get(e.name());
                if (def == null || !def.kind().isLiteral()) {
                    throw new Refused("'" + attribute + "' of " + where + " is the variable '" + e.name() + "', which is not "
                            + "one plain literal assigned once: edit it in the script (line " + line + ")");
                }
                return new Edit(def.start(), def.end(), literal, "changed the variable " + e.name() + " (line " + lineOf(script, def.start()) + ")");
            }
            case PARAMETER -> {
                Argument arg = argument(object, call, attribute, e.name());
                return new Edit(arg.literal().start(), arg.literal().end(), literal, "changed the argument " + arg.parameter() + " of "
                        + arg.call().macro() + "(…) at line " + arg.call().span().line());
            }
            case EXPRESSION, OBJECT -> throw new Refused("'" + attribute + "' of " + where + " is computed by " + e.text()
                    + " (line " + line + "): edit the expression in the script");
            default -> {
                if (object.inMacro()) {
                    throw new Refused("'" + attribute + "' of " + where + " is written inside a macro and shared by every call of it:"
                            + " change it there, line " + line + (call != null ? ", or pass it as an argument" : ""));
                }
                return new Edit(e.start(), e.end(), literal, "changed " + attribute + " of " + where + " (line " + line + ")");
            }
        }
    }

    /** The argument literal a macro parameter's value is written as: the parameter, the call it is an argument of, the literal. */
    record Argument(String parameter, MacroCall call, Expr literal) {}

    /**
     * Where the value of {@code parameter}, read by {@code attribute} of {@code object} (written in a
     * macro body), is written as a literal: the argument of {@code call} (the call that made the
     * object), or, when that argument passes on a parameter of the macro the call is written in, the
     * argument of that call's caller, and so on out to the top level of the script. Refused when an
     * argument on the way is computed, or is a literal written inside a macro body (shared by every
     * call of that macro).
     */
    static Argument argument(ObjectInfo object, MacroCall call, String attribute, String parameter) throws Refused {
        String where = object.type() + (object.variable() != null ? " " + object.variable() : "");
        if (call == null || !call.parameters().equals(object.macroParameters()) || call.argument(parameter) == null) {
            throw new Refused("'" + attribute + "' of " + where + " comes from the macro parameter '" + parameter
                    + "': edit the macro call in the script");
        }
        StringBuilder path = new StringBuilder();
        for (MacroCall c = call; ; c = c.caller()) {
            Expr arg = c.argument(parameter);
            String written = "the argument " + parameter + " = " + arg.text() + " of the call " + c.macro() + "(…) at line " + c.span().line();
            path.append(path.length() == 0 ? "" : ", from ").append(written);
            if (arg.kind() == SourceMap.Kind.PARAMETER && c.caller() != null && c.caller().argument(arg.name()) != null) {
                parameter = arg.name();
                continue;
            }
            if (!arg.kind().isLiteral()) {
                throw new Refused("'" + attribute + "' comes from " + path + ", which is computed, not a plain literal: edit the call");
            }
            if (c.caller() != null) {
                throw new Refused("'" + attribute + "' comes from " + path + ", written inside the macro " + c.caller().macro()
                        + " and shared by every call of it: change it there, or make it a parameter of " + c.caller().macro());
            }
            return new Argument(parameter, c, arg);
        }
    }

    /** Inserts {@code attribute -> literal} as the last attribute of the object, in the layout the object already has. */
    private static Edit insert(String script, ObjectInfo object, String attribute, String literal) {
        String written = attribute + " -> " + literal;
        int close = object.closeBrace();
        int lastEnd = -1;
        for (Expr a : object.attributes().values()) lastEnd = Math.max(lastEnd, a.end());
        String what = "added " + attribute + " to " + object.type() + " (line " + object.span().line() + ")";
        if (lastEnd < 0) {
            int open = script.indexOf('{', object.span().start());
            String inside = script.substring(open + 1, close);
            if (inside.contains("\n")) {
                String indent = indentOf(script, object.span().start()) + "  ";
                return new Edit(open + 1, close, "\n" + indent + written + "\n" + indentOf(script, close), what);
            }
            return new Edit(open + 1, close, " " + written + " ", what);
        }
        if (script.substring(lastEnd, close).contains("\n")) {
            return new Edit(lastEnd, lastEnd, "\n" + indentOf(script, lastEnd) + written, what);
        }
        return new Edit(lastEnd, lastEnd, " " + written, what);
    }

    private static String indentOf(String script, int offset) {
        int start = script.lastIndexOf('\n', Math.max(0, offset - 1)) + 1;
        int i = start;
        while (i < script.length() && (script.charAt(i) == ' ' || script.charAt(i) == '\t')) i++;
        return script.substring(start, i);
    }

    static int lineOf(String script, int offset) {
        int line = 1;
        for (int i = 0; i < Math.min(offset, script.length()); i++) if (script.charAt(i) == '\n') line++;
        return line;
    }

    private static final CompileOptions CHECK = new CompileOptions(0, List.of(), CompileOptions.DEFAULT_LOOP_BUDGET, Duration.ofSeconds(2));

    /** How many errors the script has now. */
    static long errors(String name, String script) { return CrtCompiler.compile(Source.of(name, script), CHECK).errorCount(); }

    /**
     * Null when {@code edited} compiles with no more errors than the script had before the edit
     * ({@code errorsBefore}), else the first error as a sentence: an edit that breaks the script is not made.
     */
    static String breaks(String name, long errorsBefore, String edited) {
        CompileResult now = CrtCompiler.compile(Source.of(name, edited), CHECK);
        if (now.errorCount() <= errorsBefore) return null;
        Diagnostic first = now.diagnostics().stream().filter(Diagnostic::isError).findFirst().orElseThrow();
        return "the script would not compile: " + first.span().line() + ":" + first.span().column() + ": " + first.message();
    }

    // ---- literals ----------------------------------------------------------------------------

    /** A number as a person writes it: 2, 0.25, -1.5 (ten significant digits at most, so 0.1 + 0.2 writes 0.3). */
    static String number(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) return Long.toString((long) v);
        if (!Double.isFinite(v)) throw new IllegalArgumentException("not a finite number: " + v);
        BigDecimal d = new BigDecimal(v).round(new MathContext(10)).stripTrailingZeros();
        return Math.abs(v) >= 1e-6 && Math.abs(v) < 1e15 ? d.toPlainString() : NumberValue.format(d.doubleValue());
    }

    static String vec3(double x, double y, double z) { return "vec3(" + number(x) + ", " + number(y) + ", " + number(z) + ")"; }

    static String rgb(double r, double g, double b) { return "rgb(" + number(r) + ", " + number(g) + ", " + number(b) + ")"; }

    static String string(String s) { return "\"" + s.replace("\\", "\\\\").replace("\"", "\\\"") + "\""; }

    /** The number a NUMBER literal writes (with its sign). */
    static double parseNumber(String literal) { return Double.parseDouble(literal.replaceAll("\\s+", "")); }

    /** The three numbers of a VECTOR or COLOR literal: {@code vec3(1, -2, 0.5)}. */
    static double[] parseTriple(String literal) {
        String inside = literal.substring(literal.indexOf('(') + 1, literal.lastIndexOf(')'));
        String[] parts = inside.split(",");
        return new double[] {parseNumber(parts[0]), parseNumber(parts[1]), parseNumber(parts[2])};
    }

    /** The text of a STRING literal, escapes undone. */
    static String parseString(String literal) {
        StringBuilder out = new StringBuilder();
        for (int i = 1; i < literal.length() - 1; i++) {
            char c = literal.charAt(i);
            if (c == '\\' && i + 1 < literal.length() - 1) c = literal.charAt(++i);
            out.append(c);
        }
        return out.toString();
    }
}
