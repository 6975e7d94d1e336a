// G-buffer codec: how the geometry pass packs a surface into 10 bytes per pixel and the lighting
// passes unpack it (RblLoadGBuffer; position is never stored, it comes back from depth):
//   RT0 RGBA8    rgb albedo, sRGB-encoded (8-bit steps where the eye needs them), a occlusion
//   RT1 RGBA8 + RT2 RG8: one 48-bit word, RT1.r its most significant byte, RT2.g its least:
//     GGX, Lambert   normal 30 bits | perceptual roughness 10 (GGX; Lambert: 0) | metalness 8 (Lambert:
//                    the specular map, for the debug view)
//     Blinn-Phong    normal 29 bits | shininess 10 | specular intensity 9 (colour folded to its luminance)
//   RT3 RGBA16F  light accumulation: emission from the geometry pass, then ambient and lights
// Every field is stored in the form whose step is the same relative change of what the BRDF reads
// (a highlight's error is relative), except metalness (linear in the output). Not stored: the
// normal's third coordinate, roughness below RBL_MIN_ROUGHNESS (the BRDF clamps it), F0, the
// (n + 8)/8 normalisation.
//   normal       octahedral (Cigolle et al. 2014), L levels per coordinate, L odd so that 0 and +-1
//                are codes (axis-aligned normals exact), code = x L + y; of the 4 neighbouring codes
//                the one decoding nearest the normal. L = 32767 (GGX, Lambert), 23169 (Blinn-Phong).
//   roughness    log over [RBL_MIN_ROUGHNESS, 1], 1023 steps
//   metalness    linear, 255 steps (0 and 1 exact)
//   shininess    log2(n)/11, 1023 steps (n in 1..2048)
//   intensity    log2(1 + 256 s)/9, 511 steps: relative above 1/256, linear toward 0 (0 exact), s <= 511/256
#include "common.glsl"

#if RBL_BRDF == 1
#define RBL_GB_NORMAL_LEVELS 23169u     // 23169^2 < 2^29
#define RBL_GB_NORMAL_BITS 29u
#define RBL_GB_FIELD1_BITS 10u          // shininess
#define RBL_GB_FIELD2_BITS 9u           // specular intensity
#else
#define RBL_GB_NORMAL_LEVELS 32767u     // 32767^2 < 2^30
#define RBL_GB_NORMAL_BITS 30u
#define RBL_GB_FIELD1_BITS 10u          // roughness
#define RBL_GB_FIELD2_BITS 8u           // metalness (Lambert: specular map)
#endif
#define RBL_GB_SPLIT (32u - RBL_GB_NORMAL_BITS)     // bits of field 1 in RT1 (the rest in RT2)

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
uint rblPackNormal(vec3 n)
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
    return uint(q.x)*RBL_GB_NORMAL_LEVELS + uint(q.y);
}

vec3 rblUnpackNormal(uint code)
{
    float centre = float(RBL_GB_NORMAL_LEVELS - 1u)*0.5;
    uint x = code/RBL_GB_NORMAL_LEVELS;
    return rblOctahedralDecode((vec2(float(x), float(code - x*RBL_GB_NORMAL_LEVELS)) - centre)/centre);
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

// The 48-bit word as RT1 (4 bytes) and RT2 (2 bytes), each byte /255 as an 8-bit target stores it
void rblPackWord(vec3 normal, uint field1, uint field2, out vec4 rt1, out vec2 rt2)
{
    uint hi = (rblPackNormal(normal) << RBL_GB_SPLIT) | (field1 >> (RBL_GB_FIELD1_BITS - RBL_GB_SPLIT));
    uint lo = ((field1 & ((1u << (RBL_GB_FIELD1_BITS - RBL_GB_SPLIT)) - 1u)) << RBL_GB_FIELD2_BITS) | field2;
    rt1 = vec4(float(hi >> 24u), float((hi >> 16u) & 255u), float((hi >> 8u) & 255u), float(hi & 255u))/255.0;
    rt2 = vec2(float(lo >> 8u), float(lo & 255u))/255.0;
}

void rblUnpackWord(vec4 rt1, vec2 rt2, out vec3 normal, out uint field1, out uint field2)
{
    uvec4 a = uvec4(floor(rt1*255.0 + 0.5));
    uvec2 b = uvec2(floor(rt2*255.0 + 0.5));
    uint hi = (a.x << 24u) | (a.y << 16u) | (a.z << 8u) | a.w;
    uint lo = (b.x << 8u) | b.y;
    normal = rblUnpackNormal(hi >> RBL_GB_SPLIT);
    field1 = ((hi & ((1u << RBL_GB_SPLIT) - 1u)) << (RBL_GB_FIELD1_BITS - RBL_GB_SPLIT)) | (lo >> RBL_GB_FIELD2_BITS);
    field2 = lo & ((1u << RBL_GB_FIELD2_BITS) - 1u);
}
