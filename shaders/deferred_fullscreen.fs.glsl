// Deferred full-screen light pass, fragment stage: up to RBL_LIGHTS unbounded lights (directional,
// range 0), added into the accumulation target's rgb (alpha 0 keeps the occlusion there).
//   RBL_COUNT_LIGHTS    add the number of lights evaluated instead of light (heat-map view)
#include "gbuffer_read.glsl"
#include "lights.glsl"

RBL_VARYING vec2 fragUv;
out vec4 finalColor;

void main()
{
    ivec2 texel;
    float depth;
    if (!rblLightPassTexel(texel, depth)) discard;
#ifdef RBL_COUNT_LIGHTS
    finalColor = vec4(vec3(float(rblLightCount)), 0.0);
#else
    RblShadingPoint s = rblGBufferSurface(texel, rblPositionFromDepth(texel, depth));
    finalColor = vec4(rblDirectLight(s, rblViewVector(rblEye, rblViewAxis, s.position, s.normal)), 0.0);
#endif
}
