package dev.crt.scene;

/** A material's local shading model: CRT's Phong, or Gooch's cool-to-warm shading with outlines. */
public enum ShadingModel {
    PHONG("phong"), GOOCH("gooch");

    private final String scriptName;

    ShadingModel(String scriptName) { this.scriptName = scriptName; }

    public String scriptName() { return scriptName; }
}
