package dev.crt.studio;

import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import javax.swing.JPanel;
import javax.swing.UIManager;

/** Shows one frame of an animation fitted into the panel, marked when it is a low-resolution preview. */
final class FrameView extends JPanel {
    private BufferedImage picture;
    private boolean preview;

    FrameView() {
        setName("animView");
        getAccessibleContext().setAccessibleName("Animation frame");
        setPreferredSize(new Dimension(320, 200));
        setOpaque(true);
    }

    void show(BufferedImage image, boolean lowResolution) {
        picture = image;
        preview = lowResolution;
        getAccessibleContext().setAccessibleDescription(lowResolution ? "preview at low resolution" : "rendered frame");
        repaint();
    }

    BufferedImage picture() { return picture; }

    boolean isPreview() { return preview; }

    @Override
    protected void paintComponent(Graphics g) {
        Color back = UIManager.getColor("Panel.background");
        g.setColor(back == null ? Color.DARK_GRAY : back.darker());
        g.fillRect(0, 0, getWidth(), getHeight());
        BufferedImage p = picture;
        if (p == null) return;
        // A preview is 1/8 of the size: its blocks show, so nobody takes it for the frame.
        double scale = Math.min((double) getWidth() / p.getWidth(), (double) getHeight() / p.getHeight());
        int w = Math.max(1, (int) (p.getWidth() * scale)), h = Math.max(1, (int) (p.getHeight() * scale));
        Graphics2D g2 = (Graphics2D) g.create();
        g2.setRenderingHint(RenderingHints.KEY_INTERPOLATION, preview ? RenderingHints.VALUE_INTERPOLATION_NEAREST_NEIGHBOR
                : RenderingHints.VALUE_INTERPOLATION_BILINEAR);
        int x = (getWidth() - w) / 2, y = (getHeight() - h) / 2;
        g2.drawImage(p, x, y, w, h, null);
        if (preview) {
            String label = "preview (low resolution)";
            java.awt.FontMetrics fm = g2.getFontMetrics();
            g2.setColor(new Color(0, 0, 0, 150));
            g2.fillRect(x, y, fm.stringWidth(label) + 12, fm.getHeight() + 6);
            g2.setColor(Color.WHITE);
            g2.drawString(label, x + 6, y + 3 + fm.getAscent());
        }
        g2.dispose();
    }
}
