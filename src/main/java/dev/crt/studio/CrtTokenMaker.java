package dev.crt.studio;

import dev.crt.lang.parser.CRTLexer;
import javax.swing.text.Segment;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.Token;
import org.fife.ui.rsyntaxtextarea.AbstractTokenMakerFactory;
import org.fife.ui.rsyntaxtextarea.TokenMakerBase;
import org.fife.ui.rsyntaxtextarea.TokenMakerFactory;
import org.fife.ui.rsyntaxtextarea.folding.FoldParserManager;
import org.fife.ui.rsyntaxtextarea.TokenTypes;

/**
 * Colours a line of a script with the compiler's own lexer (grammar/CRT.g4), so the editor and the
 * compiler never disagree about what a token is. CRT has no multi-line tokens, so each line lexes alone.
 */
public final class CrtTokenMaker extends TokenMakerBase {
    /** The syntax style name under which the editor finds this token maker. */
    public static final String STYLE = "text/crt";

    static {
        AbstractTokenMakerFactory factory = (AbstractTokenMakerFactory) TokenMakerFactory.getDefaultInstance();
        factory.putMapping(STYLE, CrtTokenMaker.class.getName());
        FoldParserManager.get().addFoldParserMapping(STYLE, new BraceFoldParser());
    }

    private CRTLexer lexer;

    /** Makes the editor library know the CRT style; documents call it before they are created. */
    static void register() {
        // The work is in the static initialiser, which runs once, on first use.
    }

    @Override
    public org.fife.ui.rsyntaxtextarea.Token getTokenList(Segment text, int initialTokenType, int startOffset) {
        resetTokenList();
        String line = new String(text.array, text.offset, text.count);
        boolean simple = line.codePointCount(0, line.length()) == line.length();
        // One lexer per token maker, given each line in turn: making a lexer per line cost more than
        // lexing the line (opening a 2,500-line script lexes every line once, on the EDT).
        if (lexer == null) {
            lexer = new CRTLexer(CharStreams.fromString(line));
            lexer.removeErrorListeners();
        } else {
            lexer.setInputStream(CharStreams.fromString(line));
        }
        int shift = startOffset - text.offset;
        int pos = 0;
        for (Token t = lexer.nextToken(); t.getType() != Token.EOF; t = lexer.nextToken()) {
            int start = simple ? t.getStartIndex() : line.offsetByCodePoints(0, t.getStartIndex());
            int end = simple ? t.getStopIndex() + 1 : line.offsetByCodePoints(0, t.getStopIndex() + 1);
            if (start > pos) addGap(text, line, pos, start, shift);
            addToken(text.array, text.offset + start, text.offset + end - 1, typeOf(t.getType()), shift + text.offset + start);
            pos = end;
        }
        if (pos < line.length()) addGap(text, line, pos, line.length(), shift);
        addNullToken();
        return firstToken;
    }

    /** Text the lexer skips: whitespace, then possibly a comment that runs to the end of the line. */
    private void addGap(Segment text, String line, int from, int to, int shift) {
        int comment = line.indexOf("--", from);
        int wsEnd = comment >= 0 && comment < to ? comment : to;
        if (wsEnd > from) {
            addToken(text.array, text.offset + from, text.offset + wsEnd - 1, TokenTypes.WHITESPACE, shift + text.offset + from);
        }
        if (wsEnd < to) {
            addToken(text.array, text.offset + wsEnd, text.offset + to - 1, TokenTypes.COMMENT_EOL, shift + text.offset + wsEnd);
        }
    }

    static int typeOf(int lexerType) {
        return switch (lexerType) {
            case CRTLexer.SETTINGS, CRTLexer.SCENE, CRTLexer.MACRO, CRTLexer.WHILE, CRTLexer.IF, CRTLexer.ELSE -> TokenTypes.RESERVED_WORD;
            case CRTLexer.SCALE, CRTLexer.TRANSLATE, CRTLexer.ROTATE -> TokenTypes.RESERVED_WORD_2;
            case CRTLexer.TRUE, CRTLexer.FALSE -> TokenTypes.LITERAL_BOOLEAN;
            case CRTLexer.INT -> TokenTypes.LITERAL_NUMBER_DECIMAL_INT;
            case CRTLexer.FLOAT -> TokenTypes.LITERAL_NUMBER_FLOAT;
            case CRTLexer.STRING -> TokenTypes.LITERAL_STRING_DOUBLE_QUOTE;
            case CRTLexer.UNTERMINATED_STRING -> TokenTypes.ERROR_STRING_DOUBLE;
            case CRTLexer.IDENT -> TokenTypes.IDENTIFIER;
            case CRTLexer.NAME -> TokenTypes.DATA_TYPE;
            case CRTLexer.LPAREN, CRTLexer.RPAREN, CRTLexer.LBRACE, CRTLexer.RBRACE, CRTLexer.LBRACKET,
                    CRTLexer.RBRACKET, CRTLexer.COMMA -> TokenTypes.SEPARATOR;
            case CRTLexer.BAD_CHARACTER -> TokenTypes.ERROR_CHAR;
            default -> TokenTypes.OPERATOR;
        };
    }

    @Override
    public String[] getLineCommentStartAndEnd(int languageIndex) {
        return new String[] {"-- ", null};
    }

    @Override
    public boolean getMarkOccurrencesOfTokenType(int type) {
        return type == TokenTypes.IDENTIFIER;
    }

    @Override
    public boolean getCurlyBracesDenoteCodeBlocks(int languageIndex) {
        return true;
    }
}
