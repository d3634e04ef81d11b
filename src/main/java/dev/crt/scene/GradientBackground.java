package dev.crt.scene;

/** A gradient from {@code horizon} (elevation 0 and below) to {@code sky} (straight up). */
public record GradientBackground(Rgb horizon, Rgb sky) implements Background {}
