// G-buffer codec: how the geometry pass packs a surface into 10 bytes per pixel and the lighting
// passes unpack it (RblLoadGBuffer; position is never stored, it comes back from depth):
//   RT0 RGBA8    rgb albedo, sRGB-encoded (8-bit steps where the eye needs them), a bits 23..16 of the word
//   RT1 RGBA8    bits 55..24 of a 56-bit normal/material word, RT1.r its most significant byte
//   RT2 RG8      bits 15..0 of the word
//   RT3 RGBA16F  light accumulation: emission from the geometry pass, then the lights; alpha keeps
//                the occlusion (light passes add alpha 0), which scales the ambient the resolve adds
//   RT4 RGBA8    RblGBufferDesc.transmission or .relief only: rg the transmission share in 16 bits
//                (r high), b the relief bits of the scene's first 8 lights (bit i: light i behind relief)
//   word         normal x | normal y | field 1 | field 2, from the most significant bit; per BRDF:
//     GGX          normal 18 + 18 | roughness 12 | metalness 8
//     Blinn-Phong  normal 16 + 16 | shininess 12 | specular intensity 12 (colour folded to its luminance)
//     Lambert      normal 18 + 18 | 0 12 | the specular map 8 (the debug view)
// The split follows what each BRDF's error is made of. A normal off by d moves a highlight's flank by
// about (lobe sharpness) x d: GGX needs 36 bits at its sharpest lobe (alpha = 0.045^2), a Blinn-Phong
// lobe (n <= 2048) is at least 25 times wider and keeps the same error with 32. A constant material
// value rounded to its nearest code is the same error on every pixel, a bias the image's mean shows:
// Blinn-Phong's 4 spare bits go to its two fields (12 + 12 instead of 11 + 9). Every field is stored
// in the form whose step is the same relative change of what the BRDF reads (a highlight's error is
// relative), except metalness (linear in the output). Not stored: the normal's third coordinate,
// roughness below RBL_MIN_ROUGHNESS (the BRDF clamps it), F0, the (n + 8)/8 normalisation.
//   normal       octahedral (Cigolle et al. 2014), L = 2^b - 1 levels per coordinate, odd so that 0 and
//                +-1 are codes (axis-aligned normals exact); of the 4 neighbouring codes the one
//                decoding nearest the normal
//   roughness    log over [RBL_MIN_ROUGHNESS, 1], 4095 steps
//   metalness    linear, 255 steps (0 and 1 exact)
//   shininess    log2(n)/11, 4095 steps (n in 1..2048)
//   intensity    log2(1 + 256 s)/9, 4095 steps: relative above 1/256, linear toward 0 (0 exact), s <= 511/256
#include "common.glsl"

#if RBL_BRDF == 1
#define RBL_GB_NORMAL_BITS 16u          // per coordinate
#define RBL_GB_FIELD1_BITS 12u          // shininess
#define RBL_GB_FIELD2_BITS 12u          // specular intensity
#else
#define RBL_GB_NORMAL_BITS 18u          // per coordinate
#define RBL_GB_FIELD1_BITS 12u          // roughness (Lambert: 0)
#define RBL_GB_FIELD2_BITS 8u           // metalness (Lambert: specular map)
#endif
#define RBL_GB_NORMAL_LEVELS ((1u << RBL_GB_NORMAL_BITS) - 1u)
#define RBL_GB_FIELDS_BITS (RBL_GB_FIELD1_BITS + RBL_GB_FIELD2_BITS)

// Octahedral map of a unit vector onto [-1,1]^2 and back (the lower hemisphere folded over the diagonals)
vec2 rblOctahedral(vec3 n)
{
    n /= max(abs(n.x) + abs(n.y) + abs(n.z), 1e-20);
    vec2 e = n.xy;
    if (n.z < 0.0) e = (1.0 - abs(n.yx))*vec2((n.x >= 0.0)? 1.0 : -1.0, (n.y >= 0.0)? 1.0 : -1.0);
    return e;
}

vec3 rblOctahedralDecode(vec2 e)
{
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    float t = max(-n.z, 0.0);
    n.xy += vec2((n.x >= 0.0)? -t : t, (n.y >= 0.0)? -t : t);
    return normalize(n);        // |n| >= 1/sqrt(3): never zero
}

