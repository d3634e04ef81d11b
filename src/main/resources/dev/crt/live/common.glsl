// Shared by the entity and background fragment shaders: the camera model of rendering-model.md
// and the background formulas.
uniform vec2 viewportOrigin;
uniform vec2 viewportSize;
uniform bool orthographic;
uniform vec3 cameraPosition;
uniform vec3 cameraForward;
uniform vec3 cameraRight;
uniform vec3 cameraUp;
uniform float halfHeight;     // tan(fov/2), or the half height of an orthographic view in scene units
uniform vec3 background0;
uniform vec3 background1;
uniform float panoramaAngle;
uniform sampler2D panorama;
uniform float gamma;
uniform float gridSpacing;
uniform int gridAxis;

#define INF uintBitsToFloat(0x7F800000u)
const float PI = 3.14159265358979;

// Pixel (i, j) of the viewport, j = 0 at the top, through its centre: gl_FragCoord is already the centre.
void primaryRay(out vec3 origin, out vec3 direction) {
    vec2 p = gl_FragCoord.xy - viewportOrigin;
    float x = 2.0 * p.x / viewportSize.x - 1.0;
    float y = 2.0 * p.y / viewportSize.y - 1.0;
    float aspect = viewportSize.x / viewportSize.y;
    if (orthographic) {
        origin = cameraPosition + x * halfHeight * aspect * cameraRight + y * halfHeight * cameraUp;
        direction = cameraForward;
    } else {
        origin = cameraPosition;
        direction = normalize(cameraForward + x * halfHeight * aspect * cameraRight + y * halfHeight * cameraUp);
    }
}

// BACKGROUND_KIND is defined per program (0 colour, 1 gradient, 2 panorama): llvmpipe runs every
// branch of a shader for every pixel, so the kinds not used must not be compiled in.
vec3 backgroundColour(vec3 d) {
#if BACKGROUND_KIND == 0
    return background0;
#elif BACKGROUND_KIND == 1
    float e = clamp(asin(clamp(d.y / length(d), -1.0, 1.0)) / (PI / 2.0), 0.0, 1.0);
    return (1.0 - e) * background0 + e * background1;
#else
    float u = fract(0.5 + (atan(d.x, d.z) + panoramaAngle) / (2.0 * PI));
    float v = 0.5 - asin(clamp(d.y / length(d), -1.0, 1.0)) / PI;
    return textureLod(panorama, vec2(u, v), 0.0).rgb;
#endif
}

vec4 encode(vec3 c) {
#ifdef LINEAR_OUTPUT
    return vec4(clamp(c, 0.0, 1.0), 1.0);
#else
    return vec4(pow(clamp(c, 0.0, 1.0), vec3(1.0 / gamma)), 1.0);
#endif
}
