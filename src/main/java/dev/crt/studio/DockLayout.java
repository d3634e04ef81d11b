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
import javax.swing.JFrame;

/**
 * The studio's docking area: a registry of {@link StudioPanel}s, each a dockable the user can move,
 * stack, minimise or float; the default layout; saving and restoring the user's layout.
 */
final class DockLayout {
    private final CControl control;
    private final List<StudioPanel> panels = new ArrayList<>();
    private final Map<String, DefaultSingleCDockable> dockables = new LinkedHashMap<>();

    DockLayout(JFrame frame) {
        control = new CControl(frame);
        control.setTheme(ThemeMap.KEY_FLAT_THEME);
    }

    CControl control() { return control; }

    /** Adds a panel; call before {@link #resetLayout} or {@link #restore}. */
    void register(StudioPanel panel) {
        DefaultSingleCDockable d = new DefaultSingleCDockable(panel.id(), panel.title(), panel.content());
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

    void dispose() { control.destroy(); }
}