// Normal code: the nearest of the 4 codes around the octahedral point (rounding each coordinate
// alone can pick a farther one: the map's cells are sheared). Compared as |d - n|^2, which float
// resolves at these angles (1 - cos would not).
uvec2 rblPackNormal(vec3 n)
{
    float centre = float(RBL_GB_NORMAL_LEVELS - 1u)*0.5;
    vec2 f = clamp(rblOctahedral(n)*centre + centre, 0.0, 2.0*centre);
    vec2 base = floor(f), q = base;
    float best = 1e30;
    for (int k = 0; k < 4; k++)
    {
        vec2 c = min(base + vec2(float(k & 1), float(k >> 1)), vec2(2.0*centre));
        vec3 d = rblOctahedralDecode((c - centre)/centre) - n;
        float e = dot(d, d);
        if (e < best) { best = e; q = c; }
    }
    return uvec2(q);
}

vec3 rblUnpackNormal(uvec2 code)
{
    float centre = float(RBL_GB_NORMAL_LEVELS - 1u)*0.5;
    return rblOctahedralDecode((vec2(code) - centre)/centre);
}

// Fields in [0,1] <-> codes of b bits
uint rblQuantize(float t, uint bits) { return uint(floor(clamp(t, 0.0, 1.0)*float((1u << bits) - 1u) + 0.5)); }
float rblDequantize(uint code, uint bits) { return float(code)/float((1u << bits) - 1u); }

float rblEncodeRoughness(float r) { return 1.0 - log2(clamp(r, RBL_MIN_ROUGHNESS, 1.0))/log2(RBL_MIN_ROUGHNESS); }
float rblDecodeRoughness(float t) { return exp2(log2(RBL_MIN_ROUGHNESS)*(1.0 - t)); }
float rblEncodeShininess(float n) { return log2(max(n, 1.0))/11.0; }
float rblDecodeShininess(float t) { return exp2(t*11.0); }
float rblEncodeIntensity(float s) { return log2(1.0 + 256.0*max(s, 0.0))/9.0; }
float rblDecodeIntensity(float t) { return (exp2(t*9.0) - 1.0)/256.0; }

// The 56-bit word as RT1 (4 bytes), RT0's alpha and RT2 (2 bytes), each byte /255 as an 8-bit target
// stores it: hi = bits 55..24, lo = bits 23..0. The fields (at most 24 bits together) lie in lo; the
// normal's y code straddles the two where they are fewer than 24 (shifts by 0 otherwise).
#define RBL_GB_HI_SHIFT (RBL_GB_NORMAL_BITS + RBL_GB_FIELDS_BITS - 24u)     // x code's lowest bit in hi
#define RBL_GB_Y_SPLIT (24u - RBL_GB_FIELDS_BITS)                           // y code's low bits in lo

void rblPackWord(vec3 normal, uint field1, uint field2, out vec4 rt1, out float rt0a, out vec2 rt2)
{
    uvec2 q = rblPackNormal(normal);
    uint hi = (q.x << RBL_GB_HI_SHIFT) | (q.y >> RBL_GB_Y_SPLIT);
    uint lo = ((q.y << RBL_GB_FIELDS_BITS) & 16777215u) | (field1 << RBL_GB_FIELD2_BITS) | field2;
    rt1 = vec4(float(hi >> 24u), float((hi >> 16u) & 255u), float((hi >> 8u) & 255u), float(hi & 255u))/255.0;
    rt0a = float(lo >> 16u)/255.0;
    rt2 = vec2(float((lo >> 8u) & 255u), float(lo & 255u))/255.0;
}

void rblUnpackWord(vec4 rt1, float rt0a, vec2 rt2, out vec3 normal, out uint field1, out uint field2)
{
    uvec4 a = uvec4(floor(rt1*255.0 + 0.5));
    uvec3 b = uvec3(floor(vec3(rt0a, rt2)*255.0 + 0.5));
    uint hi = (a.x << 24u) | (a.y << 16u) | (a.z << 8u) | a.w;
    uint lo = (b.x << 16u) | (b.y << 8u) | b.z;
    uint mask = (1u << RBL_GB_NORMAL_BITS) - 1u;
    normal = rblUnpackNormal(uvec2(hi >> RBL_GB_HI_SHIFT, ((hi << RBL_GB_Y_SPLIT) | (lo >> RBL_GB_FIELDS_BITS)) & mask));
    field1 = (lo >> RBL_GB_FIELD2_BITS) & ((1u << RBL_GB_FIELD1_BITS) - 1u);
    field2 = lo & ((1u << RBL_GB_FIELD2_BITS) - 1u);
}
