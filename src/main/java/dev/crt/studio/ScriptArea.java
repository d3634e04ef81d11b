package dev.crt.studio;

import javax.swing.SwingUtilities;
import org.fife.ui.rsyntaxtextarea.RSyntaxTextArea;

/**
 * The editor's text area: an {@link RSyntaxTextArea} that skips the whole-area repaint the
 * library's fold manager asks for after every fold reparse when the folds came out as they were.
 * The reparse runs 50 ms after each keystroke and repainted every visible line of the script,
 * 10 to 40 ms of the EDT each time (docs/studio.md, "EDT stalls while typing"); the edited line is
 * repainted by the edit itself.
 */
final class ScriptArea extends RSyntaxTextArea {
    private boolean foldsUnchanged;

    ScriptArea(int rows, int columns) {
        super(rows, columns);
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
        super.repaint();
    }
}
