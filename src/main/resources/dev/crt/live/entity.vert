// Proxy geometry: a bounding box per entity (back faces, so a camera inside still covers it),
// or a full-screen triangle for entities that reach infinity. The fragment shader does the rest.
layout(location = 0) in vec3 corner;
layout(location = 1) in vec3 boxMin;
layout(location = 2) in vec3 boxMax;
layout(location = 3) in int offset;
uniform mat4 viewProjection;
uniform bool fullScreen;
flat out int entity;
#ifdef PRIMITIVES
// A one-primitive entity's data, read here once per vertex and handed to every fragment as flat
// inputs: a texel read in the fragment shader is a gather per pixel group on llvmpipe.
uniform samplerBuffer scene;
flat out vec4 leafData[6];
flat out int entityId;
#endif

void main() {
    entity = offset;
#ifdef PRIMITIVES
    entityId = int(texelFetch(scene, offset).z);
    for (int i = 0; i < 6; i++) leafData[i] = texelFetch(scene, offset + 4 + i);
#endif
    if (fullScreen) {
        gl_Position = vec4(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0, 0.0, 1.0);
    } else {
        // Widened a little: float rounding of the box must never cut off a silhouette pixel.
        vec3 pad = (boxMax - boxMin) * 1e-3 + 1e-4 * (abs(boxMin) + abs(boxMax)) + 1e-6;
        gl_Position = viewProjection * vec4(mix(boxMin - pad, boxMax + pad, corner), 1.0);
    }
}
