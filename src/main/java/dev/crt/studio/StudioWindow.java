package dev.crt.studio;

import com.formdev.flatlaf.FlatDarkLaf;
import com.formdev.flatlaf.FlatLaf;
import com.formdev.flatlaf.FlatLightLaf;
import dev.crt.lang.CompileResult;
import dev.crt.lang.Diagnostic;
import dev.crt.lang.ScriptFiles;
import dev.crt.lang.Source;
import dev.crt.image.ImageFiles;
import dev.crt.render.Pick;
import dev.crt.render.RenderStats;
import dev.crt.scene.Entity;
import dev.crt.scene.Settings;
import dev.crt.scene.Shading;
import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Frame;
import java.awt.datatransfer.DataFlavor;
import java.awt.event.ActionEvent;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.IntConsumer;
import javax.swing.AbstractAction;
import javax.swing.Action;
import javax.swing.BorderFactory;
import javax.swing.ButtonGroup;
import javax.swing.JButton;
import javax.swing.JCheckBoxMenuItem;
import javax.swing.JComponent;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JProgressBar;
import javax.swing.JRadioButtonMenuItem;
import javax.swing.JTabbedPane;
import javax.swing.JToolBar;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import javax.swing.TransferHandler;
import javax.swing.filechooser.FileNameExtensionFilter;
import javax.swing.text.Element;

/**
 * The studio's main window: the dock (Script, Render, Console), menus, toolbar and status bar, and
 * the file, render and theme actions behind them. Built and used on the Event Dispatch Thread.
 */
final class StudioWindow implements StudioModel.Listener {
    static final String TITLE = "CRT Studio";

    private final StudioPaths paths;
    private final StudioSettings settings;
    private final StudioModel model = new StudioModel();
    private final LiveCompiler compiler = new LiveCompiler();
    private final Recovery recovery;
    private final JFrame frame = new JFrame(TITLE);
    private final DockLayout dock;
    private final JTabbedPane tabs = new ScriptTabs();
    private final Map<ScriptDocument, ScriptEditor> editors = new HashMap<>();
    private final RenderView renderView = new RenderView();
    private final JLabel renderInfo = new JLabel("F5 renders the current script");
    private final ConsolePanel console = new ConsolePanel();
    private final LiveDock live = new LiveDock(model, editors::get, console);
    private final RenderSelection renderSelection = new RenderSelection(renderView);
    private final RenderFreshness renderFreshness = new RenderFreshness(renderView);
    private final JLabel caretStatus = new JLabel("–");
    private final JLabel renderStatus = new JLabel(" ");
    private final JProgressBar progress = new JProgressBar(0, 1000);
    private final JLabel heapStatus = new JLabel();
    /** Render → Settings… for this session only, which renders and animations apply. */
    private final SessionSettings session = new SessionSettings();
    private final Throughput throughput = new Throughput();
    private final AnimationPanel animation = new AnimationPanel(model, session, throughput, console);
    private final SystemPanel system = new SystemPanel(throughput);
    private final Map<String, Action> actions = new LinkedHashMap<>();
    private final JMenu recentMenu = new JMenu("Open recent");
    {
        recentMenu.setMnemonic(KeyEvent.VK_R);
    }
    private final JCheckBoxMenuItem renderOnSaveItem = new JCheckBoxMenuItem();
    /** Render → "Look of CRT 2015": renders use shading "original" whatever the script says (this session only). */
    private final JCheckBoxMenuItem originalShadingItem = new JCheckBoxMenuItem();
    private final Map<String, JRadioButtonMenuItem> themeItems = new HashMap<>();
    private final Timer diskWatch;
    private final Timer heapTimer;
    private final TransferHandler fileDrop;
    private IntConsumer onExit = code -> {};
    private Runnable firstPaint;
    private boolean painted;
    private RenderJob job;
    /** The Navigator and Properties panels and the Insert menu (issue 8). */
    private ObjectPanels objects;
    private RenderJob.Result lastRender;
    private ScriptDocument lastRenderDocument;
    private boolean askingAboutDisk;
    /**
     * The frame itself owning the focus helps nobody; it happens when the window is shown with no
     * window manager running (the X server's focus arrives after the editor asked for it), so the
     * editor takes it then.
     */
    private final java.beans.PropertyChangeListener frameFocus = e -> {
        if (e.getNewValue() == frame) SwingUtilities.invokeLater(this::focusEditor);
    };

    StudioWindow(StudioPaths paths) {
        this.paths = paths;
        LibraryLogs.quiet();
        this.settings = StudioSettings.load(paths.settingsFile());
        recovery = new Recovery(paths.recovery(), model);
        recovery.onProblem(m -> SwingUtilities.invokeLater(() -> console.log(ConsolePanel.Kind.ERROR, m)));
        applyLookAndFeel(settings.dark);
        dock = new DockLayout(frame);
        fileDrop = new FileDropHandler(null, this::openAll);
        model.addListener(compiler);
        model.addListener(recovery);
        model.addListener(this);
        model.addListener(renderSelection);
        model.addListener(renderFreshness);
        buildActions();
        buildPanels();
        frame.setJMenuBar(buildMenus());
        JPanel root = new JPanel(new BorderLayout()) {
            @Override public void paint(java.awt.Graphics g) {
                super.paint(g);
                if (!painted) {
                    painted = true;
                    // While the artist looks at the window, not when a compile first selects an object.
                    ValueEditors.findPlainEditorsInBackground();
                }
                Runnable r = firstPaint;
                firstPaint = null;
                if (r != null) r.run();
            }
        };
        root.add(buildToolBar(), BorderLayout.NORTH);
        root.add(dock.control().getContentArea(), BorderLayout.CENTER);
        root.add(buildStatusBar(), BorderLayout.SOUTH);
        frame.setContentPane(root);
        frame.setTransferHandler(fileDrop);
        root.setTransferHandler(fileDrop);
        bindKeys(frame.getRootPane(), JComponent.WHEN_IN_FOCUSED_WINDOW);
        frame.setDefaultCloseOperation(JFrame.DO_NOTHING_ON_CLOSE);
        frame.addWindowListener(new WindowAdapter() {
            @Override public void windowClosing(WindowEvent e) { quit(); }
        });
        java.awt.KeyboardFocusManager.getCurrentKeyboardFocusManager().addPropertyChangeListener("focusOwner", frameFocus);
        frame.setIconImages(StudioIcon.images());
        if (settings.bounds != null) frame.setBounds(settings.bounds);
        else {
            frame.setSize(new Dimension(1280, 800));
            frame.setLocationRelativeTo(null);
        }
        if (!dock.restore(paths.layoutFile())) dock.resetLayout();
        if (settings.maximized) frame.setExtendedState(Frame.MAXIMIZED_BOTH);
        rebuildRecentMenu();
        console.onPlaceClicked(this::openPlace);
        renderView.onPixelClicked(this::pickPixel);
        tabs.addChangeListener(e -> {
            ScriptEditor ed = (ScriptEditor) tabs.getSelectedComponent();
            model.setCurrent(ed == null ? null : ed.document());
        });
        diskWatch = new Timer(1500, e -> checkDisk());
        heapTimer = new Timer(1000, e -> showHeap());
        diskWatch.start();
        heapTimer.start();
        recovery.start();
        showHeap();
        updateTitle();
    }

