package dev.crt.lang.syntax;

import dev.crt.lang.TextPositions;
import dev.crt.lang.eval.Spelling;
import dev.crt.lang.parser.CRTParser;
import dev.crt.scene.SourceSpan;
import java.util.ArrayList;
import java.util.List;
import org.antlr.v4.runtime.DefaultErrorStrategy;
import org.antlr.v4.runtime.FailedPredicateException;
import org.antlr.v4.runtime.InputMismatchException;
import org.antlr.v4.runtime.NoViableAltException;
import org.antlr.v4.runtime.Parser;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.misc.IntervalSet;

/**
 * ANTLR's recovery (so that later errors are found too) with messages for people: "unexpected
 * '->'", "expected '}' to close Sphere opened at 3:5", never a dump of token sets.
 */
final class HumanErrorStrategy extends DefaultErrorStrategy {
    private static final int[] EXPRESSION_STARTS = {CRTParser.INT, CRTParser.IDENT, CRTParser.LPAREN};
    private static final List<String> MODIFIERS = List.of("translate", "rotate", "scale");
    private static final List<String> CONTROL_WORDS = List.of("if", "else", "while");

    private final TextPositions positions;

    HumanErrorStrategy(TextPositions positions) { this.positions = positions; }

    @Override
    protected void reportNoViableAlternative(Parser parser, NoViableAltException e) {
        report(parser, e.getOffendingToken(), unexpected(parser, e.getOffendingToken(), null), e);
    }

    @Override
    protected void reportInputMismatch(Parser parser, InputMismatchException e) {
        report(parser, e.getOffendingToken(), unexpected(parser, e.getOffendingToken(), e.getExpectedTokens()), e);
    }

    @Override
    protected void reportUnwantedToken(Parser parser) {
        if (inErrorRecoveryMode(parser)) return;
        beginErrorCondition(parser);
        Token token = parser.getCurrentToken();
        report(parser, token, unexpected(parser, token, null), null);
    }

    private static void report(Parser parser, Token token, String message, org.antlr.v4.runtime.RecognitionException e) {
        Token word = misspeltModifier(parser, token);
        Token cut = operatorAtLineEnd(parser, token);
        if (word != null) {
            parser.notifyErrorListeners(word, unknownModifier(word.getText()), e);
        } else if (cut != null) {
            parser.notifyErrorListeners(cut, "expected an expression after '" + cut.getText() + "' at the end of line "
                    + cut.getLine(), e);
        } else {
            parser.notifyErrorListeners(token, message, e);
        }
    }

    /**
     * An operator that ends its line when the parse fails on a later line: the expression was cut
     * there (`x = 2 *` newline `Scene {…}`, or `x = 1 +` newline `y = 2`, where `y` was taken as the
     * missing operand), and that is where the mistake is, not at the next line's token.
     */
    private static Token operatorAtLineEnd(Parser parser, Token offending) {
        Token before = previous(parser, offending);
        if (before == null) return null;
        if (offending.getType() == CRTParser.ASSIGN && before.getType() == CRTParser.IDENT) {
            Token operator = previous(parser, before);
            if (operator != null && needsOperand(operator) && operator.getLine() < before.getLine()) return operator;
            return null;
        }
        boolean later = offending.getType() == Token.EOF || before.getLine() < offending.getLine();
        return later && needsOperand(before) ? before : null;
    }

    private static boolean needsOperand(Token token) {
        return switch (token.getType()) {
            case CRTParser.PLUS, CRTParser.MINUS, CRTParser.STAR, CRTParser.SLASH, CRTParser.PERCENT, CRTParser.CARET,
                    CRTParser.LT, CRTParser.GT, CRTParser.LE, CRTParser.GE, CRTParser.EQ, CRTParser.NE, CRTParser.AND,
                    CRTParser.OR, CRTParser.QUESTION, CRTParser.COLON, CRTParser.ASSIGN, CRTParser.ARROW, CRTParser.BANG -> true;
            default -> false;
        };
    }

    private static String unknownModifier(String word) {
        String suggestion = Spelling.suggestion(word, MODIFIERS);
        return "unknown modifier '" + word + "'"
                + (suggestion.isEmpty() ? " (the modifiers are translate, rotate and scale)" : suggestion);
    }

