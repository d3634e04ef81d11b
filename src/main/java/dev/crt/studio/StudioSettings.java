package dev.crt.studio;

import java.awt.Rectangle;
import java.io.IOException;
import java.io.StringReader;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;

/** What the studio remembers between runs: theme, window bounds, recent files, render on save. */
final class StudioSettings {
    static final int MAX_RECENT = 10;

    boolean dark;
    Rectangle bounds;
    boolean maximized;
    boolean renderOnSave;
    final List<Path> recent = new ArrayList<>();

    static StudioSettings load(Path file) {
        StudioSettings s = new StudioSettings();
        if (!Files.isRegularFile(file)) return s;
        Properties p = new Properties();
        try {
            p.load(new StringReader(Files.readString(file, StandardCharsets.UTF_8)));
        } catch (IOException | IllegalArgumentException e) {
            // Unreadable settings are replaced by the defaults and rewritten on exit.
            return s;
        }
        s.dark = "dark".equals(p.getProperty("theme"));
        s.maximized = Boolean.parseBoolean(p.getProperty("window.maximized"));
        s.renderOnSave = Boolean.parseBoolean(p.getProperty("render.onSave"));
        String b = p.getProperty("window.bounds");
        if (b != null) {
            String[] parts = b.split(",");
            try {
                if (parts.length == 4) {
                    s.bounds = new Rectangle(Integer.parseInt(parts[0].trim()), Integer.parseInt(parts[1].trim()),
                            Integer.parseInt(parts[2].trim()), Integer.parseInt(parts[3].trim()));
                }
            } catch (NumberFormatException e) {
                s.bounds = null;
            }
        }
        for (int i = 0; i < MAX_RECENT; i++) {
            String r = p.getProperty("recent." + i);
            if (r != null) s.recent.add(Path.of(r));
        }
        return s;
    }

    void save(Path file) throws IOException {
        Properties p = new Properties();
        p.setProperty("theme", dark ? "dark" : "light");
        p.setProperty("window.maximized", Boolean.toString(maximized));
        p.setProperty("render.onSave", Boolean.toString(renderOnSave));
        if (bounds != null) p.setProperty("window.bounds", bounds.x + "," + bounds.y + "," + bounds.width + "," + bounds.height);
        for (int i = 0; i < recent.size(); i++) p.setProperty("recent." + i, recent.get(i).toString());
        StringWriter w = new StringWriter();
        p.store(w, "crt studio");
        AtomicText.write(file, w.toString());
    }

    void addRecent(Path file) {
        Path f = file.toAbsolutePath().normalize();
        recent.remove(f);
        recent.add(0, f);
        while (recent.size() > MAX_RECENT) recent.remove(recent.size() - 1);
    }
}
