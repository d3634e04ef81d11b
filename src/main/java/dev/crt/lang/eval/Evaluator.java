package dev.crt.lang.eval;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.lang.CompileOptions;
import dev.crt.lang.Diagnostic;
import dev.crt.lang.Severity;
import dev.crt.lang.TextPositions;
import dev.crt.lang.parser.CRTBaseVisitor;
import dev.crt.lang.parser.CRTParser;
import dev.crt.lang.syntax.WrittenStatement;
import dev.crt.lang.value.BooleanValue;
import dev.crt.lang.value.ColorValue;
import dev.crt.lang.value.EntityValue;
import dev.crt.lang.value.ListValue;
import dev.crt.lang.value.MacroValue;
import dev.crt.lang.value.NumberValue;
import dev.crt.lang.value.StringValue;
import dev.crt.lang.value.Value;
import dev.crt.lang.value.VectorValue;
import dev.crt.scene.Cone;
import dev.crt.scene.Csg;
import dev.crt.scene.Cylinder;
import dev.crt.scene.Mesh;
import dev.crt.scene.CsgOperation;
import dev.crt.scene.Entity;
import dev.crt.scene.Rgb;
import dev.crt.scene.Scene;
import dev.crt.scene.SourceSpan;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.Iterator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.tree.ParseTree;
import org.antlr.v4.runtime.tree.TerminalNode;

/**
 * Runs a parsed script: statements top to bottom, expressions by the rules of the language
 * reference, and collects the entities the Scene blocks place.
 */
public final class Evaluator extends CRTBaseVisitor<Value> {
    static final int MAX_ERRORS = 20;
    static final int MAX_MACRO_DEPTH = 256;
    // Seeded identically for every compile: rand() gives the same numbers on every run.
    private static final long RANDOM_SEED = 2015;

    /** Where a statement's value goes: nowhere (top level), into the scene, or into a macro's result. */
    private enum Place { TOP, SCENE, MACRO }

    private record Frame(String macro, SourceSpan call) {}

    private final TextPositions positions;
    private final Budget budget;
    private boolean ranOutOfMemory;
    private final ScriptRandom random = new ScriptRandom(RANDOM_SEED);
    private final ObjectBuilder objects;
    private final WrittenObjects written;
    private final SettingsState settings;
    private final List<Diagnostic> diagnostics = new ArrayList<>();
    private final Set<String> warned = new HashSet<>();
    private final Map<String, Value> globals = new HashMap<>();
    private Map<String, Value> locals;
    private final List<Frame> callStack = new ArrayList<>();
    private final List<EntityValue> placed = new ArrayList<>();
    private final Map<ParseTree, Code> compiled = new IdentityHashMap<>();
    private Set<String> assignedNames = Set.of();
    private int loopDepth;
    private boolean sawScene;
    private int errors;
    /** Null unless the options ask for a source map: then every hook below records into it. */
    private final SourceRecorder recorder;

    /** {@code startNanos} (System.nanoTime) is when the compile began: its time budget counts from then. */
    public Evaluator(TextPositions positions, CompileOptions options, Path scriptFolder, long startNanos) {
        this.positions = positions;
        this.budget = new Budget(options.loopBudget(), options.timeBudget(), startNanos);
        this.objects = new ObjectBuilder(this, new Assets(scriptFolder, options.assetDirs()));
        this.written = new WrittenObjects(this, objects, positions);
        this.settings = new SettingsState();
        this.recorder = options.sourceMap() ? new SourceRecorder(this, positions.text()) : null;
        // A whole time (every frame number of crt animate) is an integer, so `xs[t]` and `t % 2` work.
        double time = options.time();
        globals.put("t", time == Math.rint(time) && Math.abs(time) < 1e15 ? NumberValue.ofInt(time) : NumberValue.ofFloat(time));
        globals.put("pi", NumberValue.ofFloat(Math.PI));
    }

    /** Whether the evaluation stopped because the Java heap was full. */
    public boolean ranOutOfMemory() { return ranOutOfMemory; }

    /** Asks a running evaluation to stop soon (another thread may call it). */
    public void cancel() { budget.cancel(); }

    /**
     * Runs the script's top-level statements in order; {@code assignedNames} are the names it ever
     * assigns or binds. The scene is null when there were errors. Diagnostics are in source order.
     */
    public Scene run(Iterator<CRTParser.StatementContext> statements, Set<String> assignedNames, String sourceName) {
        this.assignedNames = assignedNames;
        try {
            while (statements.hasNext()) runRecovering(statements.next(), Place.TOP, null);
        } catch (EvaluationStopped stop) {
            record(stop.severity(), stop.getMessage(), stop.span(), stop.callChain());
            if (stop.severity() == Severity.ERROR) errors++;
        }
        if (errors > 0) return null;
        if (!sawScene) warn("no Scene block: the picture shows only the background", positions.span(0, 0));
        if (!settings.hasCamera()) {
            warn("no camera in Settings: using the default camera at vec3(0, 0, -5) pointing at the origin",
                    settings.firstBlock() != null ? settings.firstBlock() : positions.span(0, 0));
        }
        List<Entity> entities = new ArrayList<>(placed.size());
        for (EntityValue e : placed) {
            Entity entity = e.entity();
            Entity degenerate = degenerateTransform(entity, Transform.IDENTITY);
            if (degenerate != null) {
                record(Severity.ERROR, "the modifiers of this entity scale it too far for numbers to hold"
                        + " (its transform cannot be computed or undone)", degenerate.span(), List.of());
                errors++;
            }
            entities.add(entity);
        }
        if (errors > 0) return null;
        return new Scene(sourceName, settings.build(), entities);
    }

