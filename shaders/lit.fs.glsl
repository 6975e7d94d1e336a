// Forward lit fragment shader: albedo (texture0 x colDiffuse x vertex colour) with an alpha cutoff,
// optional tangent-space normal map (texture2, OpenGL convention: +X = +U, +Y = image up),
// Lambert diffuse from RBL_LIGHTS point lights plus a flat ambient term.
// Variant defines (prepended by the loader): RBL_LIGHTS (slots compiled in), RBL_NORMAL_MAP.

in vec3 fragPosition;
in vec2 fragTexCoord;
in vec4 fragColor;
in vec3 fragNormal;
in vec4 fragTangent;

uniform sampler2D texture0;     // albedo
#ifdef RBL_NORMAL_MAP
uniform sampler2D texture2;     // tangent-space normal map (raylib's MATERIAL_MAP_NORMAL slot)
#endif
uniform vec4 colDiffuse;
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

void main()
{
    vec4 albedo = texture(texture0, fragTexCoord)*colDiffuse*fragColor;
    if (albedo.a < rblAlphaCutoff) discard;

    vec3 n = rblSafeNormalize(fragNormal, vec3(0.0, 0.0, 1.0));
#ifdef RBL_NORMAL_MAP
    // Re-orthogonalise the interpolated tangent; cross(N,T)*w is the +V direction (raylib's
    // GenMeshTangents convention), and +V runs down the image, so the map's +Y is -B.
    vec3 t = fragTangent.xyz - n*dot(n, fragTangent.xyz);
    vec3 anyPerp = (abs(n.z) < 0.9)? vec3(-n.y, n.x, 0.0) : vec3(0.0, -n.z, n.y);
    t = rblSafeNormalize(t, rblSafeNormalize(anyPerp, vec3(1.0, 0.0, 0.0)));
    vec3 b = cross(n, t)*((fragTangent.w < 0.0)? -1.0 : 1.0);
    vec3 m = texture(texture2, fragTexCoord).xyz*2.0 - 1.0;
    n = rblSafeNormalize(t*m.x - b*m.y + n*m.z, n);
#endif

    vec3 irradiance = rblAmbient;
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
    finalColor = vec4(albedo.rgb*irradiance, albedo.a);
}
