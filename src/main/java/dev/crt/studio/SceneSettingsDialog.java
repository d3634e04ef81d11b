package dev.crt.studio;

import dev.crt.lang.CompileResult;
import dev.crt.scene.Settings;
import java.awt.BorderLayout;
import java.awt.FlowLayout;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.awt.Window;
import java.math.BigDecimal;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import javax.swing.BorderFactory;
import javax.swing.ButtonGroup;
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JRadioButton;
import javax.swing.JSpinner;
import javax.swing.KeyStroke;
import javax.swing.SpinnerNumberModel;
import javax.swing.text.BadLocationException;
import org.fife.ui.rsyntaxtextarea.RSyntaxTextArea;

/**
 * Render → Settings…: the scene's size, sampling, recursion depth and gamma, and the render threads,
 * either written into the script's Settings block as one undoable edit ({@link SettingsWriter}) or
 * kept for this session only ({@link SessionSettings}). Threads are always for the session.
 */
final class SceneSettingsDialog extends JDialog {
    private final ScriptDocument document;
    private final RSyntaxTextArea area;
    private final SessionSettings session;
    private final Consumer<String> log;
    /** The script's own values, as its latest compile gave them. */
    private final Settings script;

    private final JSpinner width = spinner("settingsWidth", new SpinnerNumberModel(1, 1, 100_000, 1));
    private final JSpinner height = spinner("settingsHeight", new SpinnerNumberModel(1, 1, 100_000, 1));
    private final JSpinner supersampling = spinner("settingsSupersampling", new SpinnerNumberModel(1, 1, Settings.MAX_SUPERSAMPLING, 1));
    private final JSpinner dofSamples = spinner("settingsDofSamples", new SpinnerNumberModel(1, 1, Settings.MAX_DOF_SAMPLES, 1));
    private final JSpinner recursionDepth = spinner("settingsRecursionDepth", new SpinnerNumberModel(0, 0, 1000, 1));
    private final JSpinner gamma = spinner("settingsGamma", new SpinnerNumberModel(1.0, 0.05, 10.0, 0.1));
    private final JSpinner threads = spinner("settingsThreads", new SpinnerNumberModel(0, 0, 1024, 1));
    private final JRadioButton toScript = new JRadioButton("Write into the script's Settings block (undo with Ctrl+Z)");
    private final JRadioButton toSession = new JRadioButton("This session only (the script is not changed)");

