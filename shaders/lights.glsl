// Lights: light uniforms, falloff, spot cones, BRDFs (Lambert, normalised Blinn-Phong,
// GGX), and the sum over the light slots. Units: a light of linear colour c and intensity I delivers
// irradiance E = c*I*attenuation*cone; reflected radiance = pi*BRDF*E*NdotL, pi folded into the
// light, so a white Lambert surface lit head-on by E = 1 returns exactly 1.
//   RBL_LIGHTS n              light slots
//   RBL_LIGHT_GRID            every light of the scene from the light grid instead (light_grid.glsl)
//   RBL_LIGHT_DIRECTIONAL     directional lights present (rblLightPosition.w = 0)
//   RBL_LIGHT_SPOT            spot cones
//   RBL_LIGHT_CLASSIC         constant/linear/quadratic attenuation
//   RBL_BRDF b                0 Lambert, 1 normalised Blinn-Phong, 2 GGX (Cook-Torrance)
//   RBL_TRANSMISSION          light behind a card shows through it (transmission.glsl)
//   RBL_RELIEF_STEPS          each light marched through the relief (rblReliefShadow, material.glsl)
//   RBL_GB_RELIEF             deferred: each light's relief bit stored by the geometry pass
//                             (rblReliefShadow and rblGbReliefSelect, gbuffer_read.glsl)
//   RBL_SHADOW_TINT           blended casters tint the light they let through (shadow_tint.glsl)
#include "surface.glsl"
#include "ambient.glsl"
#include "shadows.glsl"
#include "shadow_tint.glsl"
#include "transmission.glsl"
#include "light_grid.glsl"

#define RBL_MIN_NDOTV 1e-4          // grazing views: the visibility term stays finite
#define RBL_MIN_DIST2 1e-4          // falloff denominator: a light on the surface stays finite

#if (RBL_LIGHTS > 0) && !defined(RBL_LIGHT_GRID)
uniform int rblLightCount;
uniform vec4 rblLightPosition[RBL_LIGHTS];  // xyz position, w 1; directional: xyz unit vector toward the light, w 0
uniform vec4 rblLightColor[RBL_LIGHTS];     // rgb linear colour x intensity, a 1/range (0 = no window)
#ifdef RBL_LIGHT_SPOT
uniform vec4 rblLightSpot[RBL_LIGHTS];      // xyz cone axis * scale, w offset; (0,0,0,1) = no cone
#endif
#ifdef RBL_LIGHT_CLASSIC
uniform vec3 rblLightAttenuation[RBL_LIGHTS]; // constant, linear, quadratic (windowed lights: 0, 0, 1)
#endif
#endif
#if RBL_SHADOWS > 0
uniform ivec4 rblShadowLight;               // light slot (grid: scene light) shadowed by map k (-1 = none)
#endif

// Radiance reflected toward v per unit irradiance arriving from l (pi folded in), for NdotL > 0
vec3 rblBrdf(RblShadingPoint s, vec3 v, vec3 l, float NdotL)
{
#if RBL_BRDF == 1
    // Normalised Blinn-Phong: (n + 8)/(8 pi) NdotH^n, pi folded
    vec3 h = rblSafeNormalize(l + v, s.normal);
    float NdotH = max(dot(s.normal, h), 0.0);
    float n = s.shininess;
    return s.albedo + s.specularColor*(s.specular*(n + 8.0)/8.0*pow(NdotH, n));
#elif RBL_BRDF == 2
    // Cook-Torrance: GGX D, Smith height-correlated V, Schlick F; diffuse Lambert scaled by (1 - metalness)
    float perceptual = max(s.roughness, RBL_MIN_ROUGHNESS);
    float a = perceptual*perceptual;
    float a2 = a*a;
    float metal = s.metalness;
    vec3 f0 = mix(vec3(0.04), s.albedo, metal);
    vec3 h = rblSafeNormalize(l + v, s.normal);
    float NdotH = clamp(dot(s.normal, h), 0.0, 1.0);
    vec3 nxh = cross(s.normal, h);                              // 1 - NdotH^2 without cancellation
    float k = a/(dot(nxh, nxh) + NdotH*NdotH*a2);
    float D = k*k*(1.0/RBL_PI);
    float NdotV = max(dot(s.normal, v), RBL_MIN_NDOTV);
    float V = 0.5/(NdotL*sqrt(NdotV*NdotV*(1.0 - a2) + a2) + NdotV*sqrt(NdotL*NdotL*(1.0 - a2) + a2));
    float LdotH = clamp(dot(l, h), 0.0, 1.0);
    float fw = pow(1.0 - LdotH, 5.0);
    vec3 F = f0 + (1.0 - f0)*fw;
    return s.albedo*(1.0 - metal) + (RBL_PI*D*V)*F;
#else
    return s.albedo;
#endif
}

