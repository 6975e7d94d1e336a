// Instanced billboard vertex stage: expands one quad per instance (6 vertices, gl_VertexID 0..5)
// from per-instance data. Each function mirrors the CPU function of the same name in the header's
// geometry section (rblSinCosDeg = rbl__sinCosDeg, rblFacingBasis = rbl__facingBasis,
// rblBillboardVertex = one corner of rbl__billboardVertices), with the same degenerate-frame
// fallbacks, so all three paths emit the same vertices. Pairs with lit.fs.glsl, gbuffer.fs.glsl and
// shadow_caster.fs.glsl.
#include "common.glsl"

// An RblInstance, or in the resident-sprite variant (RBL_SPRITE_BUFFER, compiled by the header for
// RblDrawSpriteBuffer) an RblSpriteInstance whose 32 bytes the same locations read as: 10 pivot,
// scale; 11 start (x); 12 rotation, frame, speed (half-float bits), mode, as unsigned shorts; 13 tint
#ifdef RBL_BATCH_RECORD
// The batch-record variant (RblBatch on GLSL 3 with the header's programs): one record per
// billboard, the RblBillboard as added (flags: its rotated-frame and cylinder bits; a FIXED or AXIS
// up and axis tamed as the CPU tames them). Its facing, up, axis and roundness are its own, not the
// draw's. Locations 6..9 are the cross-fade's elsewhere: record programs have no cross-fade
layout(location = 10) in vec3 rblRecordPosition;    // pivot
layout(location = 11) in vec4 rblRecordSizeOrigin;  // xy: size (negative mirrors), zw: origin
layout(location = 12) in float rblRecordRotation;   // degrees
layout(location = 13) in vec4 rblRecordSource;      // x, y, width, height in texels (all zero = whole texture)
layout(location = 14) in vec4 rblRecordTint;        // normalised bytes (all zero = white)
layout(location = 15) in float rblRecordFacing;     // RblFacing
layout(location = 6) in vec3 rblRecordUp;           // as RblInstancedDesc.up
layout(location = 7) in vec3 rblRecordAxis;         // as RblInstancedDesc.axis
layout(location = 8) in float rblRecordRoundness;   // as RblInstancedDesc.roundness
layout(location = 9) in float rblRecordFlags;       // RBL_FRAME_ROTATED, RBL_ROUND_CYLINDER
#else
layout(location = 10) in vec4 rblInstancePosition;  // xyz: pivot, w: rotation in degrees
layout(location = 11) in vec4 rblInstanceSize;      // xy: size (negative mirrors), zw: origin
layout(location = 12) in vec4 rblInstanceSource;    // x, y, width, height in texels (all zero = whole texture)
layout(location = 13) in vec4 rblInstanceTint;      // normalised bytes (all zero = white)
layout(location = 14) in float rblInstanceFlags;    // RblBillboardFlags
#endif
#ifdef RBL_CROSS_FADE
// RblInstancedDesc.fades, a second per-instance buffer (without it: constant, weight 0)
layout(location = 15) in vec4 rblInstanceFadeSource; // the second frame, as rblInstanceSource
layout(location = 6) in float rblInstanceFadeWeight; // 0..1
layout(location = 7) in float rblInstanceFadeFlags;  // its RBL_FRAME_ROTATED bit
layout(location = 8) in vec4 rblInstanceFadeClip;   // RblFade.clip[0]: the first frame's trimmed part of the quad (zero = all)
layout(location = 9) in vec4 rblInstanceFadeClip2;  // RblFade.clip[1]: the second frame's
RBL_VARYING vec2 fragTexCoord2;
RBL_FLAT RBL_VARYING vec2 fragFade;                  // weight, tangent axes code (material.glsl rblFadeAxes)
RBL_VARYING vec4 fragFadeClip;                       // both frames' positions in their rectangles
#endif

#ifdef RBL_CASTER_ID
RBL_FLAT RBL_VARYING vec2 fragCasterId;              // the instance's caster identity (rblCasterIdOf)
#endif

uniform mat4 mvp;
// Per-draw frame, one upload (uniform calls cost more than the data in most drivers):
//   [0] eye, facing code: RblFacing + 8 in a shadow pass with light-facing casters (AXIS tilts turn
//       the front face to the light); the batch-record variant's facing is each record's, the code
//       adds 8 as above and 16 in an omni pass with light-facing casters (its CAMERA_PLANE cards
//       face the light's position, rbl__castFacing)
//   [1] right, roundness   [2] up, texture width   [3] back, texture height
//   [4] facing up (CAMERA_PLANE: caller up, zero = camera up; FIXED: up, zero = +Y), w: shadow pass
//       minimum sine at which the light sees an AXIS billboard (0 = no tilt)
//   [5] facing axis (AXIS: locked axis, zero = +Y; FIXED: normal, zero = +Z), w: 1 orthographic camera
//   [6] shadow pass light: xyz toward the light (w 0) or its position (w 1); zero outside shadow passes
#ifdef RBL_SPRITE_BUFFER
//   [7] (the resident-sprite variant only) x: 1, y: the sprites' clock (seconds), z: frame table
//       width, w: the atlas's frame count
uniform vec4 rblInstancing[8];

