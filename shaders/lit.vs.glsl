// Lit vertex stage of vertex-buffer geometry: billboards (world-space vertices, matModel = identity)
// and raylib Models (matModel = the model transform) go through the same code. Pairs with lit.fs.glsl,
// gbuffer.fs.glsl and shadow_caster.fs.glsl.
#include "common.glsl"
#include "skinning.glsl"

#ifdef RBL_BATCH_RECORD
// The batch's compact stream (GLSL 3 only): one record per billboard (rbl__BatchRecord), read once
// per instance; gl_VertexID picks the corner of the quad's two triangles (0,1,2) (0,2,3). The CPU
// mirror of this expansion is rbl__recordVertices
layout(location = 10) in vec4 rblRecordCorner;     // xyz: corner 0 (bottom-left of the footprint), w: bits (1 mirror U, 2 mirror V, 4 rotated frame, 8 cylinder)
layout(location = 11) in vec3 rblRecordRight;      // corner 1 - corner 0 (the rotated +R times the width)
layout(location = 12) in vec3 rblRecordUp;         // corner 3 - corner 0 (the rotated +U times the height)
layout(location = 13) in vec4 rblRecordUv;         // texture coordinates: xy at corner 0, zw at corner 2
layout(location = 14) in vec4 rblRecordColor;      // tint, normalised bytes
layout(location = 15) in vec4 rblRecordNormal;     // xyz: the frame's normal (not always R x U: a CAMERA_PLANE caller up), w: roundness 0..1
#else
RBL_ATTRIBUTE vec3 vertexPosition;
RBL_ATTRIBUTE vec2 vertexTexCoord;
RBL_ATTRIBUTE vec3 vertexNormal;
RBL_ATTRIBUTE vec4 vertexColor;
RBL_ATTRIBUTE vec4 vertexTangent;      // xyz: world +U direction, w: handedness (cross(N,T)*w = +V)
#endif
#ifdef RBL_CROSS_FADE
// The fade stream (raylib's texcoord2 location 5): xy the second frame's texture coordinate, z the
// weight, w its tangent axes against the first's (material.glsl). Without the stream the attribute
// is constant (weight 0): the first frame alone
RBL_ATTRIBUTE vec4 vertexTexCoord2;
RBL_VARYING vec2 fragTexCoord2;
RBL_FLAT RBL_VARYING vec2 fragFade;
// The stream's second half: each frame's position in its trimmed rectangle (material.glsl
// fragFadeClip); its location is the linker's (queried: the 1.x dialects have no layout). Without
// the stream it is constant (0 or 1 components: inside)
RBL_ATTRIBUTE vec4 rblFadeClip;
RBL_VARYING vec4 fragFadeClip;
#endif

#ifdef RBL_CASTER_ID
// The billboard's caster identity (shadow_caster.fs.glsl, shadows.glsl): 16 bits as two normalised
// bytes, from the batch's identity stream. rblCasterIdOn is 1 for the header's billboard draws and 0
// otherwise: a Model's identity is 0 whatever its buffers hold at this attribute's location
RBL_ATTRIBUTE vec4 rblCasterId;
uniform float rblCasterIdOn;
RBL_FLAT RBL_VARYING vec2 fragCasterId;
#endif

uniform mat4 mvp;
uniform mat4 matModel;
uniform mat4 matNormal;
#ifdef RBL_VIEW_VECTOR
uniform mat4 matView;       // raylib's DrawMesh and the billboard paths set both: no viewPos glue needed
uniform mat4 matProjection;
RBL_FLAT RBL_VARYING vec3 fragEye;
RBL_FLAT RBL_VARYING vec4 fragViewAxis; // back direction, w 1 orthographic (common.glsl rblViewVector)
#endif

RBL_VARYING vec3 fragPosition;
RBL_VARYING vec2 fragTexCoord;
RBL_VARYING vec4 fragColor;
RBL_VARYING vec3 fragNormal;
RBL_VARYING vec4 fragTangent;

#ifdef RBL_BATCH_RECORD
bool rblRecordBit(float bits, float bit) { return mod(floor(bits/bit), 2.0) == 1.0; }

