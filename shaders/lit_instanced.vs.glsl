// Instanced billboard vertex shader: expands one quad per instance (6 vertices, gl_VertexID 0..5)
// from per-instance data, with the same math and degenerate-frame fallbacks as the CPU path
// (RblBillboardVertices), so all three paths emit the same vertices. Pairs with lit.fs.glsl.
// The loader prepends "#version 330" and the variant's #defines.

layout(location = 10) in vec4 rblInstancePosition;  // xyz: pivot, w: rotation in degrees
layout(location = 11) in vec4 rblInstanceSize;      // xy: size (negative mirrors), zw: origin
layout(location = 12) in vec4 rblInstanceSource;    // x, y, width, height in texels (all zero = whole texture)
layout(location = 13) in vec4 rblInstanceTint;      // normalised bytes (all zero = white)
layout(location = 14) in float rblInstanceFlags;    // RblBillboardFlags

uniform mat4 mvp;
// Per-draw frame, one upload (uniform calls cost more than the data in most drivers):
//   [0] eye, facing   [1] right, roundness   [2] up, texture width   [3] back, texture height
//   [4] facing up (CAMERA_PLANE: caller up, zero = camera up; FIXED: up, zero = +Y), w: shadow pass
//       minimum sine at which the light sees an AXIS billboard (0 = no tilt)
//   [5] facing axis (AXIS: locked axis, zero = +Y; FIXED: normal, zero = +Z)
//   [6] shadow pass light: xyz toward the light (w 0) or its position (w 1); zero outside shadow passes
uniform vec4 rblInstancing[7];

out vec3 fragPosition;
out vec2 fragTexCoord;
out vec4 fragColor;
out vec3 fragNormal;
out vec4 fragTangent;
#ifdef RBL_VIEW_VECTOR
flat out vec3 fragEye;
#endif

// Vertex colours are sRGB like every raylib Color: decode once per vertex, not per fragment
vec3 rblSrgbToLinear(vec3 c)
{
    return mix(c/12.92, pow((c + 0.055)/1.055, vec3(2.4)), step(vec3(0.04045), c));
}

bool rblNormalizeTo(vec3 v, out vec3 o)
{
    float l2 = dot(v, v);
    o = v;
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
    if ((a.z <= a.x) && (a.z <= a.y)) return vec3(0.0, 0.0, (d.y > 0.0)? -1.0 : 1.0);
    if (a.y <= a.x) return vec3(0.0, 1.0, 0.0);
    return vec3(1.0, 0.0, 0.0);
}

