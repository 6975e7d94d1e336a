// Deferred light volume pass, fragment stage: one bounded light per instance, added into the
// accumulation target; pixels outside the light's range are rejected from depth alone.
//   RBL_COUNT_LIGHTS    add 1 per light evaluated instead of light (heat-map view)
#include "gbuffer_read.glsl"
#include "lights.glsl"

RBL_FLAT RBL_VARYING vec4 volumePosition;
RBL_FLAT RBL_VARYING vec4 volumeColor;
RBL_FLAT RBL_VARYING vec4 volumeSpot;
RBL_FLAT RBL_VARYING vec4 volumeFalloff;             // xyz attenuation, w code: shadow map index + 1 (0 = none) + 8 x (relief bit + 1)
out vec4 finalColor;

void main()
{
    ivec2 texel;
    float depth;
    if (!rblLightPassTexel(texel, depth)) discard;
    vec3 position = rblPositionFromDepth(texel, depth);
    // Most of a proxy's pixels lie outside the light's range
    vec3 toLight = volumePosition.xyz - position;
    if (dot(toLight, toLight)*volumeColor.a*volumeColor.a >= 1.0) discard;
#ifdef RBL_COUNT_LIGHTS
    finalColor = vec4(1.0, 1.0, 1.0, 0.0);     // alpha 0: the accumulation target's alpha keeps the occlusion
#else
    RblShadingPoint s = rblGBufferSurface(texel, position);
    vec3 v = rblViewVector(rblEye, rblViewAxis, s.position, s.normal);
    int code = int(volumeFalloff.w + 0.5);
#ifdef RBL_GB_RELIEF
    rblGbReliefLight = code/8 - 1;
#endif
#if RBL_SHADOWS > 0
    int map = code - 8*(code/8) - 1;
    vec3 l = rblSafeNormalize(volumePosition.xyz - s.position, s.normal);
    float NdotL = dot(s.normal, l);
#ifdef RBL_TRANSMISSION
    if (s.transmission > 0.0) NdotL = 1.0;          // the light behind the card is shadowed on its way too
#endif
    float shadow = ((map >= 0) && (NdotL > 0.0))? rblShadowAt(map, s, l) : 1.0;
#else
    float shadow = 1.0;
#endif
    vec3 light = rblEvalLight(s, v, volumePosition, volumeColor, volumeSpot, volumeFalloff.xyz, shadow);
#if (RBL_SHADOWS > 0) && defined(RBL_SHADOW_TINT)
    if (map >= 0) light *= rblShadowTint(map, s.position);
#endif
    finalColor = vec4(light, 0.0);
#endif
}