#if RBL_SHADOWS > 0
// Light that map k shadows, at this point: the map's lookup, or 1 (unlit side, or no such light). Done
// once per map before the light loop, not per light slot (CPU rasterisers run every branch of a loop)
float rblShadowOfMap(int k, RblShadingPoint s, int light)
{
#ifdef RBL_LIGHT_GRID
    if (light < 0) return 1.0;
    vec4 p = rblGridLightTexel(light, 0);
    p.w = (int(p.w) == 2)? 0.0 : 1.0;               // feature bits 2: directional
#elif RBL_GLSL >= 300
    if ((light < 0) || (light >= rblLightCount)) return 1.0;
    vec4 p = rblLightPosition[light];
#else
    if ((light < 0) || (light >= rblLightCount)) return 1.0;
    vec4 p = vec4(0.0);                             // GLSL ES 1.00: uniform arrays by loop index only
    for (int i = 0; i < RBL_LIGHTS; i++) if (i == light) p = rblLightPosition[i];
#endif
    vec3 l = rblSafeNormalize(p.xyz - s.position*p.w, s.normal);
    float NdotL = dot(s.normal, l);
#ifdef RBL_TRANSMISSION
    if (s.transmission > 0.0) NdotL = 1.0;          // the light behind the card is shadowed on its way too
#endif
    return (NdotL > 0.0)? rblShadowAt(k, s, l) : 1.0;
}
#endif

// One light at a surface point seen along v: p position (w 0: directional), c colour (a: 1/range),
// spot cone (axis*scale, offset; (0,0,0,1) = none), k classic attenuation ((0,0,1) = inverse square),
// shadow the fraction its shadow map lets through (1 = unshadowed)
vec3 rblEvalLight(RblShadingPoint s, vec3 v, vec4 p, vec4 c, vec4 spot, vec3 k, float shadow)
{
#ifdef RBL_LIGHT_DIRECTIONAL
    vec3 toLight = p.xyz - s.position*p.w;
#else
    vec3 toLight = p.xyz - s.position;
#endif
    float d2 = dot(toLight, toLight);
    vec3 l = rblSafeNormalize(toLight, s.normal);      // a light on the surface lights it head-on
    float NdotL = dot(s.normal, l);
#ifdef RBL_TRANSMISSION
    if ((NdotL <= 0.0) && !(s.transmission > 0.0)) return vec3(0.0);
#else
    if (NdotL <= 0.0) return vec3(0.0);
#endif
    // Windowed inverse square (UE4/Filament): saturate(1 - (d/r)^4)^2/max(d^2, eps)
    float x2 = d2*c.a*c.a;
    float window = clamp(1.0 - x2*x2, 0.0, 1.0);
#ifdef RBL_LIGHT_CLASSIC
    float attenuation = window*window/max(k.x + k.y*sqrt(d2) + k.z*d2, RBL_MIN_DIST2);
#else
    float attenuation = window*window/max(d2, RBL_MIN_DIST2);
#endif
#ifdef RBL_LIGHT_SPOT
    float t = clamp(dot(-l, spot.xyz) + spot.w, 0.0, 1.0);
    attenuation *= t*t*(3.0 - 2.0*t);               // smoothstep from the outer to the inner cone
#endif
    attenuation *= shadow;
#ifdef RBL_TRANSMISSION
    vec3 through = rblTransmitted(s, NdotL);
    if (NdotL <= 0.0) return c.rgb*attenuation*through;
#endif
#if defined(RBL_RELIEF_STEPS) || defined(RBL_GB_RELIEF)
    attenuation *= rblReliefShadow(l);              // transmitted light is not: it comes through the card
#endif
#ifdef RBL_TRANSMISSION
    return c.rgb*attenuation*(NdotL*rblBrdf(s, v, l, NdotL) + through);
#else
    return c.rgb*(attenuation*NdotL)*rblBrdf(s, v, l, NdotL);
#endif
}

