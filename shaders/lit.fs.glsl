// Forward lit fragment shader for billboards and raylib Models.
// Colour (albedo, emissive, vertex tint, colDiffuse) is sRGB and decoded to linear light; data maps
// (normal, specular, occlusion) are linear. Lighting: Lambert diffuse from RBL_LIGHTS point lights
// plus an ambient term that the occlusion map attenuates (occlusion is about indirect light only).
// Variant defines, prepended by the loader (only what a material uses is compiled, so absent maps
// are never sampled):
//   RBL_LIGHTS n             light slots compiled in
//   RBL_NORMAL_ENCODING e    0 none, 1 hemi-octahedral RG, 2 XY RG (+Z rebuilt), 3 plain RGB map
//   RBL_SPECULAR             material texture B holds specular intensity (decoded for the BRDF)
//   RBL_OCCLUSION            material texture A holds ambient occlusion
//   RBL_EMISSIVE e           0 none, 1 mask (texture5.r x albedo), 2 sRGB colour (texture5.rgb)
//   RBL_LINEAR_OUTPUT        write linear light (float targets); default: encode to sRGB
//   RBL_DEBUG_VIEW v         1 tangent-space normal, 2 world normal, 3 specular, 4 occlusion (raw)

in vec3 fragPosition;
in vec2 fragTexCoord;
in vec4 fragColor;              // vertex colour, already linear (decoded in the vertex stage)
in vec3 fragNormal;
in vec4 fragTangent;

uniform sampler2D texture0;     // albedo (sRGB)
#if (RBL_NORMAL_ENCODING > 0) || defined(RBL_SPECULAR) || defined(RBL_OCCLUSION)
#define RBL_MATERIAL_TEXTURE
uniform sampler2D texture2;     // packed material (MATERIAL_MAP_NORMAL slot): RG normal, B specular, A occlusion
#endif
#if RBL_EMISSIVE > 0
uniform sampler2D texture5;     // emissive (MATERIAL_MAP_EMISSION slot)
uniform float rblEmissiveIntensity;
#endif
uniform vec4 colDiffuse;        // sRGB, as raylib sets it
uniform float rblAlphaCutoff;
uniform vec3 rblAmbient;        // linear ambient radiance
#if RBL_LIGHTS > 0
uniform int rblLightCount;
uniform vec3 rblLightPosition[RBL_LIGHTS];
uniform vec3 rblLightColor[RBL_LIGHTS];     // linear colour x intensity
uniform float rblLightInvRange[RBL_LIGHTS]; // 1/range, 0 = no range window
#endif

out vec4 finalColor;

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

// Tangent-space normal from the material texture; the exact mirror of RblDecodeNormal() on the CPU
// (a decoded vector shorter than 1/64 is quantisation noise around zero: the flat normal)
vec3 rblDecodedUnit(vec3 e)
{
    return (dot(e, e) < 1.0/4096.0)? vec3(0.0, 0.0, 1.0) : normalize(e);
}

vec3 rblDecodeNormal(vec4 m)
{
#if RBL_NORMAL_ENCODING == 1
    vec2 e = m.rg*2.0 - 1.0;                                // hemi-octahedral, stored rotated 45 degrees
    vec2 p = vec2(e.x + e.y, e.x - e.y)*0.5;
    return rblDecodedUnit(vec3(p, 1.0 - max(abs(e.x), abs(e.y))));     // = 1-|p.x|-|p.y|, never negative
#elif RBL_NORMAL_ENCODING == 2
    vec2 e = m.rg*2.0 - 1.0;                                // X and Y, Z rebuilt
    return rblDecodedUnit(vec3(e, sqrt(max(0.0, 1.0 - dot(e, e)))));
#elif RBL_NORMAL_ENCODING == 3
    return rblDecodedUnit(m.rgb*2.0 - 1.0);                 // plain RGB map
#else
    return vec3(0.0, 0.0, 1.0);
#endif
}