    /**
     * `s <rotat vec3(0, 90, 0)>` parses as a comparison with a variable 'rotat' until it fails at
     * the end; the real mistake is the word after '<', when it is close to a modifier's name.
     */
    private static Token misspeltModifier(Parser parser, Token offending) {
        // The failure comes right after the '>' that was meant to close the modifier list.
        Token closer = previous(parser, offending);
        if (closer == null || closer.getType() != CRTParser.GT) return null;
        org.antlr.v4.runtime.TokenStream tokens = parser.getInputStream();
        for (int i = closer.getTokenIndex() - 1, seen = 0; i > 0 && seen < 32; i--, seen++) {
            Token t = tokens.get(i);
            if (t.getType() == CRTParser.IDENT && tokens.get(i - 1).getType() == CRTParser.LT
                    && !Spelling.suggestion(t.getText(), MODIFIERS).isEmpty()) {
                return t;
            }
        }
        return null;
    }

    @Override
    protected void reportMissingToken(Parser parser) {
        if (inErrorRecoveryMode(parser)) return;
        beginErrorCondition(parser);
        Token token = parser.getCurrentToken();
        IntervalSet expected = getExpectedTokens(parser);
        String message = null;
        if (expected.size() == 1 && (expected.contains(CRTParser.RPAREN) || expected.contains(CRTParser.RBRACKET)
                || expected.contains(CRTParser.RBRACE) || expected.contains(CRTParser.GT))) {
            message = unclosed(parser.getContext());
        }
        if (message == null && token.getType() == CRTParser.IDENT && expected.contains(CRTParser.SCALE)
                && expected.contains(CRTParser.TRANSLATE) && expected.contains(CRTParser.ROTATE)) {
            parser.notifyErrorListeners(token, unknownModifier(token.getText()), null);
            return;
        }
        if (message == null) message = expectation(parser, expected);
        if (token.getType() != Token.EOF) message += " before " + describe(token);
        parser.notifyErrorListeners(token, message, null);
    }

    @Override
    protected void reportFailedPredicate(Parser parser, FailedPredicateException e) {
        parser.notifyErrorListeners(e.getOffendingToken(), "unexpected " + describe(e.getOffendingToken()), e);
    }

    private String unexpected(Parser parser, Token token, IntervalSet expected) {
        if (token.getType() == Token.EOF) {
            String closes = unclosed(parser.getContext());
            return closes != null ? closes : "unexpected end of file";
        }
        String message = "unexpected " + describe(token);
        if (isModifierWord(token) && inside(parser.getContext(), CRTParser.ModifiedContext.class)) {
            // `<translate v scale 2>`: the word is right, the comma before it is missing.
            return message + "; expected ',' between modifiers";
        }
        if (isReservedWord(token)) return message + " (it is a reserved word and cannot name a variable)";
        if (isCloser(token)) {
            // `<translate v }`: a closer that is not the one the innermost open construct needs.
            String closes = unclosed(parser.getContext());
            if (closes != null && !closes.startsWith("expected '" + token.getText() + "'")) return message + "; " + closes;
        }
        Token before = previous(parser, token);
        if (before != null && before.getType() == CRTParser.NAME && CONTROL_WORDS.contains(before.getText().toLowerCase(java.util.Locale.ROOT))) {
            // `If (x > 1) {…}`: a keyword with a capital reads as an object type.
            return message + " after '" + before.getText() + "' (keywords are lowercase: '"
                    + before.getText().toLowerCase(java.util.Locale.ROOT) + "')";
        }
        if (token.getType() == CRTParser.ASSIGN && inside(parser.getContext(), CRTParser.AttributeContext.class)) {
            String name = before != null && before.getType() == CRTParser.IDENT ? before.getText() : "name";
            return message + "; attributes are given with '->', as in '" + name + " -> value'";
        }
        String continued = continuation(parser.getContext());
        if (continued != null) return message + continued;
        if (token.getType() == CRTParser.ASSIGN && before != null && isControlWord(before)) {
            return message + " ('" + before.getText() + "' is a reserved word and cannot name a variable)";
        }
        if (token.getType() == CRTParser.ASSIGN) {
            // `v[0] = 1`, `3 = x`, `Sphere = 1`: values never change, only names are bound.
            return message + "; only a variable can be assigned, as in 'name = value'";
        }
        if (token.getType() == CRTParser.LBRACE && before != null && before.getType() == CRTParser.IDENT) {
            // `sphere { … }`: an object type written in lowercase.
            String name = before.getText();
            return message + " after '" + name + "' (type names start with an uppercase letter: '"
                    + Character.toUpperCase(name.charAt(0)) + name.substring(1) + "')";
        }
        if (expected != null && expected.size() == 1 && !expected.contains(CRTParser.RBRACE)) {
            message += "; " + expectation(parser, expected);
        }
        return message;
    }