    /** The first entity of the tree whose transform to the world overflows or underflows, or null. */
    private static Entity degenerateTransform(Entity e, Transform toWorld) {
        Transform t = e.transform().then(toWorld);
        if (!t.isFinite()) return e;
        if (e instanceof Csg c) {
            Entity left = degenerateTransform(c.left(), t);
            return left != null ? left : degenerateTransform(c.right(), t);
        }
        return null;
    }

    /** What {@link #run} recorded about where things were written, or null when the options did not ask. */
    public dev.crt.lang.SourceMap sourceMap() { return recorder == null ? null : recorder.finish(placed); }

    int charOffset(int codePointIndex) { return positions.charOffset(codePointIndex); }

    /** Every diagnostic so far, in source order. */
    public List<Diagnostic> diagnostics() {
        List<Diagnostic> sorted = new ArrayList<>(diagnostics);
        // Most compiles have none to sort, and then no comparator is made: the JDK links the lambda
        // inside Comparator.comparingInt at run time (the start-up cache does not hold it), about
        // a millisecond of a fresh process's compile.
        if (sorted.size() > 1) sorted.sort(Comparator.comparingInt(d -> d.span().start()));
        return sorted;
    }

    // ---- statements ----------------------------------------------------------------------------

    private void runRecovering(CRTParser.StatementContext statement, Place place, List<EntityValue> out) {
        try {
            execute(statement, place, out);
        } catch (EvaluationStopped stop) {
            throw stop;
        } catch (ScriptError e) {
            report(e);
            markFailed(statement);
        } catch (Failed f) {
            markFailed(statement);
        }
    }

    /** A failed assignment leaves its variable failed, so reading it later adds no second error. */
    private void markFailed(CRTParser.StatementContext statement) {
        if (statement instanceof WrittenStatement w) {
            if (w.assigns()) scope().put(w.assignedName(), null);
            return;
        }
        if (statement instanceof CRTParser.ExpressionStatementContext s
                && s.expression() instanceof CRTParser.AssignmentContext a) {
            String name = a.IDENT().getText();
            if (!name.equals("t")) scope().put(name, null);
        }
    }

    private void executeAll(List<CRTParser.StatementContext> statements, Place place, List<EntityValue> out) {
        for (CRTParser.StatementContext s : statements) execute(s, place, out);
    }

    private void execute(CRTParser.StatementContext statement, Place place, List<EntityValue> out) {
        if (statement instanceof WrittenStatement w) {
            // Built from its tokens; null when it must report something: its tree then runs as any other.
            Value value = recorder == null ? written.build(w) : null;
            if (value == null) {
                execute(w.tree(), place, out);
            } else if (w.assigns()) {
                scope().put(w.assignedName(), value);
            } else if (place == Place.SCENE) {
                // The tree only for the span of a mistake.
                if (value instanceof EntityValue e) placed.add(e);
                else placeInScene(value, ((CRTParser.ExpressionStatementContext) w.tree()).expression());
            } else if (place == Place.MACRO) {
                contribute(value, out);
            }
            return;
        }
        if (statement instanceof CRTParser.ExpressionStatementContext s) {
            CRTParser.ExpressionContext e = s.expression();
            Value value = evaluate(e);
            if (e instanceof CRTParser.AssignmentContext) return;
            if (place == Place.SCENE) placeInScene(value, e);
            else if (place == Place.MACRO) contribute(value, out);
        } else if (statement instanceof CRTParser.WhileLoopContext w) {
            runWhile(w, place, out);
        } else if (statement instanceof CRTParser.IfStatementContext i) {
            runIf(i.ifChain(), place, out);
        } else if (statement instanceof CRTParser.SceneBlockContext scene) {
            if (place == Place.MACRO) throw error("a Scene block cannot be inside a macro", span(scene.SCENE().getSymbol()));
            sawScene = true;
            for (CRTParser.StatementContext s : scene.statement()) {
                if (place == Place.TOP) runRecovering(s, Place.SCENE, null);
                else execute(s, Place.SCENE, null);
            }
        } else if (statement instanceof CRTParser.SettingsBlockContext block) {
            if (place == Place.MACRO) throw error("a Settings block cannot be inside a macro", span(block.SETTINGS().getSymbol()));
            SourceSpan keyword = span(block.SETTINGS().getSymbol());
            if (recorder != null) recorder.settings(block);
            settings.apply(objects.evaluate("Settings", SettingsState.ATTRIBUTES, block.attribute(), keyword, span(block)));
        }
    }

    private void runWhile(CRTParser.WhileLoopContext loop, Place place, List<EntityValue> out) {
        List<CRTParser.StatementContext> body = loop.block().statement();
        CRTParser.ExpressionContext condition = loop.expression();
        loopDepth++;
        try {
            while (condition(condition, "while")) {
                String stop = budget.loopIteration();
                if (stop != null) throw new EvaluationStopped(stop, span(loop.WHILE().getSymbol()), callChain());
                executeAll(body, place, out);
            }
        } catch (OutOfMemoryError full) {
            // A runaway loop that makes an entity per turn (the original CRT's sample) can fill a
            // small heap before the iteration budget stops it: stop it here, at the loop, just as
            // the budget would. The evaluation ends, so what the loop made can go.
            if (out != null) out.clear();
            placed.clear();
            ranOutOfMemory = true;
            throw new EvaluationStopped(budget.outOfMemory(), span(loop.WHILE().getSymbol()), callChain());
        } finally {
            loopDepth--;
        }
    }

