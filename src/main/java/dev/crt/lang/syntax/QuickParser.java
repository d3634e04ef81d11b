package dev.crt.lang.syntax;

import static dev.crt.lang.parser.CRTParser.*;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.Iterator;
import java.util.List;
import java.util.NoSuchElementException;
import java.util.Set;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.tree.ParseTree;

/**
 * Reads a script that has no mistakes in one pass, by hand, into the parse tree the generated
 * parser builds for it (the same contexts, children, tokens and positions), several times faster
 * than ANTLR's lexer and adaptive prediction. At the first lexical or syntax mistake it gives up,
 * and the generated parser, with its error recovery and messages for people, reads the script.
 *
 * <p>The decisions are those of the grammar as the generated parser takes them: an operator
 * continues the expression before it whenever its precedence allows (see {@link GreedyOperators}),
 * a {@code <} starts a modifier list exactly when a modifier's name follows it, and an identifier
 * followed by {@code =} starts an assignment.
 */
final class QuickParser {
    /** Thrown at the first mistake: the generated parser takes over. */
    private static final class GiveUp extends RuntimeException {
        GiveUp() { super(null, null, false, false); }
    }

    private static final GiveUp GIVE_UP = new GiveUp();
    // The text of each token type that has one. Written out (SETTINGS, 1, to RBRACKET, 37, in the
    // grammar's order) rather than read from the generated lexer's vocabulary: that class
    // deserializes its ATN when first touched (3 to 7 ms of a fresh process), which a script read
    // without mistakes never needs. QuickParserTest holds it to the vocabulary.
    private static final String[] FIXED_TEXT = new String[BAD_CHARACTER + 1];
    // Templates the labelled contexts copy from (the generated constructors take one); never changed.
    private static final StatementContext STATEMENT = new StatementContext();
    private static final ExpressionContext EXPRESSION = new ExpressionContext();
    private static final OperationContext OPERATION = new OperationContext();
    private static final ArithmeticContext ARITHMETIC = new ArithmeticContext();
    private static final PrimaryContext PRIMARY = new PrimaryContext();

    static {
        String[] texts = ("Settings Scene Macro scale translate rotate true false while if else"
                + " -> <= >= == != && || < > = + - * / % ^ ! ? : , ( ) { } [ ]").split(" ");
        System.arraycopy(texts, 0, FIXED_TEXT, SETTINGS, texts.length);
    }

    /** The text every token of {@code type} has, or null (a number, a name, a string…). */
    static String fixedText(int type) { return type >= 0 && type < FIXED_TEXT.length ? FIXED_TEXT[type] : null; }

    // The trees of the top-level statements that start within this many tokens are kept from the
    // reading. A later statement's tree (in a script of hundreds of thousands of statements) is
    // let go once the reading has checked it and built again from the tokens when it is to run,
    // so that such a script never holds all of its tree, and its tokens go as its statements run.
    private static final int KEPT_TOKENS = 1 << 20;

    /** A script read without mistakes: its top-level statements, handed out in order, and the names it assigns. */
    static final class Result implements Iterator<StatementContext> {
        private final QuickParser parser;
        private final List<StatementContext> kept;
        private final int[] starts;
        private final Set<String> assignedNames;
        private int next;

        private Result(QuickParser parser, List<StatementContext> kept, int[] starts, Set<String> assignedNames) {
            this.parser = parser;
            this.kept = kept;
            this.starts = starts;
            this.assignedNames = assignedNames;
        }

        /** Every name the script assigns or binds as a macro parameter. */
        Set<String> assignedNames() { return assignedNames; }

        @Override
        public boolean hasNext() { return next < starts.length; }

        @Override
        public StatementContext next() {
            if (!hasNext()) throw new NoSuchElementException();
            StatementContext statement = kept.get(next);
            if (statement == null) {
                parser.p = starts[next];
                statement = parser.topLevelStatement();
            } else {
                kept.set(next, null);
            }
            // The statement's tokens are leaves of its tree now; the reader needs them no more.
            int end = next + 1 < starts.length ? starts[next + 1] : parser.count - 1;
            Arrays.fill(parser.tokens, starts[next], end, null);
            next++;
            return statement;
        }
    }

