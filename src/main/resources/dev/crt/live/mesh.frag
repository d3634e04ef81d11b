// The geometry pass of a rasterised mesh: the same outputs as a ray-cast entity's. The point
// interpolated at the pixel's centre lies on the triangle where the pixel's ray meets it, so its
// distance along the ray is the ray tracer's distance; the triangle is gl_PrimitiveID (one draw
// per mesh, so triangles count from 0 in the mesh's order).
in vec3 world;
layout(location = 0) out int id;
layout(location = 1) out float depth;
layout(location = 2) out int leafAddress;
layout(location = 3) out int face;
uniform float depthScale;
uniform int entityIndex;
uniform int meshLeaf;

void main() {
    vec3 ro, rd;
    primaryRay(ro, rd);
    float t = dot(world - ro, rd);
    if (!(t > 0.0)) discard;
    id = entityIndex + 1;
    depth = t;
    leafAddress = meshLeaf;
    face = gl_PrimitiveID;
    gl_FragDepth = t / (t + depthScale);
}
