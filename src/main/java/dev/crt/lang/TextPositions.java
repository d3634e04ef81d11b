package dev.crt.lang;

import dev.crt.scene.SourceSpan;
import java.util.Arrays;

/**
 * Turns character offsets of a script into 1-based lines and columns (a CR LF pair, a LF or a CR
 * is one line break; every character, a tab or an emoji too, is one column), and the code-point
 * indices ANTLR reports into character offsets.
 */
public final class TextPositions {
    private final String file;
    private final String text;
    private final int[] lineStarts;
    // Character offset of each code point, only when the text has surrogate pairs (else identity).
    private final int[] charOfCodePoint;
    // The spans asked for lately: a loop asks for the same few on every turn (an object, its
    // attributes), and a million spheres then share one span instead of a search and a copy each.
    private final SourceSpan[] recent = new SourceSpan[256];
    private int lastLine;

    public TextPositions(String file, String text) {
        this.file = file;
        this.text = text;
        this.lineStarts = lineStarts(text);
        this.charOfCodePoint = codePointOffsets(text);
    }

    private static int[] lineStarts(String text) {
        int[] starts = new int[16];
        int count = 1;
        int n = text.length();
        if (text.indexOf('\r') < 0) {
            // Line feeds only (the usual case): String.indexOf searches many characters per step.
            for (int i = text.indexOf('\n'); i >= 0; i = text.indexOf('\n', i + 1)) {
                if (count == starts.length) starts = Arrays.copyOf(starts, count * 2);
                starts[count++] = i + 1;
            }
            return Arrays.copyOf(starts, count);
        }
        for (int i = 0; i < n; i++) {
            char c = text.charAt(i);
            if (c == '\n' || c == '\r') {
                if (c == '\r' && i + 1 < n && text.charAt(i + 1) == '\n') i++;
                if (count == starts.length) starts = Arrays.copyOf(starts, count * 2);
                starts[count++] = i + 1;
            }
        }
        return Arrays.copyOf(starts, count);
    }

    private static int[] codePointOffsets(String text) {
        int n = text.length();
        // As many code points as chars: no surrogate pairs (constant time for text of one byte per char).
        if (text.codePointCount(0, n) == n) return null;
        int[] offsets = new int[text.codePointCount(0, n) + 1];
        int cp = 0;
        for (int i = 0; i < n; i += Character.charCount(text.codePointAt(i))) offsets[cp++] = i;
        offsets[cp] = n;
        return offsets;
    }

    public String file() { return file; }

    public String text() { return text; }

    /** The character offset of the code point at {@code index} (ANTLR counts code points). */
    public int charOffset(int codePointIndex) {
        if (charOfCodePoint == null) return Math.min(Math.max(codePointIndex, 0), text.length());
        return charOfCodePoint[Math.min(Math.max(codePointIndex, 0), charOfCodePoint.length - 1)];
    }

    /** The span of characters [start, end), with the line and column of {@code start}. */
    public SourceSpan span(int start, int end) {
        start = Math.min(Math.max(start, 0), text.length());
        end = Math.min(Math.max(end, start), text.length());
        int slot = (start * 31 + end) & (recent.length - 1);
        SourceSpan known = recent[slot];
        if (known != null && known.start() == start && known.end() == end) return known;
        int line = lineOf(start);
        // The column counts characters as a person sees them: an emoji (two chars in Java) is one.
        int column = charOfCodePoint == null ? start - lineStarts[line] : text.codePointCount(lineStarts[line], start);
        SourceSpan span = new SourceSpan(file, line + 1, column + 1, start, end);
        recent[slot] = span;
        return span;
    }

    private int lineOf(int offset) {
        // The compiler asks in reading order, mostly on the line of the last answer or the next.
        int line = lastLine;
        if (offset >= lineStarts[line]) {
            int limit = Math.min(line + 4, lineStarts.length);
            for (; line < limit; line++) {
                if (line + 1 == lineStarts.length || offset < lineStarts[line + 1]) return lastLine = line;
            }
        }
        int i = Arrays.binarySearch(lineStarts, offset);
        return lastLine = i >= 0 ? i : -i - 2;
    }
}
