// Material: fragment inputs, the material's maps and per-draw values, alpha test, normal-map decode
// and tangent frame -> RblShadingPoint. Shared by every pass that shades a material (lit.fs.glsl,
// gbuffer.fs.glsl, shadow_caster.fs.glsl). Colour (albedo, emissive, vertex tint, colDiffuse) is sRGB
// and decoded to linear light; data maps (normal, specular/roughness, occlusion) are linear.
// Material defines (absent maps are never declared, so never sampled):
//   RBL_NORMAL_ENCODING e    0 none, 1 hemi-octahedral RG, 2 XY RG (+Z rebuilt), 3 plain RGB map
//   RBL_SPECULAR             material texture B: Blinn-Phong specular intensity / GGX roughness
//   RBL_OCCLUSION            material texture A holds ambient occlusion
//   RBL_EMISSIVE e           0 none, 1 mask (texture5.r x albedo), 2 sRGB colour (texture5.rgb)
//   RBL_PREMULTIPLIED_ALPHA  albedo texels hold colour x alpha (libGDX pma): the filtered texel is
//                            divided by its alpha before decoding (the alpha-weighted mean of its
//                            neighbours' colours, no dark fringe); lit and written as straight alpha
//   RBL_VIEW_VECTOR          the eye position is needed (specular BRDF or fog)
//   RBL_CASTER_ID            the billboard's caster identity arrives (receivers, casters, G-buffer)
//   RBL_CROSS_FADE           a second atlas frame mixed in (RblLitShaderDesc.crossFade): every map
//                            is fetched at both texture coordinates. What is mixed: colour in linear
//                            light weighted by coverage (alpha), as the mips average; alpha linearly,
//                            the cutoff applies to the mixed alpha; the normal as a world vector (each
//                            fetch decoded in its own frame's tangent axes), then renormalised;
//                            specular, occlusion and emission with the colour's coverage weight
//   RBL_TRANSMISSION, RBL_THICKNESS_CHANNEL   the card lets light through (transmission.glsl)
//   RBL_RELIEF_STEPS, RBL_HEIGHT_CHANNEL      relief self-shadow (relief.glsl): the tangent frame kept for the lights
#include "surface.glsl"
#include "transmission.glsl"
#include "relief.glsl"

RBL_VARYING vec3 fragPosition;
RBL_VARYING vec2 fragTexCoord;
RBL_VARYING vec4 fragColor;              // vertex colour, already linear (decoded in the vertex stage)
RBL_VARYING vec3 fragNormal;
RBL_VARYING vec4 fragTangent;
#ifdef RBL_VIEW_VECTOR
RBL_FLAT RBL_VARYING vec3 fragEye;           // camera position (from matView in the vertex stage)
RBL_FLAT RBL_VARYING vec4 fragViewAxis;      // camera back direction, w 1 orthographic (rblViewVector)
#endif

#ifdef RBL_CASTER_ID
RBL_FLAT RBL_VARYING vec2 fragCasterId;  // the billboard's caster identity (lit.vs.glsl), 0 for Models
#endif

#ifdef RBL_CROSS_FADE
RBL_VARYING vec2 fragTexCoord2;          // the second frame's texture coordinate
RBL_FLAT RBL_VARYING vec2 fragFade;      // x weight 0..1 of the second frame, y its tangent axes (rblFadeAxes)
// Each frame's position within its own trimmed rectangle (xy the first, zw the second): inside is
// 0..1 on both axes; an axis the frame covers whole is a constant 0.5 (never clipped by rounding)
RBL_VARYING vec4 fragFadeClip;
// Exact ends: weight 0 is the first frame and 1 the second, bit for bit (no mix rounding)
#define rblFadeMix(a, b, w) (((w) <= 0.0)? (a) : (((w) >= 1.0)? (b) : mix((a), (b), (w))))
#endif

