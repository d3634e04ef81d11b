package dev.crt.lang.eval;

import dev.crt.lang.SourceMap;
import dev.crt.lang.SourceMap.Expr;
import dev.crt.lang.SourceMap.Kind;
import dev.crt.lang.SourceMap.MacroCall;
import dev.crt.lang.SourceMap.ObjectInfo;
import dev.crt.lang.parser.CRTParser;
import dev.crt.lang.value.EntityValue;
import dev.crt.lang.value.Value;
import dev.crt.scene.Entity;
import dev.crt.scene.SourceSpan;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.tree.ParseTree;
import org.antlr.v4.runtime.tree.TerminalNode;

/**
 * Records a {@link SourceMap} while a script runs. The evaluator calls it only when the compile
 * options ask for a map; each object literal is described once, however often a loop or macro
 * evaluates it, and the descriptions come from the parse tree (what was written), not the values.
 */
final class SourceRecorder {
    private final Evaluator evaluator;
    private final String text;
    private final Map<Integer, ObjectInfo> objects = new HashMap<>();
    private final Map<Long, ObjectInfo> operations = new HashMap<>();
    private final List<ObjectInfo> settings = new ArrayList<>();
    private final Map<ParserRuleContext, Boolean> settingsSeen = new IdentityHashMap<>();
    private final Map<Entity, MacroCall> madeBy = new IdentityHashMap<>();
    /** Global assignments by name, each assignment once however often it ran. */
    private final Map<String, Map<ParserRuleContext, Expr>> assignments = new HashMap<>();
    private MacroCall call;

    SourceRecorder(Evaluator evaluator, String text) {
        this.evaluator = evaluator;
        this.text = text;
    }

    void object(CRTParser.ObjectContext ctx, Value value) {
        SourceSpan span = evaluator.span(ctx);
        if (!objects.containsKey(span.start())) {
            objects.put(span.start(), new ObjectInfo(ctx.NAME().getText(), span, offset(ctx.getStop().getStartIndex()),
                    attributes(ctx.attribute(), ctx), variable(ctx), macroParameters(ctx)));
        }
        built(value);
    }

    void settings(CRTParser.SettingsBlockContext block) {
        if (settingsSeen.put(block, Boolean.TRUE) != null) return;
        settings.add(new ObjectInfo("Settings", evaluator.span(block), offset(block.getStop().getStartIndex()),
                attributes(block.attribute(), block), null, null));
    }

    void operation(CRTParser.AdditiveContext ctx, Value value, String type) {
        SourceSpan span = evaluator.span(ctx);
        operations.computeIfAbsent(SourceMap.operationKey(span.start(), span.end()),
                k -> new ObjectInfo(type, span, -1, Map.of(), variable(ctx), macroParameters(ctx)));
        built(value);
    }

    private void built(Value value) {
        if (call != null && value instanceof EntityValue.Built b) madeBy.put(b.entity(), call);
    }

    /**
     * A call of a macro begins (its arguments are evaluated already); what it builds until
     * {@link #callEnded} is its, and a call made meanwhile is made under it.
     */
    void callStarted(String name, List<String> parameters, CRTParser.CallContext ctx) {
        List<String> enclosing = macroParameters(ctx);
        List<Expr> arguments = new ArrayList<>();
        for (int i = 2; i < ctx.getChildCount(); i += 2) {
            if (ctx.getChild(i) instanceof ParserRuleContext arg) arguments.add(expr(arg, enclosing));
        }
        call = new MacroCall(name, evaluator.span(ctx), List.copyOf(parameters), arguments, call);
    }

    void callEnded() { call = call == null ? null : call.caller(); }

    void assigned(CRTParser.AssignmentContext ctx) {
        assignments.computeIfAbsent(ctx.IDENT().getText(), k -> new IdentityHashMap<>())
                .computeIfAbsent(ctx, k -> expr((ParserRuleContext) ctx.getChild(2), null));
    }

    SourceMap finish(List<EntityValue> placed) {
        List<MacroCall> calls = new ArrayList<>(placed.size());
        if (madeBy.isEmpty()) {
            calls.addAll(java.util.Collections.nCopies(placed.size(), null));
        } else {
            for (EntityValue e : placed) {
                EntityValue v = e;
                while (v instanceof EntityValue.Modified m) v = m.before();
                calls.add(madeBy.get(((EntityValue.Built) v).entity()));
            }
        }
        Map<String, Expr> definitions = new HashMap<>();
        assignments.forEach((name, all) -> {
            if (all.size() == 1) definitions.put(name, all.values().iterator().next());
        });
        return new SourceMap(objects, operations, settings, calls, definitions);
    }