    private void runIf(CRTParser.IfChainContext chain, Place place, List<EntityValue> out) {
        if (condition(chain.expression(), "if")) {
            executeAll(chain.block(0).statement(), place, out);
        } else if (chain.ifChain() != null) {
            runIf(chain.ifChain(), place, out);
        } else if (chain.ELSE() != null) {
            executeAll(chain.block(chain.block().size() - 1).statement(), place, out);
        }
    }

    private boolean condition(ParserRuleContext e, String keyword) { return test(evaluate(e), e, keyword); }

    private boolean test(Value v, ParserRuleContext e, String keyword) {
        if (v instanceof BooleanValue b) return b.value();
        throw error("the condition of '" + keyword + "' must be a boolean, got " + describe(v), span(e));
    }

    private void placeInScene(Value value, ParserRuleContext where) {
        if (value instanceof EntityValue e) {
            placed.add(e);
            return;
        }
        if (!(value instanceof ListValue list)) throw error("Scene expects entities, got " + describe(value), span(where));
        List<EntityValue> flat = new ArrayList<>();
        Value odd = flatten(list, flat);
        if (odd != null) throw error("Scene expects entities, got a list containing " + describe(odd), span(where));
        placed.addAll(flat);
    }

    private static void contribute(Value value, List<EntityValue> out) {
        if (value instanceof EntityValue e) {
            out.add(e);
        } else if (value instanceof ListValue list) {
            List<EntityValue> flat = new ArrayList<>();
            if (flatten(list, flat) == null) out.addAll(flat);
        }
    }

    /** Adds the entities of a nested list to {@code out}; returns the first value that is not one, or null. */
    private static Value flatten(ListValue list, List<EntityValue> out) {
        for (Value item : list.items()) {
            if (item instanceof EntityValue e) {
                out.add(e);
            } else if (item instanceof ListValue inner) {
                Value odd = flatten(inner, out);
                if (odd != null) return odd;
            } else {
                return item;
            }
        }
        return null;
    }

    // ---- compiled expressions ------------------------------------------------------------------

    /** An expression turned into a tree of closures, for expressions that run many times. */
    interface Code {
        Value run();
    }

    /** The code of an expression whose value is known when it is compiled: a literal, or a sign applied to one. */
    private record Constant(Value value) implements Code {
        @Override
        public Value run() { return value; }
    }

    /** True inside loops and macro bodies, where the same expressions run many times. */
    boolean repeats() { return loopDepth != 0 || !callStack.isEmpty(); }

    /** The compiled form of an expression that runs many times: made on first use, then kept. */
    Code code(ParserRuleContext e) {
        Code code = compiled.get(e);
        if (code == null) {
            code = compile(e);
            compiled.put(e, code);
        }
        return code;
    }

    /**
     * Evaluates an expression. At the top level it runs once, so it is visited directly; inside
     * loops and macros it is compiled once into closures, which skip the parse tree's wrapper
     * contexts and the visitor's double dispatch on every later run.
     */
    Value evaluate(ParserRuleContext e) {
        if (!repeats()) return visit(e);
        return code(e).run();
    }

    private static ParserRuleContext unwrap(ParseTree tree) {
        ParserRuleContext c = (ParserRuleContext) tree;
        List<ParseTree> children;
        while ((children = c.children) != null && children.size() == 1 && children.get(0) instanceof ParserRuleContext inner) {
            c = inner;
        }
        return c;
    }