    JFrame frame() { return frame; }

    StudioModel model() { return model; }

    ConsolePanel console() { return console; }

    RenderView renderView() { return renderView; }

    LiveDock live() { return live; }

    DockLayout dock() { return dock; }

    JLabel renderInfo() { return renderInfo; }

    JLabel caretStatus() { return caretStatus; }

    ScriptEditor editor(ScriptDocument d) { return editors.get(d); }

    ScriptEditor currentEditor() { return model.current() == null ? null : editors.get(model.current()); }

    LiveCompiler compiler() { return compiler; }

    AnimationPanel animation() { return animation; }

    SystemPanel system() { return system; }

    Recovery recovery() { return recovery; }

    RenderJob.Result lastRender() { return lastRender; }

    Action action(String name) { return actions.get(name); }

    ObjectPanels objects() { return objects; }

    void onExit(IntConsumer listener) { onExit = listener; }

    /** {@code r} runs once on the EDT, right after the window's whole content was painted the first time. */
    void onFirstPaint(Runnable r) { firstPaint = r; }

    /** Shows the window, offers to recover unsaved work of a studio that died, and opens {@code files}. */
    void show(List<Path> files) {
        LibraryClasses.preload();
        frame.setVisible(true);
        // The X input method opens on the first key press and reads the locale's compose tables
        // meanwhile (0.1 s, over 1 s on a loaded machine, on the EDT): open it now, not on the first key.
        SwingUtilities.invokeLater(() -> frame.getInputContext().getInputMethodControlObject());
        offerRecovery();
        openAll(files);
        if (model.documents().isEmpty()) newDocument();
        focusEditor();
        // With no window manager the X server's focus can arrive after the editor asked for it, and
        // the request is lost, or be cleared by the docking library's last request made before it
        // was told the Script panel is focused (DockLayout.focused). The library used to ask again
        // and again for the window's focus, and the studio handed it to the editor each time; now
        // it asks nothing, so for the first seconds the studio asks again itself whenever the focus
        // is nowhere or on the bare window, until the editor has held it for half a second (3 s at
        // most), and never after: no later dialog can lose a click to it.
        int[] ticks = {0, 0};
        Timer startFocus = new Timer(50, null);
        startFocus.addActionListener(e -> {
            ScriptEditor editor = currentEditor();
            java.awt.Component owner = java.awt.KeyboardFocusManager.getCurrentKeyboardFocusManager().getFocusOwner();
            boolean held = editor != null && owner == editor.area();
            ticks[1] = held ? ticks[1] + 1 : 0;
            if (editor == null || ticks[1] >= 10 || ++ticks[0] > 60) startFocus.stop();
            else if (!held && (owner == null || owner == frame || owner == frame.getRootPane())) focusEditor();
        });
        startFocus.start();
    }

    /**
     * Goes through a start without showing anything, for the launcher's start-up cache: the window
     * is made (unmapped), {@code files} opened and compiled, the content painted into an image, the
     * script rendered, an object selected and a mistake typed; then the JVM exits (0 when all went
     * through, 1 when 30 s were not enough), which writes the cache. Classes and code paths a real
     * start needs are then already loaded and linked when the studio starts the next time.
     */
    void train(List<Path> files) {
        frame.addNotify();
        openAll(files);
        if (model.documents().isEmpty()) newDocument();
        frame.validate();
        paintOffscreen();
        render();
        long until = System.nanoTime() + 30_000_000_000L;
        boolean[] typed = new boolean[1];
        Timer poll = new Timer(20, null);
        poll.addActionListener(e -> {
            boolean late = System.nanoTime() > until;
            if (job != null && !late) return;
            ScriptDocument d = model.current();
            if (!typed[0] && !late && d != null) {
                // Then the caret into an object (the property sheet is made and painted) and a
                // mistake typed, as an artist does first thing: the classes of both too.
                typed[0] = true;
                var area = editors.get(d).area();
                int sphere = area.getText().indexOf("Sphere");
                if (sphere >= 0) area.setCaretPosition(sphere + 1);
                paintOffscreen();
                area.append("\nnot_defined_anywhere\n");
                return;
            }
            if (!late && d != null && !(d.resultIsCurrent() && d.result().hasErrors())) return;
            poll.stop();
            paintOffscreen();
            System.exit(lastRender != null && !late ? 0 : 1);
        });
        poll.start();
    }

    /** Paints the whole window into an image of its size, as a paint on the screen would. */
    private void paintOffscreen() {
        var image = new java.awt.image.BufferedImage(frame.getWidth(), frame.getHeight(), java.awt.image.BufferedImage.TYPE_INT_RGB);
        java.awt.Graphics2D g = image.createGraphics();
        try {
            frame.getRootPane().paint(g);
        } finally {
            g.dispose();
        }
    }

    // ---------------------------------------------------------------- building

