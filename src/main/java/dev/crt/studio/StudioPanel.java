package dev.crt.studio;

import javax.swing.JComponent;

/**
 * A panel of the studio's dock: its stable id (the saved layout refers to it), its title, its
 * content, and where the default layout puts it, as fractions of the window (x, y, width, height).
 * The navigator, properties, animation, system and live view panels of later issues are more of these.
 */
public record StudioPanel(String id, String title, JComponent content, double x, double y, double width, double height) {}
