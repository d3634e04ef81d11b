package dev.crt.studio;

import dev.crt.lang.CompileResult;
import dev.crt.lang.parser.CRTLexer;
import dev.crt.live.FreeCamera;
import dev.crt.live.GlUnavailableException;
import dev.crt.live.LiveViewPanel;
import dev.crt.scene.Camera;
import dev.crt.scene.Entity;
import dev.crt.scene.Scene;
import dev.crt.scene.SourceSpan;
import java.awt.BorderLayout;
import java.awt.event.ActionEvent;
import java.awt.event.HierarchyEvent;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.function.Function;
import javax.swing.AbstractAction;
import javax.swing.Action;
import javax.swing.JButton;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JToolBar;
import javax.swing.SwingConstants;
import javax.swing.SwingUtilities;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.Token;
import org.fife.ui.rsyntaxtextarea.RSyntaxTextArea;

/**
 * The studio's "Live view" panel: the OpenGL view of {@code dev.crt.live} showing the current
 * script's scene after every background compile without errors, its selection shared with the
 * render view and the code through {@link StudioModel}, and "Copy camera to script". OpenGL
 * starts off the Event Dispatch Thread when the panel is first shown (start-up does not wait for
 * it); where it cannot start, the panel says why in one sentence and the rest of the studio works.
 * At the Animation panel's time t other than 0 it shows the script compiled at t ({@link SceneAtTime}).
 */
final class LiveDock extends JPanel implements StudioModel.Listener {
    private static final long serialVersionUID = 1L;

    /** Where the panel is in its life. */
    enum State { NOT_STARTED, STARTING, READY, UNAVAILABLE, CLOSED }

