// Ray-casting of top-level entities (their blocks in the scene buffer, see GpuScene) exactly: each
// primitive's interval along the ray, then a walk over the sorted boundary events that evaluates
// the CSG program on the set of primitives the ray is inside: the same method as the ray tracer.
uniform samplerBuffer scene;

const int SPHERE = 0, BOX = 1, PLANE = 2, EMPTY = 3, CONE = 4, TORUS = 5, MESH = 6;
const int LEAF_TEXELS = 9;
// Two per primitive, four for a torus (two intervals). HAS_CONE and HAS_TORUS compile those kinds
// in only for scenes that have them: llvmpipe pays for every branch on every pixel.
#ifdef HAS_TORUS
const int MAX_EVENTS = 128;
#else
const int MAX_EVENTS = 64;
#endif

float evT[MAX_EVENTS];
int evL[MAX_EVENTS];
#ifdef HAS_MESH
// The triangle of each mesh crossing, and of the hit the walk returned (the shading needs its normal).
int evF[MAX_EVENTS];
int faceHit;
uniform samplerBuffer meshVertices;
uniform isamplerBuffer meshIndices;
#ifdef HAS_MESH_BVH
uniform samplerBuffer meshNodes;
#endif
#endif
#ifdef HAS_TORUS
// A torus's second interval along the ray (leafSpan returns the first); INF when there is none.
float span2A, span2B;
#endif

vec4 T(int i) { return texelFetch(scene, i); }

// The first hit after tMin of one primitive from its spans.
float firstAfter(float a, float b, float tMin) {
#ifdef HAS_TORUS
    return a > tMin ? a : b > tMin ? b : span2A > tMin ? span2A : span2B;
#else
    return a > tMin ? a : b;
#endif
}

#ifdef HAS_TORUS
// The quartic s^4 + c2 s^2 + c1 s + c0 and its derivative, Horner's way.
float quartic(float s, vec3 c) { return ((s * s + c.x) * s + c.y) * s + c.z; }
float quarticSlope(float s, vec3 c) { return (4.0 * s * s + 2.0 * c.x) * s + c.y; }

// The root of the quartic in [lo, hi], where it is monotone and changes sign: Newton steps kept
// inside a shrinking bracket (bisection when a step leaves it), robust in float32.
float quarticRoot(float lo, float hi, vec3 c) {
    bool negLo = quartic(lo, c) < 0.0;
    float x = 0.5 * (lo + hi);
    for (int i = 0; i < 16; i++) {
        float fx = quartic(x, c);
        if ((fx < 0.0) == negLo) lo = x; else hi = x;
        float xn = x - fx / quarticSlope(x, c);
        x = xn > lo && xn < hi ? xn : 0.5 * (lo + hi);
    }
    return x;
}

bool torusInside(vec3 p, float big, float small) {
    float rho = length(p.xy) - big;
    return rho * rho + p.z * p.z <= small * small;
}

