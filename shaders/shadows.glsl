// Shadows: the shadow maps a receiver samples and the lookup (bias, receiver plane, PCF). Which
// light a map shadows is the lights' business (lights.glsl, deferred_volume.fs.glsl).
//   RBL_SHADOWS n             shadow maps sampled (0..4; rblShadowMap0..3), each shadowing one light
//   RBL_SHADOW_FILTER k       PCF footprint in texels per side: (k + 1)^2 depth fetches per lookup
// A map is one light camera (directional, spot), six cube faces (a point light: tiles 3 x 2 of one
// target, +X -X +Y / -Y +Z -Z) or 2..4 cascades (tiles in a row); every tile is looked up alike.
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
uniform vec4 rblShadowTiles[4*RBL_SHADOWS]; // omni: [4k] light position, tan of a face's half width; cascade c:
                                            // [4k + c] 1/width, -left/width, -bottom/width, far split
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

// Map k of any kind: picks the tile(s) and their transform, then looks up as one camera. Omni: the
// cube face of the point's major axis from the light (rows built as the CPU's face camera, the
// guard band keeping the PCF footprint inside the face). Cascades: the first whose far split lies
// beyond the point's view depth; inside the last blend share of its range the next cascade's lookup
// is mixed in linearly (each cascade's map covers the previous one's band)
float rblShadowMap(sampler2D map, vec4 r0, vec4 r1, vec4 r2, vec4 r3, vec4 prm, vec4 bias, vec4 ax0, vec4 ax1,
                   vec4 t0, vec4 t1, vec4 t2, vec4 t3, vec3 position, vec3 n, float NdotL, float side, vec2 caster)
{
    float kind = floor(prm.y/4.0 + 0.01);
    float size = bias.w;
    vec4 p = vec4(prm.x, prm.y - 4.0*kind, prm.zw), tile = vec4(0.0, 0.0, size, size);
    vec3 right = ax0.xyz, up = ax1.xyz;
    float c = 0.0, mixing = 0.0;
    if (kind > 1.5)
    {
        float depth = dot(r3, vec4(position, 1.0));
        c = (depth < t0.w)? 0.0 : ((depth < t1.w)? 1.0 : ((depth < t2.w)? 2.0 : 3.0));
        float end = (c < 0.5)? t0.w : ((c < 1.5)? t1.w : ((c < 2.5)? t2.w : t3.w));
        if (!(c < kind) || !(depth < end)) return 1.0;
        float band = ax1.w*(end - ((c < 0.5)? ax0.w : ((c < 1.5)? t0.w : ((c < 2.5)? t1.w : t2.w))));
        mixing = ((c + 1.0 < kind) && (band > 0.0))? clamp((depth - (end - band))/band, 0.0, 1.0) : 0.0;
    }
    else if (kind > 0.5)
    {
        vec3 d = position - t0.xyz, a = abs(d);
        float face = (a.x >= a.y && a.x >= a.z)? ((d.x < 0.0)? 1.0 : 0.0) : ((a.y >= a.z)? ((d.y < 0.0)? 3.0 : 2.0) : ((d.z < 0.0)? 5.0 : 4.0));
        vec3 along = (face < 1.5)? vec3(1.0, 0.0, 0.0) : ((face < 3.5)? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0));
        along *= (mod(face, 2.0) > 0.5)? -1.0 : 1.0;
        up = (abs(along.y) > 0.5)? vec3(0.0, 0.0, 1.0) : vec3(0.0, 1.0, 0.0);
        right = cross(along, up);
        float e = dot(along, t0.xyz), s = 0.5/t0.w, g = p.w/(p.w - p.z);
        r3 = vec4(along, -e);
        r0 = vec4(right*s, -dot(right, t0.xyz)*s) + 0.5*r3;
        r1 = vec4(up*s, -dot(up, t0.xyz)*s) + 0.5*r3;
        r2 = g*r3 - vec4(0.0, 0.0, 0.0, g*p.z);
        tile = vec4(mod(face, 3.0)*size, floor(face/3.0)*size, 3.0*size, 2.0*size);
    }
    // One lookup call (one PCF loop in the program, whatever the kind); a second pass in a blend band
    vec4 c0 = r0, c1 = r1, c3 = r3;
    float first = 1.0, lit = 1.0;
    for (int i = 0; i < 2; i++)
    {
        if ((i == 1) && !(mixing > 0.0)) break;
        if (kind > 1.5)
        {
            float ci = c + float(i);
            vec4 t = (ci < 0.5)? t0 : ((ci < 1.5)? t1 : ((ci < 2.5)? t2 : t3));
            c0 = vec4(r0.xyz*t.x, t.y); c1 = vec4(r1.xyz*t.x, t.z); c3 = vec4(0.0, 0.0, 0.0, 1.0);
            p.x = 1.0/(t.x*size);
            tile = vec4(ci*size, 0.0, kind*size, size);
        }
        lit = rblShadowLookup(map, c0, c1, r2, c3, p, bias, right, up, tile, position, n, NdotL, side, caster);
        if (i == 0) first = lit;
    }
    return (mixing > 0.0)? mix(first, lit, mixing) : first;
}

float rblShadow(int k, vec3 position, vec3 n, float NdotL, float side, vec2 caster)
{
    if (k == 0) return rblShadowMap(rblShadowMap0, rblShadowMatrix[0], rblShadowMatrix[1], rblShadowMatrix[2], rblShadowMatrix[3], rblShadowParams[0], rblShadowBias[0],
                                    rblShadowAxes[0], rblShadowAxes[1], rblShadowTiles[0], rblShadowTiles[1], rblShadowTiles[2], rblShadowTiles[3], position, n, NdotL, side, caster);
#if RBL_SHADOWS > 1
    if (k == 1) return rblShadowMap(rblShadowMap1, rblShadowMatrix[4], rblShadowMatrix[5], rblShadowMatrix[6], rblShadowMatrix[7], rblShadowParams[1], rblShadowBias[1],
                                    rblShadowAxes[2], rblShadowAxes[3], rblShadowTiles[4], rblShadowTiles[5], rblShadowTiles[6], rblShadowTiles[7], position, n, NdotL, side, caster);
#endif
#if RBL_SHADOWS > 2
    if (k == 2) return rblShadowMap(rblShadowMap2, rblShadowMatrix[8], rblShadowMatrix[9], rblShadowMatrix[10], rblShadowMatrix[11], rblShadowParams[2], rblShadowBias[2],
                                    rblShadowAxes[4], rblShadowAxes[5], rblShadowTiles[8], rblShadowTiles[9], rblShadowTiles[10], rblShadowTiles[11], position, n, NdotL, side, caster);
#endif
#if RBL_SHADOWS > 3
    if (k == 3) return rblShadowMap(rblShadowMap3, rblShadowMatrix[12], rblShadowMatrix[13], rblShadowMatrix[14], rblShadowMatrix[15], rblShadowParams[3], rblShadowBias[3],
                                    rblShadowAxes[6], rblShadowAxes[7], rblShadowTiles[12], rblShadowTiles[13], rblShadowTiles[14], rblShadowTiles[15], position, n, NdotL, side, caster);
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
