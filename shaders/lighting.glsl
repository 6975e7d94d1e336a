// Shared lighting code: lights, falloff, BRDFs, fog and output transform. The loader places it after
// the variant #defines and before the stage that shades (lit.fs.glsl), so every path evaluates the
// same equations. Units: a light of linear colour c and intensity I delivers irradiance
// E = c*I*attenuation*cone; reflected radiance = pi*BRDF*E*NdotL, pi folded into the light, so a white
// Lambert surface lit head-on by E = 1 returns exactly 1 (the scale raylib's lighting examples use).
// Variant defines (only what a material and light set use is compiled):
//   RBL_LIGHTS n              light slots
//   RBL_LIGHT_DIRECTIONAL     directional lights present (rblLightPosition.w = 0)
//   RBL_LIGHT_SPOT            spot cones
//   RBL_LIGHT_CLASSIC         constant/linear/quadratic attenuation
//   RBL_BRDF b                0 Lambert, 1 normalised Blinn-Phong, 2 GGX (Cook-Torrance)
//   RBL_AMBIENT_HEMI          hemispheric ambient (sky/ground by normal) instead of a flat colour
//   RBL_FOG f                 0 none, 1 linear, 2 exp, 3 exp2 (by distance to the eye)
//   RBL_TONEMAP t             0 none, 1 Reinhard, 2 ACES fit (Narkowicz 2015)
//   RBL_EXPOSURE              multiply by rblExposure before the tonemap
//   RBL_GAMMA g               encode with pow(1/g) instead of the exact sRGB curve
//   RBL_SHADOWS n             shadow maps sampled (0..4; rblShadowMap0..3), each shadowing one light
//   RBL_SHADOW_FILTER k       PCF footprint in texels per side: (k + 1)^2 depth fetches per lookup

#define RBL_PI 3.14159265358979
#define RBL_MIN_ROUGHNESS 0.045     // perceptual; alpha = 0.045^2 keeps D finite in fp32 (Filament's limit)
#define RBL_MIN_NDOTV 1e-4          // grazing views: the visibility term stays finite
#define RBL_MIN_DIST2 1e-4          // falloff denominator: a light on the surface stays finite
#define RBL_HALF_MAX 65504.0        // radiance clamp: a half-float target never receives Inf

#if RBL_LIGHTS > 0
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
uniform vec3 rblAmbient;                    // linear; the sky colour when hemispheric
#ifdef RBL_AMBIENT_HEMI
uniform vec3 rblAmbientGround;              // linear
uniform vec3 rblAmbientUp;                  // unit
#endif
#if RBL_FOG > 0
uniform vec4 rblFog;                        // rgb linear colour, a: density (exp/exp2) or 1/(end - start) (linear)
uniform float rblFogStart;                  // linear fog: distance where it begins
#endif
#ifdef RBL_EXPOSURE
uniform float rblExposure;
#endif
#if RBL_SHADOWS > 0
uniform ivec4 rblShadowLight;               // light slot shadowed by map k (-1 = none)
uniform mat4 rblShadowMatrix[RBL_SHADOWS];  // world -> (u, v, window depth) of map k, before the divide by w
uniform vec4 rblShadowParams[RBL_SHADOWS];  // texel world size (perspective: per unit distance), perspective (0/1), near, far
uniform vec4 rblShadowBias[RBL_SHADOWS];    // constant, slope, normal offset (all in texels), map size in texels
uniform vec4 rblShadowAxes[2*RBL_SHADOWS];  // right and up of map k's light camera (its axis = cross(up, right))
uniform sampler2D rblShadowMap0;            // depth textures (texture units RBL_SHADOW_TEXTURE_UNIT + k)
#if RBL_SHADOWS > 1
uniform sampler2D rblShadowMap1;
#endif
#if RBL_SHADOWS > 2
uniform sampler2D rblShadowMap2;
#endif
#if RBL_SHADOWS > 3
uniform sampler2D rblShadowMap3;
#endif
#endif

