// Shadow pass, fragment stage. The alpha test is the colour pass's own (albedo x colDiffuse x vertex
// colour against the material's cutoff): a sprite's silhouette casts the shadow, not its quad.
// Nothing else is sampled. The depth target gets the nearest caster; the casters target (RGBA8,
// RblShadowMap.casters; absent with RblShadowDesc.selfShadow) gets what shadows.glsl reads of it:
//   rg   its distance along the light's axis as a 16-bit code (high byte first): orthographic, the
//        window depth (linear over near..far); perspective, log(d/near)/log(far/near), a step a fixed
//        share of the distance, as a perspective texel is
//   ba   its caster identity: a billboard's from its pivot, 0 for Models (shadows.glsl)
// Blended casters (RBL_CASTER_TRANSMIT, RblBeginShadowBlend) write the transmittance target instead
// (shadow_tint.glsl): rgb what they let through, multiplied in by the blending (1 - alpha, or
// mix(1, colour, alpha) with rblCasterTint 1), a the distance code's top 8 bits (kept by min blending)
#include "material.glsl"

uniform vec4 rblCasterDepth;    // perspective (0/1), near, far, log(far/near)
#ifdef RBL_CASTER_TRANSMIT
uniform float rblCasterTint;    // 1: tinted by the caster's colour, 0: grey (coverage only)
#endif
#if RBL_GLSL >= 300
out vec4 rblOutCaster;
#else
#define rblOutCaster gl_FragColor
#endif

void main()
{
    float alpha;
    vec3 emission, tangentNormal;
    RblShadingPoint sp = rblMaterialSurface(alpha, emission, tangentNormal);     // discards below the cutoff
    float code = gl_FragCoord.z;
    if (rblCasterDepth.x > 0.5) code = log(max(1.0/gl_FragCoord.w, rblCasterDepth.y)/rblCasterDepth.y)/rblCasterDepth.w;
#ifdef RBL_CASTER_TRANSMIT
    vec3 through = (rblCasterTint > 0.5)? sp.albedo : vec3(0.0);
    rblOutCaster = vec4(mix(vec3(1.0), through, clamp(alpha, 0.0, 1.0)), floor(clamp(code, 0.0, 1.0)*255.0)/255.0);
    return;
#endif
    float v = floor(clamp(code, 0.0, 1.0)*65535.0 + 0.5);
    float high = floor(v/256.0);
    rblOutCaster = vec4(high/255.0, (v - high*256.0)/255.0, sp.caster);
}
