package dev.crt.studio;

import dev.crt.lang.parser.CRTLexer;
import dev.crt.lang.parser.CRTParser;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.antlr.v4.runtime.BaseErrorListener;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.CommonTokenStream;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.RecognitionException;
import org.antlr.v4.runtime.Recognizer;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.tree.ParseTree;

/**
 * Works out the text edits that make a script's Settings give new values: the literal of the
 * attribute that takes effect is replaced, a missing attribute is added to the last top-level
 * Settings block, and a script without one gets a block. A value the script computes (an
 * expression, or an attribute set inside an if, while or Scene block) is refused, never overwritten.
 */
final class SettingsWriter {
    /** Replace the text in [start, end) by {@code text}; offsets are Java string (and Swing document) offsets. */
    record Edit(int start, int end, String text) {}

    /** The script's settings cannot be written as asked; the message says why and what to do. */
    static final class Refused extends Exception {
        Refused(String message) {
            super(message, null, false, false);
        }
    }

    private static final String WAY_OUT = "change it in the script, or apply the settings to this session only";

    private SettingsWriter() {}

    /**
     * The edits, last first (so each applies without moving the others), that make {@code script}'s
     * Settings give each attribute of {@code literals} (attribute name → literal text, in order).
     */
    static List<Edit> edits(String script, Map<String, String> literals) throws Refused {
        CRTParser.ScriptContext tree = parse(script);
        List<CRTParser.SettingsBlockContext> blocks = new ArrayList<>();
        collect(tree, blocks);
        List<Edit> edits = new ArrayList<>();
        Map<String, String> missing = new LinkedHashMap<>();
        for (Map.Entry<String, String> wanted : literals.entrySet()) {
            String name = wanted.getKey();
            CRTParser.AttributeContext effective = null;
            for (CRTParser.SettingsBlockContext block : blocks) {
                for (CRTParser.AttributeContext a : block.attribute()) {
                    if (!a.key.getText().equals(name)) continue;
                    if (!(block.getParent() instanceof CRTParser.ScriptContext)) {
                        throw new Refused(name + " is set inside a block (an if, a while or a Scene) at " + place(a)
                                + ", so its value depends on the script: " + WAY_OUT);
                    }
                    effective = a;
                }
            }
            if (effective == null) {
                missing.put(name, wanted.getValue());
            } else if (!isNumber(effective.expression())) {
                throw new Refused(name + " is computed by the expression '" + text(script, effective.expression()) + "' at "
                        + place(effective.expression()) + ", not written as a number: " + WAY_OUT);
            } else {
                edits.add(new Edit(offset(script, effective.expression().getStart().getStartIndex()),
                        offset(script, effective.expression().getStop().getStopIndex() + 1), wanted.getValue()));
            }
        }
        if (!missing.isEmpty()) edits.add(insertion(script, tree, blocks, missing));
        edits.sort(Comparator.comparingInt(Edit::start).reversed());
        return edits;
    }

    private static CRTParser.ScriptContext parse(String script) throws Refused {
        String[] firstError = {null};
        BaseErrorListener errors = new BaseErrorListener() {
            @Override
            public void syntaxError(Recognizer<?, ?> recognizer, Object symbol, int line, int column, String msg,
                    RecognitionException e) {
                if (firstError[0] == null) firstError[0] = line + ":" + (column + 1);
            }
        };
        CRTLexer lexer = new CRTLexer(CharStreams.fromString(script));
        lexer.removeErrorListeners();
        lexer.addErrorListener(errors);
        CRTParser parser = new CRTParser(new CommonTokenStream(lexer));
        parser.removeErrorListeners();
        parser.addErrorListener(errors);
        CRTParser.ScriptContext tree = parser.script();
        if (firstError[0] != null) {
            throw new Refused("the script has a syntax error at " + firstError[0]
                    + ": fix it first, or apply the settings to this session only");
        }
        return tree;
    }

    private static void collect(ParseTree node, List<CRTParser.SettingsBlockContext> out) {
        if (node instanceof CRTParser.SettingsBlockContext block) out.add(block);
        for (int i = 0; i < node.getChildCount(); i++) collect(node.getChild(i), out);
    }

    /** A number as written: 42, 2.2, 1e-3, or one of those with a sign. */
    private static boolean isNumber(CRTParser.ExpressionContext e) {
        if (!(e instanceof CRTParser.PlainExpressionContext plain)
                || !(plain.operation() instanceof CRTParser.ArithmeticOperationContext op)) {
            return false;
        }
        CRTParser.ArithmeticContext a = op.arithmetic();
        if (a instanceof CRTParser.SignContext sign) a = sign.arithmetic();
        return a instanceof CRTParser.AtomContext atom
                && (atom.primary() instanceof CRTParser.IntLiteralContext || atom.primary() instanceof CRTParser.FloatLiteralContext);
    }

    /** The attributes not in the script, added to the last top-level Settings block or in a new block. */
    private static Edit insertion(String script, CRTParser.ScriptContext tree, List<CRTParser.SettingsBlockContext> blocks,
            Map<String, String> missing) {
        CRTParser.SettingsBlockContext last = null;
        for (CRTParser.SettingsBlockContext b : blocks) if (b.getParent() instanceof CRTParser.ScriptContext) last = b;
        if (last == null) {
            StringBuilder block = new StringBuilder("Settings {");
            missing.forEach((name, value) -> block.append(' ').append(name).append(" -> ").append(value));
            block.append(" }\n");
            // After the comments that open the script, before its first statement.
            Token first = tree.getStart();
            int at = first.getType() == Token.EOF ? script.length() : offset(script, first.getStartIndex());
            at = script.lastIndexOf('\n', at - 1) + 1;
            if (at == script.length() && !script.isEmpty() && !script.endsWith("\n")) block.insert(0, '\n');
            return new Edit(at, at, block.toString());
        }
        List<CRTParser.AttributeContext> attributes = last.attribute();
        ParserRuleContext lastAttribute = attributes.isEmpty() ? null : attributes.get(attributes.size() - 1);
        int after = lastAttribute != null ? offset(script, lastAttribute.getStop().getStopIndex() + 1)
                : offset(script, last.getToken(CRTParser.LBRACE, 0).getSymbol().getStopIndex() + 1);
        int close = offset(script, last.getStop().getStartIndex());
        StringBuilder text = new StringBuilder();
        if (script.substring(after, close).contains("\n")) {
            // A block written one attribute a line gets its new attributes the same way.
            String indent = "  ";
            if (!attributes.isEmpty()) {
                int start = offset(script, attributes.get(0).getStart().getStartIndex());
                int lineStart = script.lastIndexOf('\n', start - 1) + 1;
                String before = script.substring(lineStart, start);
                if (before.isBlank()) indent = before;
            }
            String pad = indent;
            missing.forEach((name, value) -> text.append('\n').append(pad).append(name).append(" -> ").append(value));
        } else {
            missing.forEach((name, value) -> text.append(' ').append(name).append(" -> ").append(value));
        }
        return new Edit(after, after, text.toString());
    }

    /** ANTLR counts code points; the text and Swing count UTF-16 units. */
    private static int offset(String script, int codePoints) { return script.offsetByCodePoints(0, codePoints); }

    private static String text(String script, ParserRuleContext c) {
        return script.substring(offset(script, c.getStart().getStartIndex()), offset(script, c.getStop().getStopIndex() + 1));
    }

    private static String place(ParserRuleContext c) {
        return c.getStart().getLine() + ":" + (c.getStart().getCharPositionInLine() + 1);
    }
}