    /**
     * Inside an index or a call whose '[' or '(' starts a line: the sentence that says the line
     * continues the expression before it (newlines end nothing in CRT), else null.
     */
    private static String continuation(ParserRuleContext ctx) {
        for (ParserRuleContext c = ctx; c != null; c = c.getParent()) {
            if (!(c instanceof CRTParser.IndexContext || c instanceof CRTParser.CallContext)) continue;
            if (c.getChildCount() < 2 || !(c.getChild(0) instanceof ParserRuleContext left)
                    || !(c.getChild(1) instanceof org.antlr.v4.runtime.tree.TerminalNode open) || left.getStop() == null) {
                return null;
            }
            Token t = open.getSymbol();
            if (t.getLine() <= left.getStop().getLine()) return null;
            return " (the '" + t.getText() + "' at the start of line " + t.getLine()
                    + " continues the expression of the line before it: a newline does not end a statement)";
        }
        return null;
    }

    /** The token the parser saw before {@code token}, or null at the start. */
    private static Token previous(Parser parser, Token token) {
        org.antlr.v4.runtime.TokenStream tokens = parser.getInputStream();
        for (int i = token.getTokenIndex() - 1; i >= 0; i--) {
            Token t = tokens.get(i);
            if (t.getChannel() == Token.DEFAULT_CHANNEL) return t;
        }
        return null;
    }

    private static boolean isCloser(Token token) {
        int type = token.getType();
        return type == CRTParser.RBRACE || type == CRTParser.RPAREN || type == CRTParser.RBRACKET;
    }

    private static boolean isControlWord(Token token) {
        int type = token.getType();
        return type == CRTParser.WHILE || type == CRTParser.IF || type == CRTParser.ELSE;
    }

    private static boolean isModifierWord(Token token) {
        int type = token.getType();
        return type == CRTParser.SCALE || type == CRTParser.TRANSLATE || type == CRTParser.ROTATE;
    }

    private static boolean inside(ParserRuleContext ctx, Class<? extends ParserRuleContext> kind) {
        for (ParserRuleContext c = ctx; c != null; c = c.getParent()) {
            if (kind.isInstance(c)) return true;
        }
        return false;
    }

    private static boolean isReservedWord(Token token) {
        return switch (token.getType()) {
            case CRTParser.SCALE, CRTParser.TRANSLATE, CRTParser.ROTATE, CRTParser.TRUE, CRTParser.FALSE -> true;
            default -> false;
        };
    }

    /** "expected ')' to close '(' opened at 1:5" for the innermost construct still open, or null. */
    private String unclosed(ParserRuleContext ctx) {
        for (ParserRuleContext c = ctx; c != null; c = c.getParent()) {
            String closer = null;
            String what = null;
            if (c instanceof CRTParser.ParenthesizedContext) {
                closer = ")";
                what = "'('";
            } else if (c instanceof CRTParser.CallContext || c instanceof CRTParser.WhileLoopContext
                    || c instanceof CRTParser.IfChainContext) {
                // Only a '(' that was written needs closing: `if x > 1 {` never opened one.
                if (has(c, CRTParser.LPAREN) && !")".equals(c.getChild(c.getChildCount() - 1).getText())
                        && !(c.getChild(c.getChildCount() - 1) instanceof CRTParser.BlockContext)) {
                    closer = ")";
                    what = "'('";
                }
            } else if (c instanceof CRTParser.ListContext) {
                closer = "]";
                what = "'['";
            } else if (c instanceof CRTParser.ModifiedContext) {
                closer = ">";
                what = "'<'";
            } else {
                String brace = braceOf(c);
                if (brace != null) return "expected '}' to close " + brace;
            }
            if (closer != null) return "expected '" + closer + "' to close " + what + " opened at " + opening(c, what);
        }
        return null;
    }