// The torus in its local frame (axis z, scene units): the line moved to its closest approach to
// the centre with a unit direction, so the quartic in s is depressed and of the torus's size; its
// real roots are isolated between the critical points (the roots of the cubic derivative), and the
// intervals inside are read from the inside test at midpoints, so a spindle torus's inner sheet
// never counts as a surface.
bool torusSpan(vec4 hd, vec3 o, vec3 d, out float a, out float b) {
    float big = hd.y, small = hd.z;
    float len = length(d);
    vec3 u = d / len;
    float s0 = -dot(o, u);
    vec3 c = o + s0 * u;
    float g = dot(c, c);
    float reach = big + small;
    if (g > reach * reach) return false;
    float k = g + (big - small) * (big + small);
    float r2 = 4.0 * big * big;
    vec3 co = vec3(2.0 * k - r2 * dot(u.xy, u.xy), -2.0 * r2 * dot(c.xy, u.xy), k * k - r2 * dot(c.xy, c.xy));
    float bound = sqrt(reach * reach - g) * 1.001 + 1e-5 * reach;
    // Critical points: s^3 + p s + q = 0 with p = c2/2, q = c1/4.
    float p = 0.5 * co.x, q = 0.25 * co.y;
    float cp[5];
    int nc = 0;
    cp[nc++] = -bound;
    float D = 0.25 * q * q + p * p * p / 27.0;
    if (D >= 0.0 || p >= 0.0) {
        float A = -sign(q) * pow(abs(0.5 * q) + sqrt(max(D, 0.0)), 1.0 / 3.0);
        float x = A != 0.0 ? A - p / (3.0 * A) : 0.0;
        if (abs(x) < bound) cp[nc++] = x;
    } else {
        float m = 2.0 * sqrt(-p / 3.0);
        float th = acos(clamp(3.0 * q / (p * m), -1.0, 1.0)) / 3.0;
        for (int i = 2; i >= 0; i--) {
            float x = m * cos(th - 2.0 * PI * float(i) / 3.0);
            if (abs(x) < bound) cp[nc++] = x;
        }
    }
    cp[nc++] = bound;
    float roots[4];
    int n = 0;
    for (int i = 0; i + 1 < nc; i++) {
        float lo = cp[i], hi = cp[i + 1];
        if (!(lo < hi)) continue;
        if ((quartic(lo, co) < 0.0) != (quartic(hi, co) < 0.0) && n < 4) roots[n++] = quarticRoot(lo, hi, co);
    }
    a = INF;
    b = INF;
    int spans = 0;
    bool open = false;
    float start = 0.0;
    for (int i = 0; i + 1 < n; i++) {
        float m = 0.5 * (roots[i] + roots[i + 1]);
        bool within = torusInside(c + m * u, big, small);
        if (within && !open) { start = roots[i]; open = true; }
        if (!within && open) {
            open = false;
            if (spans == 0) { a = (start + s0) / len; b = (roots[i] + s0) / len; }
            else { span2A = (start + s0) / len; span2B = (roots[i] + s0) / len; }
            spans++;
        }
    }
    if (open) {
        if (spans == 0) { a = (start + s0) / len; b = (roots[n - 1] + s0) / len; }
        else { span2A = (start + s0) / len; span2B = (roots[n - 1] + s0) / len; }
        spans++;
    }
    return spans > 0;
}

#endif

#ifdef HAS_CONE
// Cylinders, cones and frusta in a frame where the axis runs from z = 0 to z = 1 and x, y are in
// scene units: the side x^2 + y^2 = R(z)^2, R(z) = r0 + (r1 - r0) z, within the slab, the caps
// when capped; an open tube gives its crossings (two as an interval, one as an unbounded one).
bool coneSpan(vec4 hd, vec3 o, vec3 d, out float a, out float b) {
    float r0 = hd.y, k = hd.z - hd.y;
    // Moved to the closest approach to the axis's middle, as the ray tracer does.
    float t0 = -(dot(o.xy, d.xy) + (o.z - 0.5) * d.z) / dot(d, d);
    vec3 c = o + t0 * d;
    float sLo, sHi;
    if (d.z == 0.0) {
        if (c.z < 0.0 || c.z > 1.0) return false;
        sLo = -INF;
        sHi = INF;
    } else {
        float s0 = -c.z / d.z, s1 = (1.0 - c.z) / d.z;
        sLo = min(s0, s1);
        sHi = max(s0, s1);
    }
    float rho = r0 + k * c.z, kappa = k * d.z;
    float qa = dot(d.xy, d.xy) - kappa * kappa;
    float qb = dot(c.xy, d.xy) - rho * kappa;
    float qc = dot(c.xy, c.xy) - rho * rho;
    int nr = 0;
    float x1 = 0.0, x2 = 0.0;
    if (qa != 0.0) {
        float disc = qb * qb - qa * qc;
        if (disc >= 0.0) {
            float q = qb >= 0.0 ? -qb - sqrt(disc) : -qb + sqrt(disc);
            if (q != 0.0) {
                x1 = min(q / qa, qc / q);
                x2 = max(q / qa, qc / q);
            }
            nr = 2;
        }
    } else if (qb != 0.0) {
        x1 = -qc / (2.0 * qb);
        nr = 1;
    }
    if (hd.w == 0.0) {
        bool in1 = nr >= 1 && x1 >= sLo && x1 <= sHi;
        bool in2 = nr == 2 && x2 >= sLo && x2 <= sHi && x2 != x1;
        if (in1 && in2) { a = x1 + t0; b = x2 + t0; return true; }
        if (!in1 && !in2) return false;
        a = (in1 ? x1 : x2) + t0;
        b = INF;
        return true;
    }
    // Inside the double cone as one or two pieces; at most one meets the slab (a frustum is convex).
    float aLo, aHi, bLo = 1.0, bHi = 0.0;
    if (qa > 0.0) {
        if (nr == 0) return false;
        aLo = x1;
        aHi = x2;
    } else if (qa < 0.0) {
        aLo = -INF;
        if (nr == 0) {
            aHi = INF;
        } else {
            aHi = x1;
            bLo = x2;
            bHi = INF;
        }
    } else if (qb == 0.0) {
        if (qc > 0.0) return false;
        aLo = -INF;
        aHi = INF;
    } else if (qb > 0.0) {
        aLo = -INF;
        aHi = x1;
    } else {
        aLo = x1;
        aHi = INF;
    }
    float lo = max(aLo, sLo), hi = min(aHi, sHi);
    float lo2 = max(bLo, sLo), hi2 = min(bHi, sHi);
    if (lo2 <= hi2 && !(lo <= hi && hi - lo >= hi2 - lo2)) {
        lo = lo2;
        hi = hi2;
    }
    if (!(lo <= hi)) return false;
    a = lo + t0;
    b = hi + t0;
    return true;
}

