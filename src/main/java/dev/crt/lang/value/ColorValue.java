package dev.crt.lang.value;

import dev.crt.scene.Rgb;

/** An rgb colour. */
public record ColorValue(Rgb color) implements Value {
    @Override
    public String typeName() { return "rgb"; }

    @Override
    public String toString() {
        return "rgb(" + NumberValue.format(color.r()) + ", " + NumberValue.format(color.g()) + ", "
                + NumberValue.format(color.b()) + ")";
    }
}