    private final transient StudioModel model;
    private final transient Function<ScriptDocument, ScriptEditor> editors;
    private final transient ConsolePanel console;
    private final transient Callable<LiveViewPanel> opener;
    private final JLabel message = new JLabel("The live view starts when this panel is shown.", SwingConstants.CENTER);
    private final JLabel status = new JLabel(" ");
    private final transient ExecutorService timing = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "crt-studio-live-timing");
        t.setDaemon(true);
        return t;
    });
    private transient LiveViewPanel view;
    private final Action copyCamera = action("Copy camera to script", this::copyCameraToScript);
    private final Action quad = action("1 | 4 views", () -> view.setLayout(!view.isQuad(), view.singleViewport()));
    private final Action frameAll = action("Frame all", () -> view.frame(false));
    private final Action preview = action("Preview", () -> view.rayTracePreview());
    private transient State state = State.NOT_STARTED;
    /** The document whose scene the view shows, and that scene (kept until the view exists). */
    private transient ScriptDocument shown;
    private transient Scene scene;
    private volatile long followNanos = -1;
    private volatile long firstFrameNanos = -1;
    /** Compiles the shown script at the studio's time t when t is not 0 (the background compile's time). */
    private final transient SceneAtTime atTime = new SceneAtTime(this::compiledAt);

    LiveDock(StudioModel model, Function<ScriptDocument, ScriptEditor> editors, ConsolePanel console) {
        this(model, editors, console, LiveViewPanel::open);
    }

    LiveDock(StudioModel model, Function<ScriptDocument, ScriptEditor> editors, ConsolePanel console,
            Callable<LiveViewPanel> opener) {
        super(new BorderLayout());
        this.model = model;
        this.editors = editors;
        this.console = console;
        this.opener = opener;
        setName("liveDock");
        getAccessibleContext().setAccessibleName("Live view");
        JToolBar bar = new JToolBar();
        bar.setFloatable(false);
        for (Action a : new Action[] {copyCamera, quad, frameAll, preview}) {
            JButton b = new JButton(a);
            b.setFocusable(false);
            b.setName(((String) a.getValue(Action.NAME)).replace(' ', '-'));
            bar.add(b);
            a.setEnabled(false);
        }
        bar.addSeparator();
        status.setName("liveStatus");
        bar.add(status);
        add(bar, BorderLayout.NORTH);
        message.setName("liveMessage");
        add(message, BorderLayout.CENTER);
        model.addListener(this);
        addHierarchyListener(e -> {
            if ((e.getChangeFlags() & HierarchyEvent.SHOWING_CHANGED) != 0 && isShowing() && state == State.NOT_STARTED) start();
        });
    }

    private static Action action(String name, Runnable body) {
        return new AbstractAction(name) {
            @Override public void actionPerformed(ActionEvent e) { body.run(); }
        };
    }

    State state() { return state; }

    /** The one sentence shown in place of the view (why there is none, or that it is starting). */
    String message() { return message.getText(); }

    /** The OpenGL view, or null while it is not running. */
    LiveViewPanel view() { return view; }

    Action copyCameraAction() { return copyCamera; }

    /** From a compile's result reaching the studio to the view's full-size frame of it being drawn, or −1. */
    long lastFollowNanos() { return followNanos; }

    /** From a compile's result reaching the studio to the view's first frame of it (the coarse one) being drawn, or −1. */
    long lastFirstFrameNanos() { return firstFrameNanos; }

    /** Opens OpenGL on a thread of its own; the view appears when it is ready. */
    void start() {
        if (state != State.NOT_STARTED) return;
        state = State.STARTING;
        message.setText("Starting OpenGL…");
        Thread t = new Thread(() -> {
            LiveViewPanel opened;
            try {
                opened = opener.call();
            } catch (GlUnavailableException e) {
                SwingUtilities.invokeLater(() -> unavailable(e.getMessage()));
                return;
            } catch (Exception | LinkageError e) {
                SwingUtilities.invokeLater(() -> unavailable("OpenGL is not available: " + e));
                return;
            }
            SwingUtilities.invokeLater(() -> installed(opened));
        }, "crt-studio-live-open");
        t.setDaemon(true);
        t.start();
    }

    private void unavailable(String why) {
        if (state == State.CLOSED) return;
        state = State.UNAVAILABLE;
        message.setText(why);
        message.setToolTipText(why);
        console.log(ConsolePanel.Kind.WARNING, "live view off: " + why);
    }

    private void installed(LiveViewPanel v) {
        if (state == State.CLOSED) {
            v.close();
            return;
        }
        view = v;
        state = State.READY;
        v.getAccessibleContext().setAccessibleName("Live view (OpenGL)");
        v.addSelectionListener(this::picked);
        remove(message);
        add(v, BorderLayout.CENTER);
        revalidate();
        for (Action a : new Action[] {copyCamera, quad, frameAll, preview}) a.setEnabled(true);
        ScriptDocument d = model.current();
        if (d != null && d.result() != null && d.result().scene() != null) follow(d, d.result().scene(), System.nanoTime());
        else if (scene != null) show(shown, scene, System.nanoTime());
    }

    // ---------------------------------------------------------------- following the model

    @Override
    public void compiled(ScriptDocument d, CompileResult result) {
        long at = System.nanoTime();
        if (d != model.current()) return;
        // A script with errors has no scene: the view keeps the last one that compiled.
        if (result.scene() == null) {
            status.setText("showing the last version without errors");
            return;
        }
        follow(d, result.scene(), at);
    }

    @Override
    public void currentChanged(ScriptDocument d) {
        if (d == null || d == shown) return;
        CompileResult r = d.result();
        if (r != null && r.scene() != null) follow(d, r.scene(), System.nanoTime());
    }

    @Override
    public void timeChanged(double t) {
        ScriptDocument d = model.current();
        CompileResult r = d == null ? null : d.result();
        if (r != null && r.scene() != null) follow(d, r.scene(), System.nanoTime());
    }

    /**
     * Shows {@code d}'s scene at the studio's time: the background compile's {@code atZero} at
     * t = 0, else the script compiled at t (at once when that compile is at hand, else when it is
     * done; the view keeps its frame meanwhile).
     */
    private void follow(ScriptDocument d, Scene atZero, long since) {
        double t = model.time();
        if (t == 0) {
            atTime.forget();
            show(d, atZero, since);
            return;
        }
        Scene ready = atTime.request(d, d.version(), d.source(), t, since);
        if (ready != null) show(d, ready, since);
    }

    /** A compile at t finished (on the Event Dispatch Thread): shown if it is still what the studio looks at. */
    private void compiledAt(ScriptDocument d, long version, double t, CompileResult result, long since) {
        if (state == State.CLOSED || d != model.current() || d.version() != version || model.time() != t) return;
        if (result.scene() == null) {
            status.setText("t = " + fmt(t) + ": the script has errors there; showing the last scene without errors");
            return;
        }
        show(d, result.scene(), since);
    }

    private static String fmt(double t) {
        return t == Math.rint(t) ? Long.toString((long) t) : Double.toString(t);
    }

    @Override
    public void closed(ScriptDocument d) {
        if (d == shown) shown = null;
    }

    @Override
    public void selected(ScriptDocument d, Entity entity, int index) {
        if (view != null && d == shown && view.selected() != index) view.select(index);
    }

    private void show(ScriptDocument d, Scene next, long since) {
        boolean otherDocument = shown != d;
        shown = d;
        scene = next;
        if (view == null) return;
        // Camera and selection first: setScene draws at once, with them.
        // Another script brings its own camera; a recompile of the same one keeps the view's.
        if (otherDocument) view.setFreeCamera(FreeCamera.of(next.settings().camera()));
        view.select(model.selectedDocument() == d ? model.selectedIndex() : -1);
        view.setScene(next);
        double t = model.time();
        status.setText(next.entities().size() + " entities" + (t == 0 ? "" : " at t = " + fmt(t)));
        if (!view.isShowing()) return;
        LiveViewPanel v = view;
        timing.submit(() -> {
            try {
                v.awaitIdle();
                followNanos = System.nanoTime() - since;
                long first = v.firstFrameNanos();
                firstFrameNanos = first > 0 ? first - since : -1;
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            } catch (java.util.concurrent.ExecutionException e) {
                // The view is closing; there is no figure to keep.
            }
        });
    }

    /** A click in the view: select the entity for every panel and show the code that made it. */
    private void picked(int index, Entity entity) {
        ScriptDocument d = shown;
        if (d == null) return;
        model.select(d, entity, index);
        status.setText(entity == null ? "nothing selected"
                : entity.getClass().getSimpleName() + " written at line " + entity.span().line());
        ScriptEditor editor = editors.apply(d);
        if (entity == null || editor == null || !writtenIn(entity.span(), d)) return;
        model.setCurrent(d);
        editor.showCode(entity.span().start(), entity.span().end());
    }

    private static boolean writtenIn(SourceSpan span, ScriptDocument d) {
        return span.line() > 0 && span.file().equals(d.source().name());
    }

    // ---------------------------------------------------------------- camera round trip

    /**
     * Replaces the script's Camera block by the free camera's, as one edit that one undo takes
     * back; says in the status why not when the script has no Camera block of its own.
     */
    void copyCameraToScript() {
        ScriptDocument d = shown;
        ScriptEditor editor = d == null ? null : editors.apply(d);
        if (view == null || editor == null) return;
        if (!d.resultIsCurrent() || d.result().scene() == null) {
            say("the script has changed or has errors: copy the camera once it compiles");
            return;
        }
        Camera camera = d.result().scene().settings().camera();
        int[] range = writtenIn(camera.span(), d) ? blockRange(d.content(), camera.span().start()) : null;
        if (range == null) {
            say("the script has no Camera block to replace: write camera -> Camera { position -> vec3(0, 0, -5) } in its Settings first");
            return;
        }
        String block = view.cameraBlock();
        RSyntaxTextArea area = editor.area();
        area.beginAtomicEdit();
        try {
            area.replaceRange(block, range[0], range[1]);
        } finally {
            area.endAtomicEdit();
        }
        editor.showCode(range[0], range[0] + block.length());
        say("camera copied to " + d.name() + " (Ctrl+Z takes it back)");
    }

    private void say(String text) {
        status.setText(text);
        console.log(ConsolePanel.Kind.INFO, text);
    }

    /**
     * The extent [start, end) of the object literal whose type name starts at {@code at}
     * ({@code Camera { … }}, braces matched by CRT's own lexer, so braces in strings and comments
     * do not count), or null when there is none.
     */
    static int[] blockRange(String text, int at) {
        if (at < 0 || at >= text.length()) return null;
        CRTLexer lexer = new CRTLexer(CharStreams.fromString(text.substring(at)));
        lexer.removeErrorListeners();
        int depth = 0;
        boolean first = true;
        for (Token t = lexer.nextToken(); t.getType() != Token.EOF; t = lexer.nextToken()) {
            if (t.getChannel() != Token.DEFAULT_CHANNEL) continue;
            if (first) {
                first = false;
                continue;
            }
            String s = t.getText();
            if (depth == 0 && !s.equals("{")) return null;
            if (s.equals("{")) depth++;
            else if (s.equals("}") && --depth == 0) return new int[] {at, at + t.getStopIndex() + 1};
        }
        return null;
    }

    /** Frees the GL context; a view still starting is closed when it arrives. */
    void close() {
        state = State.CLOSED;
        model.removeListener(this);
        timing.shutdownNow();
        atTime.close();
        if (view != null) {
            view.close();
            view = null;
        }
    }
}
