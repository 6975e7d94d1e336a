// Relief self-shadow: embossed detail shadows the sprite itself. The material texture's height
// channel (0..1, scaled by rblRelief.x texels) is marched from the shaded texel toward each light in
// the card's tangent space, at RBL_RELIEF_STEPS evenly spaced samples of the ray up to where it
// clears the highest height; a sample whose texel stands above the ray shadows the light. Heights are
// read texel by texel (unfiltered, base level; the mirror of tests' double-precision march). The ray's
// horizontal reach is capped at 8 climbs (light below 7 degrees), and a texel is taken as square:
// a sprite drawn stretched sees its shadows stretched with it.
// Included by material.glsl; compiled only with:
//   RBL_RELIEF_STEPS n      samples per light (RblLitShaderDesc.reliefSteps)
//   RBL_HEIGHT_CHANNEL c    material texture component holding height (3 b, 4 a)
#include "surface.glsl"

#ifdef RBL_RELIEF_STEPS
uniform vec4 rblRelief;     // x height 1 in texels (0 = flat: nothing marched), zw 1/size of the material texture
vec2 rblReliefAt;           // the shaded point in texels of the material texture (set by rblMaterialSurface)
float rblReliefBase;        // its height in texels
vec3 rblReliefU, rblReliefV, rblReliefN;   // world directions of +U, +V (down the image) and out of the card's shaded side

float rblReliefHeight(sampler2D map, vec2 texel)
{
    vec2 at = clamp(floor(texel), vec2(0.0), floor(1.0/rblRelief.zw + 0.5) - 1.0);
#if RBL_GLSL >= 300
    vec4 m = texelFetch(map, ivec2(at), 0);
#else
    vec4 m = texture2D(map, (at + 0.5)*rblRelief.zw);
#endif
    return m[RBL_HEIGHT_CHANNEL - 1]*rblRelief.x;
}

// The shaded point: uv, its tangent frame (unit world +U, +V, shaded-side normal)
void rblReliefSetup(sampler2D map, vec2 uv, vec3 u, vec3 v, vec3 n)
{
    rblReliefAt = uv/rblRelief.zw;
    rblReliefU = u; rblReliefV = v; rblReliefN = n;
    rblReliefBase = rblReliefHeight(map, rblReliefAt);
}

// Light let through toward unit direction l: 0 behind relief, else 1
float rblReliefMarch(sampler2D map, vec3 l)
{
    vec3 d = vec3(dot(l, rblReliefU), dot(l, rblReliefV), dot(l, rblReliefN));
    float rise = rblRelief.x - rblReliefBase;          // texels to the top
    if (!(d.z > 0.0) || !(rise > 0.0)) return 1.0;    // behind the card (the lights decide), or nothing above
    vec2 reach = d.xy*(rise/max(d.z, 0.125));
    float delta = 1.0/float(RBL_RELIEF_STEPS);
    for (int i = 1; i <= RBL_RELIEF_STEPS; i++)
    {
        float f = float(i)*delta;
        if (rblReliefHeight(map, rblReliefAt + reach*f) > rblReliefBase + rise*f) return 0.0;
    }
    return 1.0;
}
#endif
