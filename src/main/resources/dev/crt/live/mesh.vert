#version 330 core
// A top-level mesh, rasterised: its vertices (texels of the mesh vertex buffer) placed in the world.
layout(location = 0) in vec4 position;
uniform mat4 viewProjection;
uniform vec4 meshRows[3];      // mesh-to-world, three rows of the affine matrix
out vec3 world;

void main() {
    vec4 p = vec4(position.xyz, 1.0);
    world = vec3(dot(meshRows[0], p), dot(meshRows[1], p), dot(meshRows[2], p));
    gl_Position = viewProjection * vec4(world, 1.0);
}
