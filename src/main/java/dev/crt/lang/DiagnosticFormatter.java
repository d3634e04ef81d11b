package dev.crt.lang;

import dev.crt.scene.SourceSpan;

/** Prints a diagnostic the way compilers do: location, severity, message, the line, a caret, the call chain. */
public final class DiagnosticFormatter {
    /** The most columns of a source line shown; a longer line is cut around the caret, with '…' at the cuts. */
    static final int MAX_SHOWN = 160;

    private DiagnosticFormatter() {}

    /**
     * {@code scene.crt:12:8: error: message}, then (when the span is in {@code sourceText}) the source
     * line and a {@code ^~~~} under the span's part on that line, then one line per call-chain entry.
     * Lines are separated by '\n'; there is no trailing line break. Control characters of the line
     * (a binary file's bytes) are shown escaped, never sent raw to the terminal, and the caret is
     * placed by display width, as terminals draw: a CJK character takes two columns.
     */
    public static String format(Diagnostic d, String sourceText) {
        SourceSpan span = d.span();
        StringBuilder out = new StringBuilder();
        out.append(span.file()).append(':').append(span.line()).append(':').append(span.column())
                .append(": ").append(d.severity().label()).append(": ").append(d.message());
        if (sourceText != null && span.line() >= 1 && span.start() >= 0 && span.start() <= sourceText.length()) {
            appendSourceLine(out, sourceText, span);
        }
        for (String call : d.callChain()) out.append('\n').append("  ").append(call);
        return out.toString();
    }

    private static void appendSourceLine(StringBuilder out, String text, SourceSpan span) {
        int start = span.start();
        int lineStart = start;
        while (lineStart > 0 && !isBreak(text.charAt(lineStart - 1))) lineStart--;
        int lineEnd = start;
        while (lineEnd < text.length() && !isBreak(text.charAt(lineEnd))) lineEnd++;
        int end = Math.min(Math.max(span.end(), start), lineEnd);
        // A very long line (a generated script) is shown around the caret only.
        int from = lineStart, to = lineEnd;
        if (width(text, lineStart, lineEnd) > MAX_SHOWN) {
            from = start;
            while (from > lineStart && width(text, from, start) < MAX_SHOWN / 3) from = previous(text, from);
            to = start;
            while (to < lineEnd && width(text, from, to) < MAX_SHOWN) to = next(text, to);
        }
        StringBuilder shown = new StringBuilder();
        StringBuilder caret = new StringBuilder();
        if (from > lineStart) {
            shown.append('…');
            caret.append(' ');
        }
        for (int i = from; i < to; i = next(text, i)) {
            int cp = text.codePointAt(i);
            String glyph = glyph(cp);
            shown.append(glyph);
            if (i < start) {
                // Tabs are copied so that the caret lines up however wide the terminal draws them.
                caret.append(cp == '\t' ? "\t" : " ".repeat(width(cp, glyph)));
            } else if (i == start) {
                caret.append('^').append("~".repeat(Math.max(0, width(cp, glyph) - 1)));
            } else if (i < end) {
                caret.append("~".repeat(width(cp, glyph)));
            }
        }
        if (to < lineEnd) shown.append('…');
        if (start >= to) caret.append('^');
        out.append('\n').append(shown).append('\n').append(caret);
    }

    /** How the character is shown: itself, or an escape for a control character or an undecodable byte. */
    private static String glyph(int cp) {
        if (cp == '\t') return "\t";
        if (cp < 0x20 || cp == 0x7F || (cp >= 0x80 && cp < 0xA0) || cp == 0xFFFD
                || Character.getType(cp) == Character.SURROGATE) {
            return String.format("\\u%04X", cp);
        }
        return new String(Character.toChars(cp));
    }

    /** Columns a terminal gives the shown glyph: 2 for East Asian wide characters, 0 for combining marks. */
    private static int width(int cp, String glyph) {
        if (glyph.length() > 2) return glyph.length();
        int type = Character.getType(cp);
        if (type == Character.NON_SPACING_MARK || type == Character.ENCLOSING_MARK || type == Character.FORMAT) return 0;
        return isWide(cp) ? 2 : 1;
    }

    private static int width(String text, int from, int to) {
        int w = 0;
        for (int i = from; i < to; i = next(text, i)) {
            int cp = text.codePointAt(i);
            w += cp == '\t' ? 1 : width(cp, glyph(cp));
        }
        return w;
    }

    // The East Asian Wide and Fullwidth blocks (Unicode TR 11) that terminals draw two columns wide.
    private static boolean isWide(int cp) {
        return (cp >= 0x1100 && cp <= 0x115F) || (cp >= 0x2E80 && cp <= 0x303E) || (cp >= 0x3041 && cp <= 0x33FF)
                || (cp >= 0x3400 && cp <= 0x4DBF) || (cp >= 0x4E00 && cp <= 0x9FFF) || (cp >= 0xA000 && cp <= 0xA4CF)
                || (cp >= 0xAC00 && cp <= 0xD7A3) || (cp >= 0xF900 && cp <= 0xFAFF) || (cp >= 0xFE30 && cp <= 0xFE4F)
                || (cp >= 0xFF00 && cp <= 0xFF60) || (cp >= 0xFFE0 && cp <= 0xFFE6) || (cp >= 0x1F300 && cp <= 0x1F64F)
                || (cp >= 0x1F900 && cp <= 0x1F9FF) || (cp >= 0x20000 && cp <= 0x3FFFD);
    }

    private static int next(String text, int i) { return i + Character.charCount(text.codePointAt(i)); }

    private static int previous(String text, int i) { return text.offsetByCodePoints(i, -1); }

    private static boolean isBreak(char c) { return c == '\n' || c == '\r'; }
}
