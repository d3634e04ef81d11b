package dev.crt.scene;

/**
 * An equirectangular panorama, turned by {@code angle} radians about +y.
 * {@code path} is the resolved file the image came from.
 */
public record PanoramaBackground(String path, Picture image, double angle) implements Background {}
