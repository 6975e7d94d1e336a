// Shadow pass, fragment stage: depth only. The alpha test is the colour pass's own (albedo x
// colDiffuse x vertex colour against the material's cutoff): a sprite's silhouette casts the shadow,
// not its quad. Nothing else is sampled; the target has no colour attachment.
#include "material.glsl"

void main()
{
    float alpha;
    vec3 emission, tangentNormal;
    rblMaterialSurface(alpha, emission, tangentNormal);     // discards below the cutoff
}