    private void buildPanels() {
        JPanel scriptPanel = new JPanel(new BorderLayout());
        tabs.setName("scriptTabs");
        tabs.getAccessibleContext().setAccessibleName("Open scripts");
        scriptPanel.add(tabs, BorderLayout.CENTER);

        JPanel renderPanel = new JPanel(new BorderLayout());
        JToolBar renderBar = new JToolBar();
        renderBar.setFloatable(false);
        renderBar.add(button("render"));
        renderBar.add(button("cancel"));
        renderBar.addSeparator();
        renderBar.add(button("zoomFit"));
        renderBar.add(button("zoomActual"));
        renderBar.addSeparator();
        renderInfo.setName("renderInfo");
        renderBar.add(renderInfo);
        renderPanel.add(renderBar, BorderLayout.NORTH);
        renderPanel.add(renderView, BorderLayout.CENTER);

        dock.register(new StudioPanel("script", "Script", scriptPanel, 0.24, 0, 0.38, 0.75));
        dock.register(new StudioPanel("render", "Render", renderPanel, 0.62, 0, 0.38, 0.75));
        dock.register(new StudioPanel("live", "Live view", live, 0.62, 0, 0.38, 0.75));
        objects = new ObjectPanels(this);
        objects.panels().forEach(dock::register);
        dock.register(new StudioPanel("console", "Console", console, 0, 0.75, 1, 0.25));

        // Animation stacks behind the render view (frames are pictures too, and want its room), System behind the console.
        StudioPanel render = dock.panel("render"), bottom = dock.panel("console");
        dock.register(new StudioPanel("animation", "Animation", animation, render.x(), render.y(), render.width(), render.height()));
        dock.register(new StudioPanel("system", "System", system, bottom.x(), bottom.y(), bottom.width(), bottom.height()));
        model.addListener(animation);
    }

    private JButton button(String action) {
        JButton b = new JButton(actions.get(action));
        b.setHideActionText(false);
        b.setFocusable(false);
        return b;
    }

    private void action(String name, String label, KeyStroke key, Runnable body) {
        AbstractAction a = new AbstractAction(label) {
            @Override public void actionPerformed(ActionEvent e) { body.run(); }
        };
        if (key != null) {
            // One key, one action: a second binding would silently take the first one's key away.
            for (Action other : actions.values()) {
                if (key.equals(other.getValue(Action.ACCELERATOR_KEY))) {
                    throw new IllegalStateException(key + " is already the key of " + other.getValue(Action.ACTION_COMMAND_KEY));
                }
            }
            a.putValue(Action.ACCELERATOR_KEY, key);
        }
        a.putValue(Action.ACTION_COMMAND_KEY, name);
        actions.put(name, a);
    }

    private static KeyStroke ctrl(int key) { return KeyStroke.getKeyStroke(key, InputEvent.CTRL_DOWN_MASK); }

    private static KeyStroke ctrlShift(int key) {
        return KeyStroke.getKeyStroke(key, InputEvent.CTRL_DOWN_MASK | InputEvent.SHIFT_DOWN_MASK);
    }

    private void buildActions() {
        action("new", "New", ctrl(KeyEvent.VK_N), this::newDocument);
        action("open", "Open…", ctrl(KeyEvent.VK_O), this::openWithChooser);
        action("save", "Save", ctrl(KeyEvent.VK_S), () -> save(model.current()));
        action("saveAs", "Save As…", ctrlShift(KeyEvent.VK_S), () -> saveAs(model.current()));
        action("close", "Close tab", ctrl(KeyEvent.VK_W), () -> close(model.current()));
        action("quit", "Quit", ctrl(KeyEvent.VK_Q), this::quit);
        action("undo", "Undo", ctrl(KeyEvent.VK_Z), () -> withEditor(e -> e.area().undoLastAction()));
        action("redo", "Redo", ctrl(KeyEvent.VK_Y), () -> withEditor(e -> e.area().redoLastAction()));
        action("find", "Find…", ctrl(KeyEvent.VK_F), () -> withEditor(e -> e.findBar().open(false)));
        action("replace", "Replace…", ctrl(KeyEvent.VK_H), () -> withEditor(e -> e.findBar().open(true)));
        action("comment", "Toggle comment", ctrl(KeyEvent.VK_SLASH), () -> withEditor(this::toggleComment));
        action("complete", "Complete", ctrl(KeyEvent.VK_SPACE), () -> withEditor(this::complete));
        action("definition", "Go to definition", KeyStroke.getKeyStroke(KeyEvent.VK_F3, 0),
                () -> withEditor(e -> e.goToDefinition(e.area().getCaretPosition())));
        action("light", "Light theme", ctrlShift(KeyEvent.VK_L), () -> setTheme(false));
        action("dark", "Dark theme", ctrlShift(KeyEvent.VK_D), () -> setTheme(true));
        action("toggleTheme", "Switch theme", ctrlShift(KeyEvent.VK_T), () -> setTheme(!settings.dark));
        action("resetLayout", "Reset layout", ctrlShift(KeyEvent.VK_R), this::resetLayout);
        action("showScript", "Script", KeyStroke.getKeyStroke(KeyEvent.VK_1, InputEvent.ALT_DOWN_MASK),
                () -> { dock.dockable("script").toFront(); focusEditor(); });
        action("showRender", "Render view", KeyStroke.getKeyStroke(KeyEvent.VK_2, InputEvent.ALT_DOWN_MASK),
                () -> dock.dockable("render").toFront());
        action("showConsole", "Console", KeyStroke.getKeyStroke(KeyEvent.VK_3, InputEvent.ALT_DOWN_MASK),
                () -> dock.dockable("console").toFront());
        action("showLive", "Live view", KeyStroke.getKeyStroke(KeyEvent.VK_4, InputEvent.ALT_DOWN_MASK),
                () -> dock.dockable("live").toFront());
        action("copyCamera", "Copy camera to script", ctrlShift(KeyEvent.VK_C), live::copyCameraToScript);
        action("render", "Render", KeyStroke.getKeyStroke(KeyEvent.VK_F5, 0), this::render);
        action("cancel", "Cancel", KeyStroke.getKeyStroke(KeyEvent.VK_ESCAPE, 0), this::cancelRender);
        action("zoomFit", "Fit", ctrl(KeyEvent.VK_0), renderView::zoomToFit);
        action("zoomActual", "1:1", ctrl(KeyEvent.VK_1), renderView::zoomActualSize);
        action("saveImage", "Save image as…", ctrlShift(KeyEvent.VK_E), this::saveImage);
        action("renderOnSave", "Render on save", ctrlShift(KeyEvent.VK_F5), () -> {
            settings.renderOnSave = !settings.renderOnSave;
            renderOnSaveItem.setSelected(settings.renderOnSave);
        });
        action("originalShading", "Look of CRT 2015 (shading original)", ctrlShift(KeyEvent.VK_O),
                () -> originalShadingItem.setSelected(!originalShadingItem.isSelected()));
        action("shortcuts", "Keyboard shortcuts", KeyStroke.getKeyStroke(KeyEvent.VK_F1, 0), this::showShortcuts);
        action("about", "About CRT Studio", KeyStroke.getKeyStroke(KeyEvent.VK_F1, InputEvent.SHIFT_DOWN_MASK), () -> JOptionPane.showMessageDialog(frame,
                "CRT Studio: write .crt scene scripts and render them with the Cathode Ray Tracer.\nJava "
                        + System.getProperty("java.version"), "About", JOptionPane.INFORMATION_MESSAGE));
        action("showAnimation", "Animation", KeyStroke.getKeyStroke(KeyEvent.VK_7, InputEvent.ALT_DOWN_MASK),
                () -> dock.dockable("animation").toFront());
        action("showSystem", "System", KeyStroke.getKeyStroke(KeyEvent.VK_8, InputEvent.ALT_DOWN_MASK),
                () -> dock.dockable("system").toFront());
        action("sceneSettings", "Settings…", KeyStroke.getKeyStroke(KeyEvent.VK_S, InputEvent.CTRL_DOWN_MASK | InputEvent.ALT_DOWN_MASK),
                this::sceneSettings);
        action("renderFrames", "Render frames", KeyStroke.getKeyStroke(KeyEvent.VK_F5, InputEvent.SHIFT_DOWN_MASK), () -> {
            dock.dockable("animation").toFront();
            animation.renderFrames();
        });
    }

