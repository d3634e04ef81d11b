package dev.crt.studio;

import dev.crt.scene.Entity;
import java.awt.image.BufferedImage;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicLong;
import javax.swing.SwingUtilities;

/**
 * Outlines the selected entity in the render view's last picture, whichever panel selected it (the
 * live view, the navigator, a click in the picture): the outline follows the edge of the pixels
 * whose id pass shows that entity. The id pass (one primary ray per pixel) is made off the Event
 * Dispatch Thread, once per render.
 */
final class RenderSelection implements StudioModel.Listener {
    private static final int OUTLINE = 0xFFFF9800;

    private final RenderView view;
    private final ExecutorService worker = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "crt-studio-selection");
        t.setDaemon(true);
        return t;
    });
    /** A newer render or selection makes an outline still being made obsolete. */
    private final AtomicLong generation = new AtomicLong();
    private ScriptDocument document;
    private RenderJob.Result render;
    private int[] ids;
    /** The latest selection, kept also while no render of its document is shown. */
    private ScriptDocument selectedDocument;
    private int selected = -1;

    RenderSelection(RenderView view) {
        this.view = view;
    }

    /** A render of {@code d} finished; its picture is outlined from now on. */
    void rendered(ScriptDocument d, RenderJob.Result r) {
        document = d;
        render = r;
        ids = null;
        generation.incrementAndGet();
        view.setOutline(null);
        if (d != null && d == selectedDocument && selected >= 0) outline(selected);
    }

    @Override
    public void selected(ScriptDocument d, Entity entity, int index) {
        selectedDocument = d;
        selected = index;
        outline(d == document ? index : -1);
    }

    @Override
    public void closed(ScriptDocument d) {
        if (d == document) rendered(null, null);
    }

    private void outline(int index) {
        long mine = generation.incrementAndGet();
        RenderJob.Result r = render;
        if (index < 0 || r == null) {
            view.setOutline(null);
            return;
        }
        int[] known = ids;
        worker.submit(() -> {
            int[] pass = known != null ? known : r.renderer().idPass();
            BufferedImage image = outlineOf(pass, r.picture().getWidth(), r.picture().getHeight(), index);
            SwingUtilities.invokeLater(() -> {
                if (render == r) ids = pass;
                if (generation.get() == mine) view.setOutline(image);
            });
        });
    }

    /** The pixels of entity {@code index} that touch a pixel of something else, opaque; the rest clear. */
    static BufferedImage outlineOf(int[] ids, int w, int h, int index) {
        BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_INT_ARGB);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int i = y * w + x;
                if (ids[i] != index) continue;
                boolean edge = x == 0 || y == 0 || x == w - 1 || y == h - 1
                        || ids[i - 1] != index || ids[i + 1] != index || ids[i - w] != index || ids[i + w] != index;
                if (edge) image.setRGB(x, y, OUTLINE);
            }
        }
        return image;
    }

    void shutdown() { worker.shutdownNow(); }
}