// A sprite buffer's frame table (RGBA32F, read with texelFetch; rbl__buildFrameTable writes it):
//   frame k at texels 3k (source), 3k + 1 (size, origin per unit of scale), 3k + 2 (duration, rotated)
//   tag t (-1: every frame, forward) at texels 3 frameCount + 2(t + 1): (first timeline entry,
//   entries, period, first pass) and (last frame after an odd / an even count of passes, the tag's
//   repeat, a pingpong's first frame duration or 0); then the timeline entries
//   (frame, start within the period)
uniform highp sampler2D rblFrameTable;
#else
uniform vec4 rblInstancing[7];
#endif

#ifdef RBL_POLYGONS
// Polygon frames (the variant the header compiles for draws with RBL_FRAME_POLYGON instances or a
// sprite buffer of a polygon sheet): rblPolygon x: vertices drawn per instance (the draw's largest
// polygon's corners, 6 at least; a quad uses 6, the rest collapse), y: table width in texels, z: lowest
// handle in the polygon table. A polygon is kept cut along each frame diagonal (a = b, a + b = 1: the
// quad's two triangles meet on one of them; rounded draws) and uncut (flat draws), each cut as
// corners: pairs (a, b) of fractions of its frame's source, two a texel, 3 per triangle (each turning
// as the quad's (0, 1, 2) seen from the front). Its two header texels hold each cut's first corner
// texel and corner count; the plain variant finds them at texel 2 (handle - z) of rblPolygonTable, the
// resident-sprite variant at the frame table texel that frame k's texel 3k + 2 names in z (w: 1 + its
// most corners, 0 for a quad frame)
uniform vec4 rblPolygon;
#ifndef RBL_SPRITE_BUFFER
uniform highp sampler2D rblPolygonTable;
#endif
#endif

// The instance being expanded, from either layout (main reads it once)
vec4 rblPivot;          // xyz pivot, w rotation in degrees
vec4 rblSizeOrigin;     // size (negative mirrors), origin
vec4 rblSource;         // texels (all zero = whole texture)
float rblFlagBits;      // RblBillboardFlags
#ifdef RBL_POLYGONS
vec4 rblPolygonSpan;    // The instance's polygon header: both diagonal cuts' first corner texel and count
vec2 rblPolygonFlat;    // ... and the uncut triangles'
bool rblPolygonal;      // ... when it has one (else the quad)
#endif
#ifdef RBL_CROSS_FADE
vec4 rblFadeSource, rblFadeClip0, rblFadeClip1;
float rblFadeWeight, rblFadeFlagBits;
#endif

RBL_VARYING vec3 fragPosition;
RBL_VARYING vec2 fragTexCoord;
RBL_VARYING vec4 fragColor;
RBL_VARYING vec3 fragNormal;
RBL_VARYING vec4 fragTangent;
#ifdef RBL_VIEW_VECTOR
RBL_FLAT RBL_VARYING vec3 fragEye;
RBL_FLAT RBL_VARYING vec4 fragViewAxis; // back direction, w 1 orthographic (common.glsl rblViewVector)
#endif

// Unit v into o, or false with o untouched when v is too short to give a direction (as the CPU's)
bool rblNormalizeTo(vec3 v, inout vec3 o)
{
    float l2 = dot(v, v);
    if (!(l2 > 1e-24)) return false;
    o = v*inversesqrt(l2);
    return true;
}

// Unit component of v perpendicular to unit n (relative threshold, as on the CPU)
bool rblPerpendicular(vec3 v, vec3 n, out vec3 o)
{
    vec3 p = v - n*dot(v, n);
    o = p;
    if (!(dot(p, p) > 1e-10*dot(v, v))) return false;
    return rblNormalizeTo(p, o);
}

vec3 rblFallbackUp(vec3 d)
{
    vec3 a = abs(d);
    if ((a.y >= a.x) && (a.y >= a.z)) return vec3(0.0, 0.0, (d.y > 0.0)? -1.0 : 1.0);
    return vec3(0.0, 1.0, 0.0);
}

// Near-degenerate blend (the CPU's rbl__blendWeight, rbl__offAxis, rbl__blendOffAxis): a direction
// off the axis n from v, blended with the fallback f's as the sine s between v and n drops from 1/8
// to 1/64, where float gives v's direction off n only to about 6e-8/s
#define RBL_BLEND_LO 0.015625
#define RBL_BLEND_HI 0.125

float rblBlendWeight(float s)
{
    float t = clamp((s - RBL_BLEND_LO)*(1.0/(RBL_BLEND_HI - RBL_BLEND_LO)), 0.0, 1.0);
    return t*t*(3.0 - 2.0*t);
}

