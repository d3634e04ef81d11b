package dev.crt.lang;

import dev.crt.scene.SourceSpan;
import java.util.List;
import java.util.Map;

/**
 * Where each compiled object was written, for tools that change the script for the user (the
 * studio's navigator and property sheet): the span of every object literal and CSG operation, the
 * span of each attribute's expression and whether it is a plain literal, the variable an object
 * was assigned to, the chain of macro calls that made each placed entity, and the names assigned once.
 * Recorded only when {@link CompileOptions#sourceMap()} asks for it.
 */
public record SourceMap(Map<Integer, ObjectInfo> objects, Map<Long, ObjectInfo> operations, List<ObjectInfo> settings,
        List<MacroCall> entityCalls, Map<String, Expr> definitions) {
    public SourceMap {
        objects = Map.copyOf(objects);
        operations = Map.copyOf(operations);
        settings = List.copyOf(settings);
        // May hold nulls (entities placed directly), which List.copyOf refuses.
        entityCalls = java.util.Collections.unmodifiableList(entityCalls);
        definitions = Map.copyOf(definitions);
    }

    /** What an expression is, as written. */
    public enum Kind {
        NUMBER, VECTOR, COLOR, STRING, BOOLEAN, VARIABLE, PARAMETER, OBJECT, EXPRESSION;

        /** A plain literal that a tool may rewrite in place: a number, vec3(…), rgb(…), string or boolean. */
        public boolean isLiteral() { return ordinal() <= BOOLEAN.ordinal(); }
    }

    /** One expression: its character offsets [start, end), what it is, its text, and the name it reads (VARIABLE, PARAMETER). */
    public record Expr(int start, int end, Kind kind, String text, String name) {}

    /**
     * An object literal ({@code Sphere { … }}), a Settings block or a CSG operation: its type (for
     * CSG "Union", "Difference" or "Intersection"), its whole span, the offset of its closing brace
     * (-1 for CSG), its attributes in the order written, the variable it was assigned to (or null),
     * and, for one written inside a macro body, that macro's parameters (null outside macros).
     */
    public record ObjectInfo(String type, SourceSpan span, int closeBrace, Map<String, Expr> attributes, String variable,
            List<String> macroParameters) {
        public boolean inMacro() { return macroParameters != null; }
    }

    /**
     * One run of a macro call: the macro's name, the call's span, the macro's parameters and the
     * arguments as written, and the call whose macro body this call is written in, which was running
     * when it was made ({@code caller}; null for a call at the top level of the script). An
     * argument of a call inside a macro body that names that macro's parameter is a
     * {@link Kind#PARAMETER}, whose value the caller's argument gives.
     */
    public record MacroCall(String macro, SourceSpan span, List<String> parameters, List<Expr> arguments, MacroCall caller) {
        /** A call at the top level of the script. */
        public MacroCall(String macro, SourceSpan span, List<String> parameters, List<Expr> arguments) {
            this(macro, span, parameters, arguments, null);
        }

        /** The call at the top level of the script this call was made under (itself when it is one). */
        public MacroCall outermost() {
            MacroCall c = this;
            while (c.caller != null) c = c.caller;
            return c;
        }

        /** The argument written for {@code parameter}, or null. */
        public Expr argument(String parameter) {
            int i = parameters.indexOf(parameter);
            return i < 0 || i >= arguments.size() ? null : arguments.get(i);
        }
    }

    /** The object literal that starts at {@code offset}, or null. */
    public ObjectInfo objectAt(int offset) { return objects.get(offset); }

    /** The CSG operation written over exactly {@code span}, or null. */
    public ObjectInfo operation(SourceSpan span) { return operations.get(key(span.start(), span.end())); }

    /**
     * The call at the top level of the script under which the placed entity number {@code index} of
     * the scene was made, or null when the script placed it directly.
     */
    public MacroCall callOf(int index) {
        MacroCall maker = makerOf(index);
        return maker == null ? null : maker.outermost();
    }

    /**
     * The innermost macro call that made the placed entity number {@code index} (the one running when
     * its object literal was evaluated; its {@link MacroCall#caller()} chain leads to {@link #callOf}),
     * or null when the script placed it directly. {@code entityCalls} holds these.
     */
    public MacroCall makerOf(int index) { return index >= 0 && index < entityCalls.size() ? entityCalls.get(index) : null; }

    static long key(int start, int end) { return ((long) start << 32) | (end & 0xffffffffL); }

    /** The key of {@link #operations} for a span. */
    public static long operationKey(int start, int end) { return key(start, end); }
}