// Corner of the record's quad: position, texture coordinate, normal, tangent and handedness as
// rbl__expandQuad writes them (a zero edge draws nothing: its normal is never used)
void rblRecordVertex(out vec3 position, out vec2 uv, out vec3 normal, out vec4 tangent)
{
    int id = gl_VertexID;
    int c = (id < 3)? id : ((id == 3)? 0 : id - 2);
    bool s = (c == 1) || (c == 2), t = (c >= 2);
    position = rblRecordCorner.xyz + (s? rblRecordRight : vec3(0.0)) + (t? rblRecordUp : vec3(0.0));
    float bits = rblRecordCorner.w;
    bool flipU = rblRecordBit(bits, 1.0), flipV = rblRecordBit(bits, 2.0), rotated = rblRecordBit(bits, 4.0), cylinder = rblRecordBit(bits, 8.0);
    // A rotated frame's u runs along the sprite's t (its v along s)
    bool su = rotated? t : s, sv = rotated? s : t;
    uv = vec2(su? rblRecordUv.z : rblRecordUv.x, sv? rblRecordUv.w : rblRecordUv.y);
    vec3 R = normalize(rblRecordRight), U = normalize(rblRecordUp), N = rblRecordNormal.xyz;
    vec3 T = rotated? (flipV? -U : U) : (flipU? -R : R);
    normal = N;
    vec3 tg = T;
    float roundness = rblRecordNormal.w;
    if (roundness > 0.0)
    {
        // Corner normals lean outward from the centre (rbl__expandQuad)
        float dx = (s? 1.0 : -1.0)*roundness, dy = cylinder? 0.0 : (t? 1.0 : -1.0)*roundness;
        normal = normalize(N + R*dx + U*dy);
        vec3 p = T - normal*dot(T, normal);
        if (dot(p, p) > 1e-10*dot(T, T)) tg = normalize(p);
    }
    tangent = vec4(tg, (flipU != flipV)? 1.0 : -1.0);
}
#endif

void main()
{
#ifdef RBL_BATCH_RECORD
    vec3 position, normal;
    vec2 vertexTexCoord;
    vec4 vertexTangent;
    rblRecordVertex(position, vertexTexCoord, normal, vertexTangent);
    vec3 tangent = vertexTangent.xyz;
    vec4 vertexColor = rblRecordColor;
#else
    vec3 position = vertexPosition, normal = vertexNormal, tangent = vertexTangent.xyz;
#endif
#ifdef RBL_SKINNING
    rblSkin(position, normal, tangent);     // bind pose -> animated pose, in the model's space
#endif
    fragPosition = vec3(matModel*vec4(position, 1.0));
    fragTexCoord = vertexTexCoord;
#ifdef RBL_CASTER_ID
    fragCasterId = rblCasterId.xy*rblCasterIdOn;
#endif
#ifdef RBL_CROSS_FADE
    fragTexCoord2 = vertexTexCoord2.xy;
    fragFade = vertexTexCoord2.zw;
    fragFadeClip = rblFadeClip;
#endif
    fragColor = vec4(rblSrgbToLinear(vertexColor.rgb), vertexColor.a);     // sRGB like every raylib Color: decoded once per vertex
    fragNormal = rblMat3(matNormal)*normal;
    // Tangents transform with the model matrix (they lie in the surface), normals with its inverse transpose.
    fragTangent = vec4(rblMat3(matModel)*tangent, vertexTangent.w);
#ifdef RBL_VIEW_VECTOR
    vec3 t = matView[3].xyz;                                // view = [R|t]: eye = -R^T t
    fragEye = -vec3(dot(matView[0].xyz, t), dot(matView[1].xyz, t), dot(matView[2].xyz, t));
    // Orthographic: clip w does not depend on the position (the projection's last row is 0 0 0 w);
    // an unset matProjection (all zero) counts as perspective, the pre-ortho behaviour
    bool parallel = (matProjection[0][3] == 0.0) && (matProjection[1][3] == 0.0) && (matProjection[2][3] == 0.0) && (matProjection[3][3] != 0.0);
    fragViewAxis = vec4(rblSafeNormalize(vec3(matView[0][2], matView[1][2], matView[2][2]), vec3(0.0, 0.0, 1.0)), parallel? 1.0 : 0.0);
#endif
    gl_Position = mvp*vec4(position, 1.0);
}
