// Shadows: the shadow maps a receiver samples and the lookup (bias, receiver plane, PCF). Which
// light a map shadows is the lights' business (lights.glsl, deferred_volume.fs.glsl).
//   RBL_SHADOWS n             shadow maps sampled (0..4; rblShadowMap0..3), each shadowing one light
//   RBL_SHADOW_FILTER k       PCF footprint in texels per side: (k + 1)^2 depth fetches per lookup
#include "surface.glsl"

#if RBL_SHADOWS > 0
uniform vec4 rblShadowMatrix[4*RBL_SHADOWS]; // rows 4k..4k+3: world -> (u, v, window depth, w) of map k (rows: no
                                            // transpose convention to differ between GL and ES uploads)
uniform vec4 rblShadowParams[RBL_SHADOWS];  // texel world size (perspective: per unit distance), format, near, far; format:
                                            // 0, 1 depth texture (orthographic, perspective); 2, 3 the casters
                                            // target (RGBA8: 16-bit distance code, caster identity)
uniform vec4 rblShadowBias[RBL_SHADOWS];    // constant, slope, normal offset (all in texels), map size in texels
uniform vec4 rblShadowAxes[2*RBL_SHADOWS];  // right and up of map k's light camera (its axis = cross(up, right))
uniform sampler2D rblShadowMap0;            // casters targets or depth textures (texture units RBL_SHADOW_TEXTURE_UNIT + k)
#if RBL_SHADOWS > 1
uniform sampler2D rblShadowMap1;
#endif
#if RBL_SHADOWS > 2
uniform sampler2D rblShadowMap2;
#endif
#if RBL_SHADOWS > 3
uniform sampler2D rblShadowMap3;
#endif
#endif

#if RBL_SHADOWS > 0
// Distance along the light's axis from a value v of map k (prm: texel, format, near, far): a window
// depth, or a casters target's code (shadow_caster.fs.glsl); both are linear when orthographic
float rblShadowDistance(float v, vec4 prm)
{
    if (prm.y > 2.5) return prm.z*exp(v*log(prm.w/prm.z));
    if ((prm.y > 0.5) && (prm.y < 1.5)) return prm.z*prm.w/(prm.w - v*(prm.w - prm.z));
    return prm.z + v*(prm.w - prm.z);
}

// Fraction of light k's map lets through to a surface point of unit normal n (either sign) lit at
// cos(incidence) NdotL (> 0), that lies on the billboard of identity caster (0: a Model). Depths are
// compared as distances along the light's axis, in world units:
//   normal offset   the lookup moves along n*side (side: +-1 toward the light) by normal*texel*
//                   sin(incidence) (lateral shift <= that)
//   receiver plane  each PCF fetch is compared with the receiver's own plane extended to that texel's
//                   centre (depth gradient from n in the light's frame, clamped at 10 texels per
//                   texel), so a flat receiver never shadows itself at any incidence below 84 degrees
//   depth bias      texel*(constant + slope*tan(incidence)), tan clamped at 10; a casters target
//                   adds half its code's step (its rounding)
//   identity        a fetch holding the point's own caster (same identity, not 0) lets light through:
//                   a billboard is flat, so its own card never shadows it, wherever the pass turned it
//                   (the light-facing card, the AXIS tilt) and however its normal map bends the normal
// PCF: a box of RBL_SHADOW_FILTER texels per side over bilinear-weighted comparisons, (k + 1)^2
// fetches: at k = 1 the footprint of hardware 2x2 comparison filtering (rlgl exposes no compare mode).
// Outside the map, behind a spot light or beyond the far plane the point is lit, and so is a fetch
// outside the map or of a texel nothing was drawn into.
// Map k's uniforms come in as arguments, indexed by constants at the call: GLSL ES 1.00 fragment
// stages may index uniform arrays only by constants and loop indices.
vec4 rblShadowTransform(vec4 r0, vec4 r1, vec4 r2, vec4 r3, vec3 p)
{
    vec4 h = vec4(p, 1.0);
    return vec4(dot(r0, h), dot(r1, h), dot(r2, h), dot(r3, h));
}