    // Each case does exactly what the matching visit method does, through the same helpers.
    private Code compile(ParseTree tree) {
        ParserRuleContext c = unwrap(tree);
        if (c instanceof CRTParser.ParenthesizedContext) return compile(c.getChild(1));
        if (c instanceof CRTParser.IntLiteralContext || c instanceof CRTParser.FloatLiteralContext
                || c instanceof CRTParser.StringLiteralContext || c instanceof CRTParser.BooleanLiteralContext) {
            try {
                return new Constant(visit(c));
            } catch (ScriptError e) {
                return () -> visit(c);
            }
        }
        if (c instanceof CRTParser.VariableContext v) {
            String name = name(v);
            return () -> {
                Value x = lookupOrNull(name);
                return x != null ? x : visitVariable(v);
            };
        }
        if (c instanceof CRTParser.AssignmentContext a && !a.IDENT().getText().equals("t")) {
            Code value = compile(a.getChild(2));
            // The names and operators are read from their tokens once here: a token's text is a
            // new string each time it is asked for, which the map then hashes again.
            String name = a.IDENT().getText();
            return () -> assign(a, name, value.run());
        }
        if (c instanceof CRTParser.ComparisonContext k) {
            Code x = compile(k.getChild(0)), y = compile(k.getChild(2));
            return () -> compare(k, x.run(), y.run());
        }
        if (c instanceof CRTParser.AndContext || c instanceof CRTParser.OrContext) {
            ParserRuleContext left = (ParserRuleContext) c.getChild(0), right = (ParserRuleContext) c.getChild(2);
            Code x = compile(left), y = compile(right);
            if (c instanceof CRTParser.AndContext) {
                return () -> BooleanValue.of(truth(x.run(), left, "&&") && truth(y.run(), right, "&&"));
            }
            return () -> BooleanValue.of(truth(x.run(), left, "||") || truth(y.run(), right, "||"));
        }
        if (c instanceof CRTParser.ConditionalContext) {
            ParserRuleContext condition = (ParserRuleContext) c.getChild(0);
            Code test = compile(condition), x = compile(c.getChild(2)), y = compile(c.getChild(4));
            return () -> test(test.run(), condition, "?") ? x.run() : y.run();
        }
        if (c instanceof CRTParser.NotContext n) {
            Code x = compile(n.getChild(1));
            return () -> not(n, x.run());
        }
        if (c instanceof CRTParser.SignContext n) {
            Code x = compile(n.getChild(1));
            if (x instanceof Constant k) {
                // -10 in a loop is the same number on every turn (an error, if any, stays at run time).
                try {
                    return new Constant(sign(n, k.value()));
                } catch (ScriptError e) {
                    // reported when it runs
                }
            }
            return () -> sign(n, x.run());
        }
        if (c instanceof CRTParser.MultiplicativeContext m) {
            Code x = compile(m.getChild(0)), y = compile(m.getChild(2));
            String op = m.op.getText();
            return () -> Arithmetic.multiplicative(op, x.run(), y.run(), m, this);
        }
        if (c instanceof CRTParser.AdditiveContext m) {
            Code x = compile(m.getChild(0)), y = compile(m.getChild(2));
            String op = m.op.getText();
            return () -> add(m, op, x.run(), y.run());
        }
        if (c instanceof CRTParser.ModifiedContext m) {
            Code target = compile(m.getChild(0));
            int count = (m.getChildCount() - 2) / 2;
            CRTParser.ModifierContext[] modifiers = new CRTParser.ModifierContext[count];
            Code[] amounts = new Code[count];
            for (int i = 0; i < count; i++) {
                modifiers[i] = (CRTParser.ModifierContext) m.getChild(2 + 2 * i);
                amounts[i] = compile(modifiers[i].getChild(1));
            }
            return () -> {
                Value value = target.run();
                for (int i = 0; i < count; i++) value = modify(m, modifiers[i], value, amounts[i].run());
                return value;
            };
        }
        if (c instanceof CRTParser.IndexContext k) {
            Code target = compile(k.arithmetic()), index = compile(k.expression());
            return () -> index(k, target.run(), index.run());
        }
        if (c instanceof CRTParser.CallContext call && call.getChild(0) instanceof CRTParser.AtomContext atom
                && atom.getChild(0) instanceof CRTParser.VariableContext callee) {
            String name = name(callee);
            int count = argumentCount(call);
            // A built-in whose name the script never binds always means the built-in.
            if (Builtins.exists(name) && !assignedNames.contains(name) && Builtins.arity(name) == count) {
                Code[] args = new Code[count];
                for (int i = 0; i < count; i++) args[i] = compile(call.getChild(2 + 2 * i));
                Builtins.Body body = Builtins.body(name);
                return () -> {
                    Value[] values = new Value[count];
                    for (int i = 0; i < count; i++) values[i] = args[i].run();
                    return callBuiltin(body, name, values, call);
                };
            }
        }
        return () -> visit(c);
    }

    // ---- expressions ---------------------------------------------------------------------------

    /**
     * Skips the chains of one-child contexts the precedence rules leave around every operand
     * (expression, operation, arithmetic, atom): visiting them costs more than the work they wrap.
     */
    @Override
    public Value visit(ParseTree tree) { return unwrap(tree).accept(this); }

    @Override
    public Value visitAssignment(CRTParser.AssignmentContext ctx) {
        String name = ctx.IDENT().getText();
        if (name.equals("t")) {
            throw error("cannot assign to 't': it is the animation time, set from the command line", span(ctx.IDENT().getSymbol()));
        }
        return assign(ctx, ctx.IDENT().getText(), visit(ctx.getChild(2)));
    }

    private Value assign(CRTParser.AssignmentContext ctx, String name, Value value) {
        if (recorder != null && locals == null) recorder.assigned(ctx);
        scope().put(name, value);
        return value;
    }

    private Map<String, Value> scope() { return locals != null ? locals : globals; }

    @Override
    public Value visitPlainExpression(CRTParser.PlainExpressionContext ctx) { return visit(ctx.getChild(0)); }

    @Override
    public Value visitArithmeticOperation(CRTParser.ArithmeticOperationContext ctx) { return visit(ctx.getChild(0)); }

    @Override
    public Value visitAtom(CRTParser.AtomContext ctx) { return visit(ctx.getChild(0)); }

    @Override
    public Value visitParenthesized(CRTParser.ParenthesizedContext ctx) { return visit(ctx.getChild(1)); }

    @Override
    public Value visitComparison(CRTParser.ComparisonContext ctx) {
        // Children by position: the generated accessors search and allocate on every call.
        return compare(ctx, visit(ctx.getChild(0)), visit(ctx.getChild(2)));
    }

    private Value compare(CRTParser.ComparisonContext ctx, Value a, Value b) {
        int type = ctx.op.getType();
        if (type == CRTParser.EQ || type == CRTParser.NE) {
            if (!a.typeName().equals(b.typeName())) throw badOperands(ctx.op.getText(), a, b, ctx);
            return BooleanValue.of(same(a, b) == (type == CRTParser.EQ));
        }
        if (!(a instanceof NumberValue x) || !(b instanceof NumberValue y)) throw badOperands(ctx.op.getText(), a, b, ctx);
        return BooleanValue.of(switch (ctx.op.getType()) {
            case CRTParser.LT -> x.value() < y.value();
            case CRTParser.LE -> x.value() <= y.value();
            case CRTParser.GT -> x.value() > y.value();
            default -> x.value() >= y.value();
        });
    }