#endif

#ifdef HAS_MESH
// The corners of triangle f of the mesh leaf L, in the mesh's coordinates.
void meshTriangle(int L, int f, out vec3 a, out vec3 b, out vec3 c) {
    vec4 hd = T(L);
    int vb = int(hd.z), ib = int(hd.w) + 3 * f;
    a = texelFetch(meshVertices, vb + texelFetch(meshIndices, ib).x).xyz;
    b = texelFetch(meshVertices, vb + texelFetch(meshIndices, ib + 1).x).xyz;
    c = texelFetch(meshVertices, vb + texelFetch(meshIndices, ib + 2).x).xyz;
}

// Triangle f of the mesh of leaf k at L against the line o + t d (mesh coordinates): a crossing
// up to tMin toggles whether the line is inside at once, a later one before tMax is an event.
void meshTriangleEvent(int k, int L, int f, vec3 o, vec3 d, float tMin, float tMax, inout uint mask, inout int n) {
    vec3 a, b, c;
    meshTriangle(L, f, a, b, c);
    // Moller and Trumbore, edges inclusive.
    vec3 e1 = b - a, e2 = c - a, pv = cross(d, e2);
    float det = dot(e1, pv);
    if (det == 0.0) return;
    float inv = 1.0 / det;
    vec3 tv = o - a;
    float u = dot(tv, pv) * inv;
    if (u < 0.0 || u > 1.0) return;
    vec3 qv = cross(tv, e1);
    float v = dot(d, qv) * inv;
    if (v < 0.0 || u + v > 1.0) return;
    float t = dot(e2, qv) * inv;
    if (t <= tMin) {
        mask ^= 1u << uint(k);
    } else if (t < tMax && n < MAX_EVENTS) {
        evT[n] = t; evL[n] = k; evF[n] = f; n++;
    }
}

