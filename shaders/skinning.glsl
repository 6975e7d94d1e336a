// GPU skinning of raylib Models (RBL_SKINNING: RblLitShaderDesc.skinning, and the skinned caster):
// raylib's bone attributes (DrawMesh binds them by these names when raylib is built with
// SUPPORT_GPU_SKINNING) and the Model's boneMatrices (RblDrawModel uploads them). Same sum as raylib's
// CPU skinning: p' = sum w_k M_k p, n' = sum w_k M_k^-T n (normals with the inverse transpose, so a
// non-uniformly scaled bone keeps them perpendicular); tangents lie in the surface: sum w_k M_k t.
// Weights are used as given (not renormalised, as raylib's CPU path); a vertex whose weights are all
// zero belongs to no bone and keeps its bind pose (raylib's sum would put it at the origin).
#include "common.glsl"

#ifdef RBL_SKINNING
RBL_ATTRIBUTE vec4 vertexBoneIndices;      // unsigned bytes, not normalised: 0..255 as floats
RBL_ATTRIBUTE vec4 vertexBoneWeights;
uniform mat4 boneMatrices[RBL_MAX_BONES];

void rblSkin(inout vec3 position, inout vec3 normal, inout vec3 tangent)
{
    vec3 p = vec3(0.0), n = vec3(0.0), t = vec3(0.0);
    float total = 0.0;
    for (int k = 0; k < 4; k++)
    {
        float w = vertexBoneWeights[k];
        // A zero weight adds nothing, even from a bone matrix never uploaded
        if (w == 0.0) continue;
        total += abs(w);
        mat4 m = boneMatrices[int(clamp(vertexBoneIndices[k] + 0.5, 0.0, float(RBL_MAX_BONES) - 0.5))];
        vec3 a = m[0].xyz, b = m[1].xyz, c = m[2].xyz;
        p += w*(a*position.x + b*position.y + c*position.z + m[3].xyz);
        // Inverse transpose = cofactors/det: columns b x c, c x a, a x b (no inverse(), which GLSL ES 1.00
        // lacks); a singular bone keeps its cofactor direction rather than dividing by zero
        vec3 ca = cross(b, c), cb = cross(c, a), cc = cross(a, b);
        float det = dot(a, ca);
        n += w*(ca*normal.x + cb*normal.y + cc*normal.z)/((abs(det) > 1e-30)? det : 1.0);
        t += w*(a*tangent.x + b*tangent.y + c*tangent.z);
    }
    if (total > 0.0) { position = p; normal = n; tangent = t; }
}
#endif