void main()
{
    vec4 texel = texture(texture0, fragTexCoord);
    vec4 albedo = vec4(rblSrgbToLinear(texel.rgb)*rblSrgbToLinear(colDiffuse.rgb)*fragColor.rgb, texel.a*colDiffuse.a*fragColor.a);
    if (albedo.a < rblAlphaCutoff) discard;

    vec3 n = rblSafeNormalize(fragNormal, vec3(0.0, 0.0, 1.0));
#ifdef RBL_MATERIAL_TEXTURE
    vec4 material = texture(texture2, fragTexCoord);
#endif
    vec3 tangentNormal = vec3(0.0, 0.0, 1.0);
#if RBL_NORMAL_ENCODING > 0
    // Re-orthogonalise the interpolated tangent; cross(N,T)*w is the +V direction (raylib's
    // GenMeshTangents convention), and +V runs down the image, so the map's +Y is -B.
    vec3 t = fragTangent.xyz - n*dot(n, fragTangent.xyz);
    vec3 anyPerp = (abs(n.z) < 0.9)? vec3(-n.y, n.x, 0.0) : vec3(0.0, -n.z, n.y);
    t = rblSafeNormalize(t, rblSafeNormalize(anyPerp, vec3(1.0, 0.0, 0.0)));
    vec3 b = cross(n, t)*((fragTangent.w < 0.0)? -1.0 : 1.0);
    tangentNormal = rblDecodeNormal(material);
    n = rblSafeNormalize(t*tangentNormal.x - b*tangentNormal.y + n*tangentNormal.z, n);
#endif
    float specular = 0.5;
#ifdef RBL_SPECULAR
    specular = material.b;
#endif
    float occlusion = 1.0;
#ifdef RBL_OCCLUSION
    occlusion = material.a;
#endif

    vec3 irradiance = rblAmbient*occlusion;
#if RBL_LIGHTS > 0
    for (int i = 0; i < RBL_LIGHTS; i++)
    {
        if (i >= rblLightCount) break;
        vec3 toLight = rblLightPosition[i] - fragPosition;
        float d2 = dot(toLight, toLight);
        vec3 l = rblSafeNormalize(toLight, n);      // a light on the surface lights it head-on
        // Windowed inverse square (UE4/Filament): I*saturate(1-(d/r)^4)^2/max(d^2, eps).
        float x2 = d2*rblLightInvRange[i]*rblLightInvRange[i];
        float window = clamp(1.0 - x2*x2, 0.0, 1.0);
        float falloff = window*window/max(d2, 1e-4);
        irradiance += rblLightColor[i]*(max(dot(n, l), 0.0)*falloff);
    }
#endif
    vec3 color = albedo.rgb*irradiance;
#if RBL_EMISSIVE == 1
    color += albedo.rgb*texture(texture5, fragTexCoord).r*rblEmissiveIntensity;
#elif RBL_EMISSIVE == 2
    color += rblSrgbToLinear(texture(texture5, fragTexCoord).rgb)*rblEmissiveIntensity;
#endif

#if defined(RBL_DEBUG_VIEW) && (RBL_DEBUG_VIEW == 1)
    finalColor = vec4(tangentNormal*0.5 + 0.5, 1.0);
#elif defined(RBL_DEBUG_VIEW) && (RBL_DEBUG_VIEW == 2)
    finalColor = vec4(n*0.5 + 0.5, 1.0);
#elif defined(RBL_DEBUG_VIEW) && (RBL_DEBUG_VIEW == 3)
    finalColor = vec4(vec3(specular), 1.0);
#elif defined(RBL_DEBUG_VIEW) && (RBL_DEBUG_VIEW == 4)
    finalColor = vec4(vec3(occlusion), 1.0);
#elif defined(RBL_LINEAR_OUTPUT)
    finalColor = vec4(color, albedo.a);
#else
    finalColor = vec4(rblLinearToSrgb(color), albedo.a);
#endif
}