uniform sampler2D texture0;     // albedo (sRGB)
#if (RBL_NORMAL_ENCODING > 0) || defined(RBL_SPECULAR) || defined(RBL_OCCLUSION) || defined(RBL_HEIGHT_CHANNEL) || defined(RBL_THICKNESS_CHANNEL)
#define RBL_MATERIAL_TEXTURE
uniform sampler2D texture2;     // packed material (MATERIAL_MAP_NORMAL slot): RG normal, B specular, A occlusion
#endif
#if RBL_EMISSIVE > 0
uniform sampler2D texture5;     // emissive (MATERIAL_MAP_EMISSION slot)
uniform float rblEmissiveIntensity;
#endif
uniform vec3 rblEmissiveColor;  // constant emission (linear, intensity applied; the material's EMISSION colour)
#if RBL_BRDF == 1
uniform vec4 rblSpecularColor;  // rgb linear specular colour x intensity, a shininess
#elif RBL_BRDF == 2
uniform vec2 rblRoughMetal;     // perceptual roughness (when no map), metalness
#endif
uniform vec4 colDiffuse;        // sRGB, as raylib sets it
uniform vec2 rblAlphaCutoff;   // kept from x (the material's cutoff) up to, not including, y (a hybrid batch's solid alpha; 2 otherwise)

// Tangent-space normal from the material texture; the exact mirror of RblDecodeNormal() on the CPU
// (a decoded vector shorter than 1/64 is quantisation noise around zero: the flat normal)
vec3 rblDecodedUnit(vec3 e)
{
    return (dot(e, e) < 1.0/4096.0)? vec3(0.0, 0.0, 1.0) : normalize(e);
}

vec3 rblDecodeNormal(vec4 m)
{
#if RBL_NORMAL_ENCODING == 1
    vec2 e = m.rg*2.0 - 1.0;                                // hemi-octahedral, stored rotated 45 degrees
    vec2 p = vec2(e.x + e.y, e.x - e.y)*0.5;
    return rblDecodedUnit(vec3(p, 1.0 - max(abs(e.x), abs(e.y))));     // = 1-|p.x|-|p.y|, never negative
#elif RBL_NORMAL_ENCODING == 2
    vec2 e = m.rg*2.0 - 1.0;                                // X and Y, Z rebuilt
    return rblDecodedUnit(vec3(e, sqrt(max(0.0, 1.0 - dot(e, e)))));
#elif RBL_NORMAL_ENCODING == 3
    return rblDecodedUnit(m.rgb*2.0 - 1.0);                 // plain RGB map
#else
    return vec3(0.0, 0.0, 1.0);
#endif
}

#ifdef RBL_CROSS_FADE
// The second frame's tangent axes from the first's (t = +U, b = +V, both world): code = swap + 2 negT
// + 4 negV, where swap says its +U runs along the first's V (a frame stored rotated differently)
void rblFadeAxes(float code, vec3 t, vec3 b, out vec3 t2, out vec3 b2)
{
    float c = floor(code + 0.5);                // interpolated (GLSL 1.x has no flat): round
    bool swapAxes = mod(c, 2.0) > 0.5;
    t2 = (swapAxes? b : t)*((mod(floor(c*0.5), 2.0) > 0.5)? -1.0 : 1.0);
    b2 = (swapAxes? t : b)*((c > 3.5)? -1.0 : 1.0);
}

// Weight of the second frame's surface values: its share of the mixed coverage, so the colour and
// data of a transparent texel (gutter or background) never bleed in
// 1 inside a frame's trimmed rectangle, 0 outside (there it is transparent: no colour, no normal)
float rblFadeInside(vec2 local)
{
    return ((local.x >= 0.0) && (local.x <= 1.0) && (local.y >= 0.0) && (local.y <= 1.0))? 1.0 : 0.0;
}

float rblFadeCoverage(float w, float a1, float a2)
{
    if (w <= 0.0) return 0.0;
    if (w >= 1.0) return 1.0;
    float a = mix(a1, a2, w);
    return (a > 0.0)? clamp(w*a2/a, 0.0, 1.0) : w;
}
#endif

// A filtered albedo texel as straight (not premultiplied) sRGB colour and alpha
vec4 rblStraightAlpha(vec4 texel)
{
#ifdef RBL_PREMULTIPLIED_ALPHA
    return vec4((texel.a > 0.0)? min(texel.rgb/texel.a, vec3(1.0)) : vec3(0.0), texel.a);
#else
    return texel;
#endif
}

