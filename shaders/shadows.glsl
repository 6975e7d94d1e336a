// Shadows: the shadow maps a receiver samples and the lookup (bias, receiver plane, PCF). Which
// light a map shadows is the lights' business (lights.glsl, deferred_volume.fs.glsl).
//   RBL_SHADOWS n             shadow maps sampled (0..4; rblShadowMap0..3), each shadowing one light
//   RBL_SHADOW_FILTER k       PCF footprint in texels per side: (k + 1)^2 depth fetches per lookup
//   RBL_SHADOW_KIND<k>        map k's kind: 0 one light camera (directional, spot), 1 omni (a point
//                             light: six cube faces, tiles 3 x 2 of one target, +X -X +Y / -Y +Z -Z),
//                             2 cascades (2..4 tiles in a row); every tile is looked up alike
//   RBL_SHADOW_FORMAT<k>      map k's format: perspective + 2 for the casters target (else a depth texture)
//   RBL_SHADOW_OMNI           some map is omni (its face code is compiled in)
//   RBL_SHADOW_CASCADES       some map is cascaded (its cascade code is compiled in)
// Kind and format are compiled per map (the program registry compiles the variant a scene's maps
// need, RblSetScene): a program receiving one-camera maps holds no tile, face or cascade code, and
// no lookup branches on a format at run time.
#include "surface.glsl"

#if RBL_SHADOWS > 0
uniform vec4 rblShadowMatrix[4*RBL_SHADOWS]; // rows 4k..4k+3: world -> (u, v, window depth, w) of map k (rows: no
                                            // transpose convention to differ between GL and ES uploads)
                                            // cascades: light-frame rows (right, up, window depth), the camera plane
uniform vec4 rblShadowParams[RBL_SHADOWS];  // texel world size (perspective: per unit distance), format, near, far; format:
                                            // 0, 1 depth texture (orthographic, perspective); 2, 3 the casters
                                            // target (RGBA8: 16-bit distance code, caster identity); + 4 x kind
                                            // (0 one camera, 1 omni, 2..4 cascades)
uniform vec4 rblShadowBias[RBL_SHADOWS];    // constant, slope, normal offset (all in texels), tile size in texels
uniform vec4 rblShadowAxes[2*RBL_SHADOWS];  // right and up of map k's light camera (its axis = cross(up, right));
                                            // cascades: w the first split, the blend band's share
#if defined(RBL_SHADOW_OMNI) || defined(RBL_SHADOW_CASCADES)
uniform vec4 rblShadowTiles[4*RBL_SHADOWS]; // omni: [4k] light position, tan of a face's half width; cascade c:
                                            // [4k + c] 1/width, -left/width, -bottom/width, far split
#endif
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
// stages may index uniform arrays only by constants and loop indices. prm.y (the format) is map k's
// compiled RBL_SHADOW_FORMAT<k> at every call, so the compiler folds each branch on it away.
vec4 rblShadowTransform(vec4 r0, vec4 r1, vec4 r2, vec4 r3, vec3 p)
{
    vec4 h = vec4(p, 1.0);
    return vec4(dot(r0, h), dot(r1, h), dot(r2, h), dot(r3, h));
}

