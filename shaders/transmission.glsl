// Transmission: light through a thin card (leaves, paper, cloth) from a light on its other side. The
// card is a thin diffuse sheet: of the irradiance reaching its back it lets through the share t
// (the material's rblTransmission x (1 - thickness)) and spreads it diffusely over the front, in
// its own colour (albedo). The back's cosine is wrapped by RBL_TRANSMISSION_WRAP: a light edge-on
// to the card still shows through its rim, fading to nothing at N.L = wrap on the lit side.
// Included by material.glsl (the uniform) and lights.glsl (the term); compiled only with:
//   RBL_TRANSMISSION            RblLitShaderDesc.transmission (forward variants)
//   RBL_THICKNESS_CHANNEL c     material texture component (3 b, 4 a) holding thickness 0..1
#include "surface.glsl"

#ifdef RBL_TRANSMISSION
#define RBL_TRANSMISSION_WRAP 0.25
uniform float rblTransmission;      // share of the back's light let through, 0..1 (0: the term costs one compare)

// Radiance toward the viewer per unit irradiance (pi folded in, as rblBrdf) from a light at
// cos(incidence) NdotL on the shaded side (negative: behind the card)
vec3 rblTransmitted(RblShadingPoint s, float NdotL)
{
    float back = clamp((RBL_TRANSMISSION_WRAP - NdotL)/(1.0 + RBL_TRANSMISSION_WRAP), 0.0, 1.0);
    return s.albedo*(s.transmission*back);
}
#endif