float rblOffAxis(vec3 v, vec3 n, out vec3 vp)
{
    vp = v - n*dot(v, n);
    float vv = dot(v, v), pp = dot(vp, vp);
    if (!(vv > 1e-24)) return 0.0;
    if (pp >= (RBL_BLEND_HI*RBL_BLEND_HI)*vv) return 1.0;
    return rblBlendWeight(sqrt(pp/vv));
}

vec3 rblBlendOffAxis(vec3 vp, float w, vec3 f, vec3 n)
{
    vec3 c = vec3(0.0);
    if (w > 0.0)
    {
        c = vp*(w*inversesqrt(dot(vp, vp)));
        if (w >= 1.0) return c;
    }
    vec3 fp = f - n*dot(f, n);
    c = c + fp*((1.0 - w)*inversesqrt(dot(fp, fp)));
    for (int i = 0; i < 2; i++) c = c - n*dot(c, n);
    if (!(dot(c, c) > 1e-24)) c = fp;
    return c*inversesqrt(dot(c, c));
}

// fmod(degrees, 360) exactly (as the CPU's fmodf), for |degrees| > 368640: there degrees = m 2^e
// with e >= -5, so 32 degrees is the integer m 2^(e + 5), reduced mod 32*360 by doubling
float rblReduceDegrees(float degrees)
{
    uint bits = floatBitsToUint(degrees);
    int e = int((bits >> 23) & 255u) - 150;
    uint r = ((bits & 0x7fffffu) | 0x800000u) % 11520u;
    for (int i = 0; i < e + 5; i++) r = (r*2u) % 11520u;
    float f = float(r)/32.0;
    return (degrees < 0.0)? -f : f;
}

// sin and cos of an angle in degrees: reduction to [-45, 45] exact in degrees (multiples of 90 come
// out exact), then the same minimax polynomials as the CPU
vec2 rblSinCosDeg(float degrees)
{
    if (abs(degrees) > 368640.0) degrees = rblReduceDegrees(degrees);
    int q = int(degrees*(1.0/90.0) + ((degrees < 0.0)? -0.5 : 0.5));      // nearest quadrant (truncation, as C)
    float x = (degrees - float(q)*90.0)*(3.14159265358979323846/180.0);
    float x2 = x*x;
    float sn = x + x*x2*(-1.6666654611e-1 + x2*(8.3321608736e-3 + x2*(-1.9515295891e-4)));
    float cs = 1.0 - 0.5*x2 + x2*x2*(4.166664568298827e-2 + x2*(-1.388731625493765e-3 + x2*2.443315711809948e-5));
    // Quadrant q: (sin, cos) = (sn, cs), (cs, -sn), (-sn, -cs), (-cs, sn)
    bool swap = (q & 1) != 0;
    vec2 r = swap? vec2(cs, sn) : vec2(sn, cs);
    if ((q & 2) != 0) r.x = -r.x;
    if (((q + 1) & 2) != 0) r.y = -r.y;
    return r;
}

// Right r, up u (unit, except CAMERA_PLANE's caller up) and unit normal n of a billboard at position
// for facing code (rblInstancing[0].w), from the view frame and the draw's up and axis; a shadow pass
// tilts AXIS billboards until the light sees them at the minimum angle. As on the CPU: each mode picks
// an axis, a vector v and a fallback f, one blend follows, then the frame is built.
void rblFacingBasis(int code, vec3 position, vec3 eye, float orthographic, vec3 viewRight, vec3 viewUp, vec3 viewBack,
                    vec3 facingUp, vec3 facingAxis, float minCastSin, vec4 light, out vec3 r, out vec3 u, out vec3 n)
{
    int facing = code & 3;
    bool faceLight = (code & 8) != 0;
    r = viewRight; u = viewUp; n = viewBack;
    vec3 toEye = (orthographic > 0.5)? viewBack : eye - position;     // a parallel view's eye is at infinity (a directional light's too)
    vec3 axis = r, v = u, f = u, a = vec3(0.0, 1.0, 0.0);
    bool own = true;
    if (facing == 0) { own = dot(facingUp, facingUp) > 1e-24; v = facingUp; }
    else if (facing == 1) { own = rblNormalizeTo(toEye, axis); f = cross(axis, r); }
    else if (facing == 2)
    {
        if (dot(facingAxis, facingAxis) > 1e-24) rblNormalizeTo(facingAxis, a);
        vec3 q;
        float wb = rblOffAxis(viewBack, a, q);
        axis = a; v = toEye; f = rblBlendOffAxis(q, wb, viewUp, a);
    }
    else
    {
        axis = vec3(0.0, 0.0, 1.0);
        if (dot(facingAxis, facingAxis) > 1e-24) rblNormalizeTo(facingAxis, axis);
        v = (dot(facingUp, facingUp) > 1e-24)? facingUp : vec3(0.0, 1.0, 0.0); f = rblFallbackUp(axis);
    }
    if (!own) return;
    vec3 p;
    float w = rblOffAxis(v, axis, p);
    vec3 d = rblBlendOffAxis(p, w, f, axis);
    if (facing == 0)
    {
        n = cross(r, d);
        u = facingUp;
        if (w < 1.0) u = r*dot(facingUp, r) + d*sqrt(dot(p, p));
    }
    else if (facing == 1) { n = axis; u = d; r = cross(u, n); }
    else if (facing == 2)
    {
        vec3 nn = d;
        u = a; n = nn; r = cross(u, n);
        vec3 l = a;
        if ((minCastSin > 0.0) && rblNormalizeTo(light.xyz - position*light.w, l))
        {
            float ln = dot(l, n), la = dot(l, a);
            float x = faceLight? ln : abs(ln), y = abs(la), rho = sqrt(x*x + y*y);
            if ((x < minCastSin) && (rho > 0.0))
            {
                float k = min(minCastSin/rho, 1.0), m = sqrt(1.0 - k*k);
                float sg = faceLight? ((la >= 0.0)? 1.0 : -1.0) : (((ln >= 0.0) == (la >= 0.0))? 1.0 : -1.0);
                float c = (k*x + m*y)/rho, sn = (k*y - m*x)/rho*sg;
                float wt = rblBlendWeight(rho);
                if (wt < 1.0)
                {
                    c = c*wt + (1.0 - wt); sn = sn*wt;
                    float inv = 1.0/sqrt(c*c + sn*sn);
                    c *= inv; sn *= inv;
                }
                n = nn*c + a*sn;
                u = a*c - nn*sn;
            }
        }
    }
    else { n = axis; u = d; r = cross(u, n); }
}

