package dev.crt.studio;

import dev.crt.geom.Vec3;
import dev.crt.scene.Rgb;
import java.awt.Color;
import java.awt.Component;
import java.awt.FlowLayout;
import java.awt.FontMetrics;
import java.awt.Graphics;
import java.awt.Rectangle;
import java.beans.PropertyEditorSupport;
import java.util.List;
import javax.swing.BoxLayout;
import javax.swing.JColorChooser;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JSpinner;
import javax.swing.SpinnerNumberModel;

/**
 * The property sheet's editors for CRT's values: a vec3 as text ("1, 0, -2") or three spinners, a
 * colour as text, a swatch, or a colour chooser with its 0–1 rgb values, a word from a fixed list.
 */
final class ValueEditors {
    private ValueEditors() {}

    /** The types of the sheet's rows that take the JDK's own editors (numbers, booleans, text). */
    private static final List<Class<?>> PLAIN_TYPES = List.of(Double.class, Integer.class, Boolean.class, String.class);

    /**
     * A new editor of {@code type} as {@link java.beans.PropertyEditorManager#findEditor} gives, or
     * null. For a type nobody registered, the manager looks for the editor's class by name on every
     * call (java.lang.DoubleEditor, then its search path), misses no cache can keep: 60 to 70 ms of
     * the EDT at the property sheet's first paint, in the middle of typing. The class it finds is
     * registered for the type, so that later calls make the editor from the manager's registry
     * (0.002 to 0.04 ms instead of 0.02 to 0.12 ms warm, and no search when cold). Making the editor
     * here from its class, as before, failed on every call: the JDK's editors live in a package
     * java.desktop does not export (IllegalAccessException), and the search by name followed.
     */
    static java.beans.PropertyEditor plain(Class<?> type) {
        java.beans.PropertyEditor found = java.beans.PropertyEditorManager.findEditor(type);
        // The registry is per thread group: registering on every call costs a map update and
        // covers the EDT and the background thread below alike.
        if (found != null) java.beans.PropertyEditorManager.registerEditor(type, found.getClass());
        return found;
    }

    /** Finds the plain editors on a low-priority thread of its own, so that the EDT never has to. */
    static void findPlainEditorsInBackground() {
        Thread t = new Thread(() -> PLAIN_TYPES.forEach(ValueEditors::plain), "property-editors");
        t.setDaemon(true);
        t.setPriority(Thread.MIN_PRIORITY);
        t.start();
    }

    /** Three numbers from "x, y, z", "vec3(x, y, z)" or "rgb(r, g, b)". */
    static double[] triple(String text) {
        String t = text.trim();
        int open = t.indexOf('(');
        if (open >= 0 && t.endsWith(")")) t = t.substring(open + 1, t.length() - 1);
        String[] parts = t.split("[,;\\s]+");
        if (parts.length != 3) throw new IllegalArgumentException("write three numbers, as in 1, 0.5, -2");
        double[] v = new double[3];
        for (int i = 0; i < 3; i++) {
            try {
                v[i] = Double.parseDouble(parts[i]);
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("'" + parts[i] + "' is not a number");
            }
            if (!Double.isFinite(v[i])) throw new IllegalArgumentException("'" + parts[i] + "' is not a finite number");
        }
        return v;
    }

    /** vec3: text or three spinners. */
    static final class VectorEditor extends PropertyEditorSupport {
        @Override
        public String getAsText() {
            return getValue() instanceof Vec3 v ? ScriptEdits.number(v.x()) + ", " + ScriptEdits.number(v.y()) + ", " + ScriptEdits.number(v.z()) : "";
        }

        @Override
        public void setAsText(String text) {
            double[] v = triple(text);
            setValue(new Vec3(v[0], v[1], v[2]));
        }

        @Override public boolean supportsCustomEditor() { return true; }

        @Override
        public Component getCustomEditor() {
            Vec3 v = getValue() instanceof Vec3 x ? x : Vec3.ZERO;
            JPanel panel = new JPanel(new FlowLayout(FlowLayout.LEFT));
            JSpinner[] s = new JSpinner[3];
            double[] start = {v.x(), v.y(), v.z()};
            String[] names = {"x", "y", "z"};
            for (int i = 0; i < 3; i++) {
                s[i] = new JSpinner(new SpinnerNumberModel(start[i], -1e9, 1e9, 0.1));
                s[i].setName("vector" + names[i]);
                s[i].getAccessibleContext().setAccessibleName(names[i]);
                panel.add(new JLabel(names[i]));
                panel.add(s[i]);
            }
            for (JSpinner spinner : s) {
                spinner.addChangeListener(e -> setValue(new Vec3(num(s[0]), num(s[1]), num(s[2]))));
            }
            return panel;
        }
    }