// normalize() of a zero vector is undefined (NaN on most GPUs): fall back instead.
vec3 rblSafeNormalize(vec3 v, vec3 fallback)
{
    float len2 = dot(v, v);
    return (len2 > 1e-20)? v*inversesqrt(len2) : fallback;
}

// Exact sRGB transfer functions (IEC 61966-2-1)
vec3 rblSrgbToLinear(vec3 c)
{
    return mix(c/12.92, pow((c + 0.055)/1.055, vec3(2.4)), step(vec3(0.04045), c));
}

vec3 rblLinearToSrgb(vec3 c)
{
    c = clamp(c, 0.0, 1.0);
    return mix(c*12.92, 1.055*pow(c, vec3(1.0/2.4)) - 0.055, step(vec3(0.0031308), c));
}

// World normal <-> octahedral 12+12 bits in three 8-bit channels (the G-buffer's normal). Octahedral
// map (Cigolle et al. 2014), each coordinate rounded to 12 bits, packed high byte / two nibbles / low byte.
vec3 rblPackNormal(vec3 n)
{
    n /= max(abs(n.x) + abs(n.y) + abs(n.z), 1e-20);
    vec2 e = n.xy;
    if (n.z < 0.0) e = (1.0 - abs(n.yx))*vec2((n.x >= 0.0)? 1.0 : -1.0, (n.y >= 0.0)? 1.0 : -1.0);
    uvec2 q = uvec2(floor(clamp(e*0.5 + 0.5, 0.0, 1.0)*4095.0 + 0.5));
    return vec3(float(q.x >> 4u), float(((q.x & 15u) << 4u) | (q.y >> 8u)), float(q.y & 255u))/255.0;
}

vec3 rblUnpackNormal(vec3 c)
{
    uvec3 b = uvec3(floor(c*255.0 + 0.5));
    vec2 e = vec2(float((b.x << 4u) | (b.y >> 4u)), float(((b.y & 15u) << 8u) | b.z))/4095.0*2.0 - 1.0;
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    float t = max(-n.z, 0.0);
    n.xy += vec2((n.x >= 0.0)? -t : t, (n.y >= 0.0)? -t : t);
    return normalize(n);        // |n| >= 1/sqrt(3): never zero
}

// What a surface point needs for shading, in linear units (filled by the forward fragment stage from
// maps and uniforms, or by the deferred passes from the G-buffer)
struct RblShadingPoint {
    vec3 position;      // world
    vec3 normal;        // unit, world
    vec3 albedo;        // linear base colour
    float specular;     // Blinn-Phong: specular intensity; GGX: perceptual roughness
    float occlusion;    // ambient occlusion (indirect light only)
    vec3 specularColor; // Blinn-Phong: linear specular colour (white in the G-buffer)
    float shininess;    // Blinn-Phong exponent
    float metalness;    // GGX
};

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
    float perceptual = max(s.specular, RBL_MIN_ROUGHNESS);
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

// Ambient: uniform light from every direction, attenuated by occlusion. GGX adds F0 times it (the
// specular reflectance of a uniform environment, without a split-sum table).
vec3 rblAmbientLight(RblShadingPoint s)
{
#ifdef RBL_AMBIENT_HEMI
    vec3 ambient = mix(rblAmbientGround, rblAmbient, dot(s.normal, rblAmbientUp)*0.5 + 0.5);
#else
    vec3 ambient = rblAmbient;
#endif
#if RBL_BRDF == 2
    vec3 reflectance = s.albedo*(1.0 - s.metalness) + mix(vec3(0.04), s.albedo, s.metalness);
#else
    vec3 reflectance = s.albedo;
#endif
    return ambient*s.occlusion*reflectance;
}

#if RBL_SHADOWS > 0
// Distance along the light's axis from a window depth of map k (prm: texel, perspective, near, far)
float rblShadowDistance(float d, vec4 prm)
{
    return (prm.y > 0.5)? prm.z*prm.w/(prm.w - d*(prm.w - prm.z)) : prm.z + d*(prm.w - prm.z);
}

