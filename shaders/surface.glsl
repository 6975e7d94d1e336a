// Surface: what a shaded point is, in linear units. Filled by the material decode (material.glsl)
// in forward and geometry passes, or from the G-buffer (gbuffer_read.glsl) in the deferred passes;
// read by the lights (lights.glsl).
#include "common.glsl"

struct RblShadingPoint {
    vec3 position;      // world
    vec3 normal;        // unit, world
    vec3 albedo;        // linear base colour
    float specular;     // Blinn-Phong: specular intensity (the map, or 1: its colour holds the scale)
    float roughness;    // GGX: perceptual roughness
    float occlusion;    // ambient occlusion (indirect light only)
    vec3 specularColor; // Blinn-Phong: linear specular colour (white in the G-buffer)
    float shininess;    // Blinn-Phong exponent
    float metalness;    // GGX
    vec2 caster;        // identity of the billboard the point lies on (two bytes /255; 0 = a Model): its own caster never shadows it
    vec3 face;          // unit normal of the rasterised surface (the card's plane, a Model's triangle), either sign: shadow biasing
    float transmission; // share of the light on the card's back let through (transmission.glsl; 0 = none)
};