// Every crossing of the line o + t d (mesh coordinates) with the mesh of leaf k at L: each one
// toggles whether the line is inside (a closed mesh's inside by parity, as the ray tracer's),
// those up to tMin at once, the later ones before tMax as events. A mesh of more than
// MESH_CAST_LIMIT triangles is walked through its hierarchy (MeshBvh): every node the line
// meets, before tMin too, since the crossings there decide the inside at tMin.
void meshEvents(int k, int L, vec3 o, vec3 d, float tMin, float tMax, inout uint mask, inout int n) {
    int count = int(T(L + 4).x);
#ifdef HAS_MESH_BVH
    int nodes = int(T(L + 5).x) - 1;
    if (nodes >= 0) {
        vec3 inv = 1.0 / mix(d, vec3(1e-30), equal(d, vec3(0.0)));
        int stack[MESH_BVH_DEPTH];
        int sp = 0, node = 0;
        while (true) {
            vec4 lo = texelFetch(meshNodes, nodes + 2 * node), hi = texelFetch(meshNodes, nodes + 2 * node + 1);
            vec3 t0 = (lo.xyz - o) * inv, t1 = (hi.xyz - o) * inv;
            vec3 tn = min(t0, t1), tf = max(t0, t1);
            bool met = max(max(tn.x, tn.y), tn.z) <= min(min(tf.x, tf.y), tf.z) && max(max(tn.x, tn.y), tn.z) < tMax;
            int first = int(lo.w), leafCount = int(hi.w);
            for (int i = 0; met && i < leafCount; i++) meshTriangleEvent(k, L, first + i, o, d, tMin, tMax, mask, n);
            if (met && leafCount == 0) {
                stack[sp++] = first + 1;
                node = first;
            } else {
                if (sp == 0) break;
                node = stack[--sp];
            }
        }
        return;
    }
#endif
    if (count > MESH_CAST_LIMIT) return;
    for (int f = 0; f < count; f++) meshTriangleEvent(k, L, f, o, d, tMin, tMax, mask, n);
}

// The winding normal of the triangle meshNormal last looked at, and how far the origin of its
// shadow rays moves onto the smooth surface, in mesh coordinates.
vec3 meshGeometric, meshLift;

// The normal of triangle f of mesh leaf L at world point p, in mesh coordinates: the vertex
// normals blended by the point's barycentric coordinates when smooth, the winding's otherwise.
vec3 meshNormal(int L, int f, vec3 q) {
    vec3 a, b, c;
    meshTriangle(L, f, a, b, c);
    vec3 e1 = b - a, e2 = c - a;
    vec3 n = cross(e1, e2);
    meshGeometric = n;
    meshLift = vec3(0.0);
    vec4 hd = T(L);
    if (hd.y == 0.0) return n;
    vec3 w = q - a;
    float d00 = dot(e1, e1), d01 = dot(e1, e2), d11 = dot(e2, e2), d20 = dot(w, e1), d21 = dot(w, e2);
    float den = d00 * d11 - d01 * d01;
    if (den == 0.0) return n;
    float b1 = clamp((d11 * d20 - d01 * d21) / den, 0.0, 1.0);
    float b2 = clamp((d00 * d21 - d01 * d20) / den, 0.0, 1.0 - b1);
    int vb = int(hd.z) + int(T(L + 4).z), ib = int(hd.w) + 3 * f;
    vec3 na = texelFetch(meshVertices, vb + texelFetch(meshIndices, ib).x).xyz;
    vec3 nb = texelFetch(meshVertices, vb + texelFetch(meshIndices, ib + 1).x).xyz;
    vec3 nc = texelFetch(meshVertices, vb + texelFetch(meshIndices, ib + 2).x).xyz;
    float b0 = 1.0 - b1 - b2;
    vec3 s = b0 * na + b1 * nb + b2 * nc;
    if (!(dot(s, s) > 0.0)) return n;
    // Shadow rays leave from the smooth surface the vertex normals describe, as the ray tracer's
    // do (MeshShape.lift): the flat point moved out of each corner's tangent plane it lies below.
    vec3 x = a + b1 * e1 + b2 * e2;
    vec3 lifted = x - b0 * min(0.0, dot(x - a, na)) * na - b1 * min(0.0, dot(x - b, nb)) * nb
            - b2 * min(0.0, dot(x - c, nc)) * nc;
    meshLift = lifted - q;
    return s;
}
#endif

