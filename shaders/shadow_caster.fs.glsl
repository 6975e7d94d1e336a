// Shadow caster fragment stage: depth only. The loader prepends "#version 330", the variant #defines,
// lighting.glsl and material.glsl, so the alpha test is the colour pass's own (albedo x colDiffuse x
// vertex colour against rblAlphaCutoff): a sprite's silhouette casts the shadow, not its quad.
// Nothing else is sampled; the target has no colour attachment.

void main()
{
    float alpha;
    vec3 emission, tangentNormal;
    rblMaterialSurface(alpha, emission, tangentNormal);     // discards below the cutoff
}