#ifdef RBL_CASTER_ID
// MurmurHash3's 32-bit finaliser (the CPU's rbl__mix32)
uint rblMix32(uint h)
{
    h ^= h >> 16; h *= 0x85ebca6bu;
    h ^= h >> 13; h *= 0xc2b2ae35u;
    return h ^ (h >> 16);
}

// A billboard's caster identity: 16 bits mixed from the float bits of its pivot, size and origin (the
// CPU's rbl__casterId; never 0, which marks Models), as two normalised bytes (high, low)
vec2 rblCasterIdOf(vec3 pivot, vec4 sizeOrigin)
{
    uvec3 p = floatBitsToUint(pivot);
    uvec4 s = floatBitsToUint(sizeOrigin);
    uint h = rblMix32(rblMix32(rblMix32(rblMix32(rblMix32(rblMix32(rblMix32(p.x) ^ p.y) ^ p.z) ^ s.x) ^ s.y) ^ s.z) ^ s.w);
    h = (h ^ (h >> 16)) & 0xffffu;
    if (h == 0u) h = 1u;
    return vec2(float(h >> 8), float(h & 255u))/255.0;
}
#endif

// One corner (0 bottom-left, 1 bottom-right, 2 top-right, 3 top-left) of the instance's quad, given
// its rotated frame: world position, texture coordinate, rounded normal and tangent
void rblBillboardVertex(int corner, vec3 r, vec3 u, vec3 n, vec2 textureSize, float roundness,
                        out vec3 position, out vec2 texCoord, out vec3 normal, out vec4 tangent)
{
    int flags = int(rblFlagBits + 0.5);
    vec2 size = rblSizeOrigin.xy, origin = rblSizeOrigin.zw;
    float sx = abs(size.x), sy = abs(size.y);
    vec3 un = u;
    rblNormalizeTo(u, un);
    float ulen = length(u);
    float cs = (corner == 1 || corner == 2)? 1.0 : 0.0;     // sprite-space s (right)
    float ct = (corner < 2)? 1.0 : 0.0;                      // sprite-space t (down)
    float x = (cs > 0.5)? sx - origin.x : -origin.x;
    float y = (ct < 0.5)? sy*ulen - origin.y : -origin.y;
    position = rblPivot.xyz + r*x + un*y;

    vec4 src = rblSource;
    if (src == vec4(0.0)) src = vec4(0.0, 0.0, textureSize);
    bool flipU = (size.x < 0.0) != (src.z < 0.0);
    bool flipV = (size.y < 0.0) != (src.w < 0.0);
    bool rotated = (flags & 1) != 0;
    float s = flipU? 1.0 - cs : cs;
    float t = flipV? 1.0 - ct : ct;
    vec2 frame = rotated? vec2(1.0 - t, s) : vec2(s, t);
    texCoord = (src.xy + frame*abs(src.zw))/textureSize;

    vec3 T, V;
    if (!rotated) { T = flipU? -r : r; V = flipV? un : -un; }
    else { T = flipV? -un : un; V = flipU? -r : r; }
    float w = (dot(cross(n, T), V) < 0.0)? -1.0 : 1.0;

    vec3 nv = n, tv = T;
    float round = clamp(roundness, 0.0, 1.0);
    if (round > 0.0)
    {
        float dx = (cs < 0.5)? -1.0 : 1.0;
        float dy = ((flags & 2) != 0)? 0.0 : ((ct > 0.5)? -1.0 : 1.0);
        rblNormalizeTo(n + (r*dx + un*dy)*round, nv);
        if (!rblPerpendicular(T, nv, tv)) tv = T;
    }
    normal = nv;
    tangent = vec4(tv, w);
}

