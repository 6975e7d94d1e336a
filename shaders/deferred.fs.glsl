// Deferred lighting passes, fragment stage. The loader prepends "#version 330", the defines and
// lighting.glsl, so lights, falloff, BRDFs, clamps, fog and tonemap are the forward path's code.
//   RBL_PASS 1          ambient + up to RBL_LIGHTS unbounded lights (directional, range 0), full screen
//   RBL_PASS 2          one bounded light per instance (volume), additive
//   RBL_PASS 3          resolve: fog, exposure, tonemap, display encoding, depth; debug views
//   RBL_COUNT_LIGHTS    passes 1-2 add the number of lights evaluated instead of light (heat map)

in vec2 fragUv;
#if RBL_PASS == 2
flat in vec4 volumePosition;
flat in vec4 volumeColor;
flat in vec4 volumeSpot;
flat in vec4 volumeFalloff;           // xyz attenuation, w shadow map index + 1 (0 = none)
#endif

uniform sampler2D rblGAlbedo;           // RGBA8: sRGB albedo, occlusion
uniform sampler2D rblGNormal;           // RGBA8: octahedral 12+12 normal, specular/roughness
uniform sampler2D rblGParams;           // RG8: shininess (16-bit log) or metalness
uniform sampler2D rblGDepth;            // depth texture of the geometry pass
uniform sampler2D rblGAccum;            // RGBA16F light accumulation (resolve only)
uniform vec4 rblDepthLinear;            // perspective: n*f, f - n, f, 1; orthographic: n, f - n, 0, 0
uniform vec2 rblInvP;                   // 1/P00, 1/P11 of the geometry pass's projection
uniform mat4 rblInvView;                // inverse view (camera to world)
uniform vec3 rblEye;                    // camera position
#if RBL_PASS == 3
uniform int rblDebugView;               // RblGBufferView
uniform float rblDebugScale;            // linear depth / position / light count range of the debug views
#endif

out vec4 finalColor;

// Pixel coordinate in the G-buffer: the light passes draw at its size; the resolve covers the
// target with fragUv 0..1 (same size expected; nearest texel otherwise)
ivec2 rblTexel()
{
#if RBL_PASS == 3
    return ivec2(min(fragUv*vec2(textureSize(rblGDepth, 0)), vec2(textureSize(rblGDepth, 0) - 1)));
#else
    return ivec2(gl_FragCoord.xy);
#endif
}

// World position from the depth buffer, in closed form (an inverse projection matrix would cancel two
// large terms). Perspective: view distance z = n f/(f - d (f - n)) from the window depth d, then x, y
// along the pixel's ray. Orthographic: z = n + d (f - n), x, y straight from NDC. Then the inverse view.
vec3 rblPositionFromDepth(ivec2 texel, float depth)
{
    vec2 ndc = (vec2(texel) + 0.5)/vec2(textureSize(rblGDepth, 0))*2.0 - 1.0;
    vec3 view;
    if (rblDepthLinear.w > 0.0)
    {
        float z = rblDepthLinear.x/(rblDepthLinear.z - depth*rblDepthLinear.y);
        view = vec3(ndc*rblInvP*z, -z);
    }
    else view = vec3(ndc*rblInvP, -(rblDepthLinear.x + depth*rblDepthLinear.y));
    return (rblInvView*vec4(view, 1.0)).xyz;
}

RblShadingPoint rblGBufferSurface(ivec2 texel, vec3 position)
{
    vec4 a = texelFetch(rblGAlbedo, texel, 0);
    vec4 n = texelFetch(rblGNormal, texel, 0);
    vec4 p = texelFetch(rblGParams, texel, 0);
    RblShadingPoint s;
    s.position = position;
    s.normal = rblUnpackNormal(n.rgb);
    s.albedo = rblSrgbToLinear(a.rgb);
    s.occlusion = a.a;
    s.specular = n.a;
    s.specularColor = vec3(1.0);
    s.shininess = 1.0;
    s.metalness = 0.0;
#if RBL_BRDF == 1
    // raylib samples RG8 (GRAY_ALPHA) as (r, r, r, g)
    s.shininess = exp2((floor(p.r*255.0 + 0.5)*256.0 + floor(p.a*255.0 + 0.5))/65535.0*11.0);
#elif RBL_BRDF == 2
    s.metalness = p.r;
#endif
    return s;
}