    /**
     * Equality of two values of the same type. Numbers compare by value wherever they sit, so
     * {@code 1 == 1.0}, {@code [1] == [1.0]} and {@code -vec3(0, 1, 0) == vec3(0, -1, 0)} (whose
     * zeros carry a sign) all hold, unlike the records' own equals.
     */
    private static boolean same(Value a, Value b) {
        if (a instanceof NumberValue x && b instanceof NumberValue y) return x.value() == y.value();
        if (a instanceof VectorValue x && b instanceof VectorValue y) {
            Vec3 v = x.vector(), w = y.vector();
            return v.x() == w.x() && v.y() == w.y() && v.z() == w.z();
        }
        if (a instanceof ColorValue x && b instanceof ColorValue y) {
            Rgb c = x.color(), d = y.color();
            return c.r() == d.r() && c.g() == d.g() && c.b() == d.b();
        }
        if (a instanceof ListValue xs && b instanceof ListValue ys) {
            if (xs.items().size() != ys.items().size()) return false;
            for (int i = 0; i < xs.items().size(); i++) {
                Value x = xs.items().get(i), y = ys.items().get(i);
                if (!x.typeName().equals(y.typeName()) || !same(x, y)) return false;
            }
            return true;
        }
        return a.equals(b);
    }

    @Override
    public Value visitAnd(CRTParser.AndContext ctx) {
        return BooleanValue.of(logical(ctx.operation(0), "&&") && logical(ctx.operation(1), "&&"));
    }

    @Override
    public Value visitOr(CRTParser.OrContext ctx) {
        return BooleanValue.of(logical(ctx.operation(0), "||") || logical(ctx.operation(1), "||"));
    }

    private boolean logical(ParserRuleContext operand, String op) { return truth(visit(operand), operand, op); }

    private boolean truth(Value v, ParserRuleContext operand, String op) {
        if (v instanceof BooleanValue b) return b.value();
        throw error("operator '" + op + "' takes booleans, got " + describe(v), span(operand));
    }

    @Override
    public Value visitConditional(CRTParser.ConditionalContext ctx) {
        return condition((ParserRuleContext) ctx.getChild(0), "?") ? visit(ctx.getChild(2)) : visit(ctx.getChild(4));
    }

    @Override
    public Value visitNot(CRTParser.NotContext ctx) {
        return not(ctx, visit(ctx.getChild(1)));
    }

    private Value not(CRTParser.NotContext ctx, Value v) {
        if (v instanceof BooleanValue b) return BooleanValue.of(!b.value());
        throw error("operator '!' cannot apply to " + describe(v), span(ctx));
    }

    @Override
    public Value visitSign(CRTParser.SignContext ctx) {
        return sign(ctx, visit(ctx.getChild(1)));
    }

    private Value sign(CRTParser.SignContext ctx, Value v) {
        boolean minus = ctx.op.getType() == CRTParser.MINUS;
        if (v instanceof NumberValue n) return minus ? new NumberValue(-n.value(), n.integral()) : n;
        if (v instanceof VectorValue vec) return minus ? new VectorValue(vec.vector().negate()) : vec;
        if (v instanceof ColorValue c) return minus ? new ColorValue(c.color().times(-1)) : c;
        throw error("operator '" + ctx.op.getText() + "' cannot apply to " + describe(v), span(ctx));
    }

    @Override
    public Value visitMultiplicative(CRTParser.MultiplicativeContext ctx) {
        return Arithmetic.multiplicative(ctx.op.getText(), visit(ctx.getChild(0)), visit(ctx.getChild(2)), ctx, this);
    }

    @Override
    public Value visitAdditive(CRTParser.AdditiveContext ctx) {
        return add(ctx, ctx.op.getText(), visit(ctx.getChild(0)), visit(ctx.getChild(2)));
    }

    private Value add(CRTParser.AdditiveContext ctx, String op, Value a, Value b) {
        if (a instanceof EntityValue x && b instanceof EntityValue y) {
            CsgOperation operation = switch (op.charAt(0)) {
                case '+' -> CsgOperation.UNION;
                case '-' -> CsgOperation.DIFFERENCE;
                default -> CsgOperation.INTERSECTION;
            };
            for (EntityValue operand : List.of(x, y)) {
                String open = openSurface(operand.entity());
                if (open != null) {
                    throw error("an open " + open + (open.equals("Mesh") ? " (not watertight)" : " (capped -> false)")
                            + " is a surface, not a solid, so it cannot be used in CSG", span(ctx));
                }
            }
            EntityValue csg = EntityValue.of(new Csg(operation, x.entity(), y.entity(), Transform.IDENTITY, span(ctx)));
            if (recorder != null) recorder.operation(ctx, csg, operation.name().charAt(0) + operation.name().substring(1).toLowerCase(java.util.Locale.ROOT));
            return csg;
        }
        return Arithmetic.additive(op, a, b, ctx, this);
    }

    @Override
    public Value visitIndex(CRTParser.IndexContext ctx) {
        return index(ctx, visit(ctx.arithmetic()), visit(ctx.expression()));
    }

    private Value index(CRTParser.IndexContext ctx, Value target, Value indexValue) {
        if (!(indexValue instanceof NumberValue n)) throw error("an index must be an integer, got " + describe(indexValue), span(ctx.expression()));
        if (!n.integral()) throw error("an index must be an integer, got the float " + NumberValue.formatFloat(n.value()), span(ctx.expression()));
        int length;
        if (target instanceof ListValue list) length = list.items().size();
        else if (target instanceof VectorValue || target instanceof ColorValue) length = 3;
        else throw error("cannot index " + describe(target) + ": only lists, vec3 and rgb have elements"
                + continuation(ctx), span(ctx));
        double i = n.value();
        if (i < 0 || i >= length) {
            throw error("index " + n + " is out of range for a " + target.typeName() + " of length " + length, span(ctx.expression()));
        }
        int k = (int) i;
        if (target instanceof ListValue list) return list.items().get(k);
        if (target instanceof VectorValue v) return NumberValue.ofFloat(v.vector().get(k));
        return NumberValue.ofFloat(((ColorValue) target).color().get(k));
    }

