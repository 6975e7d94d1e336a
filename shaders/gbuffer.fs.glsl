// Deferred geometry pass, fragment stage: the forward path's material decoding, packed into the
// G-buffer (layout: gbuffer_codec.glsl) instead of being lit. The emission (material data, like the
// albedo) and the occlusion go to the accumulation target; the scene's ambient is added once per
// pixel by the resolve, not per overdrawn layer here.
#include "material.glsl"
#include "gbuffer_codec.glsl"

layout(location = 0) out vec4 rblOutAlbedo;
layout(location = 1) out vec4 rblOutNormal;
layout(location = 2) out vec4 rblOutParams;
layout(location = 3) out vec4 rblOutAccum;
#ifdef RBL_GB_THIN
// RT4 where the context has 5 draw buffers: every geometry variant writes it (zero without the
// features), so a G-buffer with the thin target never keeps a hidden layer's values; a G-buffer
// without it has no 5th draw buffer and the output goes nowhere
layout(location = 4) out vec4 rblOutThin;
#endif
#ifdef RBL_RELIEF_STEPS
// The scene's first RBL_LIGHTS lights (as lights.glsl declares them), each marched through the relief
uniform int rblLightCount;
uniform vec4 rblLightPosition[RBL_LIGHTS];
#endif

void main()
{
    float alpha;
    vec3 emission, tangentNormal;
    RblShadingPoint sp = rblMaterialSurface(alpha, emission, tangentNormal);
#if RBL_BRDF == 1
    // Blinn-Phong: the specular colour is folded into one intensity (its luminance; white in the G-buffer)
    float specular = sp.specular*dot(sp.specularColor, vec3(0.2126, 0.7152, 0.0722));
    uint field1 = rblQuantize(rblEncodeShininess(sp.shininess), RBL_GB_FIELD1_BITS);
    uint field2 = rblQuantize(rblEncodeIntensity(specular), RBL_GB_FIELD2_BITS);
#elif RBL_BRDF == 2
    uint field1 = rblQuantize(rblEncodeRoughness(sp.roughness), RBL_GB_FIELD1_BITS);
    uint field2 = rblQuantize(sp.metalness, RBL_GB_FIELD2_BITS);
#else
    uint field1 = 0u;                      // Lambert reads neither; the debug output shows the map
    uint field2 = rblQuantize(sp.specular, RBL_GB_FIELD2_BITS);
#endif
    vec2 params;
    float albedoA;
    rblPackWord(sp.normal, field1, field2, rblOutNormal, albedoA, params);
    rblOutAlbedo = vec4(rblLinearToSrgb(sp.albedo), albedoA);
    // RG8 keeps x, y (raylib samples it r,r,r,g: read back as .ra); RGBA8 (ES, or a G-buffer that
    // receives shadows) also the caster identity (gbuffer_read.glsl)
    rblOutParams = vec4(params.x, params.y, sp.caster);
    rblOutAccum = vec4(emission, sp.occlusion);
#ifdef RBL_GB_THIN
    // Relief: bit i set where the scene's light i is behind relief (lights.glsl's l, at the unquantised
    // position), for the light passes to read; transmission: the share in 16 bits (8 would leave
    // 2/255 in dark sRGB output under a bright light behind)
    float mask = 0.0;
#ifdef RBL_RELIEF_STEPS
    for (int i = 0; i < RBL_LIGHTS; i++)
    {
        if (i >= rblLightCount) break;
        vec4 p = rblLightPosition[i];
        if (rblReliefShadow(rblSafeNormalize(p.xyz - sp.position*p.w, sp.normal)) == 0.0) mask += exp2(float(i));
    }
#endif
    float t = floor(clamp(sp.transmission, 0.0, 1.0)*65535.0 + 0.5);
    rblOutThin = vec4(floor(t/256.0), mod(t, 256.0), mask, 0.0)/255.0;
#endif
}
