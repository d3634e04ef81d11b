package dev.crt.scene;

/** A basic solid with one material. */
public sealed interface Primitive extends Entity permits Sphere, Box, Plane, Cylinder, Cone, Torus, Mesh {
    Material material();
}
