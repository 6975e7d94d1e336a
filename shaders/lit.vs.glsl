// Lit vertex stage of vertex-buffer geometry: billboards (world-space vertices, matModel = identity)
// and raylib Models (matModel = the model transform) go through the same code. Pairs with lit.fs.glsl,
// gbuffer.fs.glsl and shadow_caster.fs.glsl.
#include "common.glsl"
#include "skinning.glsl"

in vec3 vertexPosition;
in vec2 vertexTexCoord;
in vec3 vertexNormal;
in vec4 vertexColor;
in vec4 vertexTangent;      // xyz: world +U direction, w: handedness (cross(N,T)*w = +V)

uniform mat4 mvp;
uniform mat4 matModel;
uniform mat4 matNormal;
#ifdef RBL_VIEW_VECTOR
uniform mat4 matView;       // raylib's DrawMesh and the billboard paths set both: no viewPos glue needed
uniform mat4 matProjection;
flat out vec3 fragEye;
flat out vec4 fragViewAxis; // back direction, w 1 orthographic (common.glsl rblViewVector)
#endif

out vec3 fragPosition;
out vec2 fragTexCoord;
out vec4 fragColor;
out vec3 fragNormal;
out vec4 fragTangent;

void main()
{
    vec3 position = vertexPosition, normal = vertexNormal, tangent = vertexTangent.xyz;
#ifdef RBL_SKINNING
    rblSkin(position, normal, tangent);     // bind pose -> animated pose, in the model's space
#endif
    fragPosition = vec3(matModel*vec4(position, 1.0));
    fragTexCoord = vertexTexCoord;
    fragColor = vec4(rblSrgbToLinear(vertexColor.rgb), vertexColor.a);     // sRGB like every raylib Color: decoded once per vertex
    fragNormal = mat3(matNormal)*normal;
    // Tangents transform with the model matrix (they lie in the surface), normals with its inverse transpose.
    fragTangent = vec4(mat3(matModel)*tangent, vertexTangent.w);
#ifdef RBL_VIEW_VECTOR
    fragEye = -(transpose(mat3(matView))*matView[3].xyz);     // view = [R|t]: eye = -R^T t
    // Orthographic: clip w does not depend on the position (the projection's last row is 0 0 0 w);
    // an unset matProjection (all zero) counts as perspective, the pre-ortho behaviour
    bool parallel = (matProjection[0][3] == 0.0) && (matProjection[1][3] == 0.0) && (matProjection[2][3] == 0.0) && (matProjection[3][3] != 0.0);
    fragViewAxis = vec4(rblSafeNormalize(vec3(matView[0][2], matView[1][2], matView[2][2]), vec3(0.0, 0.0, 1.0)), parallel? 1.0 : 0.0);
#endif
    gl_Position = mvp*vec4(position, 1.0);
}
