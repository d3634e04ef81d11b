package dev.crt.scene;

/**
 * A colour that varies over a surface, for a Material's colour channels and its bump map. A kind
 * of texture is one class implementing this (and one line registering its script name): the
 * renderer fills a {@link TexturePoint} and asks for the colour, without knowing the kind.
 * Implementations are immutable and allocate nothing in {@link #evaluate}, which render threads
 * call concurrently.
 */
public interface Texture {
    /** The linear colour at {@code p} into {@code out[0..2]}. */
    void evaluate(TexturePoint p, double[] out);

    /** Whether {@link #evaluate} reads the surface's own (u, v): only then does the renderer compute them. */
    default boolean needsUv() { return false; }

    /**
     * The texture as the renderer uses it for pictures written with output gamma {@code gamma}
     * (image textures decode their sRGB texels to linear light and build their mipmaps here).
     */
    default Texture prepared(double gamma) { return this; }

    /** Rec. 709 luminance of a linear colour: how a texture gives the number channels (specular…). */
    static double luminance(double r, double g, double b) { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }
}