    /** rgb: text, a swatch in the sheet, and a colour chooser with the three 0–1 values. */
    static final class ColorEditor extends PropertyEditorSupport {
        @Override
        public String getAsText() {
            return getValue() instanceof Rgb c ? ScriptEdits.number(c.r()) + ", " + ScriptEdits.number(c.g()) + ", " + ScriptEdits.number(c.b()) : "";
        }

        @Override
        public void setAsText(String text) {
            double[] v = triple(text);
            setValue(new Rgb(v[0], v[1], v[2]));
        }

        @Override public boolean isPaintable() { return true; }

        @Override
        public void paintValue(Graphics g, Rectangle box) {
            Color swatch = getValue() instanceof Rgb c ? awt(c) : Color.GRAY;
            int size = box.height - 4;
            g.setColor(swatch);
            g.fillRect(box.x + 2, box.y + 2, size, size);
            g.setColor(Color.GRAY);
            g.drawRect(box.x + 2, box.y + 2, size, size);
            g.setColor(javax.swing.UIManager.getColor("Table.foreground"));
            FontMetrics fm = g.getFontMetrics();
            g.drawString(getAsText(), box.x + size + 8, box.y + (box.height + fm.getAscent() - fm.getDescent()) / 2);
        }

        @Override public boolean supportsCustomEditor() { return true; }

        @Override
        public Component getCustomEditor() {
            Rgb c = getValue() instanceof Rgb x ? x : new Rgb(0.5, 0.5, 0.5);
            JPanel panel = new JPanel();
            panel.setLayout(new BoxLayout(panel, BoxLayout.Y_AXIS));
            JColorChooser chooser = new JColorChooser(awt(c));
            chooser.setName("colorChooser");
            JPanel values = new JPanel(new FlowLayout(FlowLayout.LEFT));
            JSpinner[] s = new JSpinner[3];
            double[] start = {c.r(), c.g(), c.b()};
            String[] names = {"r", "g", "b"};
            for (int i = 0; i < 3; i++) {
                // Colours above 1 are legal (an emission can be brighter than white), so the spinners allow them.
                s[i] = new JSpinner(new SpinnerNumberModel(start[i], 0.0, 1e6, 0.01));
                s[i].setName("color" + names[i]);
                s[i].getAccessibleContext().setAccessibleName(names[i] + " from 0 to 1");
                values.add(new JLabel(names[i]));
                values.add(s[i]);
            }
            boolean[] syncing = {false};
            Runnable fromSpinners = () -> {
                if (syncing[0]) return;
                Rgb v = new Rgb(num(s[0]), num(s[1]), num(s[2]));
                syncing[0] = true;
                chooser.setColor(awt(v));
                syncing[0] = false;
                setValue(v);
            };
            for (JSpinner spinner : s) spinner.addChangeListener(e -> fromSpinners.run());
            chooser.getSelectionModel().addChangeListener(e -> {
                if (syncing[0]) return;
                Color picked = chooser.getColor();
                syncing[0] = true;
                s[0].setValue(round(picked.getRed() / 255.0));
                s[1].setValue(round(picked.getGreen() / 255.0));
                s[2].setValue(round(picked.getBlue() / 255.0));
                syncing[0] = false;
                setValue(new Rgb(num(s[0]), num(s[1]), num(s[2])));
            });
            panel.add(chooser);
            panel.add(values);
            return panel;
        }

        private static double round(double v) { return Math.round(v * 1000) / 1000.0; }
    }

    /** A string that is one of a fixed list of words (aperture shape, projection, sampler…). */
    static final class ChoiceEditor extends PropertyEditorSupport {
        private final List<String> words;

        ChoiceEditor(List<String> words) { this.words = words; }

        @Override public String[] getTags() { return words.toArray(String[]::new); }

        @Override public String getAsText() { return getValue() == null ? "" : getValue().toString(); }

        @Override
        public void setAsText(String text) {
            if (!words.contains(text)) throw new IllegalArgumentException("one of " + String.join(", ", words));
            setValue(text);
        }
    }

    static Color awt(Rgb c) {
        return new Color(clamp(c.r()), clamp(c.g()), clamp(c.b()));
    }

    private static int clamp(double v) { return (int) Math.round(Math.max(0, Math.min(1, v)) * 255); }

    private static double num(JSpinner s) { return ((Number) s.getValue()).doubleValue(); }
}