    SceneSettingsDialog(Window owner, ScriptDocument document, RSyntaxTextArea area, SessionSettings session, Consumer<String> log) {
        super(owner, "Scene settings — " + document.name(), ModalityType.APPLICATION_MODAL);
        this.document = document;
        this.area = area;
        this.session = session;
        this.log = log;
        CompileResult r = document.result();
        script = r != null && r.scene() != null ? r.scene().settings() : Settings.DEFAULT;
        Settings shown = session.apply(script);
        width.setValue(shown.width());
        height.setValue(shown.height());
        supersampling.setValue(shown.supersampling());
        dofSamples.setValue(shown.dofSamples());
        recursionDepth.setValue(shown.recursionDepth());
        gamma.setValue(shown.gamma());
        threads.setValue(session.threads);

        JPanel form = new JPanel(new GridBagLayout());
        form.setBorder(BorderFactory.createEmptyBorder(10, 12, 6, 12));
        row(form, 0, "Width (pixels)", width);
        row(form, 1, "Height (pixels)", height);
        row(form, 2, "Supersampling (n×n per pixel)", supersampling);
        row(form, 3, "DOF samples (per pixel sample)", dofSamples);
        row(form, 4, "Recursion depth", recursionDepth);
        row(form, 5, "Gamma", gamma);
        row(form, 6, "Threads (0: all " + Runtime.getRuntime().availableProcessors() + " cores; this session)", threads);
        ButtonGroup where = new ButtonGroup();
        where.add(toScript);
        where.add(toSession);
        toScript.setName("settingsToScript");
        toSession.setName("settingsToSession");
        (session.isEmpty() ? toScript : toSession).setSelected(true);
        GridBagConstraints c = new GridBagConstraints();
        c.gridx = 0;
        c.gridwidth = 2;
        c.anchor = GridBagConstraints.LINE_START;
        c.insets = new Insets(8, 0, 0, 0);
        c.gridy = 7;
        form.add(toScript, c);
        c.insets = new Insets(0, 0, 0, 0);
        c.gridy = 8;
        form.add(toSession, c);
        if (r == null || r.scene() == null) {
            c.gridy = 9;
            form.add(new JLabel("The script does not compile now: the values shown are the defaults."), c);
        }

        JButton ok = new JButton("OK");
        ok.setName("settingsOk");
        JButton cancel = new JButton("Cancel");
        cancel.setName("settingsCancel");
        ok.addActionListener(e -> {
            if (apply()) dispose();
        });
        cancel.addActionListener(e -> dispose());
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.TRAILING));
        buttons.add(ok);
        buttons.add(cancel);
        getContentPane().add(form, BorderLayout.CENTER);
        getContentPane().add(buttons, BorderLayout.SOUTH);
        getRootPane().setDefaultButton(ok);
        getRootPane().registerKeyboardAction(e -> dispose(), KeyStroke.getKeyStroke("ESCAPE"), JComponent.WHEN_IN_FOCUSED_WINDOW);
        getAccessibleContext().setAccessibleName("Scene settings");
        pack();
        setLocationRelativeTo(owner);
    }

    private static JSpinner spinner(String name, SpinnerNumberModel model) {
        JSpinner s = new JSpinner(model);
        s.setEditor(new JSpinner.NumberEditor(s, model.getValue() instanceof Double ? "0.0##" : "#"));
        s.setName(name);
        ((JSpinner.DefaultEditor) s.getEditor()).getTextField().setColumns(6);
        return s;
    }

    private static void row(JPanel form, int y, String label, JSpinner field) {
        GridBagConstraints c = new GridBagConstraints();
        c.gridy = y;
        c.anchor = GridBagConstraints.LINE_START;
        c.insets = new Insets(2, 0, 2, 12);
        JLabel l = new JLabel(label);
        l.setLabelFor(field);
        field.getAccessibleContext().setAccessibleName(label);
        form.add(l, c);
        c.gridx = 1;
        c.insets = new Insets(2, 0, 2, 0);
        form.add(field, c);
    }

    private int integer(JSpinner s) { return ((Number) s.getValue()).intValue(); }

    private double number(JSpinner s) { return ((Number) s.getValue()).doubleValue(); }

    /** Applies the values as chosen; false (the dialog stays) when the script cannot take them. */
    private boolean apply() {
        session.threads = integer(threads);
        if (toSession.isSelected()) {
            session.width = differs(integer(width), script.width());
            session.height = differs(integer(height), script.height());
            session.supersampling = differs(integer(supersampling), script.supersampling());
            session.dofSamples = differs(integer(dofSamples), script.dofSamples());
            session.recursionDepth = differs(integer(recursionDepth), script.recursionDepth());
            session.gamma = number(gamma) != script.gamma() ? number(gamma) : null;
            log.accept("settings for this session: " + describe());
            return true;
        }
        Map<String, String> changed = new LinkedHashMap<>();
        putIfChanged(changed, "width", integer(width), script.width());
        putIfChanged(changed, "height", integer(height), script.height());
        putIfChanged(changed, "supersampling", integer(supersampling), script.supersampling());
        putIfChanged(changed, "dofsamples", integer(dofSamples), script.dofSamples());
        putIfChanged(changed, "recursiondepth", integer(recursionDepth), script.recursionDepth());
        if (number(gamma) != script.gamma()) changed.put("gamma", BigDecimal.valueOf(number(gamma)).stripTrailingZeros().toPlainString());
        try {
            List<SettingsWriter.Edit> edits = SettingsWriter.edits(document.content(), changed);
            area.beginAtomicEdit();
            try {
                for (SettingsWriter.Edit e : edits) document.text().replace(e.start(), e.end() - e.start(), e.text(), null);
            } finally {
                area.endAtomicEdit();
            }
        } catch (SettingsWriter.Refused e) {
            JOptionPane.showMessageDialog(this, e.getMessage(), "Cannot write the Settings block", JOptionPane.ERROR_MESSAGE);
            return false;
        } catch (BadLocationException e) {
            throw new IllegalStateException(e);
        }
        // What the script now says needs no session override on top.
        session.width = session.height = session.supersampling = session.dofSamples = session.recursionDepth = null;
        session.gamma = null;
        if (!changed.isEmpty()) log.accept("wrote into the Settings block of " + document.name() + ": " + changed);
        return true;
    }

    private static Integer differs(int chosen, int script) { return chosen != script ? chosen : null; }

    private static void putIfChanged(Map<String, String> changed, String name, int chosen, int script) {
        if (chosen != script) changed.put(name, Integer.toString(chosen));
    }

    private String describe() {
        StringBuilder s = new StringBuilder();
        if (session.width != null) s.append("width ").append(session.width).append(", ");
        if (session.height != null) s.append("height ").append(session.height).append(", ");
        if (session.supersampling != null) s.append("supersampling ").append(session.supersampling).append(", ");
        if (session.dofSamples != null) s.append("dof samples ").append(session.dofSamples).append(", ");
        if (session.recursionDepth != null) s.append("recursion depth ").append(session.recursionDepth).append(", ");
        if (session.gamma != null) s.append("gamma ").append(session.gamma).append(", ");
        s.append("threads ").append(session.threads == 0 ? "all cores" : Integer.toString(session.threads));
        return s.toString();
    }
}
