package dev.crt.studio;

import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.Point;
import java.awt.RenderingHints;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.MouseWheelEvent;
import java.awt.image.BufferedImage;
import java.util.function.BiConsumer;
import javax.swing.UIManager;

/**
 * Shows the picture being rendered: fitted to the panel or at a chosen zoom, dragged to pan, wheel
 * to zoom around the mouse. A click (without a drag) reports the picture pixel under the mouse.
 */
final class RenderView extends javax.swing.JPanel {
    private BufferedImage picture;
    /** Drawn over the picture, same size (the selected object's outline), or null. */
    private BufferedImage overlay;
    /** The selected entity's outline, the picture's size, drawn over it; or null. */
    private BufferedImage outline;
    /** False while the script's text is not the text the picture was rendered from: its outlines are then stale. */
    private boolean pictureCurrent = true;
    private boolean fit = true;
    private double zoom = 1;
    private double panX, panY;
    private BiConsumer<Integer, Integer> pixelClicked = (x, y) -> {};

    RenderView() {
        setName("renderView");
        getAccessibleContext().setAccessibleName("Render view");
        getAccessibleContext().setAccessibleDescription("The rendered picture; click a pixel to find the code of the object there");
        setPreferredSize(new Dimension(400, 300));
        setFocusable(true);
        MouseAdapter mouse = new MouseAdapter() {
            private Point pressed, last;

            @Override public void mousePressed(MouseEvent e) {
                pressed = e.getPoint();
                last = e.getPoint();
                requestFocusInWindow();
            }

            @Override public void mouseDragged(MouseEvent e) {
                if (last == null) return;
                if (fit) startFreeZoom();
                panX += e.getX() - last.x;
                panY += e.getY() - last.y;
                last = e.getPoint();
                repaint();
            }

            @Override public void mouseReleased(MouseEvent e) {
                if (pressed != null && pressed.distance(e.getPoint()) < 4 && e.getButton() == MouseEvent.BUTTON1) {
                    Point p = toPicture(e.getX(), e.getY());
                    if (p != null) pixelClicked.accept(p.x, p.y);
                }
                pressed = null;
                last = null;
            }

            @Override public void mouseWheelMoved(MouseWheelEvent e) {
                if (picture == null) return;
                if (fit) startFreeZoom();
                double factor = Math.pow(1.15, -e.getPreciseWheelRotation());
                double next = Math.max(0.05, Math.min(32, zoom * factor));
                // Keep the picture point under the mouse where it is.
                panX = e.getX() - (e.getX() - panX) * next / zoom;
                panY = e.getY() - (e.getY() - panY) * next / zoom;
                zoom = next;
                repaint();
            }
        };
        addMouseListener(mouse);
        addMouseMotionListener(mouse);
        addMouseWheelListener(mouse);
    }

    void onPixelClicked(BiConsumer<Integer, Integer> listener) { pixelClicked = listener; }

    /** Shows {@code image}, which render threads may keep writing into; keeps the zoom if the size is unchanged. */
    void show(BufferedImage image) {
        boolean sameSize = picture != null && image != null && picture.getWidth() == image.getWidth()
                && picture.getHeight() == image.getHeight();
        if (image != picture) overlay = null;
        // Another picture (a new render) shows other pixels: the old outline no longer fits it.
        if (image != picture) outline = null;
        picture = image;
        if (!sameSize) fit = true;
        repaint();
    }

    BufferedImage picture() { return picture; }

    /** Draws {@code image} (the picture's size; null: nothing) over the picture. */
    void showOverlay(BufferedImage image) {
        overlay = image;
        repaint();
    }

    BufferedImage overlay() { return overlay; }

    void zoomToFit() {
        fit = true;
        repaint();
    }

    void zoomActualSize() {
        if (picture == null) return;
        fit = false;
        zoom = 1;
        panX = (getWidth() - picture.getWidth()) / 2.0;
        panY = (getHeight() - picture.getHeight()) / 2.0;
        repaint();
    }

    boolean isFitted() { return fit; }

    double zoom() { return fit ? fitZoom() : zoom; }

    private void startFreeZoom() {
        zoom = fitZoom();
        panX = originX(zoom);
        panY = originY(zoom);
        fit = false;
    }

    private double fitZoom() {
        if (picture == null || getWidth() == 0 || getHeight() == 0) return 1;
        return Math.min((double) getWidth() / picture.getWidth(), (double) getHeight() / picture.getHeight());
    }

    private double originX(double z) { return fit ? (getWidth() - picture.getWidth() * z) / 2 : panX; }