    private final String text;
    // Whether top-level object literals of plain values are left as their tokens (WrittenStatement).
    private final boolean written;
    // Null once the reading is done: a statement built again when it runs was already timed.
    private ParseClock clock;
    // The tokens as the lexer finds them, one array per field: a token object (a leaf of the tree)
    // is made only when a tree is built, and a written-out object never needs one.
    private int[] types;
    private int[] starts;
    private int[] stops;
    private int[] lines;
    private int[] columns;
    // The text of names, keywords and operators, shared; null for numbers and strings (cut when asked).
    private String[] texts;
    private ScriptToken[] tokens;
    private int count;
    private int p;
    // Names by their characters, so that each distinct name is one String however often it occurs.
    private String[] names = new String[256];
    private int[] nameTypes = new int[256];

    private QuickParser(String text, ParseClock clock, boolean written) {
        this.text = text;
        this.clock = clock;
        this.written = written;
        // Sized for a token every four characters (written-out scenes have one every five or six),
        // so that a large script's arrays are not copied again and again as they grow.
        int capacity = Math.max(1024, text.length() / 4);
        types = new int[capacity];
        starts = new int[capacity];
        stops = new int[capacity];
        lines = new int[capacity];
        columns = new int[capacity];
        texts = new String[capacity];
        tokens = new ScriptToken[capacity];
    }

    /**
     * The parse of {@code text}, or null when it has a mistake (or characters beyond the Basic
     * Multilingual Plane, whose code-point positions the generated lexer counts).
     */
    static Result parse(String text, ParseClock clock) { return parse(text, clock, KEPT_TOKENS, false); }

    /**
     * The same; with {@code written}, a top-level statement (or one directly in a top-level Scene
     * block) that is an object literal of plain values, or an assignment of one, is a
     * {@link WrittenStatement}: its tokens, no tree.
     */
    static Result parse(String text, ParseClock clock, boolean written) { return parse(text, clock, KEPT_TOKENS, written); }

    /** The same, keeping from the reading the trees of the statements that start within {@code keptTokens} tokens. */
    static Result parse(String text, ParseClock clock, int keptTokens) { return parse(text, clock, keptTokens, false); }

    private static Result parse(String text, ParseClock clock, int keptTokens, boolean written) {
        QuickParser parser = new QuickParser(text, clock, written);
        try {
            boolean lexed = parser.lex();
            parser.chars = null;
            if (!lexed) return null;
            List<StatementContext> kept = new ArrayList<>();
            int[] starts = new int[16];
            int n = 0;
            while (parser.type() != EOF) {
                if (n == starts.length) starts = Arrays.copyOf(starts, n * 2);
                int start = parser.p;
                starts[n++] = start;
                StatementContext statement = parser.topLevelStatement();
                kept.add(start < keptTokens ? statement : null);
            }
            parser.clock = null;
            return new Result(parser, kept, Arrays.copyOf(starts, n), parser.assignedNames);
        } catch (GiveUp mistake) {
            return null;
        }
    }

    // ---- lexer ----------------------------------------------------------------------------------

