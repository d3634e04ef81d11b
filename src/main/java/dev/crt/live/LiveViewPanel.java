package dev.crt.live;

import dev.crt.geom.Aabb;
import dev.crt.geom.Vec3;
import dev.crt.scene.Camera;
import dev.crt.scene.Entity;
import dev.crt.scene.Scene;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.RenderingHints;
import java.awt.event.KeyAdapter;
import java.awt.event.KeyEvent;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.MouseWheelEvent;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.awt.image.VolatileImage;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicBoolean;
import javax.swing.JPanel;
import javax.swing.SwingUtilities;

/**
 * The live view as a plain Swing panel: an OpenGL thread draws the scene offscreen and the panel
 * shows the read-back image, so it can be docked, undocked and re-parented freely. One viewport
 * or four (top, front, side, free); mouse and keys move the camera of the viewport under the
 * mouse; a click selects the entity under it, the mouse hovering highlights one.
 *
 * <p>Controls: left drag orbits (free view) or pans (orthographic views); right or middle drag
 * pans; Ctrl + left drag rolls; the wheel zooms. Keys: arrows orbit, Shift + arrows pan, + and −
 * zoom, Z and X roll, F frames the selection, A frames all, 1–5 show the free, scene camera, top,
 * front and side view, V switches between one and four viewports, P ray-traces the free view at
 * half resolution into it (until the camera or the scene changes), Escape clears the selection.
 */
public final class LiveViewPanel extends JPanel implements AutoCloseable {
    private static final long serialVersionUID = 1L;

    /** Told when the user selects an entity in the view (index in the scene's entities), or −1 and null when none. */
    public interface SelectionListener {
        void selected(int entityIndex, Entity entity);
    }

    private final transient ExecutorService glThread;
    private final transient GlContext context;
    private final transient LiveRenderer renderer;
    private final transient List<SelectionListener> listeners = new CopyOnWriteArrayList<>();
    private final AtomicBoolean framePending = new AtomicBoolean();

    // View state: read and written on the event dispatch thread, copied into each frame request.
    private transient Scene scene;
    private transient GpuScene gpu;
    private transient FreeCamera free = FreeCamera.of(Camera.DEFAULT);
    private final transient Map<Viewport, OrthoCamera> ortho = new EnumMap<>(Viewport.class);
    private Viewport single = Viewport.FREE;
    private boolean quad;
    private int selected = -1, hovered = -1;
    private transient String problem;

    // The last frame: written by the GL thread, shown by the event dispatch thread.
    private transient volatile Frame frame;
    private volatile long lastUpdateNanos;

    /** The ray-traced preview of the free view, for the camera and scene it was made with. */
    private record Traced(BufferedImage image, FreeCamera camera, Scene scene) {}