    private double originY(double z) { return fit ? (getHeight() - picture.getHeight() * z) / 2 : panY; }

    /** Repaints the part of the view that shows the picture pixels in {@code r}. */
    void repaintPicture(java.awt.Rectangle r) {
        if (picture == null || r == null) return;
        double z = zoom();
        double ox = originX(z), oy = originY(z);
        repaint((int) Math.floor(ox + r.x * z) - 1, (int) Math.floor(oy + r.y * z) - 1,
                (int) Math.ceil(r.width * z) + 3, (int) Math.ceil(r.height * z) + 3);
    }

    /** The picture pixel under a point of this component, or null outside the picture. */
    Point toPicture(int x, int y) {
        if (picture == null) return null;
        double z = zoom();
        int px = (int) Math.floor((x - originX(z)) / z), py = (int) Math.floor((y - originY(z)) / z);
        if (px < 0 || py < 0 || px >= picture.getWidth() || py >= picture.getHeight()) return null;
        return new Point(px, py);
    }

    /** Outlines the selected entity: an image of the picture's size, clear but for the outline (null: none). */
    void setOutline(BufferedImage image) {
        outline = image;
        repaint();
    }

    /** The outline shown over the picture, or null. */
    BufferedImage outline() { return outline; }

    /** Whether the picture is of the script as it is; when not, the selection's outlines over it are not drawn. */
    void setPictureCurrent(boolean current) {
        if (current == pictureCurrent) return;
        pictureCurrent = current;
        repaint();
    }

    boolean isPictureCurrent() { return pictureCurrent; }

    /** True when an outline of the selection is drawn over the picture now. */
    boolean showsOutline() { return picture != null && pictureCurrent && (fits(overlay) || fits(outline)); }

    private boolean fits(BufferedImage over) {
        return over != null && over.getWidth() == picture.getWidth() && over.getHeight() == picture.getHeight();
    }

    /** The centre of picture pixel (px, py) in this component's coordinates. */
    Point fromPicture(int px, int py) {
        double z = zoom();
        return new Point((int) Math.floor(originX(z) + (px + 0.5) * z), (int) Math.floor(originY(z) + (py + 0.5) * z));
    }

    @Override
    protected void paintComponent(Graphics g) {
        Color background = UIManager.getColor("Panel.background");
        g.setColor(background == null ? Color.DARK_GRAY : background.darker());
        g.fillRect(0, 0, getWidth(), getHeight());
        if (picture == null) return;
        Graphics2D g2 = (Graphics2D) g.create();
        double z = zoom();
        g2.setRenderingHint(RenderingHints.KEY_INTERPOLATION, z < 1
                ? RenderingHints.VALUE_INTERPOLATION_BILINEAR : RenderingHints.VALUE_INTERPOLATION_NEAREST_NEIGHBOR);
        double ox = originX(z), oy = originY(z);
        // Only the part of the picture inside the clip is drawn: the picture is written by render
        // threads, so Java2D uploads whatever it draws to the X server again on every paint.
        java.awt.Rectangle clip = g2.getClipBounds();
        if (clip == null) clip = new java.awt.Rectangle(0, 0, getWidth(), getHeight());
        int sx0 = Math.max(0, (int) Math.floor((clip.x - ox) / z));
        int sy0 = Math.max(0, (int) Math.floor((clip.y - oy) / z));
        int sx1 = Math.min(picture.getWidth(), (int) Math.ceil((clip.x + clip.width - ox) / z) + 1);
        int sy1 = Math.min(picture.getHeight(), (int) Math.ceil((clip.y + clip.height - oy) / z) + 1);
        if (sx0 < sx1 && sy0 < sy1) {
            g2.drawImage(picture, (int) Math.round(ox + sx0 * z), (int) Math.round(oy + sy0 * z),
                    (int) Math.round(ox + sx1 * z), (int) Math.round(oy + sy1 * z), sx0, sy0, sx1, sy1, null);
            for (BufferedImage over : pictureCurrent ? new BufferedImage[] {overlay, outline} : new BufferedImage[0]) {
                if (!fits(over)) continue;
                g2.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_NEAREST_NEIGHBOR);
                g2.drawImage(over, (int) Math.round(ox + sx0 * z), (int) Math.round(oy + sy0 * z),
                        (int) Math.round(ox + sx1 * z), (int) Math.round(oy + sy1 * z), sx0, sy0, sx1, sy1, null);
            }
        }
        g2.dispose();
    }
}
