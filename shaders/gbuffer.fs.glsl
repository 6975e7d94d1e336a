// Deferred geometry pass, fragment stage: the forward path's material decoding, packed into the
// G-buffer (layout: gbuffer_codec.glsl) instead of being lit.
#include "material.glsl"
#include "gbuffer_codec.glsl"

layout(location = 0) out vec4 rblOutAlbedo;
layout(location = 1) out vec4 rblOutNormal;
layout(location = 2) out vec4 rblOutParams;
layout(location = 3) out vec4 rblOutAccum;

void main()
{
    float alpha;
    vec3 emission, tangentNormal;
    RblShadingPoint sp = rblMaterialSurface(alpha, emission, tangentNormal);
    rblOutAlbedo = vec4(rblLinearToSrgb(sp.albedo), sp.occlusion);
#if RBL_BRDF == 1
    // Blinn-Phong: the specular colour is folded into one intensity (its luminance; white in the G-buffer)
    float specular = sp.specular*dot(sp.specularColor, vec3(0.2126, 0.7152, 0.0722));
#elif RBL_BRDF == 2
    float specular = sp.roughness;
#else
    float specular = sp.specular;         // Lambert reads neither; the debug output shows the map
#endif
    rblOutNormal = vec4(rblPackNormal(sp.normal), clamp(specular, 0.0, 1.0));
#if RBL_BRDF == 1
    rblOutParams = vec4(rblPackShininess(sp.shininess), 0.0, 1.0);
#else
    rblOutParams = vec4(sp.metalness, 0.0, 0.0, 1.0);
#endif
    rblOutAccum = vec4(emission, 1.0);
}