// The interval along the ray inside the primitive of texels hd, r0 to r2 (the matrix rows, or a
// plane) and lo, hi (a box's corners), false if none; a torus's second interval in span2A, span2B.
bool span(vec4 hd, vec4 r0, vec4 r1, vec4 r2, vec4 lo4, vec4 hi4, vec3 ro, vec3 rd, out float a, out float b) {
#ifdef HAS_TORUS
    span2A = INF;
    span2B = INF;
#endif
#ifdef ONE_KIND
    // A program for one kind of one-primitive entity: the other kinds' code folds away.
    const int kind = ONE_KIND;
#else
    int kind = int(hd.x);
#endif
    if (kind == PLANE) {
        vec4 pl = r0;
        float dn = dot(pl.xyz, rd), on = dot(pl.xyz, ro);
        if (dn == 0.0) { a = -INF; b = INF; return on <= pl.w; }
        float t = (pl.w - on) / dn;
        if (dn < 0.0) { a = t; b = INF; } else { a = -INF; b = t; }
        return true;
    }
    if (kind == EMPTY) return false;
    vec3 o = vec3(dot(r0.xyz, ro) + r0.w, dot(r1.xyz, ro) + r1.w, dot(r2.xyz, ro) + r2.w);
    vec3 d = vec3(dot(r0.xyz, rd), dot(r1.xyz, rd), dot(r2.xyz, rd));
#ifdef HAS_CONE
    if (kind == CONE) return coneSpan(hd, o, d, a, b);
#endif
#ifdef HAS_TORUS
    if (kind == TORUS) return torusSpan(hd, o, d, a, b);
#endif
    if (kind == SPHERE) {
        // The stable form: the discriminant from the closest approach, the small root from c/q.
        float aa = dot(d, d), bb = dot(o, d);
        vec3 closest = o - (bb / aa) * d;
        float disc = 1.0 - dot(closest, closest);
        if (disc < 0.0) return false;
        float q = -(bb + (bb < 0.0 ? -1.0 : 1.0) * sqrt(aa * disc));
        float c = dot(o, o) - 1.0;
        float t1 = q / aa, t2 = q != 0.0 ? c / q : t1;
        a = min(t1, t2);
        b = max(t1, t2);
        return true;
    }
    vec3 lo = lo4.xyz, hi = hi4.xyz;
    // A ray parallel to a slab: a tiny component instead of 0 keeps the slab test branch-free (a
    // branch costs every pixel on llvmpipe) and gives ±huge distances of the right sign.
    vec3 inv = 1.0 / mix(d, vec3(1e-30), equal(d, vec3(0.0)));
    vec3 t0 = (lo - o) * inv, t1 = (hi - o) * inv;
    vec3 tn = min(t0, t1), tf = max(t0, t1);
    a = max(max(tn.x, tn.y), tn.z);
    b = min(min(tf.x, tf.y), tf.z);
    return a <= b;
}

// The interval of primitive L along the ray (see span).
bool leafSpan(int L, vec3 ro, vec3 rd, out float a, out float b) {
    return span(T(L), T(L + 1), T(L + 2), T(L + 3), T(L + 4), T(L + 5), ro, rd, a, b);
}

bool inside(int program, int steps, uint mask) {
#ifdef CSG_TABLE
    // The program's truth table (SceneConverter.truthTable): one texel read instead of a loop over the program.
    uint chunk = mask >> 4u;
    vec4 entries = T(program + int(chunk >> 1u));
    uint bits = uint((chunk & 1u) == 0u ? entries.z : entries.w);
    return ((bits >> (mask & 15u)) & 1u) != 0u;
#else
    uint stack = 0u;
    for (int s = 0; s < steps; s++) {
        vec4 p = T(program + s);
        int op = int(p.x);
        if (op == 0) {
            stack = (stack << 1) | ((mask >> uint(p.y)) & 1u);
        } else {
            uint b = stack & 1u, a = (stack >> 1) & 1u;
            stack >>= 2;
            uint r = op == 1 ? (a | b) : op == 2 ? (a & b) : (a & (b ^ 1u));
            stack = (stack << 1) | r;
        }
    }
    return (stack & 1u) != 0u;
#endif
}