// Heat map for the light count view: black -> blue -> green -> yellow -> red -> white
vec3 rblHeat(float t)
{
    t = clamp(t, 0.0, 1.0)*5.0;
    vec3 c0 = vec3(0.0), c1 = vec3(0.0, 0.2, 1.0), c2 = vec3(0.0, 0.9, 0.3), c3 = vec3(1.0, 0.9, 0.0), c4 = vec3(1.0, 0.1, 0.0), c5 = vec3(1.0);
    if (t < 1.0) return mix(c0, c1, t);
    if (t < 2.0) return mix(c1, c2, t - 1.0);
    if (t < 3.0) return mix(c2, c3, t - 2.0);
    if (t < 4.0) return mix(c3, c4, t - 3.0);
    return mix(c4, c5, t - 4.0);
}

void main()
{
    ivec2 texel = rblTexel();
    float depth = texelFetch(rblGDepth, texel, 0).r;
    if (depth >= 1.0) discard;                          // background: nothing was drawn here
#if RBL_PASS == 3
    vec3 position = rblPositionFromDepth(texel, depth);
    gl_FragDepth = depth;                               // later forward draws sort against this
    vec3 color = texelFetch(rblGAccum, texel, 0).rgb;
    if (rblDebugView == 0) { finalColor = vec4(rblFinish(color, position, rblEye), 1.0); return; }
    RblShadingPoint s = rblGBufferSurface(texel, position);
    vec3 v = vec3(0.0);
    if (rblDebugView == 1) v = rblLinearToSrgb(s.albedo);
    else if (rblDebugView == 2) v = s.normal*0.5 + 0.5;
    else if (rblDebugView == 3) v = vec3(s.specular);
    else if (rblDebugView == 4) v = vec3(s.occlusion);
    else if (rblDebugView == 5) v = vec3(clamp(length(position - rblEye)/rblDebugScale, 0.0, 1.0));
    else if (rblDebugView == 6) v = fract(position/rblDebugScale);
    else if (rblDebugView == 7) v = rblHeat(color.r/rblDebugScale);
    finalColor = vec4(v, 1.0);
#else
    vec3 position = rblPositionFromDepth(texel, depth);
#if RBL_PASS == 2
    // Most of a proxy's pixels lie outside the light's range: reject them from depth alone
    vec3 toLight = volumePosition.xyz - position;
    if (dot(toLight, toLight)*volumeColor.a*volumeColor.a >= 1.0) discard;
#endif
    RblShadingPoint s = rblGBufferSurface(texel, position);
    vec3 v = rblSafeNormalize(rblEye - s.position, s.normal);
#if RBL_PASS == 1
#ifdef RBL_COUNT_LIGHTS
    finalColor = vec4(vec3(float(rblLightCount)), 1.0);
#else
    finalColor = vec4(rblAmbientLight(s) + rblDirectLight(s, rblEye), 1.0);
#endif
#else
#ifdef RBL_COUNT_LIGHTS
    finalColor = vec4(1.0);
#else
#if RBL_SHADOWS > 0
    int map = int(volumeFalloff.w + 0.5) - 1;
    vec3 l = rblSafeNormalize(volumePosition.xyz - s.position, s.normal);
    float NdotL = dot(s.normal, l);
    float shadow = ((map >= 0) && (NdotL > 0.0))? rblShadow(map, s.position, s.normal, NdotL) : 1.0;
#else
    float shadow = 1.0;
#endif
    finalColor = vec4(rblEvalLight(s, v, volumePosition, volumeColor, volumeSpot, volumeFalloff.xyz, shadow), 1.0);
#endif
#endif
#endif
}