    private boolean lex() {
        // An array, not the String: the lexer runs mostly before the JIT has compiled it, and the
        // interpreter reads an array element in one bytecode where charAt is several calls. Bytes,
        // not chars: a script of Latin-1 text (nearly every one) is held as such by its String, and
        // copied out in one step, where a char[] copy widens every character in a loop that runs
        // interpreted at first. A character beyond Latin-1 is a '?' in these bytes: the lexer then
        // asks the String. A surrogate pair is one '?', so a text with one has fewer bytes than
        // characters; such a text is refused here, as the generated lexer's code-point positions
        // would need (see parse).
        byte[] s = text.getBytes(StandardCharsets.ISO_8859_1);
        chars = s;
        int n = s.length;
        if (n != text.length()) return false;
        int i = 0;
        int line = 1;
        int lineStart = 0;
        while (true) {
            char c = 0;
            while (i < n) {
                c = (char) (s[i] & 0xFF);
                if (c == '\n') {
                    line++;
                    lineStart = ++i;
                } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || (c == '?' && text.charAt(i) == '\uFEFF')) {
                    i++;
                } else if (c == '-' && i + 1 < n && s[i + 1] == '-') {
                    for (i += 2; i < n && (c = (char) (s[i] & 0xFF)) != '\n' && c != '\r'; i++) {
                        if (c == '?' && Character.isSurrogate(text.charAt(i))) return false;
                    }
                } else {
                    break;
                }
            }
            if (i >= n) {
                add(null, EOF, n, n - 1, line, n - lineStart);
                return true;
            }
            int start = i;
            int type;
            String fixed = null;
            char next = i + 1 < n ? (char) (s[i + 1] & 0xFF) : 0;
            switch (c) {
                case '-' -> type = next == '>' ? ARROW : MINUS;
                case '<' -> type = next == '=' ? LE : LT;
                case '>' -> type = next == '=' ? GE : GT;
                case '=' -> type = next == '=' ? EQ : ASSIGN;
                case '!' -> type = next == '=' ? NE : BANG;
                case '&' -> type = next == '&' ? AND : 0;
                case '|' -> type = next == '|' ? OR : 0;
                case '+' -> type = PLUS;
                case '*' -> type = STAR;
                case '/' -> type = SLASH;
                case '%' -> type = PERCENT;
                case '^' -> type = CARET;
                case '?' -> type = text.charAt(i) == '?' ? QUESTION : 0;
                case ':' -> type = COLON;
                case ',' -> type = COMMA;
                case '(' -> type = LPAREN;
                case ')' -> type = RPAREN;
                case '{' -> type = LBRACE;
                case '}' -> type = RBRACE;
                case '[' -> type = LBRACKET;
                case ']' -> type = RBRACKET;
                default -> type = -1;
            }
            if (type == 0) return false;
            if (type > 0) {
                fixed = FIXED_TEXT[type];
                i += fixed.length();
            } else if (c == '"') {
                for (i++;; i++) {
                    if (i >= n) return false;
                    c = (char) (s[i] & 0xFF);
                    if (c == '"') break;
                    if (c == '\r' || c == '\n' || (c == '?' && Character.isSurrogate(text.charAt(i)))) return false;
                    if (c == '\\') {
                        if (i + 1 >= n) return false;
                        char escaped = (char) (s[++i] & 0xFF);
                        if (escaped == '\r' || escaped == '\n' || (escaped == '?' && Character.isSurrogate(text.charAt(i)))) return false;
                    }
                }
                i++;
                type = STRING;
            } else if (isDigit(c) || (c == '.' && isDigit(next))) {
                while (i < n && isDigit(s[i])) i++;
                type = INT;
                if (i < n && s[i] == '.') {
                    i++;
                    while (i < n && isDigit(s[i])) i++;
                    type = FLOAT;
                }
                if (i < n && (s[i] == 'e' || s[i] == 'E')) {
                    int j = i + 1;
                    if (j < n && (s[j] == '+' || s[j] == '-')) j++;
                    // An exponent without digits is a mistake the compiler reports ("1e", "2.5e-").
                    if (j >= n || !isDigit(s[j])) return false;
                    while (j < n && isDigit(s[j])) j++;
                    i = j;
                    type = FLOAT;
                }
            } else if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z')) {
                i++;
                while (i < n && isNameCharacter(s[i])) i++;
                int slot = name(start, i);
                fixed = names[slot];
                type = nameTypes[slot];
            } else {
                return false;
            }
            add(fixed, type, start, i - 1, line, start - lineStart);
            if (clock.due()) clock.check(token(count - 1));
        }
    }

    private static boolean isDigit(int c) { return c >= '0' && c <= '9'; }

    private static boolean isNameCharacter(int c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    }

    private static int keyword(String word, boolean lowercase) {
        if (!lowercase) {
            return switch (word) {
                case "Settings" -> SETTINGS;
                case "Scene" -> SCENE;
                case "Macro" -> MACRO;
                default -> NAME;
            };
        }
        return switch (word) {
            case "scale" -> SCALE;
            case "translate" -> TRANSLATE;
            case "rotate" -> ROTATE;
            case "true" -> TRUE;
            case "false" -> FALSE;
            case "while" -> WHILE;
            case "if" -> IF;
            case "else" -> ELSE;
            default -> IDENT;
        };
    }

    /**
     * The slot of the name at [start, end) in an open-addressing table of its one String and its
     * token type (a keyword's, else IDENT or NAME), worked out once per distinct name.
     */
    private int name(int start, int end) {
        int hash = 0;
        byte[] s = chars;
        for (int i = start; i < end; i++) hash = 31 * hash + s[i];
        int mask = names.length - 1;
        for (int slot = mix(hash) & mask;; slot = (slot + 1) & mask) {
            String known = names[slot];
            if (known == null) {
                String name = text.substring(start, end);
                names[slot] = name;
                nameTypes[slot] = keyword(name, s[start] >= 'a');
                if (++nameCount * 2 > names.length) return growNames(name);
                return slot;
            }
            if (known.length() == end - start && text.regionMatches(start, known, 0, end - start)) return slot;
        }
    }

    private int nameCount;
    // The script's characters while it is lexed (Latin-1, see lex).
    private byte[] chars;

    private static int mix(int hash) { return hash ^ (hash >>> 16); }

    /** Doubles the table of names; the new slot of {@code added}. */
    private int growNames(String added) {
        String[] old = names;
        int[] oldTypes = nameTypes;
        names = new String[old.length * 2];
        nameTypes = new int[old.length * 2];
        int mask = names.length - 1;
        int addedSlot = -1;
        for (int k = 0; k < old.length; k++) {
            String name = old[k];
            if (name == null) continue;
            int slot = mix(name.hashCode()) & mask;
            while (names[slot] != null) slot = (slot + 1) & mask;
            names[slot] = name;
            nameTypes[slot] = oldTypes[k];
            if (name == added) addedSlot = slot;
        }
        return addedSlot;
    }

    private void add(String fixed, int type, int start, int stop, int line, int column) {
        if (count == types.length) {
            types = Arrays.copyOf(types, count * 2);
            starts = Arrays.copyOf(starts, count * 2);
            stops = Arrays.copyOf(stops, count * 2);
            lines = Arrays.copyOf(lines, count * 2);
            columns = Arrays.copyOf(columns, count * 2);
            texts = Arrays.copyOf(texts, count * 2);
            tokens = Arrays.copyOf(tokens, count * 2);
        }
        if (type == ASSIGN && count > 0 && types[count - 1] == IDENT) {
            assignedNames.add(texts[count - 1]);
        } else if (type == LPAREN && count > 0 && types[count - 1] == MACRO) {
            inParameters = true;
        } else if (type == RPAREN) {
            inParameters = false;
        } else if (type == IDENT && inParameters) {
            assignedNames.add(fixed);
        }
        types[count] = type;
        starts[count] = start;
        stops[count] = stop;
        lines[count] = line;
        columns[count] = column;
        texts[count++] = fixed;
    }

    /** Token {@code i} as a leaf of the tree, made on first use. */
    private ScriptToken token(int i) {
        ScriptToken t = tokens[i];
        if (t == null) tokens[i] = t = new ScriptToken(text, texts[i], types[i], starts[i], stops[i], lines[i], columns[i], i);
        return t;
    }

    int typeOf(int i) { return types[i]; }

    int startOf(int i) { return starts[i]; }

    int stopOf(int i) { return stops[i]; }

    String textOf(int i) {
        String fixed = texts[i];
        return fixed != null ? fixed : types[i] == EOF ? "<EOF>" : text.substring(starts[i], stops[i] + 1);
    }

    String script() { return text; }

    // Names assigned ({@code name =}) or bound as macro parameters ({@code Macro (a, b)}), gathered
    // as the tokens are added (a pass of their own over a large script's tokens ran interpreted,
    // then made the JIT compile it while the compile waited).
    private final Set<String> assignedNames = new HashSet<>();
    // Between a Macro's '(' and the next ')'.
    private boolean inParameters;

    // ---- parser ---------------------------------------------------------------------------------
    //
    // Children are kept in immutable lists of their exact size (the tree of a written-out scene is
    // mostly one-child contexts around each number, and all of it lives until the scene is built):
    // a fixed shape is listed when its last child is read, a variable one collected and copied.

    private int type() { return types[p]; }

    private int typeAfter() { return types[p + 1]; }

    /** Starts {@code ctx} under {@code parent} at the current token. */
    private <C extends ParserRuleContext> C open(C ctx, ParserRuleContext parent) {
        ctx.parent = parent;
        ctx.start = token(p);
        return ctx;
    }

    /** Ends {@code ctx} at the last token read, with {@code children}. */
    private <C extends ParserRuleContext> C close(C ctx, List<ParseTree> children) {
        ctx.stop = token(p - 1);
        ctx.children = children;
        return ctx;
    }

    /** The current token, read as a child of {@code ctx}. */
    private ScriptToken take(ParserRuleContext ctx) {
        ScriptToken token = token(p++);
        if (clock != null) clock.tick(token);
        token.parent = ctx;
        return token;
    }

    private ScriptToken take(ParserRuleContext ctx, int expected) {
        if (type() != expected) throw GIVE_UP;
        return take(ctx);
    }

    private static boolean startsStatement(int type) {
        return type == SETTINGS || type == SCENE || type == WHILE || type == IF || startsExpression(type);
    }

    private static boolean startsExpression(int type) {
        return switch (type) {
            case MACRO, TRUE, FALSE, PLUS, MINUS, BANG, LPAREN, LBRACKET, FLOAT, INT, STRING, IDENT, NAME -> true;
            default -> false;
        };
    }

    private static boolean startsAttribute(int type) {
        return type == IDENT || type == SCALE || type == ROTATE || type == TRANSLATE;
    }

    private static boolean isModifier(int type) { return type == SCALE || type == ROTATE || type == TRANSLATE; }

    private StatementContext statement(ParserRuleContext parent) {
        switch (type()) {
            case SETTINGS -> {
                SettingsBlockContext c = open(new SettingsBlockContext(STATEMENT), parent);
                List<ParseTree> children = new ArrayList<>();
                children.add(take(c));
                children.add(take(c, LBRACE));
                while (startsAttribute(type())) children.add(attribute(c));
                children.add(take(c, RBRACE));
                return close(c, List.copyOf(children));
            }
            case SCENE -> {
                SceneBlockContext c = open(new SceneBlockContext(STATEMENT), parent);
                List<ParseTree> children = new ArrayList<>();
                children.add(take(c));
                children.add(take(c, LBRACE));
                while (startsStatement(type())) children.add(parent == null ? topLevelStatement(c) : statement(c));
                children.add(take(c, RBRACE));
                return close(c, List.copyOf(children));
            }
            case WHILE -> {
                WhileLoopContext c = open(new WhileLoopContext(STATEMENT), parent);
                ScriptToken loop = take(c), open = take(c, LPAREN);
                ExpressionContext condition = expression(c);
                ScriptToken close = take(c, RPAREN);
                return close(c, List.of(loop, open, condition, close, block(c)));
            }
            case IF -> {
                IfStatementContext c = open(new IfStatementContext(STATEMENT), parent);
                return close(c, List.of(ifChain(c)));
            }
            default -> {
                if (!startsExpression(type())) throw GIVE_UP;
                ExpressionStatementContext c = open(new ExpressionStatementContext(STATEMENT), parent);
                return close(c, List.of(expression(c)));
            }
        }
    }

    /** A statement at the top level or directly in a top-level Scene block ({@code parent}). */
    private StatementContext topLevelStatement(ParserRuleContext parent) {
        if (written) {
            StatementContext w = writtenStatement(parent);
            if (w != null) return w;
        }
        return statement(parent);
    }

    private StatementContext topLevelStatement() { return topLevelStatement(null); }

    // ---- written-out objects --------------------------------------------------------------------
    //
    // Exporters write scenes as thousands of `Type { attr -> value … }` literals whose values are
    // numbers, vec3(…)/rgb(…)-like calls of numbers, names, strings and nested literals of the same
    // kind. Such a statement is checked here by a scan of its tokens (it is then exactly what the
    // grammar accepts) and kept as its tokens: the evaluator builds it from them, and builds its
    // tree only if it must report something.

    /** The statement at the current token as a {@link WrittenStatement}, or null (nothing read). */
    private StatementContext writtenStatement(ParserRuleContext parent) {
        int at = p;
        boolean assigns = type() == IDENT && typeAfter() == ASSIGN;
        if (assigns) {
            // Assigning 't' is a mistake the general path reports.
            if (texts[p].equals("t")) return null;
            at += 2;
        }
        if (typeAt(at) != NAME) return null;
        int end = scanObject(at, 0);
        if (end < 0 || continuesExpression(typeAt(end))) return null;
        if (clock != null) for (int i = p; i < end; i++) if (clock.due()) clock.check(token(i));
        WrittenStatement statement = new WrittenStatement(this, p, end, parent, assigns);
        p = end;
        return statement;
    }

    private int typeAt(int i) { return types[i]; }

    // Literals nested deeper are left to the general reading, so that an absurdly deep one fails
    // where it always did (the scan needs less stack than the reading of its tree).
    private static final int MAX_WRITTEN_DEPTH = 32;

    /** The index after the object literal starting at {@code i} (its type name), or -1 if it is not plain. */
    private int scanObject(int i, int depth) {
        if (typeAt(i + 1) != LBRACE) return -1;
        i += 2;
        while (true) {
            int type = typeAt(i);
            if (type == RBRACE) return i + 1;
            if (!startsAttribute(type) || typeAt(i + 1) != ARROW) return -1;
            i = scanValue(i + 2, depth);
            if (i < 0) return -1;
        }
    }

    /** The index after the plain value starting at {@code i}, or -1. */
    private int scanValue(int i, int depth) {
        switch (typeAt(i)) {
            case PLUS, MINUS -> {
                int t = typeAt(i + 1);
                return t == INT || t == FLOAT ? i + 2 : -1;
            }
            case INT, FLOAT, STRING, TRUE, FALSE -> {
                return i + 1;
            }
            case IDENT -> {
                if (typeAt(i + 1) != LPAREN) return i + 1;
                i += 2;
                if (typeAt(i) == RPAREN) return i + 1;
                while (true) {
                    int t = typeAt(i);
                    if (t == PLUS || t == MINUS) t = typeAt(++i);
                    if (t != INT && t != FLOAT) return -1;
                    t = typeAt(++i);
                    if (t == RPAREN) return i + 1;
                    if (t != COMMA) return -1;
                    i++;
                }
            }
            case NAME -> {
                return depth < MAX_WRITTEN_DEPTH ? scanObject(i, depth + 1) : -1;
            }
            default -> {
                return -1;
            }
        }
    }

    /** Whether a token of this type after an operand continues the expression (an operator, a call, an index). */
    private static boolean continuesExpression(int type) {
        return switch (type) {
            case LE, GE, LT, GT, EQ, NE, AND, OR, QUESTION, STAR, SLASH, PERCENT, PLUS, MINUS, CARET, LBRACKET, LPAREN -> true;
            default -> false;
        };
    }

    /** The parse tree of the statement at token {@code from}, as the general reading builds it. */
    StatementContext tree(int from, ParserRuleContext parent) {
        p = from;
        return statement(parent);
    }

    private IfChainContext ifChain(ParserRuleContext parent) {
        IfChainContext c = open(new IfChainContext(parent, -1), parent);
        List<ParseTree> children = new ArrayList<>(7);
        children.add(take(c, IF));
        children.add(take(c, LPAREN));
        children.add(expression(c));
        children.add(take(c, RPAREN));
        children.add(block(c));
        if (type() == ELSE) {
            children.add(take(c));
            if (type() == IF) children.add(ifChain(c));
            else if (type() == LBRACE) children.add(block(c));
            else throw GIVE_UP;
        }
        return close(c, List.copyOf(children));
    }

    private BlockContext block(ParserRuleContext parent) {
        BlockContext c = open(new BlockContext(parent, -1), parent);
        List<ParseTree> children = new ArrayList<>();
        children.add(take(c, LBRACE));
        while (startsStatement(type())) children.add(statement(c));
        children.add(take(c, RBRACE));
        return close(c, List.copyOf(children));
    }

    private AttributeContext attribute(ParserRuleContext parent) {
        AttributeContext c = open(new AttributeContext(parent, -1), parent);
        ScriptToken key = take(c), arrow = take(c, ARROW);
        c.key = key;
        return close(c, List.of(key, arrow, expression(c)));
    }

    private ExpressionContext expression(ParserRuleContext parent) {
        if (type() == IDENT && typeAfter() == ASSIGN) {
            AssignmentContext c = open(new AssignmentContext(EXPRESSION), parent);
            ScriptToken name = take(c), assign = take(c);
            return close(c, List.of(name, assign, expression(c)));
        }
        PlainExpressionContext c = open(new PlainExpressionContext(EXPRESSION), parent);
        return close(c, List.of(operation(c, 0)));
    }

    /** The rule {@code operation} entered with precedence {@code min}, as the generated parser does. */
    private OperationContext operation(ParserRuleContext parent, int min) {
        OperationContext left = open(new ArithmeticOperationContext(OPERATION), parent);
        close(left, List.of(arithmetic(left, 0)));
        while (true) {
            OperationContext c;
            switch (type()) {
                case LE, GE, LT, GT, EQ, NE -> {
                    if (min > 4) return left;
                    ComparisonContext k = grow(new ComparisonContext(OPERATION), left, parent);
                    ScriptToken op = take(k);
                    k.op = op;
                    c = close(k, List.of(left, op, operation(k, 5)));
                }
                case AND -> {
                    if (min > 3) return left;
                    c = grow(new AndContext(OPERATION), left, parent);
                    ScriptToken op = take(c);
                    close(c, List.of(left, op, operation(c, 4)));
                }
                case OR -> {
                    if (min > 2) return left;
                    c = grow(new OrContext(OPERATION), left, parent);
                    ScriptToken op = take(c);
                    close(c, List.of(left, op, operation(c, 3)));
                }
                case QUESTION -> {
                    if (min > 1) return left;
                    c = grow(new ConditionalContext(OPERATION), left, parent);
                    ScriptToken question = take(c);
                    OperationContext yes = operation(c, 0);
                    ScriptToken colon = take(c, COLON);
                    close(c, List.of(left, question, yes, colon, operation(c, 1)));
                }
                default -> {
                    return left;
                }
            }
            left = c;
        }
    }

    /** Makes {@code ctx}, an operator's context, the parent of {@code left}, as the left recursion does. */
    private static <C extends ParserRuleContext> C grow(C ctx, ParserRuleContext left, ParserRuleContext parent) {
        ctx.parent = parent;
        ctx.start = left.start;
        left.parent = ctx;
        return ctx;
    }

    /** The rule {@code arithmetic} entered with precedence {@code min}. */
    private ArithmeticContext arithmetic(ParserRuleContext parent, int min) {
        ArithmeticContext left;
        switch (type()) {
            case PLUS, MINUS -> {
                SignContext s = open(new SignContext(ARITHMETIC), parent);
                ScriptToken op = take(s);
                s.op = op;
                left = close(s, List.of(op, arithmetic(s, 5)));
            }
            case BANG -> {
                left = open(new NotContext(ARITHMETIC), parent);
                ScriptToken op = take(left);
                close(left, List.of(op, arithmetic(left, 4)));
            }
            default -> {
                left = open(new AtomContext(ARITHMETIC), parent);
                close(left, List.of(primary(left)));
            }
        }
        while (true) {
            ArithmeticContext c;
            switch (type()) {
                case STAR, SLASH, PERCENT -> {
                    if (min > 3) return left;
                    MultiplicativeContext m = grow(new MultiplicativeContext(ARITHMETIC), left, parent);
                    ScriptToken op = take(m);
                    m.op = op;
                    c = close(m, List.of(left, op, arithmetic(m, 4)));
                }
                case PLUS, MINUS, CARET -> {
                    if (min > 2) return left;
                    AdditiveContext a = grow(new AdditiveContext(ARITHMETIC), left, parent);
                    ScriptToken op = take(a);
                    a.op = op;
                    c = close(a, List.of(left, op, arithmetic(a, 3)));
                }
                case LBRACKET -> {
                    c = grow(new IndexContext(ARITHMETIC), left, parent);
                    ScriptToken open = take(c);
                    ExpressionContext index = expression(c);
                    close(c, List.of(left, open, index, take(c, RBRACKET)));
                }
                case LPAREN -> {
                    c = grow(new CallContext(ARITHMETIC), left, parent);
                    List<ParseTree> children = new ArrayList<>(8);
                    children.add(left);
                    children.add(take(c));
                    if (type() != RPAREN) {
                        children.add(expression(c));
                        while (type() == COMMA) {
                            children.add(take(c));
                            children.add(expression(c));
                        }
                    }
                    children.add(take(c, RPAREN));
                    close(c, List.copyOf(children));
                }
                case LT -> {
                    if (!isModifier(typeAfter())) return left;
                    c = grow(new ModifiedContext(ARITHMETIC), left, parent);
                    List<ParseTree> children = new ArrayList<>(8);
                    children.add(left);
                    children.add(take(c));
                    children.add(modifier(c));
                    while (type() == COMMA) {
                        children.add(take(c));
                        children.add(modifier(c));
                    }
                    children.add(take(c, GT));
                    close(c, List.copyOf(children));
                }
                default -> {
                    return left;
                }
            }
            left = c;
        }
    }

    private ModifierContext modifier(ParserRuleContext parent) {
        if (!isModifier(type())) throw GIVE_UP;
        ModifierContext c = open(new ModifierContext(parent, -1), parent);
        ScriptToken kind = take(c);
        c.kind = kind;
        return close(c, List.of(kind, arithmetic(c, 0)));
    }

    private PrimaryContext primary(ParserRuleContext parent) {
        PrimaryContext c;
        switch (type()) {
            case INT -> c = open(new IntLiteralContext(PRIMARY), parent);
            case FLOAT -> c = open(new FloatLiteralContext(PRIMARY), parent);
            case STRING -> c = open(new StringLiteralContext(PRIMARY), parent);
            case TRUE, FALSE -> c = open(new BooleanLiteralContext(PRIMARY), parent);
            case IDENT -> c = open(new VariableContext(PRIMARY), parent);
            case NAME -> {
                c = open(new ObjectContext(PRIMARY), parent);
                List<ParseTree> children = new ArrayList<>();
                children.add(take(c));
                children.add(take(c, LBRACE));
                while (startsAttribute(type())) children.add(attribute(c));
                children.add(take(c, RBRACE));
                return close(c, List.copyOf(children));
            }
            case MACRO -> {
                c = open(new MacroContext(PRIMARY), parent);
                List<ParseTree> children = new ArrayList<>();
                children.add(take(c));
                children.add(take(c, LPAREN));
                if (type() == IDENT) {
                    children.add(take(c));
                    while (type() == COMMA) {
                        children.add(take(c));
                        children.add(take(c, IDENT));
                    }
                }
                children.add(take(c, RPAREN));
                children.add(take(c, LBRACE));
                while (startsStatement(type())) children.add(statement(c));
                children.add(take(c, RBRACE));
                return close(c, List.copyOf(children));
            }
            case LBRACKET -> {
                c = open(new ListContext(PRIMARY), parent);
                List<ParseTree> children = new ArrayList<>();
                children.add(take(c));
                if (type() != RBRACKET) {
                    children.add(expression(c));
                    while (type() == COMMA) {
                        children.add(take(c));
                        children.add(expression(c));
                    }
                }
                children.add(take(c, RBRACKET));
                return close(c, List.copyOf(children));
            }
            case LPAREN -> {
                c = open(new ParenthesizedContext(PRIMARY), parent);
                ScriptToken open = take(c);
                ExpressionContext inner = expression(c);
                return close(c, List.of(open, inner, take(c, RPAREN)));
            }
            default -> throw GIVE_UP;
        }
        // A literal or a variable: one token.
        return close(c, List.of(take(c)));
    }
}
