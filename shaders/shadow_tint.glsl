// Shadow tint: what blended casters (smoke, coloured glass; RblBeginShadowBlend) let through to a
// receiver behind them. Each map with RblShadowDesc.transmittance has an RGBA8 target: rgb the product
// of the blended casters' transmittance over that texel (coverage a: 1 - a, or mix(1, colour, a)
// coloured), a the nearest one's distance code in 8 bits (shadow_caster.fs.glsl); only casters in
// front of the opaque depth were kept. A receiver more than 1.5 code steps behind that distance
// takes the texel's tint: a caster never tints itself or what lies in front of it. Bilinear over the
// 2 x 2 texels around the point (the tint's edge is as soft as PCF 1's). Forward receivers and the
// G-buffer's light passes (RblGBufferDesc.shadowTransmittance).
//   RBL_SHADOW_TINT          RblLitShaderDesc.shadowTransmittance (needs RBL_SHADOWS > 0)
#include "shadows.glsl"

#if defined(RBL_SHADOW_TINT) && (RBL_SHADOWS > 0)
uniform sampler2D rblShadowTint0;           // units RBL_SHADOW_TINT_TEXTURE_UNIT + k (white 1 x 1 where a map has none)
#if RBL_SHADOWS > 1
uniform sampler2D rblShadowTint1;
#endif
#if RBL_SHADOWS > 2
uniform sampler2D rblShadowTint2;
#endif
#if RBL_SHADOWS > 3
uniform sampler2D rblShadowTint3;
#endif

vec3 rblTintLookup(sampler2D map, vec4 r0, vec4 r1, vec4 r2, vec4 r3, vec4 prm, float size, vec3 position)
{
    vec4 c = rblShadowTransform(r0, r1, r2, r3, position);
    if (!(c.w > 0.0)) return vec3(1.0);
    vec3 q = c.xyz/c.w;
    if (!((q.x >= 0.0) && (q.x <= 1.0) && (q.y >= 0.0) && (q.y <= 1.0) && (q.z < 1.0))) return vec3(1.0);
    bool perspective = mod(prm.y, 2.0) > 0.5;
    float d = rblShadowDistance(max(q.z, 0.0), vec4(prm.x, perspective? 1.0 : 0.0, prm.zw));
    float code = perspective? log(max(d, prm.z)/prm.z)/log(prm.w/prm.z) : (d - prm.z)/(prm.w - prm.z);
    vec2 st = q.xy*size - 0.5;
    vec2 base = floor(st), f = st - base;
    vec3 sum = vec3(0.0);
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 2; i++)
        {
            vec2 at = clamp(base + vec2(float(i), float(j)), vec2(0.0), vec2(size - 1.0));
            vec4 t = rblFetch(map, ivec2(at), size);
            float w = ((i == 0)? 1.0 - f.x : f.x)*((j == 0)? 1.0 - f.y : f.y);
            sum += w*((code > t.a + 1.5/255.0)? t.rgb : vec3(1.0));
        }
    return sum;
}

// Map k's tint at a world position (1: untinted)
vec3 rblShadowTint(int k, vec3 position)
{
    if (k == 0) return rblTintLookup(rblShadowTint0, rblShadowMatrix[0], rblShadowMatrix[1], rblShadowMatrix[2], rblShadowMatrix[3], rblShadowParams[0], rblShadowBias[0].w, position);
#if RBL_SHADOWS > 1
    if (k == 1) return rblTintLookup(rblShadowTint1, rblShadowMatrix[4], rblShadowMatrix[5], rblShadowMatrix[6], rblShadowMatrix[7], rblShadowParams[1], rblShadowBias[1].w, position);
#endif
#if RBL_SHADOWS > 2
    if (k == 2) return rblTintLookup(rblShadowTint2, rblShadowMatrix[8], rblShadowMatrix[9], rblShadowMatrix[10], rblShadowMatrix[11], rblShadowParams[2], rblShadowBias[2].w, position);
#endif
#if RBL_SHADOWS > 3
    if (k == 3) return rblTintLookup(rblShadowTint3, rblShadowMatrix[12], rblShadowMatrix[13], rblShadowMatrix[14], rblShadowMatrix[15], rblShadowParams[3], rblShadowBias[3].w, position);
#endif
    return vec3(1.0);
}
#endif