// Fraction of light k's map lets through to a surface point with unit normal n, lit at cos(incidence)
// NdotL (> 0). Depths are compared as distances along the light's axis, in world units:
//   normal offset   the lookup moves along n by normal*texel*sin(incidence) (lateral shift <= that)
//   receiver plane  each PCF fetch is compared with the receiver's own plane extended to that texel's
//                   centre (depth gradient from n in the light's frame, clamped at 10 texels per
//                   texel), so a flat receiver never shadows itself at any incidence below 84 degrees
//   depth bias      texel*(constant + slope*tan(incidence)), tan clamped at 10
// PCF: a box of RBL_SHADOW_FILTER texels per side over bilinear-weighted comparisons, (k + 1)^2
// fetches: at k = 1 the footprint of hardware 2x2 comparison filtering (rlgl exposes no compare mode).
// Outside the map, behind a spot light or beyond the far plane the point is lit, and so is a fetch
// outside the map or of a texel nothing was drawn into.
float rblShadowLookup(sampler2D map, int k, vec3 position, vec3 n, float NdotL)
{
    vec4 prm = rblShadowParams[k], bias = rblShadowBias[k];
    vec3 right = rblShadowAxes[2*k].xyz, up = rblShadowAxes[2*k + 1].xyz, along = cross(up, right);
    vec4 c0 = rblShadowMatrix[k]*vec4(position, 1.0);
    float texel = prm.x*((prm.y > 0.5)? max(c0.w, 0.0) : 1.0);      // world size of a texel here
    float sinI = sqrt(max(1.0 - NdotL*NdotL, 0.0));
    float tanI = min(sinI/max(NdotL, 1e-4), 10.0);
    vec4 c = rblShadowMatrix[k]*vec4(position + n*(bias.z*texel*sinI), 1.0);
    if (!(c.w > 0.0)) return 1.0;
    vec3 q = c.xyz/c.w;
    if (!((q.x >= 0.0) && (q.x <= 1.0) && (q.y >= 0.0) && (q.y <= 1.0) && (q.z < 1.0))) return 1.0;
    float z = rblShadowDistance(max(q.z, 0.0), prm) - texel*(bias.x + bias.y*tanI);
    // Receiver plane: distance change per texel step along the map's x and y
    vec2 slope = vec2(dot(n, right), dot(n, up))/max(-dot(n, along), 1e-4);
    slope *= min(1.0, 10.0/max(length(slope), 1e-20))*texel;
    float size = bias.w;
    vec2 st = q.xy*size - 0.5*float(RBL_SHADOW_FILTER);         // first bilinear tap's position - 0.5, in texels
    vec2 base = floor(st), f = st - base;
    ivec2 b0 = ivec2(base), top = ivec2(int(size) - 1);
    vec2 origin = base + 0.5 - q.xy*size;                       // first fetched centre relative to the point
    float lit = 0.0;
    for (int j = 0; j <= RBL_SHADOW_FILTER; j++)
    {
        float wy = (j == 0)? 1.0 - f.y : ((j == RBL_SHADOW_FILTER)? f.y : 1.0);
        for (int i = 0; i <= RBL_SHADOW_FILTER; i++)
        {
            float wx = (i == 0)? 1.0 - f.x : ((i == RBL_SHADOW_FILTER)? f.x : 1.0);
            // Texels outside the map or never written (cleared to 1: beyond the far plane) hold no occluder
            ivec2 at = b0 + ivec2(i, j);
            float raw = (all(greaterThanEqual(at, ivec2(0))) && all(lessThanEqual(at, top)))? texelFetch(map, at, 0).r : 1.0;
            float receiver = z + dot(slope, origin + vec2(float(i), float(j)));
            lit += ((raw >= 1.0) || (receiver <= rblShadowDistance(raw, prm)))? wx*wy : 0.0;
        }
    }
    return lit/float(RBL_SHADOW_FILTER*RBL_SHADOW_FILTER);
}

