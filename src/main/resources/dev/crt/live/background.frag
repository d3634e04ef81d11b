layout(location = 0) out vec4 colour;
layout(location = 1) out int id;
layout(location = 2) out float depth;

void main() {
    vec3 o, d;
    primaryRay(o, d);
    vec3 c = backgroundColour(d);
    vec4 outColour = encode(c);
    if (grid) {
        // Lines of the plane through the origin across the view axis, in scene units.
        vec3 q = o;
        vec2 g = gridAxis == 0 ? q.yz : gridAxis == 1 ? q.xz : q.xy;
        vec2 w = fwidth(g);
        vec2 line = abs(fract(g / gridSpacing + 0.5) - 0.5) * gridSpacing / max(w, vec2(1e-20));
        vec2 major = abs(fract(g / (10.0 * gridSpacing) + 0.5) - 0.5) * 10.0 * gridSpacing / max(w, vec2(1e-20));
        float minorOn = 1.0 - clamp(min(line.x, line.y), 0.0, 1.0);
        float majorOn = 1.0 - clamp(min(major.x, major.y), 0.0, 1.0);
        vec2 axis = abs(g) / max(w, vec2(1e-20));
        float axisOn = 1.0 - clamp(min(axis.x, axis.y), 0.0, 1.0);
        vec3 ink = mix(outColour.rgb, vec3(0.5), 0.35 * minorOn);
        ink = mix(ink, vec3(0.6), 0.6 * majorOn);
        ink = mix(ink, vec3(0.85), axisOn);
        outColour = vec4(ink, 1.0);
    }
    colour = outColour;
    id = 0;
    depth = INF;
}