    // ---- what was written --------------------------------------------------------------------

    private Map<String, Expr> attributes(List<CRTParser.AttributeContext> written, ParserRuleContext owner) {
        List<String> parameters = macroParameters(owner);
        Map<String, Expr> out = new LinkedHashMap<>();
        for (CRTParser.AttributeContext a : written) out.putIfAbsent(a.key.getText(), expr(a.expression(), parameters));
        return out;
    }

    private Expr expr(ParserRuleContext e, List<String> parameters) {
        SourceSpan span = evaluator.span(e);
        String written = text.substring(span.start(), Math.min(span.end(), text.length()));
        ParserRuleContext c = unwrap(e);
        String name = null;
        Kind kind;
        if (isNumber(c)) kind = Kind.NUMBER;
        else if (c instanceof CRTParser.StringLiteralContext s && s.STRING() != null) kind = Kind.STRING;
        else if (c instanceof CRTParser.BooleanLiteralContext) kind = Kind.BOOLEAN;
        else if (c instanceof CRTParser.ObjectContext) kind = Kind.OBJECT;
        else if (c instanceof CRTParser.VariableContext v) {
            name = v.IDENT().getText();
            kind = parameters != null && parameters.contains(name) ? Kind.PARAMETER : Kind.VARIABLE;
        } else if (isTriple(c, "vec3")) kind = Kind.VECTOR;
        else if (isTriple(c, "rgb")) kind = Kind.COLOR;
        else kind = Kind.EXPRESSION;
        return new Expr(span.start(), span.end(), kind, written, name);
    }

    private static ParserRuleContext unwrap(ParseTree tree) {
        ParserRuleContext c = (ParserRuleContext) tree;
        while (true) {
            if (c.children != null && c.children.size() == 1 && c.getChild(0) instanceof ParserRuleContext inner) c = inner;
            else if (c instanceof CRTParser.ParenthesizedContext p) c = p.expression();
            else return c;
        }
    }

    /** A number literal, with at most one sign before it. */
    private static boolean isNumber(ParserRuleContext c) {
        if (c instanceof CRTParser.SignContext s) c = unwrap(s.arithmetic());
        return c instanceof CRTParser.IntLiteralContext || c instanceof CRTParser.FloatLiteralContext;
    }

    /** {@code fn(n, n, n)} with three number literals. */
    private static boolean isTriple(ParserRuleContext c, String fn) {
        if (!(c instanceof CRTParser.CallContext call) || !(unwrap(call.arithmetic()) instanceof CRTParser.VariableContext v)
                || !v.IDENT().getText().equals(fn) || call.expression().size() != 3) {
            return false;
        }
        for (CRTParser.ExpressionContext arg : call.expression()) if (!isNumber(unwrap(arg))) return false;
        return true;
    }

    /** The variable a value is assigned to, through parentheses and modifiers: {@code ball = Sphere {…} <translate …>}. */
    private static String variable(ParserRuleContext ctx) {
        ParseTree child = ctx;
        ParserRuleContext p = ctx.getParent();
        while (p != null) {
            if (p instanceof CRTParser.AssignmentContext a) return a.IDENT().getText();
            boolean passes = (p.getChildCount() == 1)
                    || p instanceof CRTParser.ParenthesizedContext
                    || (p instanceof CRTParser.ModifiedContext && p.getChild(0) == child);
            if (!passes) return null;
            child = p;
            p = p.getParent();
        }
        return null;
    }

    /** The parameters of the innermost macro whose body holds {@code ctx}, or null outside macros. */
    private static List<String> macroParameters(ParserRuleContext ctx) {
        for (ParserRuleContext p = ctx.getParent(); p != null; p = p.getParent()) {
            if (p instanceof CRTParser.MacroContext m) return m.IDENT().stream().map(TerminalNode::getText).toList();
        }
        return null;
    }

    private int offset(int codePointIndex) { return evaluator.charOffset(codePointIndex); }
}
