package dev.crt.scene;

/** One colour in every direction. */
public record SolidBackground(Rgb color) implements Background {}
