package dev.crt.studio;

import java.awt.Shape;
import javax.swing.SwingUtilities;
import javax.swing.event.DocumentEvent;
import javax.swing.text.BadLocationException;
import javax.swing.text.Element;
import javax.swing.text.View;
import javax.swing.text.ViewFactory;
import org.fife.ui.rsyntaxtextarea.RSyntaxTextArea;
import org.fife.ui.rsyntaxtextarea.RSyntaxTextAreaUI;
import org.fife.ui.rsyntaxtextarea.SyntaxView;
import org.fife.ui.rtextarea.RTextAreaUI;

/**
 * The editor's text area: an {@link RSyntaxTextArea} that skips two whole-area repaints a keystroke
 * does not need (docs/studio.md, "EDT stalls while typing"; each repaints every visible line, 10
 * to 40 ms of the EDT). One is the library's fold manager's, after every fold reparse, when the
 * folds came out as they were: the reparse runs 50 ms after each keystroke, and the edited line is
 * repainted by the edit itself. The other is the text view's, for text typed at the start of a
 * line: Swing's document records such an insert as lines replaced (it looks at the line break
 * before the insert), so the view repainted every visible line as if lines had been added, when
 * only the line typed into changed; that line is repainted instead.
 */
final class ScriptArea extends RSyntaxTextArea {
    private boolean foldsUnchanged;
    /**
     * One more than the line typed into, while the text view asks for its repaint after an insert
     * at the line's start; else 0 (the default: the constructors above this class's repaint).
     */
    private int lineStartInsert;

    ScriptArea(int rows, int columns) {
        super(rows, columns);
    }

    @Override
    protected RTextAreaUI createRTextAreaUI() {
        return new RSyntaxTextAreaUI(this) {
            @Override
            public View create(Element elem) {
                View v = super.create(elem);
                return v.getClass() == SyntaxView.class ? new LineStartView(elem) : v;
            }
        };
    }

    /** The library's unwrapped text view, told which line an insert at a line's start changed. */
    private final class LineStartView extends SyntaxView {
        LineStartView(Element elem) {
            super(elem);
        }

        @Override
        protected void updateDamage(DocumentEvent changes, Shape a, ViewFactory f) {
            int line = changes.getType() == DocumentEvent.EventType.INSERT ? lineTypedInto(changes) : -1;
            lineStartInsert = line + 1;
            try {
                super.updateDamage(changes, a, f);
            } finally {
                lineStartInsert = 0;
            }
        }

        /** The line an insert changed when it moved no line (the same number of lines, no line break typed); else -1. */
        private int lineTypedInto(DocumentEvent changes) {
            Element root = getElement();
            DocumentEvent.ElementChange change = changes.getChange(root);
            if (change == null || change.getChildrenAdded().length != change.getChildrenRemoved().length) return -1;
            try {
                if (changes.getDocument().getText(changes.getOffset(), changes.getLength()).indexOf('\n') >= 0) return -1;
            } catch (BadLocationException e) {
                return -1;
            }
            return root.getElementIndex(changes.getOffset());
        }
    }

    /**
     * The fold parser found the same folds as the fold manager holds: its next whole-area repaint,
     * which the manager asks for right after taking them, is not needed. The mark lasts until the
     * events queued now have run, so it never swallows a later repaint.
     */
    void foldsUnchanged() {
        if (foldsUnchanged) return;
        foldsUnchanged = true;
        SwingUtilities.invokeLater(() -> foldsUnchanged = false);
    }

    @Override
    public void repaint() {
        if (foldsUnchanged) {
            foldsUnchanged = false;
            return;
        }
        if (lineStartInsert > 0) {
            try {
                int y = yForLine(lineStartInsert - 1);
                if (y >= 0) {
                    repaint(0, y, getWidth(), getLineHeight());
                    return;
                }
            } catch (BadLocationException e) {
                // Not a line any more: repaint everything, as the view asked.
            }
        }
        super.repaint();
    }
}