// tile: the map's texel origin in its target, the target's size in texels
float rblShadowLookup(sampler2D map, vec4 r0, vec4 r1, vec4 r2, vec4 r3, vec4 prm, vec4 bias, vec3 right, vec3 up, vec4 tile,
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
    // Receiver plane: distance change per texel step along the map's x and y. A perspective map's
    // texel is a ray (along + right x + up y, x and y its tangents at the texel centre): the plane's
    // distance changes with the ray's angle to it, not the axis's (a floor seen by a cube side face
    // lies along the axis), and is the same for n and -n
    vec3 ray = along, nf = n;
    if (perspective)
    {
        ray += (right*(2.0*q.x - 1.0) + up*(2.0*q.y - 1.0))*(0.5*prm.x*bias.w);
        nf = (dot(n, ray) > 0.0)? -n : n;
    }
    vec2 slope = vec2(dot(nf, right), dot(nf, up))/max(-dot(nf, ray), 1e-4);
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
            vec4 t = (all(greaterThanEqual(at, ivec2(0))) && all(lessThanEqual(at, top)))? rblFetch(map, at + ivec2(tile.xy), tile.zw) : vec4(1.0);
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

#if defined(RBL_SHADOW_OMNI)
// An omni map: the cube face of the point's major axis from the light (rows built as the CPU's face
// camera, the guard band keeping the PCF footprint inside the face), looked up as one camera
float rblShadowOmni(sampler2D map, vec4 prm, vec4 bias, vec4 t0, vec3 position, vec3 n, float NdotL, float side, vec2 caster)
{
    float size = bias.w;
    vec3 d = position - t0.xyz, a = abs(d);
    float face = (a.x >= a.y && a.x >= a.z)? ((d.x < 0.0)? 1.0 : 0.0) : ((a.y >= a.z)? ((d.y < 0.0)? 3.0 : 2.0) : ((d.z < 0.0)? 5.0 : 4.0));
    vec3 along = (face < 1.5)? vec3(1.0, 0.0, 0.0) : ((face < 3.5)? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0));
    along *= (mod(face, 2.0) > 0.5)? -1.0 : 1.0;
    vec3 up = (abs(along.y) > 0.5)? vec3(0.0, 0.0, 1.0) : vec3(0.0, 1.0, 0.0);
    vec3 right = cross(along, up);
    float e = dot(along, t0.xyz), s = 0.5/t0.w, g = prm.w/(prm.w - prm.z);
    vec4 r3 = vec4(along, -e);
    vec4 r0 = vec4(right*s, -dot(right, t0.xyz)*s) + 0.5*r3;
    vec4 r1 = vec4(up*s, -dot(up, t0.xyz)*s) + 0.5*r3;
    vec4 r2 = g*r3 - vec4(0.0, 0.0, 0.0, g*prm.z);
    vec4 tile = vec4(mod(face, 3.0)*size, floor(face/3.0)*size, 3.0*size, 2.0*size);
    return rblShadowLookup(map, r0, r1, r2, r3, prm, bias, right, up, tile, position, n, NdotL, side, caster);
}
#endif

#if defined(RBL_SHADOW_CASCADES)
// A cascaded map (kind: the cascade count, from the uniforms): the first cascade whose far split lies
// beyond the point's view depth; inside the last blend share of its range the next cascade's lookup
// is mixed in linearly (each cascade's map covers the previous one's band). One lookup call in the
// program; a second pass in a blend band
float rblShadowCascades(sampler2D map, vec4 r0, vec4 r1, vec4 r2, vec4 r3, vec4 prm, float kind, vec4 bias, vec4 ax0, vec4 ax1,
                        vec4 t0, vec4 t1, vec4 t2, vec4 t3, vec3 position, vec3 n, float NdotL, float side, vec2 caster)
{
    float size = bias.w;
    float depth = dot(r3, vec4(position, 1.0));
    float c = (depth < t0.w)? 0.0 : ((depth < t1.w)? 1.0 : ((depth < t2.w)? 2.0 : 3.0));
    float end = (c < 0.5)? t0.w : ((c < 1.5)? t1.w : ((c < 2.5)? t2.w : t3.w));
    if (!(c < kind) || !(depth < end)) return 1.0;
    float band = ax1.w*(end - ((c < 0.5)? ax0.w : ((c < 1.5)? t0.w : ((c < 2.5)? t1.w : t2.w))));
    float mixing = ((c + 1.0 < kind) && (band > 0.0))? clamp((depth - (end - band))/band, 0.0, 1.0) : 0.0;
    vec4 p = prm;
    float first = 1.0, lit = 1.0;
    for (int i = 0; i < 2; i++)
    {
        if ((i == 1) && !(mixing > 0.0)) break;
        float ci = c + float(i);
        vec4 t = (ci < 0.5)? t0 : ((ci < 1.5)? t1 : ((ci < 2.5)? t2 : t3));
        p.x = 1.0/(t.x*size);
        lit = rblShadowLookup(map, vec4(r0.xyz*t.x, t.y), vec4(r1.xyz*t.x, t.z), r2, vec4(0.0, 0.0, 0.0, 1.0), p, bias, ax0.xyz, ax1.xyz,
                              vec4(ci*size, 0.0, kind*size, size), position, n, NdotL, side, caster);
        if (i == 0) first = lit;
    }
    return (mixing > 0.0)? mix(first, lit, mixing) : first;
}
#endif