    private JMenuBar buildMenus() {
        JMenuBar bar = new JMenuBar();
        JMenu file = menu("File", KeyEvent.VK_F, "new", "open");
        file.add(recentMenu);
        add(file, "save", "saveAs", null, "close", null, "quit");
        bar.add(file);
        bar.add(menu("Edit", KeyEvent.VK_E, "undo", "redo", null, "find", "replace", null, "comment", "complete", "definition"));
        JMenu view = menu("View", KeyEvent.VK_V);
        ButtonGroup themes = new ButtonGroup();
        for (String t : new String[] {"light", "dark"}) {
            JRadioButtonMenuItem item = new JRadioButtonMenuItem(actions.get(t));
            item.setSelected(settings.dark == t.equals("dark"));
            themeItems.put(t, item);
            themes.add(item);
            view.add(item);
        }
        add(view, "toggleTheme", null, "showScript", "showRender", "showConsole", "showLive", null, "copyCamera", null, "resetLayout");
        bar.add(view);
        add(view, null, "showAnimation", "showSystem");
        JMenu render = menu("Render", KeyEvent.VK_R, "render", "cancel", null, "zoomFit", "zoomActual", null, "saveImage",
                "sceneSettings", "renderFrames");
        // The check box shows the setting; the action behind it toggles it, from the menu or the key.
        renderOnSaveItem.setText("Render on save");
        renderOnSaveItem.setAccelerator((KeyStroke) actions.get("renderOnSave").getValue(Action.ACCELERATOR_KEY));
        renderOnSaveItem.setSelected(settings.renderOnSave);
        renderOnSaveItem.addActionListener(e -> settings.renderOnSave = renderOnSaveItem.isSelected());
        render.add(renderOnSaveItem);
        originalShadingItem.setText("Look of CRT 2015 (shading original)");
        originalShadingItem.setAccelerator((KeyStroke) actions.get("originalShading").getValue(Action.ACCELERATOR_KEY));
        originalShadingItem.getAccessibleContext().setAccessibleName("Look of CRT 2015");
        render.add(originalShadingItem);
        bar.add(render);
        bar.add(objects.insertMenu());
        bar.add(menu("Help", KeyEvent.VK_H, "shortcuts", "about"));
        return bar;
    }

    private JMenu menu(String title, int mnemonic, String... names) {
        JMenu m = new JMenu(title);
        m.setMnemonic(mnemonic);
        add(m, names);
        return m;
    }

    private void add(JMenu m, String... names) {
        for (String n : names) {
            if (n == null) m.addSeparator();
            else m.add(new JMenuItem(actions.get(n)));
        }
    }

    private JToolBar buildToolBar() {
        JToolBar bar = new JToolBar();
        bar.setFloatable(false);
        for (String n : new String[] {"new", "open", "save", null, "undo", "redo", null, "render", "cancel", "saveImage"}) {
            if (n == null) bar.addSeparator();
            else bar.add(button(n));
        }
        return bar;
    }

    private JComponent buildStatusBar() {
        JPanel bar = new JPanel(new BorderLayout(12, 0));
        bar.setBorder(BorderFactory.createEmptyBorder(2, 8, 2, 8));
        caretStatus.setName("caretStatus");
        renderStatus.setName("renderStatus");
        heapStatus.setName("heapStatus");
        progress.setPreferredSize(new Dimension(160, 14));
        progress.setVisible(false);
        JPanel middle = new JPanel(new BorderLayout(8, 0));
        middle.add(renderStatus, BorderLayout.CENTER);
        middle.add(progress, BorderLayout.LINE_END);
        bar.add(caretStatus, BorderLayout.LINE_START);
        bar.add(middle, BorderLayout.CENTER);
        bar.add(heapStatus, BorderLayout.LINE_END);
        return new LayoutBoundary(bar);
    }

    /** Every action with a key works wherever the focus is in the window, also inside the editor. */
    private void bindKeys(JComponent c, int condition) {
        for (Map.Entry<String, Action> e : actions.entrySet()) {
            KeyStroke key = (KeyStroke) e.getValue().getValue(Action.ACCELERATOR_KEY);
            if (key == null) continue;
            c.getInputMap(condition).put(key, "crt." + e.getKey());
            c.getActionMap().put("crt." + e.getKey(), e.getValue());
        }
    }

