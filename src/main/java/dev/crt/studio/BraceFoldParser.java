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
        try {
            javax.swing.text.Document doc = area.getDocument();
            doc.getText(0, doc.getLength(), text);
            Fold current = null;
            boolean inString = false;
            for (int i = 0; i < text.count; i++) {
                char c = text.array[text.offset + i];
                if (c == '\n' || c == '\r') {
                    inString = false;
                } else if (inString) {
                    if (c == '\\') {
                        if (i + 1 < text.count && text.array[text.offset + i + 1] != '\n' && text.array[text.offset + i + 1] != '\r') i++;
                    } else if (c == '"') {
                        inString = false;
                    }
                } else if (c == '"') {
                    inString = true;
                } else if (c == '-' && i + 1 < text.count && text.array[text.offset + i + 1] == '-') {
                    while (i + 1 < text.count && text.array[text.offset + i + 1] != '\n' && text.array[text.offset + i + 1] != '\r') i++;
                } else if (c == '{') {
                    if (current == null) {
                        current = new Fold(FoldType.CODE, area, i);
                        folds.add(current);
                    } else {
                        current = current.createChild(FoldType.CODE, i);
                    }
                } else if (c == '}' && current != null) {
                    current.setEndOffset(i);
                    Fold parent = current.getParent();
                    if (current.isOnSingleLine() && !current.removeFromParent()) folds.remove(folds.size() - 1);
                    current = parent;
                }
            }
        } catch (BadLocationException e) {
            // The text was read from the document itself a moment ago: every offset in it exists.
            throw new IllegalStateException(e);
        }
        return folds;
    }
}
