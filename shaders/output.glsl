// Output: fog, half-float clamp, exposure, tonemap and the display encoding, in that order (the
// scene's fog and exposure; the program's compiled tonemap and encoding).
//   RBL_FOG f                 0 none, 1 linear, 2 exp, 3 exp2 (by rblViewDistance: to the eye, or
//                             along the view axis for an orthographic camera)
//   RBL_TONEMAP t             0 none, 1 Reinhard, 2 ACES fit (Narkowicz 2015)
//   RBL_GAMMA g               encode with pow(1/g) instead of the exact sRGB curve
//   RBL_LINEAR_OUTPUT         keep linear light (float targets)
#include "common.glsl"

#if RBL_FOG > 0
uniform vec4 rblFog;                        // rgb linear colour, a: density (exp/exp2) or 1/(end - start) (linear)
uniform float rblFogStart;                  // linear fog: distance where it begins
#endif
uniform float rblExposure;                  // the scene's exposure

// Fog at view distance d, exposure, tonemap and the display encoding, in that order. linearOut keeps
// linear light (clamped to half-float range) for float targets.
vec3 rblFinish(vec3 color, float d)
{
#if RBL_FOG > 0
#if RBL_FOG == 1
    float visible = clamp(1.0 - (d - rblFogStart)*rblFog.a, 0.0, 1.0);
#elif RBL_FOG == 2
    float visible = exp(-rblFog.a*d);
#else
    float visible = exp(-(rblFog.a*d)*(rblFog.a*d));
#endif
    color = mix(rblFog.rgb, color, visible);
#endif
    color = clamp(color, 0.0, RBL_HALF_MAX);
    color *= rblExposure;
#if RBL_TONEMAP == 1
    color = color/(1.0 + color);
#elif RBL_TONEMAP == 2
    color = min(color, vec3(RBL_HALF_MAX));
    color = clamp(color*(2.51*color + 0.03)/(color*(2.43*color + 0.59) + 0.14), 0.0, 1.0);
#endif
#if defined(RBL_LINEAR_OUTPUT)
    return min(color, vec3(RBL_HALF_MAX));
#elif defined(RBL_GAMMA)
    return pow(clamp(color, 0.0, 1.0), vec3(1.0/RBL_GAMMA));
#else
    return rblLinearToSrgb(color);
#endif
}
