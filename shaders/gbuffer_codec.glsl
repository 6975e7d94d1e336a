// G-buffer codec: how the geometry pass packs a surface into 10 bytes per pixel and the lighting
// passes unpack it (RblLoadGBuffer; position is never stored, it comes back from depth):
//   RT0 RGBA8    rgb albedo, sRGB-encoded (8-bit steps where the eye needs them), a occlusion
//   RT1 RGBA8    rgb world normal, octahedral 12+12 bits, a specular (Blinn-Phong intensity, specular
//                colour luminance folded in / GGX perceptual roughness)
//   RT2 RG8      Blinn-Phong: log2(shininess)/11 in 16 bits (r high, g low byte); GGX: r metalness
//   RT3 RGBA16F  light accumulation: emission from the geometry pass, then ambient and lights
#include "common.glsl"

// World normal <-> octahedral 12+12 bits in three 8-bit channels (the G-buffer's normal). Octahedral
// map (Cigolle et al. 2014), each coordinate rounded to 12 bits, packed high byte / two nibbles / low byte.
vec3 rblPackNormal(vec3 n)
{
    n /= max(abs(n.x) + abs(n.y) + abs(n.z), 1e-20);
    vec2 e = n.xy;
    if (n.z < 0.0) e = (1.0 - abs(n.yx))*vec2((n.x >= 0.0)? 1.0 : -1.0, (n.y >= 0.0)? 1.0 : -1.0);
    uvec2 q = uvec2(floor(clamp(e*0.5 + 0.5, 0.0, 1.0)*4095.0 + 0.5));
    return vec3(float(q.x >> 4u), float(((q.x & 15u) << 4u) | (q.y >> 8u)), float(q.y & 255u))/255.0;
}

vec3 rblUnpackNormal(vec3 c)
{
    uvec3 b = uvec3(floor(c*255.0 + 0.5));
    vec2 e = vec2(float((b.x << 4u) | (b.y >> 4u)), float(((b.y & 15u) << 8u) | b.z))/4095.0*2.0 - 1.0;
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    float t = max(-n.z, 0.0);
    n.xy += vec2((n.x >= 0.0)? -t : t, (n.y >= 0.0)? -t : t);
    return normalize(n);        // |n| >= 1/sqrt(3): never zero
}

// Blinn-Phong shininess <-> 16-bit code in two 8-bit channels
vec2 rblPackShininess(float shininess)
{
    float code = floor(clamp(log2(max(shininess, 1.0))/11.0, 0.0, 1.0)*65535.0 + 0.5);
    return vec2(floor(code/256.0)/255.0, mod(code, 256.0)/255.0);
}

float rblUnpackShininess(float high, float low)
{
    return exp2((floor(high*255.0 + 0.5)*256.0 + floor(low*255.0 + 0.5))/65535.0*11.0);
}
