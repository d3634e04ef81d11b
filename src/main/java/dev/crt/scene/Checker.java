package dev.crt.scene;

/**
 * A solid 3D checkerboard: {@code color1} where floor(x/scale) + floor(y/scale) + floor(z/scale)
 * is even, else {@code color2}, in the entity's own coordinates (before its modifiers).
 */
public record Checker(Rgb color1, Rgb color2, double scale) implements Texture {}
