// The shading pass, once per pixel: with BACKGROUND defined, the background (and grid) where the
// geometry pass found nothing; without, the Phong terms of rendering-model.md with shadow rays on
// the surface it found. The stencil buffer decides which pixels each program runs on.
layout(location = 0) out vec4 colour;
uniform isampler2D ids;
uniform sampler2D depths;
uniform isampler2D leaves;
uniform isampler2D faces;
uniform isamplerBuffer directory;
uniform int entityCount;
uniform int shadowLights;     // and only for the first this many lights
uniform int lightCount;
uniform vec4 lightA[16];      // kind, position or direction towards the light
uniform vec4 lightB[16];      // colour, ambient
uniform vec4 lightC[16];      // falloff, cos angle, cos innerangle (spot)
uniform vec4 lightD[16];      // spot axis, or area light normal
uniform int selected;         // entity index + 1, 0 for none
uniform int hovered;

// Light l seen from x: the direction towards it, its distance (INF for a parallel light) and its attenuation.
void lightAt(int l, vec3 x, out vec3 w, out float dist, out float att) {
    att = 1.0;
    int kind = int(lightA[l].x);
    if (kind != 1) {
        vec3 toLight = lightA[l].yzw - x;
        dist = length(toLight);
        w = toLight / dist;
        if (lightC[l].x > 0.0) att = lightC[l].x / (dist * dist);
        if (kind == 2) {
            // The spot's cone: smoothstep(cos angle, cos innerangle, ω'·a), a hard edge when they are equal.
            float e0 = lightC[l].y, e1 = lightC[l].z, ca = dot(-w, lightD[l].xyz);
            att *= e1 > e0 ? smoothstep(e0, e1, ca) : (ca >= e0 ? 1.0 : 0.0);
        } else if (kind == 3) {
            // An area light drawn as its centre: its strength falls with |normal·ω| as each sample's does.
            att *= abs(dot(lightD[l].xyz, w));
        }
    } else {
        w = lightA[l].yzw;
        dist = INF;
    }
}

// Light l's diffuse and specular factors at a point of normal n seen along v.
vec2 phong(vec3 n, vec3 v, vec3 w, float kd, float ks, float shininess) {
    float nw = dot(n, w);
    vec3 r = 2.0 * nw * n - w;
    float rv = dot(r, v);
    return vec2(kd * max(0.0, nw), ks > 0.0 && rv > 0.0 ? ks * pow(rv, shininess) : 0.0);
}

#ifdef SHADOWS
// The product of the transparencies each of the first four lights' shadow rays crosses from
// origin, for the lights marked in needed (column l of towards: the direction to light l and its
// distance). Every (light, entity) pair goes through one loop: an inner loop scans the pairs with
// the cheap bounds test and stops at the next one crossed, and only then is the entity walked.
// llvmpipe runs the body of an if, and of a loop once, on every pixel whether any needs it or not,
// but repeats a loop only while some pixel of the group does: so the walk, the costly part, runs
// once per crossing plus once, not once per entity and light.
vec4 shadows(vec3 origin, mat4 towards, bvec4 needed) {
    vec4 s = vec4(1.0);
    int lights = entityCount > 0 ? min(lightCount, shadowLights) : 0;
    int l = 0, e = 0;
    while (true) {
        int o = -1, crossedLight = 0;
        while (l < lights) {
            int c = texelFetch(directory, e).x;
            vec4 wd = towards[l];
            bool crossed = needed[l] && s[l] > 0.0 && boxCrossed(c, origin, wd.xyz, wd.w);
            crossedLight = l;
            e++;
            if (e == entityCount) { e = 0; l++; }
            if (crossed) { o = c; break; }
        }
        if (o < 0) break;
        float tHit;
        int leafHit;
        vec4 wd = towards[crossedLight];
        float r = walk(o, origin, wd.xyz, 0.0, wd.w, true, tHit, leafHit);
        s *= mix(vec4(1.0), vec4(r), equal(ivec4(crossedLight), ivec4(0, 1, 2, 3)));
    }
    return s;
}
#endif

