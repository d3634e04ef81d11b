package dev.crt.scene;

/** How an image texture's coordinates (s, t) come from a surface point (docs/rendering.md, "Image textures"). */
public enum TextureMapping {
    UV("uv"), PLANAR("planar"), SPHERICAL("spherical"), CYLINDRICAL("cylindrical"), BOX("box");

    private final String scriptName;

    TextureMapping(String scriptName) { this.scriptName = scriptName; }

    public String scriptName() { return scriptName; }
}