// The material at this fragment: discards below the alpha cutoff; alpha, emission and the
// tangent-space normal (debug views) come back through the out parameters
RblShadingPoint rblMaterialSurface(out float alpha, out vec3 emission, out vec3 tangentNormal)
{
    // The surface as rasterised (what a shadow map holds): the card's plane, not the rounded or
    // normal-mapped normal that shades it; without derivatives (ES 2 lacking the extension) the
    // interpolated vertex normal. Taken before any discard (derivatives need the whole quad)
#ifdef RBL_DERIVATIVES
    vec3 face = rblSafeNormalize(cross(dFdx(fragPosition), dFdy(fragPosition)), rblSafeNormalize(fragNormal, vec3(0.0, 0.0, 1.0)));
#else
    vec3 face = rblSafeNormalize(fragNormal, vec3(0.0, 0.0, 1.0));
#endif
    vec4 texel = rblStraightAlpha(texture(texture0, fragTexCoord));
#ifdef RBL_CROSS_FADE
    // Both fetches outside any branch: implicit derivatives (mips) need every pixel of a quad to sample
    vec4 texel2 = rblStraightAlpha(texture(texture0, fragTexCoord2));
    float fade = fragFade.x;
    float inside1 = rblFadeInside(fragFadeClip.xy), inside2 = rblFadeInside(fragFadeClip.zw);
    // Outside the frame shown alone (or both) there is no fragment, as with that frame's own quad
    if ((inside1 + inside2 == 0.0) || ((fade <= 0.0) && (inside1 == 0.0)) || ((fade >= 1.0) && (inside2 == 0.0))) discard;
    texel *= inside1;
    texel2 *= inside2;
    float cover = rblFadeCoverage(fade, texel.a, texel2.a);
    texel = vec4(rblFadeMix(rblSrgbToLinear(texel.rgb), rblSrgbToLinear(texel2.rgb), cover), rblFadeMix(texel.a, texel2.a, fade));
    vec4 albedo = vec4(texel.rgb*rblSrgbToLinear(colDiffuse.rgb)*fragColor.rgb, texel.a*colDiffuse.a*fragColor.a);
#else
    vec4 albedo = vec4(rblSrgbToLinear(texel.rgb)*rblSrgbToLinear(colDiffuse.rgb)*fragColor.rgb, texel.a*colDiffuse.a*fragColor.a);
#endif
    if ((albedo.a < rblAlphaCutoff.x) || (albedo.a >= rblAlphaCutoff.y)) discard;

    vec3 n = rblSafeNormalize(fragNormal, vec3(0.0, 0.0, 1.0));
    // Two-sided: a back face (a card seen from behind, an open mesh from inside) is shaded on the
    // side the viewer sees, as the card's mirror image through its plane: the normal flips, the
    // normal map's tangent components stay (a relief reads raised from both sides). The winding says
    // which side is seen for any projection, where dot(N, view) would also flip the interpolated
    // normals of front faces near a smooth silhouette.
    float side = gl_FrontFacing? 1.0 : -1.0;
#ifdef RBL_MATERIAL_TEXTURE
    vec4 material = texture(texture2, fragTexCoord);
#ifdef RBL_CROSS_FADE
    vec4 material2 = texture(texture2, fragTexCoord2);
#endif
#endif
    tangentNormal = vec3(0.0, 0.0, 1.0);
#if (RBL_NORMAL_ENCODING > 0) || defined(RBL_RELIEF_STEPS)
    // Re-orthogonalise the interpolated tangent; cross(N,T)*w is the +V direction (raylib's
    // GenMeshTangents convention), and +V runs down the image, so the map's +Y is -B.
    vec3 t = fragTangent.xyz - n*dot(n, fragTangent.xyz);
    vec3 anyPerp = (abs(n.z) < 0.9)? vec3(-n.y, n.x, 0.0) : vec3(0.0, -n.z, n.y);
    t = rblSafeNormalize(t, rblSafeNormalize(anyPerp, vec3(1.0, 0.0, 0.0)));
    vec3 b = cross(n, t)*((fragTangent.w < 0.0)? -1.0 : 1.0);
#ifdef RBL_RELIEF_STEPS
    rblReliefSetup(texture2, fragTexCoord, t, b, n*side);
#endif
#endif
#if RBL_NORMAL_ENCODING > 0
    tangentNormal = rblDecodeNormal(material);
#ifdef RBL_CROSS_FADE
    // Each fetch in its own frame's axes, mixed as world vectors, renormalised (opposite normals
    // cancel to the geometric one); the debug view gets the mix in the first frame's axes
    vec3 n1 = t*tangentNormal.x - b*tangentNormal.y + n*(side*tangentNormal.z);
    vec3 t2, b2;
    rblFadeAxes(fragFade.y, t, b, t2, b2);
    vec3 m2 = rblDecodeNormal(material2);
    vec3 n2 = t2*m2.x - b2*m2.y + n*(side*m2.z);
    vec3 nm = rblFadeMix(n1, n2, cover);
    if (cover > 0.0)
    {
        nm = rblSafeNormalize(nm, n*side);
        tangentNormal = vec3(dot(nm, t), -dot(nm, b), side*dot(nm, n));
    }
    n = rblSafeNormalize(nm, n*side);
#else
    n = rblSafeNormalize(t*tangentNormal.x - b*tangentNormal.y + n*(side*tangentNormal.z), n*side);
#endif
#else
    n *= side;
#endif
#if defined(RBL_CROSS_FADE) && defined(RBL_MATERIAL_TEXTURE)
    material = rblFadeMix(material, material2, cover);       // specular and occlusion (the normal is done)
#endif
    RblShadingPoint sp;
    sp.position = fragPosition;
    sp.normal = n;
    sp.albedo = albedo.rgb;
    sp.specular = 1.0;
    sp.roughness = 0.5;
    sp.specularColor = vec3(1.0);
    sp.shininess = 1.0;
    sp.metalness = 0.0;
    sp.face = face;
#ifdef RBL_CASTER_ID
    sp.caster = fragCasterId;
#else
    sp.caster = vec2(0.0);
#endif
#if RBL_BRDF == 1
    sp.specularColor = rblSpecularColor.rgb;
    sp.shininess = rblSpecularColor.a;
#elif RBL_BRDF == 2
    sp.roughness = rblRoughMetal.x;
    sp.metalness = rblRoughMetal.y;
#endif
#if defined(RBL_SPECULAR) && (RBL_BRDF == 2)
    sp.roughness = material.b;             // a GGX material texture holds roughness in B
#elif defined(RBL_SPECULAR)
    sp.specular = material.b;
#endif
    sp.occlusion = 1.0;
#ifdef RBL_OCCLUSION
    sp.occlusion = material.a;
#endif
    sp.transmission = 0.0;
#ifdef RBL_TRANSMISSION
    sp.transmission = rblTransmission;
#ifdef RBL_THICKNESS_CHANNEL
    sp.transmission *= 1.0 - material[RBL_THICKNESS_CHANNEL - 1];
#endif
#endif
    alpha = albedo.a;
    emission = vec3(0.0);
#if defined(RBL_CROSS_FADE) && (RBL_EMISSIVE == 1)
    emission += albedo.rgb*rblFadeMix(texture(texture5, fragTexCoord).r*inside1, texture(texture5, fragTexCoord2).r*inside2, cover)*rblEmissiveIntensity;
#elif defined(RBL_CROSS_FADE) && (RBL_EMISSIVE == 2)
    emission += rblFadeMix(rblSrgbToLinear(texture(texture5, fragTexCoord).rgb)*inside1, rblSrgbToLinear(texture(texture5, fragTexCoord2).rgb)*inside2, cover)*rblEmissiveIntensity;
#elif RBL_EMISSIVE == 1
    emission += albedo.rgb*texture(texture5, fragTexCoord).r*rblEmissiveIntensity;
#elif RBL_EMISSIVE == 2
    emission += rblSrgbToLinear(texture(texture5, fragTexCoord).rgb)*rblEmissiveIntensity;
#endif
    emission += rblEmissiveColor;
    return sp;
}

#ifdef RBL_RELIEF_STEPS
// The relief's light factor toward unit l at the point rblMaterialSurface last decoded (lights.glsl)
float rblReliefShadow(vec3 l)
{
    return rblReliefMarch(texture2, l);
}
#endif
