// The geometry pass: the fragments of one entity's proxy ray-cast it and keep the nearest hit per
// pixel (entity id, distance, the primitive's texel address); shading happens once per pixel after.
flat in int entity;
#ifdef PRIMITIVES
flat in vec4 leafData[6];
flat in int entityId;
#endif
layout(location = 0) out int id;
layout(location = 1) out float depth;
layout(location = 2) out int leafAddress;
layout(location = 3) out int face;
uniform float depthScale;

void main() {
    vec3 ro, rd;
    primaryRay(ro, rd);
    float t;
    int leaf;
#ifdef PRIMITIVES
    // Entities that are one primitive: no CSG walk at all (llvmpipe runs both sides of branches),
    // and the primitive's texels come from the vertex shader.
    float a, b;
    if (!span(leafData[0], leafData[1], leafData[2], leafData[3], leafData[4], leafData[5], ro, rd, a, b)) discard;
    t = firstAfter(a, b, 0.0);
    if (!(t > 0.0) || t == INF) discard;
    leaf = 0;
#else
    if (walk(entity, ro, rd, 0.0, INF, false, t, leaf) == 0.0) discard;
#endif
#ifdef PRIMITIVES
    // One primitive: the program is one step, so the primitive follows the header at once.
    id = entityId + 1;
    leafAddress = entity + 4;
#else
    vec4 header = T(entity);
    id = int(header.z) + 1;
    leafAddress = entity + 3 + int(header.y) + leaf * LEAF_TEXELS;
#endif
    depth = t;
#ifdef HAS_MESH
    face = faceHit;
#else
    face = 0;
#endif
    gl_FragDepth = t / (t + depthScale);
}
