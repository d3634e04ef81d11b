package dev.crt.lang.value;

import dev.crt.scene.Camera;

/** A Camera object. */
public record CameraValue(Camera camera) implements Value {
    @Override
    public String typeName() { return "camera"; }
}
