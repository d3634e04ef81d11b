package dev.crt.studio;

import bibliothek.gui.dock.common.CControl;
import bibliothek.gui.dock.common.CGrid;
import bibliothek.gui.dock.common.DefaultSingleCDockable;
import bibliothek.gui.dock.common.theme.ThemeMap;
import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.awt.KeyEventDispatcher;
import java.awt.KeyboardFocusManager;
import java.awt.Window;
import java.awt.event.KeyEvent;
import javax.swing.Action;
import javax.swing.JComponent;
import javax.swing.JFrame;
import javax.swing.JRootPane;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;

/**
 * The studio's docking area: a registry of {@link StudioPanel}s, each a dockable the user can move,
 * stack, minimise or float; the default layout; saving and restoring the user's layout.
 */
final class DockLayout {
    private final CControl control;
    private final JFrame frame;
    /**
     * A floated panel lives in a window of its own, where the key bindings of the studio's root
     * pane do not reach (and where the text components consume Ctrl+N and the like): there the
     * studio's shortcuts with Ctrl, Alt or a function key go straight to those bindings. Plain
     * keys (Esc, letters) stay with the panel.
     */
    private final KeyEventDispatcher floatingKeys = this::forwardFromFloatingWindow;
    private final List<StudioPanel> panels = new ArrayList<>();
    private final Map<String, DefaultSingleCDockable> dockables = new LinkedHashMap<>();

    DockLayout(JFrame frame) {
        this.frame = frame;
        control = new CControl(frame);
        control.setTheme(ThemeMap.KEY_FLAT_THEME);
        KeyboardFocusManager.getCurrentKeyboardFocusManager().addKeyEventDispatcher(floatingKeys);
    }

    private boolean forwardFromFloatingWindow(KeyEvent e) {
        if (e.getID() != KeyEvent.KEY_PRESSED || !(e.isControlDown() || e.isAltDown() || isFunctionKey(e.getKeyCode()))) return false;
        Window w = SwingUtilities.getWindowAncestor(e.getComponent());
        if (w == null && e.getComponent() instanceof Window self) w = self;
        if (w == null || w == frame || !ownedByFrame(w)) return false;
        JRootPane root = frame.getRootPane();
        KeyStroke key = KeyStroke.getKeyStrokeForEvent(e);
        Object name = root.getInputMap(JComponent.WHEN_IN_FOCUSED_WINDOW).get(key);
        Action action = name == null ? null : root.getActionMap().get(name);
        if (action == null || !action.isEnabled()) return false;
        SwingUtilities.notifyAction(action, key, e, root, e.getModifiersEx());
        e.consume();
        return true;
    }

    private static boolean isFunctionKey(int code) { return code >= KeyEvent.VK_F1 && code <= KeyEvent.VK_F12; }

    private boolean ownedByFrame(Window w) {
        for (Window o = w.getOwner(); o != null; o = o.getOwner()) if (o == frame) return true;
        return false;
    }

    CControl control() { return control; }

    /** Adds a panel; call before {@link #resetLayout} or {@link #restore}. */
    void register(StudioPanel panel) {
        DefaultSingleCDockable d = new DefaultSingleCDockable(panel.id(), panel.title(), new LayoutBoundary(panel.content()));
        d.setCloseable(false);
        d.setExternalizable(true);
        d.setMinimizable(true);
        d.setMaximizable(true);
        panels.add(panel);
        dockables.put(panel.id(), d);
        control.addDockable(d);
    }

    DefaultSingleCDockable dockable(String id) { return dockables.get(id); }

    /** The registered panel {@code id}, or null; a panel stacks with another by taking its place. */
    StudioPanel panel(String id) {
        for (StudioPanel p : panels) if (p.id().equals(id)) return p;
        return null;
    }

    /**
     * Tells the docking library that panel {@code id} is the focused one, with {@code component}
     * holding the focus, and asks for no focus itself. The library keeps its own idea of the
     * focused panel (the last one shown or clicked) and makes sure the keyboard focus is inside it:
     * while it thought another panel focused, it asked twenty times, every 10 ms, for the focus of
     * that panel or of the window (clearing the editor's each time), and the studio gave it back to
     * the editor: a focus trade per request, each an X server round trip and a repaint of the whole
     * editor, while the user typed (docs/studio.md, "EDT stalls while typing"). Told here, its
     * pending requests are dropped and its checks find the focus where it expects it.
     */
    void focused(String id, java.awt.Component component) {
        DefaultSingleCDockable d = dockables.get(id);
        if (d == null) return;
        var controller = control.getController();
        if (controller.getFocusedDockable() == d.intern()) return;
        // force: replace what the library thinks; no ensuring: the studio asks for the focus itself.
        controller.setFocusedDockable(d.intern(), component, true, false, false);
    }

    /** Puts every panel where its registration says. */
    void resetLayout() {
        CGrid grid = new CGrid(control);
        for (StudioPanel p : panels) grid.add(p.x(), p.y(), p.width(), p.height(), dockables.get(p.id()));
        // Panels registered at the same place share a stack; the first registered is in front.
        for (int i = panels.size() - 1; i >= 0; i--) {
            StudioPanel p = panels.get(i);
            grid.select(p.x(), p.y(), p.width(), p.height(), dockables.get(p.id()));
        }
        control.getContentArea().deploy(grid);
        dockables.values().forEach(d -> d.setVisible(true));
    }

    /** Restores the layout saved in {@code file}; false (default layout kept) when there is none or it is unreadable. */
    boolean restore(Path file) {
        if (!Files.isRegularFile(file)) return false;
        try {
            control.readXML(file.toFile());
            dockables.values().forEach(d -> {
                if (!d.isVisible()) d.setVisible(true);
            });
            return true;
        } catch (IOException | RuntimeException e) {
            resetLayout();
            return false;
        }
    }

    void save(Path file) throws IOException {
        Files.createDirectories(file.toAbsolutePath().getParent());
        Path temp = Files.createTempFile(file.toAbsolutePath().getParent(), ".layout", ".tmp");
        try {
            control.writeXML(new File(temp.toString()));
            AtomicText.write(file, Files.readAllBytes(temp));
        } finally {
            Files.deleteIfExists(temp);
        }
    }

    void dispose() {
        KeyboardFocusManager.getCurrentKeyboardFocusManager().removeKeyEventDispatcher(floatingKeys);
        control.destroy();
    }
}
