package dev.crt.studio;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.GradientPaint;
import java.awt.Graphics2D;
import java.awt.Image;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;

/** The studio's window icon, drawn in code: a rounded screen with a lit sphere. */
final class StudioIcon {
    private StudioIcon() {}

    static List<Image> images() {
        List<Image> images = new ArrayList<>();
        for (int size : new int[] {16, 32, 48, 64}) images.add(draw(size));
        return images;
    }

    private static BufferedImage draw(int n) {
        BufferedImage img = new BufferedImage(n, n, BufferedImage.TYPE_INT_ARGB);
        Graphics2D g = img.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(new Color(0x263238));
        g.fillRoundRect(0, 0, n, n, n / 3, n / 3);
        g.setPaint(new GradientPaint(n * 0.3f, n * 0.25f, new Color(0xFFE082), n * 0.75f, n * 0.8f, new Color(0xE65100)));
        g.fillOval(n / 5, n / 5, n * 3 / 5, n * 3 / 5);
        g.setStroke(new BasicStroke(Math.max(1, n / 16f)));
        g.setColor(new Color(0x80CBC4));
        g.drawRoundRect(1, 1, n - 3, n - 3, n / 3, n / 3);
        g.dispose();
        return img;
    }
}