    // ---------------------------------------------------------------- model events

    @Override
    public void opened(ScriptDocument d) {
        ScriptEditor editor = new ScriptEditor(d);
        editor.applyTheme(settings.dark);
        editors.put(d, editor);
        // The editor's own keys (undo, comment, completion, Esc for its popups) stay; the studio's
        // file, render and find keys take precedence over any default text binding.
        for (String n : new String[] {"new", "open", "save", "saveAs", "close", "quit", "find", "replace", "render",
                "zoomFit", "zoomActual", "saveImage", "toggleTheme", "light", "dark", "resetLayout", "renderOnSave", "originalShading",
                "shortcuts", "about"}) {
            KeyStroke key = (KeyStroke) actions.get(n).getValue(Action.ACCELERATOR_KEY);
            editor.area().getInputMap().put(key, "crt." + n);
            editor.area().getActionMap().put("crt." + n, actions.get(n));
        }
        editor.area().setTransferHandler(new FileDropHandler(objects.paletteDrop(editor.area(), editor.area().getTransferHandler()),
                this::openAll));
        editor.area().addCaretListener(e -> showCaret(editor));
        tabs.addTab(d.name(), editor);
        tabs.setSelectedComponent(editor);
        updateTab(d);
    }

    @Override
    public void closed(ScriptDocument d) {
        ScriptEditor editor = editors.remove(d);
        if (editor != null) {
            editor.dispose();
            tabs.remove(editor);
        }
        if (lastRenderDocument == d) lastRenderDocument = null;
    }

    @Override
    public void currentChanged(ScriptDocument d) {
        ScriptEditor editor = d == null ? null : editors.get(d);
        if (editor != null && tabs.getSelectedComponent() != editor) tabs.setSelectedComponent(editor);
        if (editor != null) showCaret(editor);
        else caretStatus.setText("–");
        updateTitle();
    }

    @Override
    public void documentChanged(ScriptDocument d) {
        updateTab(d);
        if (d == model.current()) updateTitle();
    }

    @Override
    public void compiled(ScriptDocument d, CompileResult result) {
        updateTab(d);
    }

    private void updateTab(ScriptDocument d) {
        ScriptEditor editor = editors.get(d);
        int at = editor == null ? -1 : tabs.indexOfComponent(editor);
        if (at < 0) return;
        tabs.setTitleAt(at, (d.isModified() ? "*" : "") + d.name());
        tabs.setToolTipTextAt(at, d.file() == null ? "not saved yet" : d.file().toString());
    }

    private void updateTitle() {
        ScriptDocument d = model.current();
        frame.setTitle(d == null ? TITLE : (d.isModified() ? "*" : "") + d.name() + " — " + TITLE);
    }

    private void showCaret(ScriptEditor editor) {
        int caret = editor.area().getCaretPosition();
        Element root = editor.document().text().getDefaultRootElement();
        int line = root.getElementIndex(caret);
        int column = caret - root.getElement(line).getStartOffset();
        caretStatus.setText((line + 1) + ":" + (column + 1));
    }

    private void showHeap() {
        Runtime rt = Runtime.getRuntime();
        long used = (rt.totalMemory() - rt.freeMemory()) >> 20;
        heapStatus.setText("heap " + used + " MB of " + (rt.maxMemory() >> 20) + " MB");
    }

    private void withEditor(java.util.function.Consumer<ScriptEditor> body) {
        ScriptEditor e = currentEditor();
        if (e != null) body.accept(e);
    }

    private void toggleComment(ScriptEditor e) {
        Action toggle = e.area().getActionMap().get(org.fife.ui.rsyntaxtextarea.RSyntaxTextAreaEditorKit.rstaToggleCommentAction);
        if (toggle != null) toggle.actionPerformed(new ActionEvent(e.area(), ActionEvent.ACTION_PERFORMED, "comment"));
    }

    private void complete(ScriptEditor e) {
        e.area().requestFocusInWindow();
        KeyStroke key = ctrl(KeyEvent.VK_SPACE);
        Object name = e.area().getInputMap().get(key);
        Action a = name == null ? null : e.area().getActionMap().get(name);
        if (a != null) a.actionPerformed(new ActionEvent(e.area(), ActionEvent.ACTION_PERFORMED, "complete"));
    }

    void focusEditor() {
        ScriptEditor e = currentEditor();
        if (e == null) return;
        // Never raise the window over a question it is waiting for: with no window manager to keep
        // the dialog above its owner (Xvfb, some kiosks), the question would be hidden and unreachable.
        for (java.awt.Window w : frame.getOwnedWindows()) {
            if (w instanceof java.awt.Dialog dialog && dialog.isModal() && dialog.isShowing()) return;
        }
        frame.toFront();
        // From a floated panel's window, focus must cross windows, which requestFocusInWindow does not.
        if (!frame.isFocused()) e.area().requestFocus();
        e.area().requestFocusInWindow();
        SwingUtilities.invokeLater(() -> e.area().requestFocusInWindow());
        dock.focused("script", e.area());
    }

    // ---------------------------------------------------------------- files

    void newDocument() {
        model.newDocument();
        focusEditor();
    }

    void openAll(List<Path> files) {
        for (Path f : files) open(f);
    }

    /** Opens {@code file} in a tab (or selects its tab); false when it cannot be read. */
    boolean open(Path file) {
        Optional<ScriptDocument> already = model.find(file);
        if (already.isPresent()) {
            model.setCurrent(already.get());
            focusEditor();
            return true;
        }
        try {
            Source s = ScriptFiles.read(file);
            if (!s.isText()) {
                error("cannot open " + file + ": " + s.decodingProblem());
                return false;
            }
            FileTime time = Files.getLastModifiedTime(file);
            ScriptDocument d = model.open(s.text(), file.toAbsolutePath().normalize(), time);
            settings.addRecent(d.file());
            rebuildRecentMenu();
            console.log(ConsolePanel.Kind.INFO, "opened " + d.file());
            focusEditor();
            return true;
        } catch (NoSuchFileException e) {
            error("cannot open " + file + ": the file does not exist");
        } catch (IOException e) {
            error("cannot open " + file + ": " + e.getMessage());
        }
        return false;
    }