    @Override
    public Value visitCall(CRTParser.CallContext ctx) {
        if (ctx.getChild(0) instanceof CRTParser.AtomContext atom
                && atom.getChild(0) instanceof CRTParser.VariableContext variable) {
            String name = name(variable);
            Value bound = lookupOrNull(name);
            if (bound == null && !isAssigned(name)) {
                if (Builtins.exists(name)) return callBuiltin(name, ctx);
                Set<String> known = new LinkedHashSet<>(Builtins.names());
                known.addAll(visibleNames());
                throw error("unknown function or macro '" + name + "'" + Spelling.suggestion(name, known), span(variable));
            }
            return callMacro(name, visit(variable), ctx);
        }
        return callMacro(null, visit(ctx.getChild(0)), ctx);
    }

    // Arguments are taken by position, children 2, 4, …: the generated accessor allocates a list.
    private static int argumentCount(CRTParser.CallContext ctx) {
        int n = ctx.getChildCount();
        return n == 3 ? 0 : (n - 2) / 2;
    }

    private Value argument(CRTParser.CallContext ctx, int i) { return visit(ctx.getChild(2 + 2 * i)); }

    private Value callBuiltin(String name, CRTParser.CallContext ctx) {
        int arity = Builtins.arity(name);
        int count = argumentCount(ctx);
        if (count != arity) {
            throw error(name + " takes " + arity + (arity == 1 ? " argument" : " arguments") + ", "
                    + Builtins.signature(name) + ", got " + count, span(ctx));
        }
        Value[] args = new Value[arity];
        for (int i = 0; i < arity; i++) args[i] = argument(ctx, i);
        return callBuiltin(name, args, ctx);
    }

    private Value callBuiltin(String name, Value[] args, CRTParser.CallContext ctx) {
        return callBuiltin(Builtins.body(name), name, args, ctx);
    }

    private Value callBuiltin(Builtins.Body body, String name, Value[] args, CRTParser.CallContext ctx) {
        Value result = body.apply(new BuiltinCall(name, args, ctx));
        // One check for every function: an infinity or NaN would only surface later, in the picture.
        boolean finite = result instanceof NumberValue n ? Double.isFinite(n.value())
                : result instanceof VectorValue v ? v.vector().isFinite()
                : !(result instanceof ColorValue c) || Double.isFinite(c.color().r() + c.color().g() + c.color().b());
        if (!finite) throw error("the result of " + name + "(…) is too large", span(ctx));
        return result;
    }

    /** The call site of a built-in, handing it its arguments checked against its signature. */
    private final class BuiltinCall implements Builtins.Call {
        private final String name;
        private final Value[] args;
        private final CRTParser.CallContext ctx;

        BuiltinCall(String name, Value[] args, CRTParser.CallContext ctx) {
            this.name = name;
            this.args = args;
            this.ctx = ctx;
        }

        @Override
        public double number(int i) {
            if (args[i] instanceof NumberValue n) return n.value();
            throw wrongArguments();
        }

        @Override
        public Vec3 vector(int i) {
            if (args[i] instanceof VectorValue v) return v.vector();
            throw wrongArguments();
        }

        @Override
        public Value arg(int i) { return args[i]; }

        @Override
        public ScriptError error(String message) { return Evaluator.this.error(message, span(ctx)); }

        @Override
        public ScriptError wrongArguments() {
            StringBuilder given = new StringBuilder(name).append('(');
            for (int i = 0; i < args.length; i++) given.append(i > 0 ? ", " : "").append(args[i].typeName());
            return error("wrong arguments: " + name + " takes " + Builtins.signature(name) + ", got " + given + ")");
        }

        @Override
        public void warn(String message) { Evaluator.this.warn(message, span(ctx)); }

        @Override
        public ScriptRandom random() { return random; }
    }

    private Value callMacro(String name, Value callee, CRTParser.CallContext ctx) {
        if (!(callee instanceof MacroValue macro)) {
            throw error("cannot call " + describe(callee) + (name != null ? " '" + name + "'" : "")
                    + ": only macros and functions take arguments" + continuation(ctx), span(ctx));
        }
        String label = name != null ? "macro '" + name + "'" : "the macro";
        List<String> params = macro.parameters();
        int count = argumentCount(ctx);
        if (count != params.size()) {
            throw error(label + " takes " + params.size() + (params.size() == 1 ? " argument" : " arguments")
                    + " (" + String.join(", ", params) + "), got " + count, span(ctx));
        }
        Map<String, Value> scope = new HashMap<>();
        for (int i = 0; i < params.size(); i++) scope.put(params.get(i), argument(ctx, i));
        SourceSpan callSpan = span(ctx);
        if (callStack.size() >= MAX_MACRO_DEPTH) {
            throw error("macro calls nested deeper than " + MAX_MACRO_DEPTH + " (endless recursion?)", callSpan);
        }
        String stop = budget.tick();
        if (stop != null) throw new EvaluationStopped(stop, callSpan, callChain());
        Map<String, Value> saved = locals;
        locals = scope;
        if (recorder != null) recorder.callStarted(name != null ? name : "(anonymous)", params, ctx);
        callStack.add(new Frame(name != null ? name : "(anonymous)", callSpan));
        try {
            List<EntityValue> out = new ArrayList<>();
            executeAll(macro.body(), Place.MACRO, out);
            return out.isEmpty() ? ListValue.EMPTY : new ListValue(new ArrayList<>(out));
        } finally {
            callStack.remove(callStack.size() - 1);
            locals = saved;
            if (recorder != null) recorder.callEnded();
        }
    }

