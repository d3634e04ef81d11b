package dev.crt.studio;

import java.awt.Component;
import javax.swing.JTabbedPane;

/**
 * The tabs of the open scripts. A changed tab title (the {@code *} of unsaved changes, put there
 * by the first keystroke after a save) repaints the strip of tabs only: Swing repainted the whole
 * tabbed pane, which is the whole visible script, on that keystroke, when the text-painting code
 * is at its slowest (docs/studio.md, "EDT stalls while typing").
 */
final class ScriptTabs extends JTabbedPane {
    private boolean titleChanging;

    @Override
    public void setTitleAt(int index, String title) {
        titleChanging = true;
        try {
            super.setTitleAt(index, title);
        } finally {
            titleChanging = false;
        }
    }

    @Override
    public void repaint(long tm, int x, int y, int width, int height) {
        Component shown = getSelectedComponent();
        // The strip is everything above the shown script (tabs sit on top, the default).
        if (titleChanging && shown != null && getTabPlacement() == TOP && shown.getY() > 0) {
            super.repaint(tm, 0, 0, getWidth(), shown.getY());
            return;
        }
        super.repaint(tm, x, y, width, height);
    }
}
