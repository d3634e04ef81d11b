package dev.crt.scene;

/** A colour that varies over a surface: accepted for a Material's {@code color}. */
public sealed interface Texture permits Checker {}
