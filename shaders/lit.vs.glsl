// Lit vertex stage of vertex-buffer geometry: billboards (world-space vertices, matModel = identity)
// and raylib Models (matModel = the model transform) go through the same code. Pairs with lit.fs.glsl,
// gbuffer.fs.glsl and shadow_caster.fs.glsl.
#include "common.glsl"
#include "skinning.glsl"

RBL_ATTRIBUTE vec3 vertexPosition;
RBL_ATTRIBUTE vec2 vertexTexCoord;
RBL_ATTRIBUTE vec3 vertexNormal;
RBL_ATTRIBUTE vec4 vertexColor;
RBL_ATTRIBUTE vec4 vertexTangent;      // xyz: world +U direction, w: handedness (cross(N,T)*w = +V)
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

void main()
{
    vec3 position = vertexPosition, normal = vertexNormal, tangent = vertexTangent.xyz;
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
