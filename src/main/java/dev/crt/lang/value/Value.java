package dev.crt.lang.value;

/** A value a script computes; the closed set of the language's types. */
public sealed interface Value
        permits NumberValue, BooleanValue, StringValue, VectorValue, ColorValue, ListValue, EntityValue,
                MaterialValue, LightValue, CameraValue, BackgroundValue, MacroValue, TextureValue {
    /** The type's name as scripts and messages say it: "number", "vec3", "rgb", … */
    String typeName();
}
