package dev.crt.scene;

/** What a ray that hits nothing sees. */
public sealed interface Background permits SolidBackground, GradientBackground, PanoramaBackground {
    Background BLACK = new SolidBackground(Rgb.BLACK);
}