    private void openWithChooser() {
        JFileChooser chooser = chooser();
        if (chooser.showOpenDialog(frame) == JFileChooser.APPROVE_OPTION) open(chooser.getSelectedFile().toPath());
    }

    private JFileChooser chooser() {
        ScriptDocument d = model.current();
        JFileChooser chooser = new JFileChooser(d != null && d.file() != null ? d.file().getParent().toFile()
                : Path.of("").toAbsolutePath().toFile());
        chooser.setFileFilter(new FileNameExtensionFilter("CRT scripts (*.crt)", "crt"));
        return chooser;
    }

    /** Saves {@code d} to its file (asking for one if it has none); false when not saved. */
    boolean save(ScriptDocument d) {
        if (d == null) return false;
        if (d.file() == null) return saveAs(d);
        return saveTo(d, d.file());
    }

    boolean saveAs(ScriptDocument d) {
        if (d == null) return false;
        JFileChooser chooser = chooser();
        chooser.setSelectedFile(new java.io.File(d.name()));
        if (chooser.showSaveDialog(frame) != JFileChooser.APPROVE_OPTION) return false;
        Path target = chooser.getSelectedFile().toPath();
        if (!target.getFileName().toString().contains(".")) target = target.resolveSibling(target.getFileName() + ".crt");
        if (Files.exists(target) && !target.equals(d.file()) && JOptionPane.showConfirmDialog(frame,
                target.getFileName() + " exists. Replace it?", "Save As", JOptionPane.YES_NO_OPTION) != JOptionPane.YES_OPTION) {
            return false;
        }
        return saveTo(d, target);
    }

    boolean saveTo(ScriptDocument d, Path target) {
        try {
            AtomicText.write(target, d.content());
            Path file = target.toAbsolutePath().normalize();
            d.saved(file, Files.getLastModifiedTime(file));
            settings.addRecent(file);
            rebuildRecentMenu();
            console.log(ConsolePanel.Kind.INFO, "saved " + file);
            if (settings.renderOnSave && d == model.current()) render();
            return true;
        } catch (IOException e) {
            error("cannot save " + target + ": " + e.getMessage());
            return false;
        }
    }

    /** Closes {@code d}, asking first about unsaved changes; false when the user cancelled. */
    boolean close(ScriptDocument d) {
        if (d == null) return true;
        if (d.isModified()) {
            model.setCurrent(d);
            int answer = JOptionPane.showOptionDialog(frame, d.name() + " has unsaved changes. Save them?",
                    "Unsaved changes", JOptionPane.YES_NO_CANCEL_OPTION, JOptionPane.WARNING_MESSAGE, null,
                    new String[] {"Save", "Don't save", "Cancel"}, "Save");
            if (answer == 0 && !save(d)) return false;
            if (answer != 0 && answer != 1) return false;
        }
        if (job != null && lastRenderDocument == d) cancelRender();
        recovery.forget(d);
        model.close(d);
        return true;
    }

    /** Asks about every unsaved script, saves settings and layout, and closes the studio with exit code 0. */
    void quit() {
        for (ScriptDocument d : model.documents()) {
            if (!close(d)) return;
        }
        cancelRender();
        animation.dispose();
        settings.maximized = (frame.getExtendedState() & Frame.MAXIMIZED_BOTH) != 0;
        if (!settings.maximized) settings.bounds = frame.getBounds();
        try {
            settings.save(paths.settingsFile());
            dock.save(paths.layoutFile());
        } catch (IOException e) {
            JOptionPane.showMessageDialog(frame, "Cannot save the studio's settings: " + e.getMessage());
        }
        java.awt.KeyboardFocusManager.getCurrentKeyboardFocusManager().removePropertyChangeListener("focusOwner", frameFocus);
        diskWatch.stop();
        heapTimer.stop();
        recovery.stop();
        compiler.shutdown();
        live.close();
        renderSelection.shutdown();
        dock.dispose();
        frame.dispose();
        onExit.accept(0);
    }

    private void rebuildRecentMenu() {
        recentMenu.removeAll();
        int n = 0;
        for (Path p : settings.recent) {
            n++;
            JMenuItem item = new JMenuItem(n + "  " + p.getFileName() + "  —  " + p.getParent());
            if (n <= 9) item.setMnemonic(KeyEvent.VK_0 + n);
            item.addActionListener(e -> open(p));
            recentMenu.add(item);
        }
        recentMenu.setEnabled(!settings.recent.isEmpty());
    }

    private void offerRecovery() {
        List<Recovery.Orphan> orphans = Recovery.orphans(paths.recovery());
        if (orphans.isEmpty()) return;
        StringBuilder names = new StringBuilder();
        for (Recovery.Orphan o : orphans) names.append("\n  ").append(o.file() == null ? o.name() : o.file().toString());
        int answer = JOptionPane.showConfirmDialog(frame, "The studio stopped before these scripts were saved:" + names
                + "\nRecover the unsaved text?", "Recover unsaved scripts", JOptionPane.YES_NO_OPTION, JOptionPane.QUESTION_MESSAGE);
        for (Recovery.Orphan o : orphans) {
            // Closing the question without an answer keeps the copies for the next start.
            if (answer == JOptionPane.NO_OPTION) recovery.discard(o);
            if (answer != JOptionPane.YES_OPTION) continue;
            FileTime time = null;
            try {
                if (o.file() != null && Files.exists(o.file())) time = Files.getLastModifiedTime(o.file());
            } catch (IOException e) {
                time = null;
            }
            ScriptDocument d = model.open(o.text(), o.file(), time);
            d.markModified();
            recovery.adopt(d, o.id());
            console.log(ConsolePanel.Kind.WARNING, "recovered unsaved text of " + d.name() + " (save it to keep it)");
        }
    }