float rblShadowLookup(sampler2D map, vec4 r0, vec4 r1, vec4 r2, vec4 r3, vec4 prm, vec4 bias, vec3 right, vec3 up,
                      vec3 position, vec3 n, float NdotL, float side, vec2 caster)
{
    bool coded = prm.y > 1.5;                  // the casters target (else a depth texture)
    bool skipOwn = coded && (caster.x + caster.y > 0.0);
    vec3 along = cross(up, right);
    vec4 c0 = rblShadowTransform(r0, r1, r2, r3, position);
    bool perspective = mod(prm.y, 2.0) > 0.5;
    float texel = prm.x*(perspective? max(c0.w, 0.0) : 1.0);       // world size of a texel here
    float sinI = sqrt(max(1.0 - NdotL*NdotL, 0.0));
    float tanI = min(sinI/max(NdotL, 1e-4), 10.0);
    vec4 c = rblShadowTransform(r0, r1, r2, r3, position + n*(bias.z*texel*sinI*side));
    if (!(c.w > 0.0)) return 1.0;
    vec3 q = c.xyz/c.w;
    if (!((q.x >= 0.0) && (q.x <= 1.0) && (q.y >= 0.0) && (q.y <= 1.0) && (q.z < 1.0))) return 1.0;
    // The receiver's own distance from its window depth (a depth texture's format, whatever the map holds)
    float z = rblShadowDistance(max(q.z, 0.0), vec4(prm.x, perspective? 1.0 : 0.0, prm.zw)) - texel*(bias.x + bias.y*tanI);
    if (coded) z -= ((prm.y > 2.5)? z*log(prm.w/prm.z) : prm.w - prm.z)*(0.5/65535.0);
    // Receiver plane: distance change per texel step along the map's x and y
    vec2 slope = vec2(dot(n, right), dot(n, up))/max(-dot(n, along), 1e-4);
    slope *= min(1.0, 10.0/max(length(slope), 1e-20))*texel;
    float size = bias.w;
    vec2 st = q.xy*size - 0.5*float(RBL_SHADOW_FILTER);         // first bilinear tap's position - 0.5, in texels
    vec2 base = floor(st), f = st - base;
    ivec2 b0 = ivec2(base), top = ivec2(int(size) - 1);
    vec2 origin = base + 0.5 - q.xy*size;                       // first fetched centre relative to the point
    float lit = 0.0;
    for (int j = 0; j <= RBL_SHADOW_FILTER; j++)
    {
        float wy = (j == 0)? 1.0 - f.y : ((j == RBL_SHADOW_FILTER)? f.y : 1.0);
        for (int i = 0; i <= RBL_SHADOW_FILTER; i++)
        {
            float wx = (i == 0)? 1.0 - f.x : ((i == RBL_SHADOW_FILTER)? f.x : 1.0);
            // Texels outside the map or never written (cleared to 1: beyond the far plane) hold no occluder
            ivec2 at = b0 + ivec2(i, j);
            vec4 t = (all(greaterThanEqual(at, ivec2(0))) && all(lessThanEqual(at, top)))? rblFetch(map, at, size) : vec4(1.0);
            float raw = t.r;
            bool through = raw >= 1.0;       // nothing drawn there (cleared to 1), or the point's own caster
            if (coded)
            {
                float code = floor(t.r*255.0 + 0.5)*256.0 + floor(t.g*255.0 + 0.5);
                raw = code/65535.0;
                through = (code > 65534.5) || (skipOwn && all(lessThan(abs(t.ba - caster), vec2(0.5/255.0))));
            }
            float receiver = z + dot(slope, origin + vec2(float(i), float(j)));
            lit += (through || (receiver <= rblShadowDistance(raw, prm)))? wx*wy : 0.0;
        }
    }
    return lit/float(RBL_SHADOW_FILTER*RBL_SHADOW_FILTER);
}

float rblShadow(int k, vec3 position, vec3 n, float NdotL, float side, vec2 caster)
{
    if (k == 0) return rblShadowLookup(rblShadowMap0, rblShadowMatrix[0], rblShadowMatrix[1], rblShadowMatrix[2], rblShadowMatrix[3],
                                     rblShadowParams[0], rblShadowBias[0], rblShadowAxes[0].xyz, rblShadowAxes[1].xyz, position, n, NdotL, side, caster);
#if RBL_SHADOWS > 1
    if (k == 1) return rblShadowLookup(rblShadowMap1, rblShadowMatrix[4], rblShadowMatrix[5], rblShadowMatrix[6], rblShadowMatrix[7],
                                     rblShadowParams[1], rblShadowBias[1], rblShadowAxes[2].xyz, rblShadowAxes[3].xyz, position, n, NdotL, side, caster);
#endif
#if RBL_SHADOWS > 2
    if (k == 2) return rblShadowLookup(rblShadowMap2, rblShadowMatrix[8], rblShadowMatrix[9], rblShadowMatrix[10], rblShadowMatrix[11],
                                     rblShadowParams[2], rblShadowBias[2], rblShadowAxes[4].xyz, rblShadowAxes[5].xyz, position, n, NdotL, side, caster);
#endif
#if RBL_SHADOWS > 3
    if (k == 3) return rblShadowLookup(rblShadowMap3, rblShadowMatrix[12], rblShadowMatrix[13], rblShadowMatrix[14], rblShadowMatrix[15],
                                     rblShadowParams[3], rblShadowBias[3], rblShadowAxes[6].xyz, rblShadowAxes[7].xyz, position, n, NdotL, side, caster);
#endif
    return 1.0;
}

// Light k's map at shading point s for the light toward l: biased by the rasterised surface (its
// face; a card is two-sided: the side toward the light), whatever normal shades it. The normal
// offset fades out through edge-on (|cos| < 1/20), so it never jumps from one side to the other
float rblShadowAt(int k, RblShadingPoint s, vec3 l)
{
    float c = dot(s.face, l);
    return rblShadow(k, s.position, s.face, max(abs(c), 1e-4), clamp(c*20.0, -1.0, 1.0), s.caster);
}
#endif
