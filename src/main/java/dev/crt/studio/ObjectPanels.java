package dev.crt.studio;

import dev.crt.geom.Vec3;
import dev.crt.lang.CompileResult;
import dev.crt.lang.SourceMap;
import dev.crt.lang.SourceMap.Expr;
import dev.crt.lang.SourceMap.MacroCall;
import dev.crt.lang.SourceMap.ObjectInfo;
import dev.crt.scene.Entity;
import dev.crt.studio.SceneOutline.Node;
import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import javax.swing.JMenu;
import javax.swing.JMenuItem;
import javax.swing.SwingUtilities;
import org.fife.ui.rsyntaxtextarea.RSyntaxTextArea;

/**
 * The scene as objects: ties the Navigator and Properties panels to the editor, the compiler and
 * the render view, and owns the Insert menu. Selecting a node puts the caret on its code and
 * outlines the object in the last render; moving the caret into an object selects its node; a
 * property edit or an insertion is one undoable edit of the script, checked to compile first.
 * Used on the Event Dispatch Thread only.
 */
final class ObjectPanels implements StudioModel.Listener {
    /** The colour of the outline and tint of the selected object in the render view. */
    private static final int HIGHLIGHT = 0xFFFF8C00;

    private final StudioWindow window;
    private final NavigatorPanel navigator = new NavigatorPanel();
    private final PropertiesPanel properties = new PropertiesPanel();
    /** The Insert menu's items, in its order; the palette shows the same. */
    private static final List<String> ITEMS = List.of("Sphere", "Box", "Plane", "Cylinder", "Point light", "Parallel light",
            "Spot light", "Camera");
    private final PalettePanel palette = new PalettePanel(ITEMS, this::insertItem);
    private Node outline;
    private SourceMap map;
    private boolean ownCaret;
    private boolean ownSelection;
    private RenderJob.Result idsOf;
    private int[] ids;
    private int highlighted = -1;

    ObjectPanels(StudioWindow window) {
        this.window = window;
        window.model().addListener(this);
        navigator.onSelect(this::chosen);
        // The dock honours minimum sizes: without one, the render view's long toolbar squeezes these to a sliver.
        navigator.setMinimumSize(new java.awt.Dimension(240, 120));
        properties.setMinimumSize(new java.awt.Dimension(240, 120));
        properties.writer(new PropertiesPanel.Writer() {
            @Override public String write(ObjectInfo object, MacroCall call, String attribute, String literal) {
                return ObjectPanels.this.write(object, call, attribute, literal);
            }

            @Override public String replace(Expr literalExpr, String literal, String what) {
                return ObjectPanels.this.write(new ScriptEdits.Edit(literalExpr.start(), literalExpr.end(), literal, what));
            }
        });
    }

    NavigatorPanel navigator() { return navigator; }

    PropertiesPanel properties() { return properties; }

    PalettePanel palette() { return palette; }

    List<StudioPanel> panels() {
        // The palette stacks behind Properties (a tab of the same place).
        return List.of(new StudioPanel("navigator", "Navigator", navigator, 0, 0, 0.24, 0.35),
                new StudioPanel("properties", "Properties", properties, 0, 0.35, 0.24, 0.4),
                new StudioPanel("palette", "Palette", palette, 0, 0.35, 0.24, 0.4));
    }

    /** The editor's transfer handler: palette items dropped on it are inserted there, the rest goes to {@code delegate}. */
    javax.swing.TransferHandler paletteDrop(RSyntaxTextArea area, javax.swing.TransferHandler delegate) {
        return PalettePanel.dropInto(area, delegate, this::insertItem);
    }

    // ---------------------------------------------------------------- following the model

    @Override
    public void opened(ScriptDocument d) {
        ScriptEditor editor = window.editor(d);
        if (editor != null) editor.area().addCaretListener(e -> caretMoved(d, e.getDot(), true));
    }

    @Override
    public void currentChanged(ScriptDocument d) {
        show(d == null ? null : d.result(), d);
    }

    @Override
    public void closed(ScriptDocument d) {
        if (window.model().current() == null) show(null, null);
    }

    @Override
    public void compiled(ScriptDocument d, CompileResult result) {
        if (d != window.model().current() || result.scene() == null || result.sourceMap() == null) return;
        show(result, d);
        ScriptEditor editor = window.editor(d);
        if (editor != null) caretMoved(d, editor.area().getCaretPosition(), false);
    }

    private void show(CompileResult result, ScriptDocument d) {
        Node fresh = d == null || result == null || !d.resultIsCurrent() ? null : SceneOutline.of(result, d.content());
        outline = fresh;
        map = fresh == null ? null : result.sourceMap();
        navigator.show(outline);
        Node selected = navigator.selected();
        properties.show(selected, map);
        highlight(selected == null ? -1 : selected.entityIndex());
    }

