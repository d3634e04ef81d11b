package dev.crt.scene;

/** A light source of the scene. */
public sealed interface Light permits PointLight, ParallelLight, SpotLight, AreaLight {
    Rgb color();

    /** The ambient factor: how much of {@code color} lights every surface regardless of direction. */
    double ambient();

    SourceSpan span();
}