#ifdef RBL_POLYGONS
vec4 rblPolygonTexel(int i)
{
    int w = int(rblPolygon.y + 0.5);
#ifdef RBL_SPRITE_BUFFER
    return texelFetch(rblFrameTable, ivec2(i % w, i / w), 0);
#else
    return texelFetch(rblPolygonTable, ivec2(i % w, i / w), 0);
#endif
}

// The instance's polygon as flat draws take it, or cut along the diagonal its quad's triangles meet
// on (rbl__billboardCut): first corner texel, corner count
vec2 rblPolygonCut()
{
    if (!(rblInstancing[1].w > 0.0)) return rblPolygonFlat;
    bool flipU = (rblSizeOrigin.x < 0.0) != (rblSource.z < 0.0);
    bool flipV = (rblSizeOrigin.y < 0.0) != (rblSource.w < 0.0);
    bool rotated = (int(rblFlagBits + 0.5) & 1) != 0;
    return ((flipU != flipV) != rotated)? rblPolygonSpan.xy : rblPolygonSpan.zw;
}

// Corner k of the instance's polygon (its cut from first) with the quad's fields there: position and
// texture coordinate of the frame point, normal and tangent interpolated over the quad's triangle
// (0, 1, 2) or (0, 2, 3) holding it, as the rasteriser would over the quad (rbl__expandQuad, the CPU
// twin). A mirror turns the triangles over: corners 1 and 2 swap. Returns sprite (s right, t down).
vec2 rblPolygonVertex(int first, int k, vec3 r, vec3 u, vec3 n, vec2 textureSize, float roundness,
                      out vec3 position, out vec2 texCoord, out vec3 normal, out vec4 tangent)
{
    int flags = int(rblFlagBits + 0.5);
    vec2 size = rblSizeOrigin.xy, origin = rblSizeOrigin.zw;
    vec4 src = rblSource;
    if (src == vec4(0.0)) src = vec4(0.0, 0.0, textureSize);
    bool flipU = (size.x < 0.0) != (src.z < 0.0);
    bool flipV = (size.y < 0.0) != (src.w < 0.0);
    bool rotated = (flags & 1) != 0;
    int m = k - (k/3)*3;
    if (flipU != flipV) k += (m == 1)? 1 : ((m == 2)? -1 : 0);
    vec4 texel = rblPolygonTexel(first + k/2);
    vec2 ab = ((k & 1) != 0)? texel.zw : texel.xy;
    float s = rotated? ab.y : ab.x, t = rotated? 1.0 - ab.x : ab.y;
    if (flipU) s = 1.0 - s;
    if (flipV) t = 1.0 - t;
    float up = 1.0 - t;
    vec3 un = u;
    rblNormalizeTo(u, un);
    float ulen = length(u), sx = abs(size.x), sy = abs(size.y);
    float x = (-origin.x)*(1.0 - s) + (sx - origin.x)*s, y = (-origin.y)*(1.0 - up) + (sy*ulen - origin.y)*up;
    position = rblPivot.xyz + r*x + un*y;
    texCoord = (src.xy + ab*abs(src.zw))/textureSize;
    vec3 pc, n1, n2;
    vec2 tc;
    vec4 g1, g2;
    rblBillboardVertex(0, r, u, n, textureSize, roundness, pc, tc, normal, tangent);
    if (clamp(roundness, 0.0, 1.0) > 0.0)
    {
        bool lower = s >= up;
        vec3 w = lower? vec3(1.0 - s, s - up, up) : vec3(1.0 - up, s, up - s);
        rblBillboardVertex(lower? 1 : 2, r, u, n, textureSize, roundness, pc, tc, n1, g1);
        rblBillboardVertex(lower? 2 : 3, r, u, n, textureSize, roundness, pc, tc, n2, g2);
        normal = normal*w.x + n1*w.y + n2*w.z;
        tangent = vec4(tangent.xyz*w.x + g1.xyz*w.y + g2.xyz*w.z, tangent.w);
    }
    return vec2(s, t);
}
#endif