    private void checkDisk() {
        if (askingAboutDisk) return;
        for (ScriptDocument d : model.documents()) {
            if (d.file() == null || d.diskTime() == null) continue;
            FileTime now;
            try {
                now = Files.getLastModifiedTime(d.file());
            } catch (IOException e) {
                continue;
            }
            if (now.equals(d.diskTime())) continue;
            d.setDiskTime(now);
            askingAboutDisk = true;
            try {
                String extra = d.isModified() ? "\nReloading discards your unsaved changes." : "";
                int answer = JOptionPane.showConfirmDialog(frame, d.file().getFileName() + " was changed by another program."
                        + extra + "\nReload it?", "File changed on disk", JOptionPane.YES_NO_OPTION);
                if (answer == JOptionPane.YES_OPTION) reload(d);
            } finally {
                askingAboutDisk = false;
            }
        }
    }

    private void reload(ScriptDocument d) {
        try {
            Source s = ScriptFiles.read(d.file());
            if (!s.isText()) {
                error("cannot reload " + d.file() + ": " + s.decodingProblem());
                return;
            }
            ScriptEditor e = editors.get(d);
            int caret = e == null ? 0 : e.area().getCaretPosition();
            d.load(s.text(), d.file(), Files.getLastModifiedTime(d.file()));
            recovery.forget(d);
            if (e != null) {
                // Undo must not bring back the text the other program replaced.
                e.area().discardAllEdits();
                e.area().setCaretPosition(Math.min(caret, d.text().getLength()));
            }
            console.log(ConsolePanel.Kind.INFO, "reloaded " + d.file());
        } catch (IOException ex) {
            error("cannot reload " + d.file() + ": " + ex.getMessage());
        }
    }

    private void openPlace(String file, int line, int column) {
        Optional<ScriptDocument> d = model.findByName(file);
        if (d.isEmpty()) {
            Path p = Path.of(file);
            if (Files.isRegularFile(p) && open(p)) d = model.find(p);
        }
        d.ifPresent(doc -> {
            model.setCurrent(doc);
            dock.dockable("script").toFront();
            editors.get(doc).goTo(line, column);
        });
    }

    private void error(String message) {
        console.log(ConsolePanel.Kind.ERROR, message);
        dock.dockable("console").toFront();
    }

    // ---------------------------------------------------------------- rendering

    void render() {
        ScriptDocument d = model.current();
        if (d == null) return;
        if (job != null) job.cancel();
        dock.dockable("render").toFront();
        renderView.zoomToFit();
        CompileResult compiled = d.resultIsCurrent() ? d.result() : null;
        lastRenderDocument = d;
        progress.setValue(0);
        progress.setVisible(true);
        renderStatus.setText("rendering " + d.name() + "…");
        RenderJob[] self = new RenderJob[1];
        Shading shading = originalShadingItem.isSelected() ? Shading.ORIGINAL : null;
        dev.crt.lang.Source source = d.source();
        self[0] = new RenderJob(source, compiled, shading, session, throughput, new RenderJob.Listener() {
            @Override public void picture(java.awt.image.BufferedImage image, boolean coarse) {
                if (job != self[0]) return;
                renderView.show(image);
            }

            @Override public void tilesChanged(long done, long total, java.awt.Rectangle dirty) {
                if (job != self[0]) return;
                progress.setValue((int) (1000 * done / Math.max(1, total)));
                double seconds = (System.nanoTime() - self[0].startNanos()) / 1e9;
                renderStatus.setText(String.format("rendering %s: %d%%, %.1f s", d.name(), 100 * done / Math.max(1, total), seconds));
                renderView.repaintPicture(dirty);
            }

            @Override public void finished(RenderJob.Result r) {
                if (job != self[0]) return;
                job = null;
                lastRender = r;
                renderView.show(r.picture());
                objects.rendered(r);
                renderSelection.rendered(d, r);
                renderFreshness.rendered(d, source.text());
                progress.setVisible(false);
                RenderStats stats = r.renderer().stats();
                Settings s = r.scene().settings();
                String summary = String.format("%d×%d in %.2f s, %.1f Mrays/s, first picture after %d ms", s.width(), s.height(),
                        r.totalNanos() / 1e9, stats.megaRaysPerSecond(), r.firstPictureNanos() / 1_000_000);
                renderInfo.setText(summary);
                renderStatus.setText("rendered " + d.name() + ": " + summary);
                console.log(ConsolePanel.Kind.INFO, "rendered " + d.source().name() + ": " + summary);
            }

            @Override public void compileFailed(CompileResult compile) {
                if (job != self[0]) return;
                job = null;
                progress.setVisible(false);
                renderStatus.setText(d.name() + " has errors; nothing rendered");
                for (Diagnostic diag : compile.diagnostics()) {
                    console.log(diag.isError() ? ConsolePanel.Kind.ERROR : ConsolePanel.Kind.WARNING,
                            diag.span() + ": " + (diag.isError() ? "error: " : "warning: ") + diag.message());
                }
                dock.dockable("console").toFront();
            }

            @Override public void failed(String message) {
                if (job != self[0]) return;
                job = null;
                progress.setVisible(false);
                renderStatus.setText(message);
                error(message);
            }

            @Override public void cancelled() {
                if (job == self[0]) job = null;
                progress.setVisible(false);
                renderStatus.setText("render cancelled");
                console.log(ConsolePanel.Kind.INFO, "render of " + d.name() + " cancelled");
            }
        });
        job = self[0];
        job.start();
    }

    void cancelRender() {
        if (job == null) return;
        RenderJob j = job;
        job = null;
        j.cancel();
        progress.setVisible(false);
        renderStatus.setText("render cancelled");
    }

    boolean isRendering() { return job != null; }

    /** Render → Settings…: the scene settings, into the script or for this session. */
    private void sceneSettings() {
        ScriptDocument d = model.current();
        ScriptEditor editor = d == null ? null : editors.get(d);
        if (editor == null) return;
        new SceneSettingsDialog(frame, d, editor.area(), session, m -> console.log(ConsolePanel.Kind.INFO, m)).setVisible(true);
    }

