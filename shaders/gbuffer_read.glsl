// G-buffer read: the targets of the geometry pass as a lighting pass sees them, the world position
// rebuilt from depth, and the surface unpacked (gbuffer_codec.glsl).
#include "surface.glsl"
#include "gbuffer_codec.glsl"

uniform sampler2D rblGAlbedo;           // RGBA8: sRGB albedo, bits 23..16 of the normal/material word
uniform sampler2D rblGNormal;           // RGBA8: bits 55..24
uniform sampler2D rblGParams;           // RG8: bits 15..0; RBL_GB_PARAMS_RGBA: RGBA8, ba the caster identity
uniform sampler2D rblGDepth;            // depth texture of the geometry pass
uniform sampler2D rblGAccum;            // RGBA16F light accumulation (resolve only)
uniform vec4 rblDepthLinear;            // perspective: n*f, f - n, f, 1; orthographic: n, f - n, 0, 0
uniform vec2 rblInvP;                   // 1/P00, 1/P11 of the geometry pass's projection
uniform mat4 rblInvView;                // inverse view (camera to world)
uniform vec3 rblEye;                    // camera position
uniform vec4 rblViewAxis;               // camera back direction, w 1 orthographic (rblViewVector)
#ifdef RBL_GB_THIN
uniform sampler2D rblGThin;             // RGBA8: transmission share (rg, 16 bits), relief bits of lights 0..7 (b)
#endif
#ifdef RBL_GB_RELIEF
uniform int rblReliefIndex[RBL_LIGHTS]; // full-screen pass: the scene index of light slot i (-1: no bit)
uint rblGbReliefMask;                   // this pixel's relief bits (rblGBufferSurface)
int rblGbReliefLight = -1;              // scene index of the light being evaluated (-1: none marched)

// Light slot i of the full-screen pass is evaluated next
void rblGbReliefSelect(int i) { rblGbReliefLight = rblReliefIndex[i]; }

// The stored relief verdict for the light being evaluated (lights.glsl): 0 behind relief, else 1
float rblReliefShadow(vec3 l)
{
    if ((rblGbReliefLight < 0) || (rblGbReliefLight > 7)) return 1.0;
    return (((rblGbReliefMask >> uint(rblGbReliefLight)) & 1u) != 0u)? 0.0 : 1.0;
}
#endif

// This pixel's G-buffer texel and depth in a light pass (drawn at the G-buffer's size); false where
// nothing was drawn (background)
bool rblLightPassTexel(out ivec2 texel, out float depth)
{
    texel = ivec2(gl_FragCoord.xy);
    depth = texelFetch(rblGDepth, texel, 0).r;
    return depth < 1.0;
}

// World position from the depth buffer, in closed form (an inverse projection matrix would cancel two
// large terms). Perspective: view distance z = n f/(f - d (f - n)) from the window depth d, then x, y
// along the pixel's ray. Orthographic: z = n + d (f - n), x, y straight from NDC. Then the inverse view.
vec3 rblPositionFromDepth(ivec2 texel, float depth)
{
    vec2 ndc = (vec2(texel) + 0.5)/vec2(textureSize(rblGDepth, 0))*2.0 - 1.0;
    vec3 view;
    if (rblDepthLinear.w > 0.0)
    {
        float z = rblDepthLinear.x/(rblDepthLinear.z - depth*rblDepthLinear.y);
        view = vec3(ndc*rblInvP*z, -z);
    }
    else view = vec3(ndc*rblInvP, -(rblDepthLinear.x + depth*rblDepthLinear.y));
    return (rblInvView*vec4(view, 1.0)).xyz;
}

#if RBL_SHADOWS > 0
// The rasterised surface's normal at texel (for shadow biasing, as the forward path's screen
// derivatives): from the positions of the neighbours on each axis, the one whose depth differs less
// (the same surface, across an edge); the shading normal where neither lies on a surface
vec3 rblFaceNormal(ivec2 texel, vec3 position, float depth, vec3 fallback)
{
    ivec2 top = textureSize(rblGDepth, 0) - 1;
    vec3 d[2];
    for (int axis = 0; axis < 2; axis++)
    {
        ivec2 step = (axis == 0)? ivec2(1, 0) : ivec2(0, 1);
        ivec2 a = min(texel + step, top), b = max(texel - step, ivec2(0));
        float da = texelFetch(rblGDepth, a, 0).r, db = texelFetch(rblGDepth, b, 0).r;
        bool useA = (a != texel) && (da < 1.0) && ((b == texel) || (db >= 1.0) || (abs(da - depth) <= abs(db - depth)));
        bool useB = !useA && (b != texel) && (db < 1.0);
        d[axis] = useA? rblPositionFromDepth(a, da) - position : (useB? position - rblPositionFromDepth(b, db) : vec3(0.0));
    }
    return rblSafeNormalize(cross(d[0], d[1]), fallback);
}
#endif

RblShadingPoint rblGBufferSurface(ivec2 texel, vec3 position)
{
    vec4 a = texelFetch(rblGAlbedo, texel, 0);
    vec4 n = texelFetch(rblGNormal, texel, 0);
    vec4 p = texelFetch(rblGParams, texel, 0);
    RblShadingPoint s;
    s.position = position;
    uint field1, field2;
#ifdef RBL_GB_PARAMS_RGBA
    rblUnpackWord(n, a.a, p.rg, s.normal, field1, field2);
    s.caster = p.ba;
#else
    rblUnpackWord(n, a.a, p.ra, s.normal, field1, field2);     // raylib samples RG8 (GRAY_ALPHA) as (r, r, r, g)
    s.caster = vec2(0.0);                   // no room for it: every caster counts
#endif
    s.albedo = rblSrgbToLinear(a.rgb);
#if RBL_SHADOWS > 0
    s.face = rblFaceNormal(texel, position, texelFetch(rblGDepth, texel, 0).r, s.normal);
#else
    s.face = s.normal;
#endif
    s.occlusion = 1.0;                  // the accumulation's alpha (the resolve reads it)
    s.transmission = 0.0;
#ifdef RBL_GB_THIN
    vec4 thin = floor(texelFetch(rblGThin, texel, 0)*255.0 + 0.5);
#ifdef RBL_TRANSMISSION
    s.transmission = (thin.r*256.0 + thin.g)/65535.0;
#endif
#ifdef RBL_GB_RELIEF
    rblGbReliefMask = uint(thin.b);
#endif
#endif
    s.specularColor = vec3(1.0);
    s.shininess = 1.0;
    s.metalness = 0.0;
    s.roughness = 0.5;
#if RBL_BRDF == 1
    s.shininess = rblDecodeShininess(rblDequantize(field1, RBL_GB_FIELD1_BITS));
    s.specular = rblDecodeIntensity(rblDequantize(field2, RBL_GB_FIELD2_BITS));
#elif RBL_BRDF == 2
    s.roughness = rblDecodeRoughness(rblDequantize(field1, RBL_GB_FIELD1_BITS));
    s.metalness = rblDequantize(field2, RBL_GB_FIELD2_BITS);
    s.specular = s.roughness;           // the debug view shows the stored channel
#else
    s.specular = rblDequantize(field2, RBL_GB_FIELD2_BITS);
#endif
    return s;
}