#ifdef RBL_CROSS_FADE
// Texture coordinate of the corner at sprite (cs right, ct down) in frame src (all zero = the whole
// texture), as rblBillboardVertex, and the frame's +U (T) and +V (V) in the quad's (right, up) plane
vec2 rblFrameTexCoord(vec4 src, bool rotated, vec2 size, float cs, float ct, vec2 textureSize, out vec2 T, out vec2 V)
{
    if (src == vec4(0.0)) src = vec4(0.0, 0.0, textureSize);
    bool flipU = (size.x < 0.0) != (src.z < 0.0);
    bool flipV = (size.y < 0.0) != (src.w < 0.0);
    float s = flipU? 1.0 - cs : cs;
    float t = flipV? 1.0 - ct : ct;
    if (!rotated) { T = vec2(flipU? -1.0 : 1.0, 0.0); V = vec2(0.0, flipV? 1.0 : -1.0); }
    else { T = vec2(0.0, flipV? -1.0 : 1.0); V = vec2(flipU? -1.0 : 1.0, 0.0); }
    return (src.xy + (rotated? vec2(1.0 - t, s) : vec2(s, t))*abs(src.zw))/textureSize;
}

// Position of picture point p (quad fractions, top-left origin) in clip rectangle c (x, y, width,
// height; zero size = the whole quad); an axis c covers whole is 0.5 (as the CPU's rbl__fadeClipLocal)
vec2 rblFadeClipLocal(vec4 c, vec2 p)
{
    if (!((c.z > 0.0) && (c.w > 0.0))) return vec2(0.5);
    vec2 l = (p - c.xy)/c.zw;
    if ((c.x <= 0.0) && (c.x + c.z >= 1.0)) l.x = 0.5;
    if ((c.y <= 0.0) && (c.y + c.w >= 1.0)) l.y = 0.5;
    return l;
}

// The second frame's axes against the first's: swap (its +U along the first's V) + 2 negT + 4 negV
float rblFadeCode(vec2 t1, vec2 v1, vec2 t2, vec2 v2)
{
    float x = dot(t2, v1);
    bool swapAxes = x != 0.0;
    float negT = ((swapAxes? x : dot(t2, t1)) < 0.0)? 2.0 : 0.0;
    float negV = ((swapAxes? dot(v2, t1) : dot(v2, v1)) < 0.0)? 4.0 : 0.0;
    return (swapAxes? 1.0 : 0.0) + negT + negV;
}
#endif

#ifdef RBL_SPRITE_BUFFER
// Texel i of the frame table (rows of rblInstancing[7].z texels)
vec4 rblTable(int i)
{
    int w = int(rblInstancing[7].z + 0.5);
    return texelFetch(rblFrameTable, ivec2(i % w, i / w), 0);
}

// An IEEE half float from its 16 bits (the CPU writes finite, non-negative speeds only)
float rblHalfBits(uint h)
{
    uint e = (h >> 10) & 31u, m = h & 1023u;
    float v = (e == 0u)? float(m)*exp2(-24.0) : exp2(float(int(e) - 15))*(1.0 + float(m)*(1.0/1024.0));
    return ((h & 0x8000u) != 0u)? -v : v;
}

// The frame tag t shows local seconds into its play, the frame after it and the weight time /
// duration (RblSpriteBlend's): the CPU's RblUpdateSprite over loops passes (0 = forever), with the
// period's frames as a timeline found by bisection
void rblSpriteFrame(int t, int loops, float local, out int frame, out int next, out float weight)
{
    int base = 3*int(rblInstancing[7].w + 0.5) + 2*(t + 1);   // tag -1 (every frame) is the first row
    vec4 row = rblTable(base), ends = rblTable(base + 1);
    int first = int(row.x + 0.5), count = int(row.y + 0.5);
    float period = row.z;
    if (loops < 0) loops = int(ends.z + 0.5);                  // the tag's repeat (0 = forever)
    if (loops > 0)
    {
        // A pingpong pass ends on a turn frame: pass 2m + 1 at m periods + the first pass, pass 2m
        // at m periods + the first frame (ends.w; 0: one pass per period)
        float end = (ends.w > 0.0)? float(loops/2)*period + (((loops & 1) != 0)? row.w : ends.w) : float(loops)*period;
        int last = int((((loops & 1) != 0)? ends.x : ends.y) + 0.5);
        if (local >= end - rblTable(3*last + 2).x) { frame = last; next = last; weight = 0.0; return; }
    }
    float tp = local - floor(local/period)*period;
    if (!(tp < period) || (tp < 0.0)) tp = 0.0;
    int lo = 0, hi = count;                                     // entries [lo, hi): start(lo) <= tp
    for (int i = 0; (i < 16) && (hi - lo > 1); i++)
    {
        int mid = (lo + hi)/2;
        if (rblTable(first + mid).y <= tp) lo = mid; else hi = mid;
    }
    vec4 entry = rblTable(first + lo);
    frame = int(entry.x + 0.5);
    next = int(rblTable(first + ((lo + 1 < count)? lo + 1 : 0)).x + 0.5);
    weight = clamp((tp - entry.y)/rblTable(3*frame + 2).x, 0.0, 1.0);
}

