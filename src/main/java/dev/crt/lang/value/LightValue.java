package dev.crt.lang.value;

import dev.crt.scene.Light;

/** A light object: PointLight, ParallelLight, SpotLight or AreaLight. */
public record LightValue(Light light) implements Value {
    @Override
    public String typeName() { return "light"; }
}
