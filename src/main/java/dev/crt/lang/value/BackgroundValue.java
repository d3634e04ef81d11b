package dev.crt.lang.value;

import dev.crt.scene.Background;

/** A Background object. */
public record BackgroundValue(Background background) implements Value {
    @Override
    public String typeName() { return "background"; }
}