    private transient volatile Traced traced;
    private final transient ExecutorService tracer = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "crt-live-view-preview");
        t.setDaemon(true);
        return t;
    });
    private final transient java.util.concurrent.atomic.AtomicLong traceGeneration = new java.util.concurrent.atomic.AtomicLong();

    /** The frame's picture where the screen is, and the frame it holds; used on the event dispatch thread. */
    private transient VolatileImage onScreen;
    private transient Frame onScreenFrame;

    private transient Point pressed;
    private transient Viewport dragged;
    private boolean moved;

    /**
     * What one frame drew: the image (at 1/{@code scale} of the panel's size) and where each
     * viewport lies in the panel.
     */
    private record Frame(BufferedImage image, int scale, Map<Viewport, Rectangle> viewports, Map<Viewport, ViewCamera> views) {}

    /**
     * A new scene is first drawn at half the panel's width and height (a quarter of the pixels, so
     * about a quarter of llvmpipe's time), shown scaled up, and then at full size: the view answers
     * a compile sooner and sharpens a moment later. Camera moves are drawn at full size only.
     */
    static final int COARSE_MIN_PIXELS = 320 * 240;
    /** Set by {@link #setScene} until the next frame request takes it: that frame is drawn coarse first. */
    private boolean coarseNext;
    /** Counts the scenes set; the GL thread notes when the first frame of the newest was shown. */
    private volatile long sceneGeneration;
    private volatile long shownGeneration;
    private volatile long firstFrameNanos;

    private LiveViewPanel(ExecutorService glThread, GlContext context, LiveRenderer renderer) {
        this.glThread = glThread;
        this.context = context;
        this.renderer = renderer;
        setPreferredSize(new Dimension(640, 480));
        setFocusable(true);
        setBackground(Color.DARK_GRAY);
        for (Viewport v : Viewport.values()) if (v.isOrthographic()) ortho.put(v, OrthoCamera.framing(Aabb.EMPTY));
        Mouse mouse = new Mouse();
        addMouseListener(mouse);
        addMouseMotionListener(mouse);
        addMouseWheelListener(mouse);
        addKeyListener(new Keys());
        addComponentListener(new java.awt.event.ComponentAdapter() {
            @Override
            public void componentResized(java.awt.event.ComponentEvent e) {
                requestFrame();
            }
        });
    }

    /**
     * Makes the OpenGL context on a thread of the view's own and the panel; fails with one
     * sentence when OpenGL is not available, so the caller can go on without a live view.
     */
    public static LiveViewPanel open() throws GlUnavailableException {
        ExecutorService thread = Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "crt-live-view-gl");
            t.setDaemon(true);
            return t;
        });
        try {
            Object[] made = thread.submit(() -> {
                GlContext c = GlContext.create();
                return new Object[] {c, new LiveRenderer()};
            }).get();
            return new LiveViewPanel(thread, (GlContext) made[0], (LiveRenderer) made[1]);
        } catch (ExecutionException e) {
            thread.shutdownNow();
            if (e.getCause() instanceof GlUnavailableException g) throw g;
            throw new GlUnavailableException("OpenGL is not available: " + e.getCause().getMessage(), e.getCause());
        } catch (InterruptedException e) {
            thread.shutdownNow();
            Thread.currentThread().interrupt();
            throw new GlUnavailableException("OpenGL is not available: interrupted while starting");
        }
    }

    public void addSelectionListener(SelectionListener l) { listeners.add(l); }

    private final transient List<java.util.function.Consumer<BufferedImage>> frameListeners = new CopyOnWriteArrayList<>();

    /** Told, on the GL thread, of every frame's picture as it is drawn (coarse ones too). */
    void addFrameListener(java.util.function.Consumer<BufferedImage> l) { frameListeners.add(l); }

    public void removeSelectionListener(SelectionListener l) { listeners.remove(l); }

    /**
     * Shows {@code next} (a new compile, or the same script at another time {@code t}). Only the
     * entities' data that changed are sent to the GPU. The first scene also places the free and
     * orthographic cameras; later ones keep them. Call on the event dispatch thread.
     */
    public void setScene(Scene next) {
        boolean first = scene == null;
        long start = System.nanoTime();
        try {
            gpu = SceneConverter.convert(next);
            problem = null;
        } catch (UnsupportedSceneException e) {
            problem = e.getMessage();
            repaint();
            return;
        }
        scene = next;
        if (first) {
            free = FreeCamera.of(next.settings().camera());
            frameAllOrtho();
        }
        if (selected >= next.entities().size()) selected = -1;
        coarseNext = true;
        sceneGeneration++;
        GpuScene upload = gpu;
        glThread.submit(() -> {
            renderer.setScene(upload);
            lastUpdateNanos = System.nanoTime() - start;
        });
        if (getWidth() <= 0 || getHeight() <= 0) {
            requestFrame();
            return;
        }
        // At once rather than through the event queue, where the other panels' work on the same
        // compile result would be ahead of it; a request still queued is taken into this frame.
        framePending.set(false);
        submitFrame();
    }

    /**
     * When ({@link System#nanoTime}) the first frame of the scene last set was ready to paint (the
     * coarse one, for a panel big enough to have one), or 0 before it.
     */
    public long firstFrameNanos() { return shownGeneration == sceneGeneration ? firstFrameNanos : 0; }

    /** How long the last {@link #setScene} took from the call until the GPU held the new data. */
    public long lastUpdateNanos() { return lastUpdateNanos; }

    /** Selects entity {@code index} (−1 for none) as the studio's navigator or code asks; listeners are not told. */
    public void select(int index) {
        if (index == selected) return;
        selected = index;
        requestFrame();
    }

    public int selected() { return selected; }

    /** The free camera as a scene camera (the script's lens kept): what "Copy camera to script" writes. */
    public Camera freeCamera() {
        return free.toCamera(scene == null ? Camera.DEFAULT : scene.settings().camera());
    }

    /** The Camera block for the free camera, for the studio to put into the script as one undoable edit. */
    public String cameraBlock() { return CameraScript.cameraBlock(freeCamera()); }

    public void setFreeCamera(FreeCamera c) {
        free = c;
        requestFrame();
    }

    public FreeCamera getFreeCamera() { return free; }

    /** Shows one viewport ({@code quad} false: {@code v}) or the four top, front, side and free. */
    public void setLayout(boolean quad, Viewport v) {
        this.quad = quad;
        this.single = v;
        requestFrame();
    }

    public boolean isQuad() { return quad; }

    public Viewport singleViewport() { return single; }

    private void frameAllOrtho() {
        Aabb b = gpu == null ? Aabb.EMPTY : gpu.bounds();
        for (Viewport v : ortho.keySet()) ortho.put(v, OrthoCamera.framing(b));
    }

    /** Frames the selection (or everything when nothing is selected) in the viewport under the mouse, or all. */
    public void frame(boolean selection) {
        if (gpu == null) return;
        Aabb b = selection && selected >= 0 ? gpu.entityBounds(selected) : gpu.bounds();
        if (b.isEmpty() || !b.isFinite()) b = gpu.bounds();
        double aspect = Math.max(1, getWidth()) / (double) Math.max(1, getHeight());
        free = free.frame(b, aspect);
        for (Viewport v : ortho.keySet()) ortho.put(v, OrthoCamera.framing(b));
        requestFrame();
    }

    /** Where each viewport lies in a panel of {@code w × h}. */
    Map<Viewport, Rectangle> layout(int w, int h) {
        Map<Viewport, Rectangle> m = new EnumMap<>(Viewport.class);
        if (!quad) {
            m.put(single, new Rectangle(0, 0, w, h));
            return m;
        }
        int hw = Math.max(1, w / 2), hh = Math.max(1, h / 2);
        m.put(Viewport.TOP, new Rectangle(0, 0, hw, hh));
        m.put(Viewport.FRONT, new Rectangle(hw, 0, w - hw, hh));
        m.put(Viewport.SIDE, new Rectangle(0, hh, hw, h - hh));
        m.put(Viewport.FREE, new Rectangle(hw, hh, w - hw, h - hh));
        return m;
    }

    ViewCamera viewOf(Viewport v) {
        return switch (v) {
            case FREE -> free.view();
            case SCENE_CAMERA -> ViewCamera.of(scene.settings().camera());
            default -> ortho.get(v).view(v, reach());
        };
    }

    private double reach() {
        Aabb b = gpu == null ? Aabb.EMPTY : gpu.bounds();
        double r = b.isEmpty() ? 1 : b.max().minus(b.min()).length();
        return 2 * r + 1;
    }

    /** Asks the GL thread for a new frame; requests made while one is pending are merged into it. */
    public void requestFrame() {
        if (scene == null || getWidth() <= 0 || getHeight() <= 0) {
            repaint();
            return;
        }
        if (!framePending.compareAndSet(false, true)) return;
        SwingUtilities.invokeLater(() -> {
            if (framePending.getAndSet(false)) submitFrame();
        });
    }

    private void submitFrame() {
        int w = getWidth(), h = getHeight();
        Map<Viewport, Rectangle> rects = layout(w, h);
        Map<Viewport, ViewCamera> views = new EnumMap<>(Viewport.class);
        Map<Viewport, LiveRenderer.Overlay> overlays = new EnumMap<>(Viewport.class);
        for (Viewport v : rects.keySet()) {
            views.put(v, viewOf(v));
            boolean grid = v.isOrthographic();
            overlays.put(v, new LiveRenderer.Overlay(selected, hovered, grid,
                    grid ? ortho.get(v).gridSpacing() : 1, Math.max(0, v.gridAxis)));
        }
        boolean coarse = coarseNext && w * h >= COARSE_MIN_PIXELS;
        coarseNext = false;
        long generation = sceneGeneration;
        if (coarse) glThread.submit(() -> draw(w, h, 2, rects, views, overlays, generation));
        glThread.submit(() -> draw(w, h, 1, rects, views, overlays, generation));
    }

    /** On the GL thread: draws the viewports at 1/{@code scale} of the panel's size and publishes the frame. */
    private void draw(int w, int h, int scale, Map<Viewport, Rectangle> rects, Map<Viewport, ViewCamera> views,
            Map<Viewport, LiveRenderer.Overlay> overlays, long generation) {
        renderer.resize(w, h);
        renderer.clear();
        for (Map.Entry<Viewport, Rectangle> e : rects.entrySet()) {
            Rectangle r = e.getValue();
            int x0 = r.x / scale, y0 = r.y / scale;
            int x1 = (r.x + r.width) / scale, y1 = (r.y + r.height) / scale;
            renderer.draw(views.get(e.getKey()), x0, y0, Math.max(1, x1 - x0), Math.max(1, y1 - y0), overlays.get(e.getKey()));
        }
        int iw = Math.max(1, w / scale), ih = Math.max(1, h / scale);
        BufferedImage image = new BufferedImage(iw, ih, BufferedImage.TYPE_INT_RGB);
        renderer.readColour(iw, ih, ((DataBufferInt) image.getRaster().getDataBuffer()).getData());
        frame = new Frame(image, scale, rects, views);
        for (java.util.function.Consumer<BufferedImage> l : frameListeners) l.accept(image);
        if (generation > shownGeneration) {
            firstFrameNanos = System.nanoTime();
            shownGeneration = generation;
        }
        SwingUtilities.invokeLater(this::repaint);
    }

    /** The last frame's image (for tests and screenshots), or null before the first; a coarse frame's is smaller than the panel. */
    public BufferedImage lastImage() {
        Frame f = frame;
        return f == null ? null : f.image();
    }

    /** Waits until every request made so far has been drawn (for tests and scripts). */
    public void awaitIdle() throws InterruptedException, ExecutionException {
        SwingUtilities.invokeLater(() -> { });
        try {
            SwingUtilities.invokeAndWait(() -> { });
        } catch (java.lang.reflect.InvocationTargetException e) {
            throw new ExecutionException(e.getCause());
        }
        Future<?> f = glThread.submit(() -> { });
        f.get();
    }

    /** The entity index seen at panel point (x, y) in the last frame, −1 for none. Blocks briefly on the GL thread. */
    public int entityAt(int x, int y) {
        if (frame == null || x < 0 || y < 0) return -1;
        try {
            return glThread.submit(() -> {
                // The frame drawn last when this runs: the ids in the framebuffer are its.
                Frame f = frame;
                int s = f.scale();
                int fx = x / s, fy = y / s;
                if (fx >= f.image().getWidth() || fy >= f.image().getHeight()) return -1;
                return renderer.idAt(fx, fy);
            }).get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return -1;
        } catch (ExecutionException e) {
            return -1;
        }
    }

    private void pick(int x, int y) {
        int id = entityAt(x, y);
        selected = id;
        requestFrame();
        Entity e = id >= 0 && scene != null && id < scene.entities().size() ? scene.entities().get(id) : null;
        for (SelectionListener l : listeners) l.selected(id, e);
    }

    private void hover(int x, int y) {
        int id = entityAt(x, y);
        if (id != hovered) {
            hovered = id;
            requestFrame();
        }
    }

    private Viewport viewportAt(Point p) {
        for (Map.Entry<Viewport, Rectangle> e : layout(getWidth(), getHeight()).entrySet()) {
            if (e.getValue().contains(p)) return e.getKey();
        }
        return single;
    }

    /** Moves the camera of viewport {@code v}: orbit (free view) or pan by a mouse drag. */
    private void drag(Viewport v, double dx, double dy, boolean pan, boolean roll) {
        int h = layout(getWidth(), getHeight()).getOrDefault(v, new Rectangle(0, 0, 1, getHeight())).height;
        if (v == Viewport.FREE || v == Viewport.SCENE_CAMERA) {
            if (v == Viewport.SCENE_CAMERA) single = Viewport.FREE;
            if (roll) free = free.rolled(dx * 0.3);
            else if (pan) free = free.pan(dx, dy, h);
            else free = free.orbit(dx * 0.3, dy * 0.3);
        } else {
            ortho.put(v, ortho.get(v).pan(v, dx, dy, h));
        }
        requestFrame();
    }

    private void zoom(Viewport v, double steps) {
        if (v.isOrthographic()) ortho.put(v, ortho.get(v).zoom(steps));
        else free = free.zoom(steps);
        requestFrame();
    }

    private final class Mouse extends MouseAdapter {
        @Override
        public void mousePressed(MouseEvent e) {
            requestFocusInWindow();
            pressed = e.getPoint();
            dragged = viewportAt(pressed);
            moved = false;
        }

        @Override
        public void mouseDragged(MouseEvent e) {
            if (pressed == null) return;
            double dx = e.getX() - pressed.x, dy = e.getY() - pressed.y;
            if (Math.abs(dx) + Math.abs(dy) < 1) return;
            moved = true;
            boolean pan = SwingUtilities.isRightMouseButton(e) || SwingUtilities.isMiddleMouseButton(e)
                    || dragged.isOrthographic();
            drag(dragged, dx, dy, pan, e.isControlDown() && SwingUtilities.isLeftMouseButton(e));
            pressed = e.getPoint();
        }

        @Override
        public void mouseReleased(MouseEvent e) {
            if (pressed != null && !moved && SwingUtilities.isLeftMouseButton(e)) pick(e.getX(), e.getY());
            pressed = null;
        }

        @Override
        public void mouseMoved(MouseEvent e) {
            hover(e.getX(), e.getY());
        }

        @Override
        public void mouseExited(MouseEvent e) {
            if (hovered != -1) {
                hovered = -1;
                requestFrame();
            }
        }

        @Override
        public void mouseWheelMoved(MouseWheelEvent e) {
            zoom(viewportAt(e.getPoint()), -e.getPreciseWheelRotation());
        }
    }

    private final class Keys extends KeyAdapter {
        @Override
        public void keyPressed(KeyEvent e) {
            // Ctrl+Z, Alt+1 and the like are the studio's shortcuts, not the view's Z and 1.
            if (e.isControlDown() || e.isAltDown() || e.isMetaDown()) return;
            key(e.getKeyCode(), e.isShiftDown());
        }
    }

    /** Acts on a key press (the key bindings of the class comment). */
    void key(int keyCode, boolean shift) {
            Point m = isShowing() ? getMousePosition() : null;
            Viewport v = m != null ? viewportAt(m) : quad ? Viewport.FREE : single;
            double step = 10;
            switch (keyCode) {
                case KeyEvent.VK_LEFT -> drag(v, shift ? -step : -step / 0.3 / 3, 0, shift || v.isOrthographic(), false);
                case KeyEvent.VK_RIGHT -> drag(v, shift ? step : step / 0.3 / 3, 0, shift || v.isOrthographic(), false);
                case KeyEvent.VK_UP -> drag(v, 0, shift ? -step : -step / 0.3 / 3, shift || v.isOrthographic(), false);
                case KeyEvent.VK_DOWN -> drag(v, 0, shift ? step : step / 0.3 / 3, shift || v.isOrthographic(), false);
                case KeyEvent.VK_PLUS, KeyEvent.VK_EQUALS, KeyEvent.VK_ADD -> zoom(v, 1);
                case KeyEvent.VK_MINUS, KeyEvent.VK_SUBTRACT -> zoom(v, -1);
                case KeyEvent.VK_Z -> { free = free.rolled(-5); requestFrame(); }
                case KeyEvent.VK_X -> { free = free.rolled(5); requestFrame(); }
                case KeyEvent.VK_F -> frame(true);
                case KeyEvent.VK_A, KeyEvent.VK_HOME -> frame(false);
                case KeyEvent.VK_1 -> setLayout(false, Viewport.FREE);
                case KeyEvent.VK_2 -> setLayout(false, Viewport.SCENE_CAMERA);
                case KeyEvent.VK_3 -> setLayout(false, Viewport.TOP);
                case KeyEvent.VK_4 -> setLayout(false, Viewport.FRONT);
                case KeyEvent.VK_5 -> setLayout(false, Viewport.SIDE);
                case KeyEvent.VK_V -> setLayout(!quad, single);
                case KeyEvent.VK_P -> rayTracePreview();
                case KeyEvent.VK_ESCAPE -> pick(-1, -1);
                default -> { }
            }
    }

    @Override
    protected void paintComponent(Graphics g) {
        super.paintComponent(g);
        Graphics2D g2 = (Graphics2D) g;
        g2.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        if (problem != null) {
            g2.setColor(Color.WHITE);
            g2.drawString("The live view cannot show this scene: " + problem, 10, 20);
            return;
        }
        Frame f = frame;
        if (f == null) return;
        drawFrame(g2, f);
        Traced t = traced;
        Rectangle freeRect = f.viewports().get(Viewport.FREE);
        if (t != null && freeRect != null && t.camera().equals(free) && t.scene() == scene) {
            g2.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_BILINEAR);
            g2.drawImage(t.image(), freeRect.x, freeRect.y, freeRect.width, freeRect.height, null);
        }
        g2.setFont(getFont().deriveFont(Font.BOLD, 12f));
        for (Map.Entry<Viewport, Rectangle> e : f.viewports().entrySet()) {
            Rectangle r = e.getValue();
            g2.setColor(new Color(255, 255, 255, 200));
            boolean showsTrace = e.getKey() == Viewport.FREE && t != null && t.camera().equals(free) && t.scene() == scene;
            g2.drawString(e.getKey().label() + (showsTrace ? " (ray-traced preview)" : ""), r.x + 8, r.y + 16);
            gizmo(g2, f.views().get(e.getKey()), r.x + 30, r.y + r.height - 30);
            if (f.viewports().size() > 1) {
                g2.setColor(Color.GRAY);
                g2.drawRect(r.x, r.y, r.width - 1, r.height - 1);
            }
        }
    }

    /**
     * The frame's picture, from an image kept where the screen is (a {@link VolatileImage}: on
     * X11 a pixmap in the X server). A new frame is sent there once; a repaint of the same frame
     * (another window or a menu uncovering the view, a docking move) is then a copy inside the
     * server instead of sending the whole picture again, which under load stalled the event
     * thread for up to half a second.
     */
    private void drawFrame(Graphics2D g, Frame f) {
        int w = f.image().getWidth() * f.scale(), h = f.image().getHeight() * f.scale();
        for (int attempt = 0; attempt < 3; attempt++) {
            VolatileImage v = onScreen;
            int status = v == null ? VolatileImage.IMAGE_INCOMPATIBLE : v.validate(getGraphicsConfiguration());
            if (status == VolatileImage.IMAGE_INCOMPATIBLE || v.getWidth() != w || v.getHeight() != h) {
                if (v != null) v.flush();
                v = getGraphicsConfiguration() == null ? null : createVolatileImage(w, h);
                onScreen = v;
                onScreenFrame = null;
                if (v == null) break;
            }
            if (status == VolatileImage.IMAGE_RESTORED) onScreenFrame = null;
            if (onScreenFrame != f) {
                Graphics2D vg = v.createGraphics();
                vg.drawImage(f.image(), 0, 0, w, h, null);
                vg.dispose();
                onScreenFrame = f;
            }
            g.drawImage(v, 0, 0, null);
            if (!v.contentsLost()) return;
            onScreenFrame = null;
        }
        g.drawImage(f.image(), 0, 0, w, h, null);
    }

    /** The axis gizmo: +x red, +y green, +z blue, as the view sees them. */
    private static void gizmo(Graphics2D g, ViewCamera view, int cx, int cy) {
        Vec3[] axes = {Vec3.X, Vec3.Y, Vec3.Z};
        Color[] colours = {new Color(230, 70, 60), new Color(90, 200, 80), new Color(80, 130, 240)};
        String[] names = {"x", "y", "z"};
        g.setStroke(new BasicStroke(2f));
        for (int i = 0; i < 3; i++) {
            double sx = axes[i].dot(view.right()), sy = axes[i].dot(view.up());
            int ex = cx + (int) Math.round(20 * sx), ey = cy - (int) Math.round(20 * sy);
            g.setColor(colours[i]);
            g.drawLine(cx, cy, ex, ey);
            g.drawString(names[i], ex + (int) Math.signum(sx) * 3, ey - (int) Math.signum(sy) * 3 + 4);
        }
    }

    /**
     * "Preview": ray-traces the free camera's view at half the viewport's resolution on a thread of
     * its own and shows it in the free viewport until the camera or the scene changes; a newer
     * request cancels an older one. Returns when the render is under way.
     */
    public Future<BufferedImage> rayTracePreview() {
        Scene s = scene;
        FreeCamera c = free;
        if (s == null) return java.util.concurrent.CompletableFuture.completedFuture(null);
        Rectangle r = layout(getWidth(), getHeight()).getOrDefault(Viewport.FREE, new Rectangle(0, 0, getWidth(), getHeight()));
        int w = Math.max(1, r.width / 2), h = Math.max(1, r.height / 2);
        long generation = traceGeneration.incrementAndGet();
        return tracer.submit(() -> {
            dev.crt.scene.Settings o = s.settings();
            Scene view = s.withSettings(new dev.crt.scene.Settings(o.title(), o.author(), o.date(), o.notes(), o.lights(),
                    c.toCamera(o.camera()), o.background(), 1, 1, o.recursionDepth(), o.gamma(), w, h)
                    .withShading(o.shading()));
            dev.crt.image.FrameBuffer fb = dev.crt.render.Renderer.prepare(view).render(0, new dev.crt.render.RenderMonitor() {
                @Override
                public boolean isCancelled() { return traceGeneration.get() != generation; }
            });
            BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
            double gamma = s.settings().gamma();
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    image.setRGB(x, y, dev.crt.image.ImageFiles.toByte(fb.get(x, y, 0), gamma) << 16
                            | dev.crt.image.ImageFiles.toByte(fb.get(x, y, 1), gamma) << 8
                            | dev.crt.image.ImageFiles.toByte(fb.get(x, y, 2), gamma));
                }
            }
            traced = new Traced(image, c, s);
            SwingUtilities.invokeLater(this::repaint);
            return image;
        });
    }

    /** Frees the GL context and stops the GL and preview threads. */
    @Override
    public void close() {
        VolatileImage v = onScreen;
        if (v != null) v.flush();
        traceGeneration.incrementAndGet();
        tracer.shutdownNow();
        Future<?> f = glThread.submit(() -> {
            renderer.close();
            context.close();
        });
        try {
            f.get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (ExecutionException e) {
            // The context is going away with its thread either way.
        }
        glThread.shutdown();
    }
}
