package dev.crt.lang;

import dev.crt.scene.SourceSpan;
import java.util.List;
import java.util.Map;

/**
 * Where each compiled object was written, for tools that change the script for the user (the
 * studio's navigator and property sheet): the span of every object literal and CSG operation, the
 * span of each attribute's expression and whether it is a plain literal, the variable an object
 * was assigned to, the macro call that made each placed entity, and the names assigned once.
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

    /** A call of a macro at the top level of the script: the macro's name, the call's span, its parameters and arguments. */
    public record MacroCall(String macro, SourceSpan span, List<String> parameters, List<Expr> arguments) {
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

    /** The macro call that made the placed entity number {@code index} of the scene, or null when the script placed it directly. */
    public MacroCall callOf(int index) { return index >= 0 && index < entityCalls.size() ? entityCalls.get(index) : null; }

    static long key(int start, int end) { return ((long) start << 32) | (end & 0xffffffffL); }

    /** The key of {@link #operations} for a span. */
    public static long operationKey(int start, int end) { return key(start, end); }
}
