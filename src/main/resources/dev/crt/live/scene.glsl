// Ray-casting of top-level entities (their blocks in the scene buffer, see GpuScene) exactly: each
// primitive's interval along the ray, then a walk over the sorted boundary events that evaluates
// the CSG program on the set of primitives the ray is inside: the same method as the ray tracer.
uniform samplerBuffer scene;

const int SPHERE = 0, BOX = 1, PLANE = 2;
const int LEAF_TEXELS = 9;
const int MAX_EVENTS = 64;

float evT[MAX_EVENTS];
int evL[MAX_EVENTS];

vec4 T(int i) { return texelFetch(scene, i); }

bool leafSpan(int L, vec3 ro, vec3 rd, out float a, out float b) {
    int kind = int(T(L).x);
    if (kind == PLANE) {
        vec4 pl = T(L + 1);
        float dn = dot(pl.xyz, rd), on = dot(pl.xyz, ro);
        if (dn == 0.0) { a = -INF; b = INF; return on <= pl.w; }
        float t = (pl.w - on) / dn;
        if (dn < 0.0) { a = t; b = INF; } else { a = -INF; b = t; }
        return true;
    }
    if (kind > PLANE) return false;
    vec4 r0 = T(L + 1), r1 = T(L + 2), r2 = T(L + 3);
    vec3 o = vec3(dot(r0.xyz, ro) + r0.w, dot(r1.xyz, ro) + r1.w, dot(r2.xyz, ro) + r2.w);
    vec3 d = vec3(dot(r0.xyz, rd), dot(r1.xyz, rd), dot(r2.xyz, rd));
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
    vec3 lo = T(L + 4).xyz, hi = T(L + 5).xyz;
    // A ray parallel to a slab: a tiny component instead of 0 keeps the slab test branch-free (a
    // branch costs every pixel on llvmpipe) and gives ±huge distances of the right sign.
    vec3 inv = 1.0 / mix(d, vec3(1e-30), equal(d, vec3(0.0)));
    vec3 t0 = (lo - o) * inv, t1 = (hi - o) * inv;
    vec3 tn = min(t0, t1), tf = max(t0, t1);
    a = max(max(tn.x, tn.y), tn.z);
    b = min(min(tf.x, tf.y), tf.z);
    return a <= b;
}

bool inside(int program, int steps, uint mask) {
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
}

// First boundary of the entity at o with tMin < t < tMax (transmittance = false: returns 1 on a hit
// and fills tHit, leafHit), or the product of the transparencies of all boundaries crossed there.
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
        float t = a > tMin ? a : b;
        if (t > tMin && t < tMax) { tHit = t; leafHit = 0; return 1.0; }
        return 0.0;
    }
    uint mask = 0u;
    int n = 0;
    for (int k = 0; k < leaves; k++) {
        float a, b;
        if (!leafSpan(first + k * LEAF_TEXELS, ro, rd, a, b)) continue;
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
    for (int i = 1; i < n; i++) {
        float t = evT[i];
        int l = evL[i];
        int j = i;
        while (j > 0 && evT[j - 1] > t) { evT[j] = evT[j - 1]; evL[j] = evL[j - 1]; j--; }
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
            if (!transmittance) { tHit = evT[shown]; leafHit = evL[shown]; return 1.0; }
            product *= T(first + evL[shown] * LEAF_TEXELS + 7).z;
            if (product == 0.0) return 0.0;
        }
        state = now;
        i = j;
    }
    return transmittance ? product : 0.0;
}

vec3 normalAt(int L, vec3 p) {
    int kind = int(T(L).x);
    if (kind == PLANE) return T(L + 1).xyz;
    vec4 r0 = T(L + 1), r1 = T(L + 2), r2 = T(L + 3);
    vec3 q = vec3(dot(r0.xyz, p) + r0.w, dot(r1.xyz, p) + r1.w, dot(r2.xyz, p) + r2.w);
    vec3 n;
    if (kind == SPHERE) {
        n = q;
    } else {
        vec3 lo = T(L + 4).xyz, hi = T(L + 5).xyz;
        vec3 c = (q - 0.5 * (lo + hi)) / max(0.5 * (hi - lo), vec3(1e-30));
        vec3 ac = abs(c);
        n = ac.x >= ac.y && ac.x >= ac.z ? vec3(sign(c.x), 0, 0) : ac.y >= ac.z ? vec3(0, sign(c.y), 0) : vec3(0, 0, sign(c.z));
    }
    // The inverse transpose: the rows of the world-to-local matrix, weighted.
    return normalize(n.x * r0.xyz + n.y * r1.xyz + n.z * r2.xyz);
}

bool boxCrossed(int o, vec3 ro, vec3 rd, float tMax) {
    vec4 lo = T(o + 1), hi = T(o + 2);
    if (lo.w != 0.0) return true;
    vec3 inv = 1.0 / rd;
    vec3 t0 = (lo.xyz - ro) * inv, t1 = (hi.xyz - ro) * inv;
    vec3 tn = min(t0, t1), tf = max(t0, t1);
    float a = max(max(tn.x, tn.y), tn.z), b = min(min(tf.x, tf.y), tf.z);
    return !(a > b) && b > 0.0 && a < tMax;
}