// A resident sprite into the instance globals: its frame (animated on the clock rblInstancing[7].y)
// from the table, the quad scaled from the frame's, flips about the pivot
void rblReadSprite()
{
    vec4 word = rblInstanceSource;                              // rotation, frame, speed bits, mode
    uint mode = uint(word.w + 0.5);
    int frame = int(word.y + 0.5), next = frame;
    float weight = 0.0;
    if ((mode & 8u) != 0u)
    {
        int tag = (frame == 65535)? -1 : frame;
        int loops = int(mode >> 8);
        loops = (loops == 0)? -1 : ((loops == 255)? 0 : loops);
        float local = max((rblInstancing[7].y - rblInstanceSize.x)*rblHalfBits(uint(word.z + 0.5)), 0.0);
        rblSpriteFrame(tag, loops, local, frame, next, weight);
    }
    vec4 quad = rblTable(3*frame + 1)*rblInstancePosition.w;   // size, origin
    if ((mode & 1u) != 0u) quad.xz = vec2(-quad.x, quad.x - quad.z);
    if ((mode & 2u) != 0u) quad.yw = vec2(-quad.y, quad.y - quad.w);
    rblPivot = vec4(rblInstancePosition.xyz, word.x*(360.0/65536.0));
    rblSizeOrigin = quad;
    rblSource = rblTable(3*frame);
    vec4 frameBits = rblTable(3*frame + 2);
    rblFlagBits = frameBits.y + (((mode & 4u) != 0u)? 2.0 : 0.0);
#ifdef RBL_POLYGONS
    rblPolygonal = frameBits.w > 0.5;
    rblPolygonSpan = rblPolygonal? rblTable(int(frameBits.z + 0.5)) : vec4(0.0);
    rblPolygonFlat = rblPolygonal? rblTable(int(frameBits.z + 0.5) + 1).xy : vec2(0.0);
#endif
#ifdef RBL_CROSS_FADE
    rblFadeSource = rblTable(3*next);
    rblFadeFlagBits = rblTable(3*next + 2).y;
    rblFadeWeight = weight;
    rblFadeClip0 = vec4(0.0); rblFadeClip1 = vec4(0.0);
#endif
}
#endif

