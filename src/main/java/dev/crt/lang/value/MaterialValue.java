package dev.crt.lang.value;

import dev.crt.scene.Material;

/** A Material object. */
public record MaterialValue(Material material) implements Value {
    @Override
    public String typeName() { return "material"; }
}
