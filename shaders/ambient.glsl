// Ambient: the scene's sky/ground light on a surface. Forward shaders add it per fragment; the
// deferred resolve once per pixel, on the stored surface (occlusion from the accumulation's alpha).
//   RBL_BRDF b                2 (GGX) adds the specular reflectance of a uniform environment
#include "surface.glsl"

uniform vec3 rblAmbient;                    // linear sky colour (the scene's ambient)
uniform vec3 rblAmbientGround;              // linear ground colour (= rblAmbient for a flat ambient)
uniform vec3 rblAmbientUp;                  // unit

// Ambient: uniform light from every direction, attenuated by occlusion. GGX adds F0 times it (the
// specular reflectance of a uniform environment, without a split-sum table).
vec3 rblAmbientLight(RblShadingPoint s)
{
    vec3 ambient = mix(rblAmbientGround, rblAmbient, dot(s.normal, rblAmbientUp)*0.5 + 0.5);
#if RBL_BRDF == 2
    vec3 reflectance = s.albedo*(1.0 - s.metalness) + mix(vec3(0.04), s.albedo, s.metalness);
#else
    vec3 reflectance = s.albedo;
#endif
    return ambient*s.occlusion*reflectance;
}