float rblShadow(int k, vec3 position, vec3 n, float NdotL)
{
    if (k == 0) return rblShadowLookup(rblShadowMap0, 0, position, n, NdotL);
#if RBL_SHADOWS > 1
    if (k == 1) return rblShadowLookup(rblShadowMap1, 1, position, n, NdotL);
#endif
#if RBL_SHADOWS > 2
    if (k == 2) return rblShadowLookup(rblShadowMap2, 2, position, n, NdotL);
#endif
#if RBL_SHADOWS > 3
    if (k == 3) return rblShadowLookup(rblShadowMap3, 3, position, n, NdotL);
#endif
    return 1.0;
}

// Light that map k shadows, at this point: the map's lookup, or 1 (unlit side, or no such light). Done
// once per map before the light loop, not per light slot (CPU rasterisers run every branch of a loop)
float rblShadowOfMap(int k, RblShadingPoint s, int light)
{
    if ((light < 0) || (light >= rblLightCount)) return 1.0;
    vec4 p = rblLightPosition[light];
    vec3 l = rblSafeNormalize(p.xyz - s.position*p.w, s.normal);
    float NdotL = dot(s.normal, l);
    return (NdotL > 0.0)? rblShadow(k, s.position, s.normal, NdotL) : 1.0;
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
    if (NdotL <= 0.0) return vec3(0.0);
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
    return c.rgb*(attenuation*NdotL)*rblBrdf(s, v, l, NdotL);
}

// Sum of the light slots at a surface point seen from eye
vec3 rblDirectLight(RblShadingPoint s, vec3 eye)
{
    vec3 sum = vec3(0.0);
#if RBL_LIGHTS > 0
    vec3 v = rblSafeNormalize(eye - s.position, s.normal);
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
#endif
    for (int i = 0; i < RBL_LIGHTS; i++)
    {
        if (i >= rblLightCount) break;
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
#if RBL_SHADOWS > 0
        float shadow = (i == rblShadowLight.x)? shadowed.x : ((i == rblShadowLight.y)? shadowed.y :
                       ((i == rblShadowLight.z)? shadowed.z : ((i == rblShadowLight.w)? shadowed.w : 1.0)));
#else
        float shadow = 1.0;
#endif
        sum += rblEvalLight(s, v, rblLightPosition[i], rblLightColor[i], spot, k, shadow);
    }
#endif
    return sum;
}

// Fog, exposure, tonemap and the display encoding, in that order. linearOut keeps linear light
// (clamped to half-float range) for float targets.
vec3 rblFinish(vec3 color, vec3 position, vec3 eye)
{
#if RBL_FOG > 0
    float d = length(position - eye);
#if RBL_FOG == 1
    float visible = clamp(1.0 - (d - rblFogStart)*rblFog.a, 0.0, 1.0);
#elif RBL_FOG == 2
    float visible = exp(-rblFog.a*d);
#else
    float visible = exp(-(rblFog.a*d)*(rblFog.a*d));
#endif
    color = mix(rblFog.rgb, color, visible);
#endif
    color = clamp(color, 0.0, RBL_HALF_MAX);
#ifdef RBL_EXPOSURE
    color *= rblExposure;
#endif
#if RBL_TONEMAP == 1
    color = color/(1.0 + color);
#elif RBL_TONEMAP == 2
    color = min(color, vec3(RBL_HALF_MAX));
    color = clamp(color*(2.51*color + 0.03)/(color*(2.43*color + 0.59) + 0.14), 0.0, 1.0);
#endif
#if defined(RBL_LINEAR_OUTPUT)
    return min(color, vec3(RBL_HALF_MAX));
#elif defined(RBL_GAMMA)
    return pow(clamp(color, 0.0, 1.0), vec3(1.0/RBL_GAMMA));
#else
    return rblLinearToSrgb(color);
#endif
}