    @Override
    public Value visitModified(CRTParser.ModifiedContext ctx) {
        Value target = visit(ctx.getChild(0));
        for (int i = 2; i < ctx.getChildCount(); i += 2) {
            CRTParser.ModifierContext m = (CRTParser.ModifierContext) ctx.getChild(i);
            target = modify(ctx, m, target, visit(m.getChild(1)));
        }
        return target;
    }

    private Value modify(CRTParser.ModifiedContext ctx, CRTParser.ModifierContext m, Value target, Value amount) {
        EntityValue.ModifierKind kind = switch (m.kind.getType()) {
            case CRTParser.TRANSLATE -> EntityValue.ModifierKind.TRANSLATE;
            case CRTParser.ROTATE -> EntityValue.ModifierKind.ROTATE;
            default -> EntityValue.ModifierKind.SCALE;
        };
        return modify(target, kind, modifierAmount(kind, amount, m), ctx);
    }

    private Vec3 modifierAmount(EntityValue.ModifierKind kind, Value amount, CRTParser.ModifierContext m) {
        String word = m.kind.getText();
        if (kind == EntityValue.ModifierKind.SCALE) {
            Vec3 s;
            if (amount instanceof NumberValue n) s = new Vec3(n.value(), n.value(), n.value());
            else if (amount instanceof VectorValue v) s = v.vector();
            else throw error("scale takes a number or a vec3, got " + describe(amount), span(m));
            if (s.x() == 0 || s.y() == 0 || s.z() == 0) {
                throw error("scale with a zero component (" + (amount instanceof VectorValue ? amount.toString() : amount + "")
                        + ") would flatten the entity", span(m));
            }
            return s;
        }
        if (amount instanceof VectorValue v) return v.vector();
        throw error(word + " takes a vec3, got " + describe(amount), span(m));
    }

    private Value modify(Value target, EntityValue.ModifierKind kind, Vec3 amount, CRTParser.ModifiedContext ctx) {
        if (target instanceof EntityValue e) return e.modified(kind, amount);
        if (target instanceof ListValue list) {
            List<Value> moved = new ArrayList<>(list.items().size());
            for (Value item : list.items()) moved.add(modify(item, kind, amount, ctx));
            return new ListValue(moved);
        }
        throw error("modifiers apply to entities, got " + describe(target), span(ctx.arithmetic()));
    }

    // ---- primaries -----------------------------------------------------------------------------

    @Override
    public Value visitIntLiteral(CRTParser.IntLiteralContext ctx) {
        if (ctx.cached == null) {
            double v = Double.parseDouble(ctx.INT().getText());
            ctx.cached = NumberValue.ofInt(v);
        }
        return (Value) ctx.cached;
    }

    @Override
    public Value visitFloatLiteral(CRTParser.FloatLiteralContext ctx) {
        if (ctx.cached == null) {
            double v = Decimals.parse(ctx.FLOAT().getText());
            if (!Double.isFinite(v)) throw error("number " + ctx.FLOAT().getText() + " is too large", span(ctx));
            ctx.cached = NumberValue.ofFloat(v);
        }
        return (Value) ctx.cached;
    }

    @Override
    public Value visitStringLiteral(CRTParser.StringLiteralContext ctx) {
        if (ctx.cached == null) ctx.cached = new StringValue(unescape(ctx.STRING().getSymbol()));
        return (Value) ctx.cached;
    }

    private String unescape(Token token) {
        String text = token.getText();
        StringBuilder out = new StringBuilder(text.length());
        for (int i = 1; i < text.length() - 1; i++) {
            char c = text.charAt(i);
            if (c == '\\') {
                char next = text.charAt(++i);
                if (next != '"' && next != '\\') {
                    int at = positions.charOffset(token.getStartIndex()) + i - 1;
                    throw error("unknown escape '\\" + next + "' in a string (only \\\" and \\\\ are escapes)",
                            positions.span(at, at + 2));
                }
                out.append(next);
            } else {
                out.append(c);
            }
        }
        return out.toString();
    }

    @Override
    public Value visitBooleanLiteral(CRTParser.BooleanLiteralContext ctx) {
        return BooleanValue.of(ctx.TRUE() != null);
    }

    @Override
    public Value visitVariable(CRTParser.VariableContext ctx) {
        String name = name(ctx);
        Value v = lookupOrNull(name);
        if (v != null) return v;
        if (isAssigned(name)) throw Failed.INSTANCE;
        if (Builtins.exists(name)) {
            throw error("'" + name + "' is a function: call it as " + Builtins.signature(name), span(ctx));
        }
        String modifier = Spelling.suggestion(name, MODIFIERS);
        if (!modifier.isEmpty() && rightOfLessThan(ctx)) {
            // `s <rotat vec3(0, 90, 0)> t` parses as two comparisons; the word was meant as a modifier.
            throw error("unknown modifier '" + name + "'" + modifier, span(ctx));
        }
        throw error("variable '" + name + "' is not assigned" + Spelling.suggestion(name, visibleNames()), span(ctx));
    }

    private static final List<String> MODIFIERS = List.of("translate", "rotate", "scale");

