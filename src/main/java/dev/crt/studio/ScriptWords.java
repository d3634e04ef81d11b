package dev.crt.studio;

import dev.crt.lang.parser.CRTLexer;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.OptionalInt;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.Token;

/**
 * What the editor needs to know about the words of a script, read with the compiler's lexer:
 * which variables and macros it assigns and where, and which object literal the caret is inside.
 * Offsets are UTF-16 char offsets, as in the editor.
 */
final class ScriptWords {
    /** A token with char offsets [start, end). */
    record Word(int type, String text, int start, int end) {}

    /** Where the caret stands for completion: inside the object literal of {@code type} (null: none), and whether an attribute name goes here. */
    record Context(String type, boolean attributeName) {}

    private ScriptWords() {}

    static List<Word> lex(String text) {
        CRTLexer lexer = new CRTLexer(CharStreams.fromString(text));
        lexer.removeErrorListeners();
        boolean simple = text.codePointCount(0, text.length()) == text.length();
        List<Word> words = new ArrayList<>();
        for (Token t = lexer.nextToken(); t.getType() != Token.EOF; t = lexer.nextToken()) {
            if (t.getChannel() != Token.DEFAULT_CHANNEL) continue;
            int start = simple ? t.getStartIndex() : text.offsetByCodePoints(0, t.getStartIndex());
            int end = simple ? t.getStopIndex() + 1 : text.offsetByCodePoints(0, t.getStopIndex() + 1);
            words.add(new Word(t.getType(), t.getText(), start, end));
        }
        return words;
    }

    /** Names assigned anywhere in the script, each with true when its first value is a Macro literal. */
    static Map<String, Boolean> assignedNames(List<Word> words) {
        Map<String, Boolean> names = new LinkedHashMap<>();
        for (int i = 0; i + 1 < words.size(); i++) {
            Word w = words.get(i);
            if (w.type() == CRTLexer.IDENT && words.get(i + 1).type() == CRTLexer.ASSIGN) {
                boolean macro = i + 2 < words.size() && words.get(i + 2).type() == CRTLexer.MACRO;
                names.putIfAbsent(w.text(), macro);
            }
        }
        return names;
    }

    /** The completion context at {@code caret}, given the text before it. */
    static Context contextAt(String text, int caret) {
        List<Word> words = lex(text.substring(0, caret));
        // Leave out the word being typed.
        if (!words.isEmpty()) {
            Word last = words.get(words.size() - 1);
            if (last.end() == caret && (last.type() == CRTLexer.IDENT || last.type() == CRTLexer.NAME)) {
                words = words.subList(0, words.size() - 1);
            }
        }
        Deque<String> open = new ArrayDeque<>();
        for (int i = 0; i < words.size(); i++) {
            Word w = words.get(i);
            if (w.type() == CRTLexer.LBRACE) {
                Word before = i > 0 ? words.get(i - 1) : null;
                String type = before == null ? "" : before.type() == CRTLexer.NAME ? before.text()
                        : before.type() == CRTLexer.SETTINGS ? "Settings" : "";
                open.push(type);
            } else if (w.type() == CRTLexer.RBRACE && !open.isEmpty()) {
                open.pop();
            }
        }
        String type = open.isEmpty() || open.peek().isEmpty() ? null : open.peek();
        if (type == null) return new Context(null, false);
        int prev = words.isEmpty() ? -1 : words.get(words.size() - 1).type();
        boolean expression = switch (prev) {
            case CRTLexer.ARROW, CRTLexer.LPAREN, CRTLexer.COMMA, CRTLexer.LBRACKET, CRTLexer.PLUS, CRTLexer.MINUS,
                    CRTLexer.STAR, CRTLexer.SLASH, CRTLexer.PERCENT, CRTLexer.CARET, CRTLexer.BANG, CRTLexer.QUESTION,
                    CRTLexer.COLON, CRTLexer.LT, CRTLexer.GT, CRTLexer.LE, CRTLexer.GE, CRTLexer.EQ, CRTLexer.NE,
                    CRTLexer.AND, CRTLexer.OR, CRTLexer.ASSIGN, CRTLexer.TRANSLATE, CRTLexer.ROTATE, CRTLexer.SCALE -> true;
            default -> false;
        };
        return new Context(type, !expression);
    }

    /**
     * The offset of the assignment that defines the variable or macro named at {@code offset}: the
     * last assignment before it, or else the first one after it.
     */
    static OptionalInt definitionAt(String text, int offset) {
        List<Word> words = lex(text);
        Word at = null;
        for (Word w : words) {
            if (w.type() == CRTLexer.IDENT && w.start() <= offset && offset <= w.end()) {
                at = w;
                break;
            }
        }
        if (at == null) return OptionalInt.empty();
        int before = -1, after = -1;
        for (int i = 0; i + 1 < words.size(); i++) {
            Word w = words.get(i);
            if (w.type() != CRTLexer.IDENT || !w.text().equals(at.text()) || words.get(i + 1).type() != CRTLexer.ASSIGN) continue;
            if (w.start() <= at.start()) before = w.start();
            else if (after < 0) after = w.start();
        }
        int found = before >= 0 ? before : after;
        return found >= 0 ? OptionalInt.of(found) : OptionalInt.empty();
    }

    /** The identifier token around {@code offset}, if any. */
    static Word identifierAt(String text, int offset) {
        for (Word w : lex(text)) {
            if (w.type() == CRTLexer.IDENT && w.start() <= offset && offset < w.end()) return w;
        }
        return null;
    }
}