// First boundary of the entity at o with tMin < t < tMax (transmittance = false: returns 1 on a hit
// and fills tHit, leafHit), or the product of the transparencies of all boundaries crossed there.
// Leaf k's interval (a, b) as events after tMin, or as inside at tMin.
void event(int k, float a, float b, float tMin, inout uint mask, inout int n) {
    if (a <= tMin) {
        if (b > tMin) {
            mask |= 1u << uint(k);
            if (b != INF) { evT[n] = b; evL[n] = k; n++; }
        }
    } else {
        evT[n] = a; evL[n] = k; n++;
        if (b != INF) { evT[n] = b; evL[n] = k; n++; }
    }
}

float walk(int o, vec3 ro, vec3 rd, float tMin, float tMax, bool transmittance, out float tHit, out int leafHit) {
    vec4 h = T(o);
    int leaves = int(h.x), steps = int(h.y);
    float scale = h.w;
    int program = o + 3;
    int first = program + steps;
    tHit = INF;
    leafHit = -1;
    if (leaves == 1 && !transmittance) {
        float a, b;
        if (!leafSpan(first, ro, rd, a, b)) return 0.0;
        float t = firstAfter(a, b, tMin);
        if (t > tMin && t < tMax) { tHit = t; leafHit = 0; return 1.0; }
        return 0.0;
    }
    uint mask = 0u;
    int n = 0;
    for (int k = 0; k < leaves; k++) {
        float a, b;
#ifdef HAS_MESH
        int L = first + k * LEAF_TEXELS;
        if (int(T(L).x) == MESH) {
            vec4 r0 = T(L + 1), r1 = T(L + 2), r2 = T(L + 3);
            vec3 o = vec3(dot(r0.xyz, ro) + r0.w, dot(r1.xyz, ro) + r1.w, dot(r2.xyz, ro) + r2.w);
            vec3 d = vec3(dot(r0.xyz, rd), dot(r1.xyz, rd), dot(r2.xyz, rd));
            meshEvents(k, L, o, d, tMin, tMax, mask, n);
            continue;
        }
#endif
        if (!leafSpan(first + k * LEAF_TEXELS, ro, rd, a, b)) continue;
        event(k, a, b, tMin, mask, n);
#ifdef HAS_TORUS
        if (span2A != INF) event(k, span2A, span2B, tMin, mask, n);
#endif
    }
    for (int i = 1; i < n; i++) {
        float t = evT[i];
        int l = evL[i];
        int j = i;
#ifdef HAS_MESH
        int f = evF[i];
        while (j > 0 && evT[j - 1] > t) { evT[j] = evT[j - 1]; evL[j] = evL[j - 1]; evF[j] = evF[j - 1]; j--; }
        evF[j] = f;
#else
        while (j > 0 && evT[j - 1] > t) { evT[j] = evT[j - 1]; evL[j] = evL[j - 1]; j--; }
#endif
        evT[j] = t;
        evL[j] = l;
    }
    bool state = inside(program, steps, mask);
    float product = 1.0;
    int i = 0;
    while (i < n) {
        float t0 = evT[i];
        if (t0 >= tMax) break;
        // Boundaries this close are one boundary: coincident faces computed through different transforms.
        float limit = t0 + 2e-5 * (abs(t0) + scale);
        int shown = i;
        int j = i;
        for (; j < n && evT[j] <= limit; j++) {
            mask ^= 1u << uint(evL[j]);
            if (evL[j] >= evL[shown]) shown = j;
        }
        bool now = inside(program, steps, mask);
        if (now != state) {
            if (!transmittance) {
                tHit = evT[shown];
                leafHit = evL[shown];
#ifdef HAS_MESH
                faceHit = evF[shown];
#endif
                return 1.0;
            }
            product *= T(first + evL[shown] * LEAF_TEXELS + 7).z;
            if (product == 0.0) return 0.0;
        }
        state = now;
        i = j;
    }
    return transmittance ? product : 0.0;
}

// The geometric normal (in world coordinates) of the point normalAt last looked at: the one it
// returned, except on a smooth mesh, whose blended vertex normal is turned to its side of it.
vec3 geometricNormal;
// Where shadow rays start from, relative to p, for the point normalAt last looked at (a smooth mesh's lift).
vec3 shadowLift;