void main()
{
    vec3 rblViewEye = rblInstancing[0].xyz, rblViewRight = rblInstancing[1].xyz;
    vec3 rblViewUp = rblInstancing[2].xyz, rblViewBack = rblInstancing[3].xyz;
    vec3 rblFacingUp = rblInstancing[4].xyz, rblFacingAxis = rblInstancing[5].xyz;
    int rblFacing = int(rblInstancing[0].w + 0.5);
    float rblRoundness = rblInstancing[1].w;
    vec2 rblTextureSize = vec2(rblInstancing[2].w, rblInstancing[3].w);
    const int cornerOf[6] = int[6](0, 1, 2, 0, 2, 3);
    int corner = cornerOf[gl_VertexID % 6];
    vec3 position = rblInstancePosition.xyz;
    int flags = int(rblInstanceFlags + 0.5);

    // Facing basis (right r, up u, normal n)
    vec3 r = rblViewRight, u = rblViewUp, n = rblViewBack;
    if (rblFacing == 0)
    {
        vec3 nn;
        if ((dot(rblFacingUp, rblFacingUp) > 0.0) && rblNormalizeTo(cross(r, rblFacingUp), nn)) { u = rblFacingUp; n = nn; }
    }
    else if (rblFacing == 1)
    {
        vec3 toEye;
        if (rblNormalizeTo(rblViewEye - position, toEye))
        {
            n = toEye;
            vec3 rr;
            if (rblNormalizeTo(cross(rblViewUp, n), rr)) { r = rr; u = cross(n, r); }
            else { r = rblViewRight; u = cross(n, r); rblNormalizeTo(u, u); r = cross(u, n); }
        }
    }
    else if (rblFacing == 2)
    {
        vec3 a = vec3(0.0, 1.0, 0.0);
        if (dot(rblFacingAxis, rblFacingAxis) > 0.0) rblNormalizeTo(rblFacingAxis, a);
        vec3 nn;
        if (!rblPerpendicular(rblViewEye - position, a, nn) && !rblPerpendicular(rblViewBack, a, nn) &&
            !rblPerpendicular(rblViewUp, a, nn)) nn = rblViewBack;
        u = a; n = nn; r = cross(u, n);
        // Shadow pass: tilt about the pivot line (r) until the light sees the quad at >= the minimum
        // angle, so an upright sprite still casts under a light along its axis (RblShadowTilt on the CPU)
        float minSin = rblInstancing[4].w;
        vec4 light = rblInstancing[6];
        vec3 l;
        if ((minSin > 0.0) && rblNormalizeTo(light.xyz - position*light.w, l))
        {
            float ln = dot(l, n), la = dot(l, a);
            float x = abs(ln), y = abs(la), rho = sqrt(x*x + y*y);
            if ((x < minSin) && (rho > 0.0))
            {
                float k = min(minSin/rho, 1.0), m = sqrt(1.0 - k*k);
                float sg = ((ln >= 0.0) == (la >= 0.0))? 1.0 : -1.0;
                float c = (k*x + m*y)/rho, sn = (k*y - m*x)/rho*sg;
                n = nn*c + a*sn;
                u = a*c - nn*sn;
            }
        }
    }
    else
    {
        vec3 nn = vec3(0.0, 0.0, 1.0);
        if (dot(rblFacingAxis, rblFacingAxis) > 0.0) rblNormalizeTo(rblFacingAxis, nn);
        vec3 uu = (dot(rblFacingUp, rblFacingUp) > 0.0)? rblFacingUp : vec3(0.0, 1.0, 0.0);
        if (!rblPerpendicular(uu, nn, uu)) rblPerpendicular(rblFallbackUp(nn), nn, uu);
        n = nn; u = uu; r = cross(u, n);
    }

    float rotation = rblInstancePosition.w;
    if (rotation != 0.0)
    {
        float ang = rotation*(3.14159265358979323846/180.0), c = cos(ang), s = sin(ang);
        vec3 nr = cross(n, r), nu = cross(n, u);
        r = r*c + nr*s;
        u = u*c + nu*s;
    }

    vec2 size = rblInstanceSize.xy, origin = rblInstanceSize.zw;
    float sx = abs(size.x), sy = abs(size.y);
    vec3 un = u;
    rblNormalizeTo(u, un);
    float ulen = length(u);
    float cs = (corner == 1 || corner == 2)? 1.0 : 0.0;     // sprite-space s (right)
    float ct = (corner < 2)? 1.0 : 0.0;                      // sprite-space t (down)
    float x = (cs > 0.5)? sx - origin.x : -origin.x;
    float y = (ct < 0.5)? sy*ulen - origin.y : -origin.y;
    vec3 p = position + r*x + un*y;

    vec4 src = rblInstanceSource;
    if (src == vec4(0.0)) src = vec4(0.0, 0.0, rblTextureSize);
    bool flipU = (size.x < 0.0) != (src.z < 0.0);
    bool flipV = (size.y < 0.0) != (src.w < 0.0);
    bool rotated = (flags & 1) != 0;
    float s = flipU? 1.0 - cs : cs;
    float t = flipV? 1.0 - ct : ct;
    vec2 frame = rotated? vec2(1.0 - t, s) : vec2(s, t);
    fragTexCoord = (src.xy + frame*abs(src.zw))/rblTextureSize;

    vec3 T, V;
    if (!rotated) { T = flipU? -r : r; V = flipV? un : -un; }
    else { T = flipV? -un : un; V = flipU? -r : r; }
    float w = (dot(cross(n, T), V) < 0.0)? -1.0 : 1.0;

    vec3 nv = n, tv = T;
    float round = clamp(rblRoundness, 0.0, 1.0);
    if (round > 0.0)
    {
        float dx = (cs < 0.5)? -1.0 : 1.0;
        float dy = ((flags & 2) != 0)? 0.0 : ((ct > 0.5)? -1.0 : 1.0);
        rblNormalizeTo(n + (r*dx + un*dy)*round, nv);
        if (!rblPerpendicular(T, nv, tv)) tv = T;
    }

    fragPosition = p;
    vec4 tint = (rblInstanceTint == vec4(0.0))? vec4(1.0) : rblInstanceTint;
    fragColor = vec4(rblSrgbToLinear(tint.rgb), tint.a);
    fragNormal = nv;
    fragTangent = vec4(tv, w);
#ifdef RBL_VIEW_VECTOR
    fragEye = rblViewEye;
#endif
    gl_Position = mvp*vec4(p, 1.0);
}