    private void pickPixel(int x, int y) {
        RenderJob.Result r = lastRender;
        ScriptDocument d = lastRenderDocument;
        if (r == null || d == null || !editors.containsKey(d)) return;
        Optional<Pick> pick = r.renderer().pick(x, y);
        if (pick.isEmpty()) {
            renderInfo.setText("pixel " + x + ", " + y + ": background");
            model.select(d, null, -1);
            return;
        }
        Entity e = pick.get().entity();
        renderInfo.setText("pixel " + x + ", " + y + ": " + e.getClass().getSimpleName() + " written at " + e.span());
        model.setCurrent(d);
        model.select(d, e, pick.get().entityIndex());
        if (e.span().line() > 0) {
            ScriptEditor editor = editors.get(d);
            editor.goTo(e.span().start());
            editor.area().select(e.span().start(), Math.min(e.span().end(), d.text().getLength()));
        }
    }

    private void saveImage() {
        RenderJob.Result r = lastRender;
        if (r == null) {
            error("nothing rendered yet: press F5 first");
            return;
        }
        JFileChooser chooser = new JFileChooser();
        chooser.setFileFilter(new FileNameExtensionFilter("Images (*.png, *.ppm, *.pfm)", "png", "ppm", "pfm"));
        String base = lastRenderDocument != null ? lastRenderDocument.name().replaceFirst("\\.crt$", "") : "render";
        chooser.setSelectedFile(new java.io.File(base + ".png"));
        if (chooser.showSaveDialog(frame) != JFileChooser.APPROVE_OPTION) return;
        Path out = chooser.getSelectedFile().toPath();
        if (!out.getFileName().toString().contains(".")) out = out.resolveSibling(out.getFileName() + ".png");
        saveImage(out);
    }

    /** Writes the last finished render to {@code out} (.png, .ppm, .pfm) atomically; false on failure. */
    boolean saveImage(Path out) {
        RenderJob.Result r = lastRender;
        if (r == null) return false;
        Settings s = r.scene().settings();
        Map<String, String> text = new LinkedHashMap<>();
        if (!s.title().isEmpty()) text.put("Title", s.title());
        if (!s.author().isEmpty()) text.put("Author", s.author());
        text.put("Software", "CRT Studio");
        try {
            ImageFiles.write(r.image(), out, s.outputGamma(), text);
            console.log(ConsolePanel.Kind.INFO, "saved image " + out.toAbsolutePath());
            return true;
        } catch (IOException e) {
            error(e.getMessage());
            return false;
        }
    }

    // ---------------------------------------------------------------- view

    private void setTheme(boolean dark) {
        if (settings.dark == dark) return;
        settings.dark = dark;
        applyLookAndFeel(dark);
        FlatLaf.updateUI();
        editors.values().forEach(e -> e.applyTheme(dark));
        themeItems.get(dark ? "dark" : "light").setSelected(true);
        for (java.awt.Component c : recentMenu.getMenuComponents()) SwingUtilities.updateComponentTreeUI(c);
        console.log(ConsolePanel.Kind.INFO, (dark ? "dark" : "light") + " theme");
    }

    boolean isDark() { return settings.dark; }

    private static void applyLookAndFeel(boolean dark) {
        if (dark) FlatDarkLaf.setup();
        else FlatLightLaf.setup();
    }

    private void resetLayout() {
        dock.resetLayout();
        focusEditor();
    }

    private void showShortcuts() {
        StringBuilder text = new StringBuilder();
        for (Action a : actions.values()) {
            KeyStroke key = (KeyStroke) a.getValue(Action.ACCELERATOR_KEY);
            if (key == null) continue;
            text.append(String.format("%-22s %s%n", a.getValue(Action.NAME), keyText(key)));
        }
        text.append(String.format("%-22s %s%n", "Go to definition", "Ctrl+click"));
        javax.swing.JTextArea area = new javax.swing.JTextArea(text.toString());
        area.setEditable(false);
        area.setFont(new java.awt.Font(java.awt.Font.MONOSPACED, java.awt.Font.PLAIN, 12));
        JOptionPane.showMessageDialog(frame, area, "Keyboard shortcuts", JOptionPane.PLAIN_MESSAGE);
    }

    static String keyText(KeyStroke key) {
        String mods = InputEvent.getModifiersExText(key.getModifiers());
        String k = KeyEvent.getKeyText(key.getKeyCode());
        return mods.isEmpty() ? k : mods + "+" + k;
    }

    /** The actions with their keys, in menu order, for the documentation and its test. */
    List<String[]> shortcuts() {
        List<String[]> out = new ArrayList<>();
        for (Action a : actions.values()) {
            KeyStroke key = (KeyStroke) a.getValue(Action.ACCELERATOR_KEY);
            if (key != null) out.add(new String[] {(String) a.getValue(Action.NAME), keyText(key)});
        }
        return out;
    }

    /** Accepts dropped files (opening the .crt ones) and passes everything else to the component's own handler. */
    private static final class FileDropHandler extends TransferHandler {
        private final TransferHandler delegate;
        private final java.util.function.Consumer<List<Path>> open;

        FileDropHandler(TransferHandler delegate, java.util.function.Consumer<List<Path>> open) {
            this.delegate = delegate;
            this.open = open;
        }

        @Override
        public boolean canImport(TransferSupport s) {
            if (s.isDataFlavorSupported(DataFlavor.javaFileListFlavor)) return true;
            return delegate != null && delegate.canImport(s);
        }

        @Override
        public boolean importData(TransferSupport s) {
            if (s.isDataFlavorSupported(DataFlavor.javaFileListFlavor)) {
                try {
                    List<?> files = (List<?>) s.getTransferable().getTransferData(DataFlavor.javaFileListFlavor);
                    List<Path> paths = new ArrayList<>();
                    for (Object f : files) paths.add(((java.io.File) f).toPath());
                    SwingUtilities.invokeLater(() -> open.accept(paths));
                    return true;
                } catch (java.awt.datatransfer.UnsupportedFlavorException | IOException e) {
                    return false;
                }
            }
            return delegate != null && delegate.importData(s);
        }

        @Override
        public int getSourceActions(JComponent c) { return delegate == null ? NONE : delegate.getSourceActions(c); }

        @Override
        public void exportAsDrag(JComponent comp, java.awt.event.InputEvent e, int action) {
            if (delegate != null) delegate.exportAsDrag(comp, e, action);
        }

        @Override
        public void exportToClipboard(JComponent comp, java.awt.datatransfer.Clipboard clip, int action) {
            if (delegate != null) delegate.exportToClipboard(comp, clip, action);
        }
    }
}