// Map k's lookup by its compiled kind and format (RBL_SHADOW_KIND<k>, RBL_SHADOW_FORMAT<k>): k a literal
#define RBL_SHADOW_ONE_OF(map, k, format) rblShadowLookup(map, rblShadowMatrix[4*k], rblShadowMatrix[4*k + 1], rblShadowMatrix[4*k + 2], rblShadowMatrix[4*k + 3], vec4(rblShadowParams[k].x, format, rblShadowParams[k].zw), rblShadowBias[k], rblShadowAxes[2*k].xyz, rblShadowAxes[2*k + 1].xyz, vec4(0.0, 0.0, rblShadowBias[k].ww), position, n, NdotL, side, caster)
#define RBL_SHADOW_OMNI_OF(map, k, format) rblShadowOmni(map, vec4(rblShadowParams[k].x, format, rblShadowParams[k].zw), rblShadowBias[k], rblShadowTiles[4*k], position, n, NdotL, side, caster)
#define RBL_SHADOW_CASCADES_OF(map, k, format) rblShadowCascades(map, rblShadowMatrix[4*k], rblShadowMatrix[4*k + 1], rblShadowMatrix[4*k + 2], rblShadowMatrix[4*k + 3], vec4(rblShadowParams[k].x, format, rblShadowParams[k].zw), floor(rblShadowParams[k].y/4.0 + 0.01), rblShadowBias[k], rblShadowAxes[2*k], rblShadowAxes[2*k + 1], rblShadowTiles[4*k], rblShadowTiles[4*k + 1], rblShadowTiles[4*k + 2], rblShadowTiles[4*k + 3], position, n, NdotL, side, caster)

float rblShadow(int k, vec3 position, vec3 n, float NdotL, float side, vec2 caster)
{
#if RBL_SHADOW_KIND0 == 1
    if (k == 0) return RBL_SHADOW_OMNI_OF(rblShadowMap0, 0, float(RBL_SHADOW_FORMAT0));
#elif RBL_SHADOW_KIND0 == 2
    if (k == 0) return RBL_SHADOW_CASCADES_OF(rblShadowMap0, 0, float(RBL_SHADOW_FORMAT0));
#else
    if (k == 0) return RBL_SHADOW_ONE_OF(rblShadowMap0, 0, float(RBL_SHADOW_FORMAT0));
#endif
#if RBL_SHADOWS > 1
#if RBL_SHADOW_KIND1 == 1
    if (k == 1) return RBL_SHADOW_OMNI_OF(rblShadowMap1, 1, float(RBL_SHADOW_FORMAT1));
#elif RBL_SHADOW_KIND1 == 2
    if (k == 1) return RBL_SHADOW_CASCADES_OF(rblShadowMap1, 1, float(RBL_SHADOW_FORMAT1));
#else
    if (k == 1) return RBL_SHADOW_ONE_OF(rblShadowMap1, 1, float(RBL_SHADOW_FORMAT1));
#endif
#endif
#if RBL_SHADOWS > 2
#if RBL_SHADOW_KIND2 == 1
    if (k == 2) return RBL_SHADOW_OMNI_OF(rblShadowMap2, 2, float(RBL_SHADOW_FORMAT2));
#elif RBL_SHADOW_KIND2 == 2
    if (k == 2) return RBL_SHADOW_CASCADES_OF(rblShadowMap2, 2, float(RBL_SHADOW_FORMAT2));
#else
    if (k == 2) return RBL_SHADOW_ONE_OF(rblShadowMap2, 2, float(RBL_SHADOW_FORMAT2));
#endif
#endif
#if RBL_SHADOWS > 3
#if RBL_SHADOW_KIND3 == 1
    if (k == 3) return RBL_SHADOW_OMNI_OF(rblShadowMap3, 3, float(RBL_SHADOW_FORMAT3));
#elif RBL_SHADOW_KIND3 == 2
    if (k == 3) return RBL_SHADOW_CASCADES_OF(rblShadowMap3, 3, float(RBL_SHADOW_FORMAT3));
#else
    if (k == 3) return RBL_SHADOW_ONE_OF(rblShadowMap3, 3, float(RBL_SHADOW_FORMAT3));
#endif
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
