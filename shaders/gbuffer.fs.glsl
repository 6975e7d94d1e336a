// Deferred geometry pass: the forward shader's material decoding (material.glsl), written to the
// G-buffer instead of being lit. The loader prepends "#version 330", the variant #defines,
// lighting.glsl and material.glsl. Layout (RblLoadGBuffer; 10 bytes per pixel + depth):
//   location 0  RGBA8    rgb albedo, sRGB-encoded (8-bit steps where the eye needs them), a occlusion
//   location 1  RGBA8    rgb world normal, octahedral 12+12 bits (rblPackNormal), a specular
//                        (Blinn-Phong intensity / GGX perceptual roughness)
//   location 2  RG8      Blinn-Phong: log2(shininess)/11 in 16 bits (r high, g low byte); GGX: r metalness
//   location 3  RGBA16F  light accumulation: the emission goes in here now, lights are added later
// Position is never stored: the lighting passes rebuild it from the depth texture.

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
#else
    float specular = sp.specular;
#endif
    rblOutNormal = vec4(rblPackNormal(sp.normal), clamp(specular, 0.0, 1.0));
#if RBL_BRDF == 1
    float code = floor(clamp(log2(max(sp.shininess, 1.0))/11.0, 0.0, 1.0)*65535.0 + 0.5);
    rblOutParams = vec4(floor(code/256.0)/255.0, mod(code, 256.0)/255.0, 0.0, 1.0);
#else
    rblOutParams = vec4(sp.metalness, 0.0, 0.0, 1.0);
#endif
    rblOutAccum = vec4(emission, 1.0);
}
