#version 330 core
// Proxy geometry: a bounding box per entity (back faces, so a camera inside still covers it),
// or a full-screen triangle for entities that reach infinity. The fragment shader does the rest.
layout(location = 0) in vec3 corner;
layout(location = 1) in vec3 boxMin;
layout(location = 2) in vec3 boxMax;
layout(location = 3) in int offset;
uniform mat4 viewProjection;
uniform bool fullScreen;
flat out int entity;

void main() {
    entity = offset;
    if (fullScreen) {
        gl_Position = vec4(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0, 0.0, 1.0);
    } else {
        // Widened a little: float rounding of the box must never cut off a silhouette pixel.
        vec3 pad = (boxMax - boxMin) * 1e-3 + 1e-4 * (abs(boxMin) + abs(boxMax)) + 1e-6;
        gl_Position = viewProjection * vec4(mix(boxMin - pad, boxMax + pad, corner), 1.0);
    }
}
