package dev.crt.studio;

import java.util.ArrayList;
import java.util.List;
import javax.swing.text.BadLocationException;
import javax.swing.text.Segment;
import org.fife.ui.rsyntaxtextarea.RSyntaxTextArea;
import org.fife.ui.rsyntaxtextarea.folding.Fold;
import org.fife.ui.rsyntaxtextarea.folding.FoldParser;
import org.fife.ui.rsyntaxtextarea.folding.FoldType;

/**
 * Folds of the {@code { }} blocks that span lines, found by reading the characters once: braces inside
 * strings and {@code --} comments do not count, as in the lexer (grammar/CRT.g4: a string ends at its
 * closing quote or the end of the line, a backslash escapes the next character). The editor asks for
 * the folds after every edit, on the Event Dispatch Thread; the library's own parser lexed every line
 * of the script for it (20 to 40 ms on 2,500 lines once warm), this reads them in well under 1 ms.
 */
final class BraceFoldParser implements FoldParser {
    @Override
    public List<Fold> getFolds(RSyntaxTextArea area) {
        List<Fold> folds = new ArrayList<>();
        Segment text = new Segment();
        // Open braces: offset, line, and their fold once one is made. A fold is made only for a
        // block that closes on a later line (and then for every block around it, which spans those
        // lines too): each fold holds two positions in the document, and making and dropping one
        // per brace pair that opens and closes on one line cost 50 ms on 2,500 such lines.
        int[] offsets = new int[16], lines = new int[16];
        Fold[] made = new Fold[16];
        int depth = 0;
        try {
            javax.swing.text.Document doc = area.getDocument();
            doc.getText(0, doc.getLength(), text);
            char[] a = text.array;
            int base = text.offset, n = text.count, line = 0;
            boolean inString = false;
            for (int i = 0; i < n; i++) {
                char c = a[base + i];
                if (c == '\n' || c == '\r') {
                    inString = false;
                    if (c == '\n' || i + 1 >= n || a[base + i + 1] != '\n') line++;
                } else if (inString) {
                    if (c == '\\') {
                        if (i + 1 < n && a[base + i + 1] != '\n' && a[base + i + 1] != '\r') i++;
                    } else if (c == '"') {
                        inString = false;
                    }
                } else if (c == '"') {
                    inString = true;
                } else if (c == '-' && i + 1 < n && a[base + i + 1] == '-') {
                    while (i + 1 < n && a[base + i + 1] != '\n' && a[base + i + 1] != '\r') i++;
                } else if (c == '{') {
                    if (depth == offsets.length) {
                        offsets = java.util.Arrays.copyOf(offsets, 2 * depth);
                        lines = java.util.Arrays.copyOf(lines, 2 * depth);
                        made = java.util.Arrays.copyOf(made, 2 * depth);
                    }
                    offsets[depth] = i;
                    lines[depth] = line;
                    made[depth] = null;
                    depth++;
                } else if (c == '}' && depth > 0) {
                    depth--;
                    if (lines[depth] != line) {
                        make(area, folds, offsets, made, depth);
                        made[depth].setEndOffset(i);
                    }
                    made[depth] = null;
                }
            }
            // Blocks never closed keep their folds, open to the end.
            if (depth > 0) make(area, folds, offsets, made, depth - 1);
        } catch (BadLocationException e) {
            // The text was read from the document itself a moment ago: every offset in it exists.
            throw new IllegalStateException(e);
        }
        if (area instanceof ScriptArea script && same(folds, area.getFoldManager())) script.foldsUnchanged();
        return folds;
    }

    /** Whether {@code folds} span what the fold manager's folds span, nesting included. */
    private static boolean same(List<Fold> folds, org.fife.ui.rsyntaxtextarea.folding.FoldManager held) {
        if (held.getFoldCount() != folds.size()) return false;
        for (int i = 0; i < folds.size(); i++) if (!same(folds.get(i), held.getFold(i))) return false;
        return true;
    }

    private static boolean same(Fold a, Fold b) {
        if (a.getStartOffset() != b.getStartOffset() || a.getEndOffset() != b.getEndOffset() || a.getChildCount() != b.getChildCount()) return false;
        for (int i = 0; i < a.getChildCount(); i++) if (!same(a.getChild(i), b.getChild(i))) return false;
        return true;
    }

    /** Makes the folds of the open blocks 0..{@code top} that have none yet, outermost first. */
    private static void make(RSyntaxTextArea area, List<Fold> folds, int[] offsets, Fold[] made, int top)
            throws BadLocationException {
        for (int d = 0; d <= top; d++) {
            if (made[d] != null) continue;
            if (d == 0) {
                made[d] = new Fold(FoldType.CODE, area, offsets[d]);
                folds.add(made[d]);
            } else {
                made[d] = made[d - 1].createChild(FoldType.CODE, offsets[d]);
            }
        }
    }
}
