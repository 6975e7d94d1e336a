// Forward pass, fragment stage, for billboards and raylib Models: material -> lights -> output, the
// same code the deferred passes evaluate.
#include "material.glsl"
#include "lights.glsl"
#include "output.glsl"
#include "soft.glsl"
//   RBL_LINEAR_OUTPUT        write linear light (float targets); default: encode for display
//   RBL_DEBUG_OUTPUT v         RblDebugOutput: 1 tangent-space normal, 2 world normal, 3 specular, 4 occlusion (raw)

#if RBL_GLSL >= 300
out vec4 finalColor;
#else
#define finalColor gl_FragColor   // GLSL 1.x: the one built-in output
#endif

void main()
{
    float alpha;
    vec3 emission, tangentNormal;
    RblShadingPoint sp = rblMaterialSurface(alpha, emission, tangentNormal);
#ifdef RBL_SOFT_PARTICLES
    alpha *= rblSoftFade();
#endif
#ifdef RBL_VIEW_VECTOR
    vec3 v = rblViewVector(fragEye, fragViewAxis, fragPosition, sp.normal);
    float viewDistance = rblViewDistance(fragEye, fragViewAxis, fragPosition);
#else
    vec3 v = sp.normal;                      // unused: no view-dependent term compiled
    float viewDistance = 0.0;
#endif
    vec3 color = rblAmbientLight(sp) + rblDirectLight(sp, v) + emission;

#if defined(RBL_DEBUG_OUTPUT) && (RBL_DEBUG_OUTPUT == 1)
    finalColor = vec4(tangentNormal*0.5 + 0.5, 1.0);
#elif defined(RBL_DEBUG_OUTPUT) && (RBL_DEBUG_OUTPUT == 2)
    finalColor = vec4(sp.normal*0.5 + 0.5, 1.0);
#elif defined(RBL_DEBUG_OUTPUT) && (RBL_DEBUG_OUTPUT == 3)
#if RBL_BRDF == 2
    finalColor = vec4(vec3(sp.roughness), 1.0);
#else
    finalColor = vec4(vec3(sp.specular), 1.0);
#endif
#elif defined(RBL_DEBUG_OUTPUT) && (RBL_DEBUG_OUTPUT == 4)
    finalColor = vec4(vec3(sp.occlusion), 1.0);
#else
    finalColor = vec4(rblFinish(color, viewDistance), alpha);
#endif
}