    private static boolean rightOfLessThan(ParserRuleContext ctx) {
        ParserRuleContext c = ctx;
        while (c.getParent() != null && c.getParent().getChildCount() == 1) c = c.getParent();
        return c.getParent() instanceof CRTParser.ComparisonContext k && k.op.getType() == CRTParser.LT && k.getChild(2) == c;
    }

    private Set<String> visibleNames() {
        Set<String> names = new LinkedHashSet<>(globals.keySet());
        if (locals != null) names.addAll(locals.keySet());
        return names;
    }

    private String name(CRTParser.VariableContext ctx) {
        if (ctx.cached == null) ctx.cached = ctx.IDENT().getText();
        return (String) ctx.cached;
    }

    /** The value of a variable as an expression reads it here, or null when it is unassigned or failed. */
    Value variable(String name) { return lookupOrNull(name); }

    private Value lookupOrNull(String name) {
        if (locals != null) {
            Value v = locals.get(name);
            if (v != null || locals.containsKey(name)) return v;
        }
        return globals.get(name);
    }

    /** True when the name was assigned, even if that assignment failed. */
    boolean isAssigned(String name) {
        return (locals != null && locals.containsKey(name)) || globals.containsKey(name);
    }

    @Override
    public Value visitObject(CRTParser.ObjectContext ctx) {
        Value value = objects.build(ctx);
        if (recorder != null) recorder.object(ctx, value);
        return value;
    }

    @Override
    public Value visitMacro(CRTParser.MacroContext ctx) {
        if (ctx.cached == null) {
            List<String> params = new ArrayList<>();
            for (TerminalNode p : ctx.IDENT()) {
                String name = p.getText();
                if (params.contains(name)) throw error("parameter '" + name + "' is named twice", span(p.getSymbol()));
                if (name.equals("t")) throw error("a parameter cannot be named 't': it is the animation time", span(p.getSymbol()));
                params.add(name);
            }
            ctx.cached = new MacroValue(params, ctx.statement());
        }
        return (Value) ctx.cached;
    }

    @Override
    public Value visitList(CRTParser.ListContext ctx) {
        List<CRTParser.ExpressionContext> items = ctx.expression();
        if (items.isEmpty()) return ListValue.EMPTY;
        List<Value> values = new ArrayList<>(items.size());
        for (CRTParser.ExpressionContext e : items) values.add(visit(e));
        return new ListValue(values);
    }

    // ---- reporting -----------------------------------------------------------------------------

    SourceSpan span(ParserRuleContext ctx) {
        int start = positions.charOffset(ctx.getStart().getStartIndex());
        Token stop = ctx.getStop();
        int end = stop == null ? start : positions.charOffset(stop.getStopIndex() + 1);
        return positions.span(start, end);
    }

    SourceSpan span(Token token) {
        int start = positions.charOffset(token.getStartIndex());
        return positions.span(start, positions.charOffset(token.getStopIndex() + 1));
    }

    /** The type name of an entity that has no inside (an uncapped Cylinder or Cone), else null. */
    private static String openSurface(Entity e) {
        if (e instanceof Cylinder c && !c.capped()) return "Cylinder";
        if (e instanceof Cone c && !c.capped()) return "Cone";
        if (e instanceof Mesh m && !m.data().closed()) return "Mesh";
        return null;
    }

    ScriptError error(String message, SourceSpan where) { return new ScriptError(message, where, callChain()); }

    /**
     * When the operator of {@code ctx} (its second child: '(', '[', '+', '-' or '^') starts a line,
     * the sentence that says that line continues the expression before it; else "". Newlines end
     * nothing in CRT, and a mistake of this kind otherwise reads as nonsense.
     */
    static String continuation(ParserRuleContext ctx) {
        if (ctx.getChildCount() < 2 || !(ctx.getChild(1) instanceof org.antlr.v4.runtime.tree.TerminalNode op)
                || !(ctx.getChild(0) instanceof ParserRuleContext left) || left.getStop() == null) {
            return "";
        }
        Token t = op.getSymbol();
        if (t.getLine() <= left.getStop().getLine()) return "";
        return " (the '" + t.getText() + "' at the start of line " + t.getLine()
                + " continues the expression of the line before it: a newline does not end a statement)";
    }

    private ScriptError badOperands(String op, Value a, Value b, ParserRuleContext ctx) {
        return Arithmetic.badOperands(op, a, b, span(ctx), this);
    }

    List<String> callChain() {
        if (callStack.isEmpty()) return List.of();
        List<String> chain = new ArrayList<>();
        int shown = 0;
        for (int i = callStack.size() - 1; i >= 0; i--) {
            if (shown == 8 && i > 0) {
                chain.add("… " + i + " more calls …");
                i = 0;
            }
            Frame f = callStack.get(i);
            chain.add("in macro '" + f.macro() + "' called at " + f.call().line() + ":" + f.call().column());
            shown++;
        }
        return chain;
    }

    /** Records an error that does not unwind (an attribute among others); stops after too many. */
    void report(ScriptError e) {
        record(Severity.ERROR, e.getMessage(), e.span(), e.callChain());
        if (++errors >= MAX_ERRORS) {
            throw EvaluationStopped.tooManyErrors(MAX_ERRORS, e.span());
        }
    }

    void warn(String message, SourceSpan where) {
        if (warned.add(message + "@" + where.start())) record(Severity.WARNING, message, where, callChain());
    }

    private void record(Severity severity, String message, SourceSpan where, List<String> chain) {
        diagnostics.add(new Diagnostic(severity, message, where, chain));
    }

    static String describe(Value v) { return v.typeName(); }
}