// The world normal of leaf L at p (face: the triangle, for a mesh leaf).
vec3 normalAt(int L, int face, vec3 p) {
    int kind = int(T(L).x);
    shadowLift = vec3(0.0);
    if (kind == PLANE) {
        geometricNormal = T(L + 1).xyz;
        return geometricNormal;
    }
    vec4 r0 = T(L + 1), r1 = T(L + 2), r2 = T(L + 3);
    vec3 q = vec3(dot(r0.xyz, p) + r0.w, dot(r1.xyz, p) + r1.w, dot(r2.xyz, p) + r2.w);
    vec3 n;
    if (kind == SPHERE) {
        n = q;
#ifdef HAS_MESH
    } else if (kind == MESH) {
        n = meshNormal(L, face, q);
#endif
#ifdef HAS_CONE
    } else if (kind == CONE) {
        // The cap or the side, whichever the point lies closer to (in scene units: the frame's z is the length).
        vec4 hd = T(L);
        float k = hd.z - hd.y, z = clamp(q.z, 0.0, 1.0), r = hd.y + k * z, rho = length(q.xy);
        float capDistance = min(abs(q.z), abs(q.z - 1.0)) * T(L + 4).x;
        if (hd.w != 0.0 && capDistance < abs(rho - r)) n = vec3(0.0, 0.0, q.z < 0.5 ? -1.0 : 1.0);
        else if (rho > 0.0 && r > 0.0) n = vec3(q.xy / rho, -k);
        else n = vec3(0.0, 0.0, k > 0.0 ? -1.0 : 1.0);
#endif
#ifdef HAS_TORUS
    } else if (kind == TORUS) {
        // Away from the nearest point of the ring circle.
        float rho = length(q.xy);
        vec2 around = rho > 0.0 ? q.xy / rho : vec2(1.0, 0.0);
        vec3 v = q - vec3(T(L).y * around, 0.0);
        n = dot(v, v) > 0.0 ? v : vec3(around, 0.0);
#endif
    } else {
        vec3 lo = T(L + 4).xyz, hi = T(L + 5).xyz;
        vec3 c = (q - 0.5 * (lo + hi)) / max(0.5 * (hi - lo), vec3(1e-30));
        vec3 ac = abs(c);
        n = ac.x >= ac.y && ac.x >= ac.z ? vec3(sign(c.x), 0, 0) : ac.y >= ac.z ? vec3(0, sign(c.y), 0) : vec3(0, 0, sign(c.z));
    }
    // The inverse transpose: the rows of the world-to-local matrix, weighted.
    vec3 world = normalize(n.x * r0.xyz + n.y * r1.xyz + n.z * r2.xyz);
    geometricNormal = world;
#ifdef HAS_MESH
    if (kind == MESH) {
        geometricNormal = normalize(meshGeometric.x * r0.xyz + meshGeometric.y * r1.xyz + meshGeometric.z * r2.xyz);
        if (T(L).y != 0.0) shadowLift = inverse(transpose(mat3(r0.xyz, r1.xyz, r2.xyz))) * meshLift;
    }
#endif
    return world;
}

// Whether the segment from ro to ro + tMax rd may meet a boundary of the entity at o: its bounds;
// for an entity that is one plane, the plane itself (the walk counts its crossing there). Both
// are computed and one kept: a branch costs every pixel its both sides on llvmpipe anyway.
bool boxCrossed(int o, vec3 ro, vec3 rd, float tMax) {
    vec4 lo = T(o + 1), hi = T(o + 2);
    vec3 inv = 1.0 / rd;
    vec3 t0 = (lo.xyz - ro) * inv, t1 = (hi.xyz - ro) * inv;
    vec3 tn = min(t0, t1), tf = max(t0, t1);
    float a = max(max(tn.x, tn.y), tn.z), b = min(min(tf.x, tf.y), tf.z);
    float tp = (hi.w - dot(hi.xyz, ro)) / dot(hi.xyz, rd);
    return lo.w == 0.0 ? !(a > b) && b > 0.0 && a < tMax : lo.w == 2.0 ? tp > 0.0 && tp < tMax : true;
}