// Sum of the light slots (or of the grid's lights reaching it) at a surface point seen along the unit
// view vector v (rblViewVector)
vec3 rblDirectLight(RblShadingPoint s, vec3 v)
{
    vec3 sum = vec3(0.0);
#if (RBL_LIGHTS > 0) || defined(RBL_LIGHT_GRID)
#if RBL_SHADOWS > 0
    vec4 shadowed = vec4(1.0);                      // each map's factor, for the light it shadows
    shadowed.x = rblShadowOfMap(0, s, rblShadowLight.x);
#if RBL_SHADOWS > 1
    shadowed.y = rblShadowOfMap(1, s, rblShadowLight.y);
#endif
#if RBL_SHADOWS > 2
    shadowed.z = rblShadowOfMap(2, s, rblShadowLight.z);
#endif
#if RBL_SHADOWS > 3
    shadowed.w = rblShadowOfMap(3, s, rblShadowLight.w);
#endif
#ifdef RBL_SHADOW_TINT
    vec3 tint0 = rblShadowTint(0, s.position), tint1 = vec3(1.0), tint2 = vec3(1.0), tint3 = vec3(1.0);
#if RBL_SHADOWS > 1
    tint1 = rblShadowTint(1, s.position);
#endif
#if RBL_SHADOWS > 2
    tint2 = rblShadowTint(2, s.position);
#endif
#if RBL_SHADOWS > 3
    tint3 = rblShadowTint(3, s.position);
#endif
#endif
#endif
#ifdef RBL_LIGHT_GRID
    // The unbounded lights, then the cell's: one loop, so the body is compiled once
    ivec2 cell = rblGridCell(s.position);
    int unbounded = rblGridDims.w;
    int entries = unbounded + cell.y - cell.x;
    for (int e = 0; e < entries; e++)
    {
        int i = rblGridEntry((e < unbounded)? e : (cell.x + e - unbounded));
        vec4 p = rblGridLightTexel(i, 0);
        int features = int(p.w);
        if ((features & RBL_GRID_SKIPPED) != 0) continue;
        p.w = (features == 2)? 0.0 : 1.0;
        vec4 c = rblGridLightTexel(i, 1);
#ifdef RBL_LIGHT_SPOT
        vec4 spot = rblGridLightTexel(i, 2);
#else
        vec4 spot = vec4(0.0, 0.0, 0.0, 1.0);
#endif
#ifdef RBL_LIGHT_CLASSIC
        vec3 k = rblGridLightTexel(i, 3).xyz;
#else
        vec3 k = vec3(0.0, 0.0, 1.0);
#endif
#else
    for (int i = 0; i < RBL_LIGHTS; i++)
    {
        if (i >= rblLightCount) break;
        vec4 p = rblLightPosition[i], c = rblLightColor[i];
#ifdef RBL_LIGHT_SPOT
        vec4 spot = rblLightSpot[i];
#else
        vec4 spot = vec4(0.0, 0.0, 0.0, 1.0);
#endif
#ifdef RBL_LIGHT_CLASSIC
        vec3 k = rblLightAttenuation[i];
#else
        vec3 k = vec3(0.0, 0.0, 1.0);
#endif
#endif
#if RBL_SHADOWS > 0
        float shadow = (i == rblShadowLight.x)? shadowed.x : ((i == rblShadowLight.y)? shadowed.y :
                       ((i == rblShadowLight.z)? shadowed.z : ((i == rblShadowLight.w)? shadowed.w : 1.0)));
#else
        float shadow = 1.0;
#endif
#ifdef RBL_GB_RELIEF
        rblGbReliefSelect(i);
#endif
#if (RBL_SHADOWS > 0) && defined(RBL_SHADOW_TINT)
        vec3 tint = (i == rblShadowLight.x)? tint0 : ((i == rblShadowLight.y)? tint1 : ((i == rblShadowLight.z)? tint2 : ((i == rblShadowLight.w)? tint3 : vec3(1.0))));
        sum += rblEvalLight(s, v, p, c, spot, k, shadow)*tint;
#else
        sum += rblEvalLight(s, v, p, c, spot, k, shadow);
#endif
    }
#endif
    return sum;
}