void main()
{
#ifdef RBL_SPRITE_BUFFER
    rblReadSprite();
#elif defined(RBL_BATCH_RECORD)
    rblPivot = vec4(rblRecordPosition, rblRecordRotation); rblSizeOrigin = rblRecordSizeOrigin; rblSource = rblRecordSource; rblFlagBits = rblRecordFlags;
#else
    rblPivot = rblInstancePosition; rblSizeOrigin = rblInstanceSize; rblSource = rblInstanceSource; rblFlagBits = rblInstanceFlags;
#ifdef RBL_CROSS_FADE
    rblFadeSource = rblInstanceFadeSource; rblFadeWeight = rblInstanceFadeWeight; rblFadeFlagBits = rblInstanceFadeFlags;
    rblFadeClip0 = rblInstanceFadeClip; rblFadeClip1 = rblInstanceFadeClip2;
#endif
#ifdef RBL_POLYGONS
    // The handle in flags bits 4..23 (flags from 2^24 up hold none: the float is exact below it)
    uint handle = (rblFlagBits < 16777216.0)? (uint(rblFlagBits + 0.5) >> 4) & 0xFFFFFu : 0u;
    rblPolygonal = handle != 0u;
    int header = 2*(int(handle) - int(rblPolygon.z + 0.5));
    rblPolygonSpan = rblPolygonal? rblPolygonTexel(header) : vec4(0.0);
    rblPolygonFlat = rblPolygonal? rblPolygonTexel(header + 1).xy : vec2(0.0);
#endif
#endif
#ifdef RBL_POLYGONS
    // Past the instance's corners (a quad's 6, or its polygon's): one point outside the view, so the
    // padding triangles have no area
    vec2 cut = rblPolygonal? rblPolygonCut() : vec2(0.0, 6.0);
    if (gl_VertexID >= int(cut.y + 0.5))
    {
        fragPosition = vec3(0.0); fragTexCoord = vec2(0.0); fragColor = vec4(0.0); fragNormal = vec3(0.0, 0.0, 1.0); fragTangent = vec4(1.0, 0.0, 0.0, 1.0);
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
#endif
    const int cornerOf[6] = int[6](0, 1, 2, 0, 2, 3);
    vec3 eye = rblInstancing[0].xyz;
    int code = int(rblInstancing[0].w + 0.5);
    vec3 facingUp = rblInstancing[4].xyz, facingAxis = rblInstancing[5].xyz;
    float roundness = rblInstancing[1].w;
#ifdef RBL_BATCH_RECORD
    vec4 tintIn = rblRecordTint;
    int facing = int(rblRecordFacing + 0.5);
    if (((code & 16) != 0) && (facing == 0)) facing = 1;
    code = facing + (code & 8);
    facingUp = rblRecordUp; facingAxis = rblRecordAxis; roundness = rblRecordRoundness;
#else
    vec4 tintIn = rblInstanceTint;
#endif
    vec3 r, u, n;
    rblFacingBasis(code, rblPivot.xyz, eye, rblInstancing[5].w, rblInstancing[1].xyz, rblInstancing[2].xyz,
                   rblInstancing[3].xyz, facingUp, facingAxis, rblInstancing[4].w, rblInstancing[6], r, u, n);
    // A tilted AXIS caster turns about its lowest edge, moving to mid-height as the light nears the
    // axis (rbl__billboardVertices)
    vec3 shift = vec3(0.0);
    vec2 sc = vec2(0.0, 1.0);
    if (rblPivot.w != 0.0) sc = rblSinCosDeg(rblPivot.w);
    if (((code & 3) == 2) && (rblInstancing[4].w > 0.0))
    {
        vec3 a = vec3(0.0, 1.0, 0.0), l = a;
        if (dot(facingAxis, facingAxis) > 1e-24) rblNormalizeTo(facingAxis, a);
        vec3 d = a - u;
        vec4 light = rblInstancing[6];
        if ((dot(d, d) > 0.0) && rblNormalizeTo(light.xyz - rblPivot.xyz*light.w, l))
        {
            float x0 = -rblSizeOrigin.z, x1 = abs(rblSizeOrigin.x) - rblSizeOrigin.z;
            float y0 = -rblSizeOrigin.w, y1 = abs(rblSizeOrigin.y) - rblSizeOrigin.w;
            vec4 e = vec4(sc.x*x0 + sc.y*y0, sc.x*x1 + sc.y*y0, sc.x*x1 + sc.y*y1, sc.x*x0 + sc.y*y1);
            float lo = min(min(e.x, e.y), min(e.z, e.w)), hi = max(max(e.x, e.y), max(e.z, e.w));
            float t = clamp((abs(dot(l, a)) - 0.8660254)*(1.0/(1.0 - 0.8660254)), 0.0, 1.0);
            shift = d*(lo + 0.5*(hi - lo)*(t*t*(3.0 - 2.0*t)));
        }
    }
    // Rotate the frame around the normal (raylib rotates the corners; same result)
    if (rblPivot.w != 0.0)
    {
        vec3 nr = cross(n, r), nu = cross(n, u);
        r = r*sc.y + nr*sc.x;
        u = u*sc.y + nu*sc.x;
    }
    vec3 p;
#ifdef RBL_POLYGONS
    vec2 polygonPoint = vec2(-1.0);
    if (rblPolygonal)
        polygonPoint = rblPolygonVertex(int(cut.x + 0.5), gl_VertexID, r, u, n, vec2(rblInstancing[2].w, rblInstancing[3].w), roundness,
                                        p, fragTexCoord, fragNormal, fragTangent);
    else
#endif
    rblBillboardVertex(cornerOf[gl_VertexID % 6], r, u, n, vec2(rblInstancing[2].w, rblInstancing[3].w), roundness,
                       p, fragTexCoord, fragNormal, fragTangent);
    p += shift;
    fragPosition = p;
#ifdef RBL_CASTER_ID
    fragCasterId = rblCasterIdOf(rblPivot.xyz, rblSizeOrigin);
#endif
#ifdef RBL_CROSS_FADE
    int corner = cornerOf[gl_VertexID % 6];
    float cs = (corner == 1 || corner == 2)? 1.0 : 0.0, ct = (corner < 2)? 1.0 : 0.0;
#ifdef RBL_POLYGONS
    if (polygonPoint.x >= 0.0) { cs = polygonPoint.x; ct = polygonPoint.y; }
#endif
    vec2 textureSize = vec2(rblInstancing[2].w, rblInstancing[3].w), t1, v1, t2, v2;
    rblFrameTexCoord(rblSource, (int(rblFlagBits + 0.5) & 1) != 0, rblSizeOrigin.xy, cs, ct, textureSize, t1, v1);
    fragTexCoord2 = rblFrameTexCoord(rblFadeSource, (int(rblFadeFlagBits + 0.5) & 1) != 0, rblSizeOrigin.xy, cs, ct, textureSize, t2, v2);
    fragFade = vec2(rblFadeWeight, rblFadeCode(t1, v1, t2, v2));
    // Clip rectangles are in the picture: a mirrored quad mirrors them with it
    vec2 picture = vec2((rblSizeOrigin.x < 0.0)? 1.0 - cs : cs, (rblSizeOrigin.y < 0.0)? 1.0 - ct : ct);
    fragFadeClip = vec4(rblFadeClipLocal(rblFadeClip0, picture), rblFadeClipLocal(rblFadeClip1, picture));
#endif
    vec4 tint = (tintIn == vec4(0.0))? vec4(1.0) : tintIn;
    fragColor = vec4(rblSrgbToLinear(tint.rgb), tint.a);       // sRGB like every raylib Color: decoded once per vertex
#ifdef RBL_VIEW_VECTOR
    fragEye = eye;
    fragViewAxis = vec4(rblInstancing[3].xyz, rblInstancing[5].w);
#endif
    gl_Position = mvp*vec4(p, 1.0);
}
