package dev.crt.lang.value;

import dev.crt.scene.Texture;

/** A texture object (Checker). */
public record TextureValue(Texture texture) implements Value {
    @Override
    public String typeName() { return "texture"; }
}