    @Override
    public void selected(ScriptDocument d, Entity entity, int index) {
        if (ownSelection) return;
        Node n = entity == null ? null : SceneOutline.ofEntity(outline, index);
        if (n == null) navigator.select("");
        else navigator.select(n.key());
        properties.show(n, map);
        highlight(index);
    }

    /** The user chose a node in the tree. */
    private void chosen(Node n) {
        ScriptDocument d = window.model().current();
        ScriptEditor editor = d == null ? null : window.editor(d);
        if (editor != null && n.span() != null && n.span().line() > 0) {
            ownCaret = true;
            try {
                editor.goTo(n.span().start());
            } finally {
                ownCaret = false;
            }
        }
        properties.say(null, false);
        properties.show(n, map);
        select(d, n);
    }

    /**
     * Selects the node of the object the caret is in. After a compile ({@code moved} false) a
     * selected node that still holds the caret stays, so a CSG operation stays selected rather than
     * its first operand; a caret the user moved selects the innermost object, unless it sits at the
     * start of the selected node (where selecting that node put it).
     */
    private void caretMoved(ScriptDocument d, int caret, boolean moved) {
        if (ownCaret || d != window.model().current() || !d.resultIsCurrent() || outline == null) return;
        Node now = navigator.selected();
        Node n = SceneOutline.at(outline, caret);
        if (now != null && now.contains(caret) && (!moved || caret == now.span().start() || n == null || n.key().equals(now.key()))) return;
        if (n == null) return;
        navigator.select(n.key());
        properties.show(n, map);
        select(d, n);
    }

    /** Tells the other panels (and the render view's outline) which entity is selected. */
    private void select(ScriptDocument d, Node n) {
        ownSelection = true;
        try {
            int index = n.entityIndex();
            Entity e = null;
            if (index >= 0 && d != null && d.result() != null && d.result().scene() != null) e = d.result().scene().entities().get(index);
            window.model().select(d, e, e == null ? -1 : index);
        } finally {
            ownSelection = false;
        }
        highlight(n.entityIndex());
    }

    // ---------------------------------------------------------------- the render view's outline

    /** A render finished: the outline of the selection is drawn again on its picture. */
    void rendered(RenderJob.Result r) {
        ids = null;
        idsOf = null;
        highlight(highlighted);
    }

    private void highlight(int index) {
        highlighted = index;
        RenderJob.Result r = window.lastRender();
        if (index < 0 || r == null || !sameEntity(r, index)) {
            window.renderView().showOverlay(null);
            return;
        }
        if (idsOf != r) {
            idsOf = r;
            ids = null;
            // The id pass traces one primary ray per pixel: off the Event Dispatch Thread.
            Thread t = new Thread(() -> {
                int[] pass = r.renderer().idPass();
                SwingUtilities.invokeLater(() -> {
                    if (idsOf != r) return;
                    ids = pass;
                    highlight(highlighted);
                });
            }, "crt-studio-id-pass");
            t.setDaemon(true);
            t.start();
            return;
        }
        if (ids == null) return;
        window.renderView().showOverlay(overlay(ids, r.scene().settings().width(), r.scene().settings().height(), index));
    }

    /** True when the last render's entity {@code index} is the one the current compile calls so (same code). */
    private boolean sameEntity(RenderJob.Result r, int index) {
        Node n = SceneOutline.ofEntity(outline, index);
        return n != null && index < r.scene().entities().size() && r.scene().entities().get(index).span().equals(n.span());
    }

