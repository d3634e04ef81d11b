package dev.crt.image;

/** An 8-bit image as its files store it: {@code width × height} pixels packed 0xRRGGBB, row by row. */
public record RgbImage(int width, int height, int[] rgb) {
    public RgbImage {
        if (width < 1 || height < 1 || rgb.length != width * height) {
            throw new IllegalArgumentException("bad image size " + width + "x" + height);
        }
    }
}
