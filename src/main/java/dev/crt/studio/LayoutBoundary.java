package dev.crt.studio;

import java.awt.BorderLayout;
import java.awt.Component;
import javax.swing.JPanel;

/**
 * A panel whose content is laid out again inside it alone when something in it changes size (a
 * label's text, a tab title, the error strip's markers, the property sheet): Swing lays out from
 * the nearest validate root, which was the window's root pane, so every compile made DockingFrames
 * lay out all its stations and tab strips again (36 times per keystroke; docs/studio.md). The
 * docked panels and the status bar are sized by the dock and the window, never by their content's
 * preferred size, so nothing outside needs that layout.
 */
final class LayoutBoundary extends JPanel {
    LayoutBoundary(Component content) {
        super(new BorderLayout());
        add(content, BorderLayout.CENTER);
    }

    @Override
    public boolean isValidateRoot() {
        return true;
    }
}