    /** A see-through tint over the entity's pixels and an opaque line along its silhouette. */
    static BufferedImage overlay(int[] ids, int width, int height, int index) {
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_ARGB);
        int tint = (0x50 << 24) | (HIGHLIGHT & 0xFFFFFF);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                int i = y * width + x;
                if (ids[i] != index) continue;
                boolean edge = x == 0 || y == 0 || x == width - 1 || y == height - 1 || ids[i - 1] != index || ids[i + 1] != index
                        || ids[i - width] != index || ids[i + width] != index;
                image.setRGB(x, y, edge ? HIGHLIGHT : tint);
            }
        }
        return image;
    }

    // ---------------------------------------------------------------- writing the script

    /** Writes a property edit into the script as one undoable edit; null when done, else why not. */
    private String write(ObjectInfo object, MacroCall call, String attribute, String literal) {
        ScriptDocument d = window.model().current();
        if (d == null || map == null || !d.resultIsCurrent()) {
            return refuse("the script changed since its last compile: try again when it has compiled");
        }
        try {
            return write(ScriptEdits.setAttribute(d.content(), map, object, call, attribute, literal));
        } catch (ScriptEdits.Refused r) {
            return refuse(r.getMessage());
        }
    }

    /** Makes {@code edit} when the compile it refers to is of the text as it is and the edit keeps it compiling. */
    private String write(ScriptEdits.Edit edit) {
        ScriptDocument d = window.model().current();
        if (d == null || map == null || !d.resultIsCurrent()) {
            return refuse("the script changed since its last compile: try again when it has compiled");
        }
        String script = d.content();
        String broken = ScriptEdits.breaks(d.source().name(), d.result().errorCount(), edit.applyTo(script));
        if (broken != null) return refuse("not changed: " + broken);
        apply(d, edit);
        properties.say(edit.what(), false);
        window.console().log(ConsolePanel.Kind.INFO, "property: " + edit.what());
        return null;
    }

    private String refuse(String why) {
        window.console().log(ConsolePanel.Kind.WARNING, "property not changed: " + why);
        return why;
    }

    /** One undoable edit, then a compile at once (not after the typing pause). */
    private void apply(ScriptDocument d, ScriptEdits.Edit edit) {
        RSyntaxTextArea area = window.editor(d).area();
        ownCaret = true;
        area.beginAtomicEdit();
        try {
            area.replaceRange(edit.text(), edit.start(), edit.end());
        } finally {
            area.endAtomicEdit();
            ownCaret = false;
        }
        window.compiler().start(d);
    }

    // ---------------------------------------------------------------- Insert menu

    JMenu insertMenu() {
        JMenu menu = new JMenu("Insert");
        menu.setMnemonic(KeyEvent.VK_I);
        menu.setName("insertMenu");
        int[] mnemonics = {KeyEvent.VK_S, KeyEvent.VK_B, KeyEvent.VK_P, KeyEvent.VK_Y, KeyEvent.VK_L, KeyEvent.VK_R, KeyEvent.VK_T,
            KeyEvent.VK_C};
        for (int i = 0; i < ITEMS.size(); i++) {
            if (i == 4 || i == 7) menu.addSeparator();
            String name = ITEMS.get(i);
            item(menu, name, mnemonics[i], () -> insertItem(name, -1));
        }
        return menu;
    }

    /** Inserts the Insert menu's (or the palette's) item {@code name} after the statement at offset {@code at} (−1: the caret). */
    void insertItem(String name, int at) {
        switch (name) {
            case "Sphere", "Box", "Plane", "Cylinder" -> insertEntity(name, at);
            case "Point light" -> insertLight("PointLight { origin -> vec3(2, 4, -3) color -> rgb(1, 1, 1) }");
            case "Parallel light" -> insertLight("ParallelLight { from -> vec3(-1, 2, -1) pointing -> vec3(0, 0, 0) color -> rgb(1, 1, 1) }");
            case "Spot light" -> insertLight("SpotLight { origin -> vec3(0, 4, -2) pointing -> vec3(0, 0, 0) angle -> 30 color -> rgb(1, 1, 1) }");
            case "Camera" -> insert(List.of("Settings { camera -> Camera { position -> vec3(0, 1, -6) pointing -> vec3(0, 0, 0) fov -> 60 } }"),
                    "a camera", at);
            default -> throw new IllegalArgumentException("no such item: " + name);
        }
    }

    private static void item(JMenu menu, String label, int mnemonic, Runnable action) {
        JMenuItem item = new JMenuItem(label);
        item.setMnemonic(mnemonic);
        item.setName("insert" + label.replace(" ", ""));
        item.addActionListener(e -> action.run());
        menu.add(item);
    }

    /** The new entity where the camera looks, so that it shows in the next render. */
    private void insertEntity(String type, int at) {
        ScriptDocument d = window.model().current();
        Vec3 p = d != null && d.result() != null && d.result().scene() != null ? d.result().scene().settings().camera().pointing() : Vec3.ZERO;
        String literal = switch (type) {
            case "Sphere" -> "Sphere { center -> " + ScriptEdits.vec3(p.x(), p.y(), p.z())
                    + " radius -> 1 material -> Material { color -> rgb(0.8, 0.3, 0.2) } }";
            case "Box" -> "Box { cornerA -> " + ScriptEdits.vec3(p.x() - 0.5, p.y() - 0.5, p.z() - 0.5) + " cornerB -> "
                    + ScriptEdits.vec3(p.x() + 0.5, p.y() + 0.5, p.z() + 0.5) + " material -> Material { color -> rgb(0.3, 0.6, 0.9) } }";
            case "Plane" -> "Plane { normal -> vec3(0, 1, 0) position -> " + ScriptEdits.vec3(p.x(), p.y() - 1, p.z()) + " }";
            default -> "Cylinder { from -> " + ScriptEdits.vec3(p.x(), p.y() - 0.5, p.z()) + " to -> "
                    + ScriptEdits.vec3(p.x(), p.y() + 0.5, p.z()) + " radius -> 0.5 }";
        };
        insert(List.of(literal, "Scene { " + literal + " }"), "a " + type, at);
    }

    /** A light goes into the list of the Settings block that writes the lights, else into a new Settings block. */
    private void insertLight(String literal) {
        ScriptDocument d = window.model().current();
        if (d == null) return;
        Expr lights = null;
        if (map != null && d.resultIsCurrent()) {
            for (ObjectInfo block : map.settings()) if (block.attributes().containsKey("lights")) lights = block.attributes().get("lights");
        }
        if (lights == null) {
            insert(List.of("Settings { lights -> [" + literal + "] }"), "a light", -1);
            return;
        }
        String script = d.content();
        String written = script.substring(lights.start(), lights.end());
        if (!written.startsWith("[") || !written.endsWith("]")) {
            properties.say(refuse("the lights are written as " + lights.text() + ", not as a list: add the light there"), true);
            return;
        }
        boolean empty = written.substring(1, written.length() - 1).isBlank();
        ScriptEdits.Edit edit = new ScriptEdits.Edit(lights.end() - 1, lights.end() - 1, (empty ? "" : ", ") + literal, "a light");
        String broken = ScriptEdits.breaks(d.source().name(), d.result().errorCount(), edit.applyTo(script));
        if (broken != null) {
            properties.say(refuse("no light inserted: " + broken), true);
            return;
        }
        apply(d, edit);
        properties.say("inserted a light into the lights of line " + ScriptEdits.lineOf(script, lights.start()), false);
    }

    /**
     * Inserts the first of {@code forms} that keeps the script compiling, on a new line after the
     * statement at offset {@code offset} (−1: the caret; after the object it is in), or else at the
     * end of the script.
     */
    private void insert(List<String> forms, String what, int offset) {
        ScriptDocument d = window.model().current();
        ScriptEditor editor = d == null ? null : window.editor(d);
        if (editor == null) return;
        String script = d.content();
        int at = statementEnd(script, offset >= 0 ? offset : editor.area().getCaretPosition(), d.resultIsCurrent() ? map : null);
        String indent = indentOfLine(script, at);
        List<ScriptEdits.Edit> tries = new ArrayList<>();
        for (String form : forms) tries.add(new ScriptEdits.Edit(at, at, "\n" + indent + form, what));
        String tail = script.endsWith("\n") || script.isEmpty() ? "" : "\n";
        for (String form : forms) tries.add(new ScriptEdits.Edit(script.length(), script.length(), tail + form + "\n", what));
        String problem = null;
        long errorsBefore = d.resultIsCurrent() ? d.result().errorCount() : ScriptEdits.errors(d.source().name(), script);
        for (ScriptEdits.Edit edit : tries) {
            problem = ScriptEdits.breaks(d.source().name(), errorsBefore, edit.applyTo(script));
            if (problem != null) continue;
            apply(d, edit);
            int start = edit.start() + edit.text().indexOf(edit.text().strip());
            editor.goTo(start);
            properties.say("inserted " + what + " at line " + ScriptEdits.lineOf(edit.applyTo(script), start), false);
            window.console().log(ConsolePanel.Kind.INFO, "inserted " + what + " at line " + ScriptEdits.lineOf(edit.applyTo(script), start));
            return;
        }
        properties.say(refuse("nothing inserted: " + problem), true);
    }

    /** The end of the line of {@code caret}, moved past any object literal or Settings block the caret is inside. */
    static int statementEnd(String script, int caret, SourceMap map) {
        int at = Math.min(caret, script.length());
        if (map != null) {
            List<ObjectInfo> all = new ArrayList<>(map.objects().values());
            all.addAll(map.settings());
            for (boolean moved = true; moved; ) {
                moved = false;
                for (ObjectInfo o : all) {
                    if (o.span().start() < at && at < o.span().end()) {
                        at = o.span().end();
                        moved = true;
                    }
                }
            }
        }
        int eol = script.indexOf('\n', at);
        return eol < 0 ? script.length() : eol;
    }

    private static String indentOfLine(String script, int offset) {
        int start = script.lastIndexOf('\n', Math.max(0, offset - 1)) + 1;
        int i = start;
        while (i < script.length() && (script.charAt(i) == ' ' || script.charAt(i) == '\t')) i++;
        return script.substring(start, i);
    }
}
