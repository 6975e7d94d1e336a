// Common: constants and helpers every stage shares (the one sRGB transfer pair, safe normalise).
// Included first by every stage (after dialect.glsl, its one include).
#include "dialect.glsl"

#define RBL_PI 3.14159265358979
#define RBL_HALF_MAX 65504.0        // radiance clamp: a half-float target never receives Inf
#define RBL_MIN_ROUGHNESS 0.045     // perceptual; alpha = 0.045^2 keeps D finite in fp32 (Filament's limit)

// Upper-left 3x3 (GLSL ES 1.00 has no mat3(mat4) constructor)
mat3 rblMat3(mat4 m)
{
    return mat3(m[0].xyz, m[1].xyz, m[2].xyz);
}

// normalize() of a zero vector is undefined (NaN on most GPUs): fall back instead.
vec3 rblSafeNormalize(vec3 v, vec3 fallback)
{
    float len2 = dot(v, v);
    return (len2 > 1e-20)? v*inversesqrt(len2) : fallback;
}

// The viewer of a shaded point: eye = camera position; axis.xyz = unit camera back direction (target
// toward eye), axis.w = 1 for an orthographic projection (else 0). A parallel projection has no eye
// point: every ray runs along the axis, so the view vector is the axis itself everywhere.
vec3 rblViewVector(vec3 eye, vec4 axis, vec3 position, vec3 fallback)
{
    return (axis.w > 0.5)? axis.xyz : rblSafeNormalize(eye - position, fallback);
}

// Fog distance: to the eye (perspective); orthographic, along the view axis from the camera's plane
float rblViewDistance(vec3 eye, vec4 axis, vec3 position)
{
    return (axis.w > 0.5)? max(dot(eye - position, axis.xyz), 0.0) : length(position - eye);
}

// Exact sRGB transfer functions (IEC 61966-2-1). Every raylib Color, albedo and emissive texel is
// sRGB; lighting runs in linear light.
vec3 rblSrgbToLinear(vec3 c)
{
    return mix(c/12.92, pow((c + 0.055)/1.055, vec3(2.4)), step(vec3(0.04045), c));
}

vec3 rblLinearToSrgb(vec3 c)
{
    c = clamp(c, 0.0, 1.0);
    return mix(c*12.92, 1.055*pow(c, vec3(1.0/2.4)) - 0.055, step(vec3(0.0031308), c));
}
