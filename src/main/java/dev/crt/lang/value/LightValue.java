package dev.crt.lang.value;

import dev.crt.scene.Light;

/** A PointLight or ParallelLight object. */
public record LightValue(Light light) implements Value {
    @Override
    public String typeName() { return "light"; }
}