vec3 gridOver(vec3 c, vec3 o) {
    // Lines of the plane through the origin across the view axis, in scene units.
    vec2 g = gridAxis == 0 ? o.yz : gridAxis == 1 ? o.xz : o.xy;
    vec2 w = max(fwidth(g), vec2(1e-20));
    vec2 line = abs(fract(g / gridSpacing + 0.5) - 0.5) * gridSpacing / w;
    vec2 major = abs(fract(g / (10.0 * gridSpacing) + 0.5) - 0.5) * 10.0 * gridSpacing / w;
    vec2 axis = abs(g) / w;
    c = mix(c, vec3(0.5), 0.35 * (1.0 - clamp(min(line.x, line.y), 0.0, 1.0)));
    c = mix(c, vec3(0.6), 0.6 * (1.0 - clamp(min(major.x, major.y), 0.0, 1.0)));
    return mix(c, vec3(0.85), 1.0 - clamp(min(axis.x, axis.y), 0.0, 1.0));
}

void main() {
    vec3 ro, rd;
    primaryRay(ro, rd);
#ifdef BACKGROUND
    vec4 c = encode(backgroundColour(rd));
#ifdef GRID
    colour = vec4(gridOver(c.rgb, ro), 1.0);
#else
    colour = c;
#endif
#else
    ivec2 p = ivec2(gl_FragCoord.xy);
    int id = texelFetch(ids, p, 0).x;
    float t = texelFetch(depths, p, 0).x;
    int L = texelFetch(leaves, p, 0).x;
    vec3 x = ro + t * rd;
    vec3 ns = normalAt(L, texelFetch(faces, p, 0).x, x);
    // Facing the ray as the geometric normal does; a smooth mesh's shading normal is turned with it, as the ray tracer turns it.
    if (dot(ns, geometricNormal) < 0.0) ns = -ns;
    float side = dot(rd, geometricNormal) < 0.0 ? 1.0 : -1.0;
    vec3 n = side * ns;
    vec4 m0 = T(L + 6), m1 = T(L + 7), m2 = T(L + 8);
    vec3 base = m0.rgb;
    float kd = m0.a, ks = m1.x, shininess = m1.y, kt = m1.z, kr = m1.w;
    vec3 v = -rd;
    vec3 c = m2.rgb;
    // Shadow rays start a little off the surface, relative to the scale of the coordinates.
    float offset = 1e-4 * (t + length(x) + 1e-3);
#ifdef SHADOWS
    // As the ray tracer: a light that adds nothing here casts no shadow ray.
    bvec4 needed = bvec4(false);
    mat4 towards = mat4(0.0);
    for (int l = 0; l < min(lightCount, shadowLights); l++) {
        vec3 w;
        float dist, att;
        lightAt(l, x, w, dist, att);
        vec2 ds = phong(n, v, w, kd, ks, shininess);
        needed[l] = ds.x != 0.0 || ds.y != 0.0;
        towards[l] = vec4(w, dist);
    }
    vec4 shadow = shadows(x + shadowLift + side * geometricNormal * offset, towards, needed);
#endif
    for (int l = 0; l < lightCount; l++) {
        vec3 cl = lightB[l].rgb;
        c += lightB[l].a * cl * base;
        vec3 w;
        float dist, att;
        lightAt(l, x, w, dist, att);
        vec2 ds = phong(n, v, w, kd, ks, shininess);
#ifdef SHADOWS
        float s = l < shadowLights ? shadow[l] : 1.0;
#else
        float s = 1.0;
#endif
        c += s * att * (ds.x * cl * base + ds.y * cl);
    }
    // Mirror and glass show what they see of the background only: the live view traces no
    // secondary rays against the scene.
#ifdef SEES_BACKGROUND
    vec3 reflected = rd - 2.0 * dot(rd, n) * n;
    c = (1.0 - kt) * c + kr * backgroundColour(reflected) + kt * backgroundColour(rd);
#endif
    vec4 outColour = encode(c);
    if (id == selected) outColour.rgb = mix(outColour.rgb, vec3(1.0, 0.6, 0.1), 0.35);
    else if (id == hovered) outColour.rgb = mix(outColour.rgb, vec3(0.3, 0.7, 1.0), 0.25);
    colour = outColour;
#endif
}
