package dev.crt.live;

import dev.crt.scene.Scene;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import javax.swing.JFrame;
import javax.swing.SwingUtilities;

/**
 * Screenshots of the live view panel for docs/live-view.md (run by docs/images/live/make.sh):
 * {@code LiveViewShots SCENE OUT.png [quad|free] [--window]}. Without --window the panel is painted
 * offscreen; with it, the panel is shown in a real frame (for an X server such as Xvfb) and stays
 * up for a few seconds so the screen can be captured.
 */
public final class LiveViewShots {
    private LiveViewShots() {}

    public static void main(String[] args) throws Exception {
        Path scriptFile = Path.of(args[0]);
        Path out = Path.of(args[1]);
        boolean quad = args.length > 2 && args[2].equals("quad");
        boolean window = args.length > 3 && args[3].equals("--window");
        Scene scene = AlignmentTest.compile(scriptFile);
        LiveViewPanel panel = LiveViewPanel.open();
        JFrame[] frame = new JFrame[1];
        SwingUtilities.invokeAndWait(() -> {
            if (window) {
                frame[0] = new JFrame("CRT live view");
                frame[0].add(panel);
                frame[0].setSize(960, 600);
                frame[0].setVisible(true);
            } else {
                panel.setSize(960, 540);
            }
            panel.setScene(scene);
            panel.setLayout(quad, Viewport.FREE);
            if (quad) panel.setFreeCamera(panel.getFreeCamera().orbit(-25, 10));
        });
        panel.awaitIdle();
        // Select the entity in the middle of the free view, as a click would.
        SwingUtilities.invokeAndWait(() -> {
            int w = panel.getWidth(), h = panel.getHeight();
            int id = quad ? panel.entityAt(3 * w / 4, 3 * h / 4) : panel.entityAt(w * 36 / 100, h / 2);
            panel.select(id);
        });
        panel.awaitIdle();
        Thread.sleep(300);
        panel.awaitIdle();
        if (window) {
            Thread.sleep(Long.getLong("shots.hold", 4000));
            SwingUtilities.invokeAndWait(() -> frame[0].dispose());
        } else {
            BufferedImage image = new BufferedImage(panel.getWidth(), panel.getHeight(), BufferedImage.TYPE_INT_RGB);
            SwingUtilities.invokeAndWait(() -> {
                Graphics2D g = image.createGraphics();
                panel.paint(g);
                g.dispose();
            });
            ImageIO.write(image, "png", out.toFile());
        }
        panel.close();
        System.exit(0);
    }
}