    private String opening(ParserRuleContext c, String what) {
        String symbol = what.substring(1, 2);
        for (int i = 0; i < c.getChildCount(); i++) {
            if (c.getChild(i) instanceof org.antlr.v4.runtime.tree.TerminalNode t && t.getText().equals(symbol)) {
                return position(t.getSymbol());
            }
        }
        return position(c.getStart());
    }

    private String position(Token token) {
        SourceSpan at = positions.span(positions.charOffset(token.getStartIndex()), 0);
        return at.line() + ":" + at.column();
    }

    private String expectation(Parser parser, IntervalSet expected) {
        if (expected.contains(CRTParser.RBRACE)) {
            String closes = openedBrace(parser.getContext());
            if (closes != null) return "expected '}' to close " + closes;
        }
        if (expected.size() == 1 && expected.contains(CRTParser.RPAREN)) return "expected ')'";
        if (expected.size() == 1 && expected.contains(CRTParser.RBRACKET)) return "expected ']'";
        boolean expression = true;
        for (int type : EXPRESSION_STARTS) expression &= expected.contains(type);
        if (expression) return "expected an expression";
        List<String> names = new ArrayList<>();
        for (int type : expected.toList()) {
            if (names.size() == 4) return "expected one of " + String.join(", ", names) + ", …";
            names.add(tokenName(parser, type));
        }
        return names.size() == 1 ? "expected " + names.get(0) : "expected one of " + String.join(", ", names);
    }

    /** "Sphere opened at 3:5" for the innermost unclosed brace around the parser's position. */
    private String openedBrace(ParserRuleContext ctx) {
        for (ParserRuleContext c = ctx; c != null; c = c.getParent()) {
            String brace = braceOf(c);
            if (brace != null) return brace;
        }
        return null;
    }

    /** "Sphere opened at 3:5" when {@code c} is a construct in braces, else null. */
    private String braceOf(ParserRuleContext c) {
        String what = null;
        if (c instanceof CRTParser.ObjectContext o) what = o.NAME().getText();
        else if (c instanceof CRTParser.SettingsBlockContext) what = "Settings";
        else if (c instanceof CRTParser.SceneBlockContext) what = "Scene";
        else if (c instanceof CRTParser.MacroContext) what = "Macro";
        else if (c instanceof CRTParser.BlockContext) what = "the block";
        Token start = c.getStart();
        // `x = Sphere` at the end of the file: no brace was opened, so none needs closing.
        if (what == null || start == null || !opensBrace(c)) return null;
        return what + " opened at " + position(start);
    }

    private static boolean opensBrace(ParserRuleContext c) { return has(c, CRTParser.LBRACE); }

    private static boolean has(ParserRuleContext c, int tokenType) {
        for (int i = 0; i < c.getChildCount(); i++) {
            // An error node is a token the recovery conjured up, not one the script has.
            if (c.getChild(i) instanceof org.antlr.v4.runtime.tree.TerminalNode t
                    && !(t instanceof org.antlr.v4.runtime.tree.ErrorNode) && t.getSymbol().getType() == tokenType) {
                return true;
            }
        }
        return false;
    }

    private static String tokenName(Parser parser, int type) {
        return switch (type) {
            case Token.EOF -> "end of file";
            case CRTParser.IDENT -> "a name";
            case CRTParser.NAME -> "a type name";
            case CRTParser.INT, CRTParser.FLOAT -> "a number";
            case CRTParser.STRING -> "a string";
            default -> parser.getVocabulary().getDisplayName(type);
        };
    }

    static String describe(Token token) {
        if (token.getType() == Token.EOF) return "end of file";
        String text = token.getText();
        if (text.length() > 24) text = text.substring(0, 24) + "…";
        return "'" + text + "'";
    }
}
