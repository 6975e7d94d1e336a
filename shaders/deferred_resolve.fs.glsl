// Deferred resolve, fragment stage: the scene's ambient on the stored surface (once per pixel, the
// occlusion from the accumulation's alpha) plus the accumulated emission and light, through fog,
// exposure, tonemap and the display encoding (output.glsl), writing the G-buffer's depth for later
// forward draws; debug views.
#include "gbuffer_read.glsl"
#include "ambient.glsl"
#include "output.glsl"

RBL_VARYING vec2 fragUv;
uniform int rblOutput;               // RblGBufferOutput
uniform float rblOutputScale;            // linear depth / position / light count range of the debug views
out vec4 finalColor;

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
    // The resolve covers the target with fragUv 0..1 (same size as the G-buffer expected; nearest texel otherwise)
    ivec2 texel = ivec2(min(fragUv*vec2(textureSize(rblGDepth, 0)), vec2(textureSize(rblGDepth, 0) - 1)));
    float depth = texelFetch(rblGDepth, texel, 0).r;
    if (depth >= 1.0) discard;                          // background: nothing was drawn here
    vec3 position = rblPositionFromDepth(texel, depth);
    gl_FragDepth = depth;                               // later forward draws sort against this
    vec4 accum = texelFetch(rblGAccum, texel, 0);
    vec3 color = accum.rgb;
    float viewDistance = rblViewDistance(rblEye, rblViewAxis, position);
    RblShadingPoint s = rblGBufferSurface(texel, position);
    if (rblOutput == 0)
    {
        s.occlusion = accum.a;
        finalColor = vec4(rblFinish(color + rblAmbientLight(s), viewDistance), 1.0);
        return;
    }
    vec3 v = vec3(0.0);
    if (rblOutput == 1) v = rblLinearToSrgb(s.albedo);
    else if (rblOutput == 2) v = s.normal*0.5 + 0.5;
    else if (rblOutput == 3) v = vec3(s.specular);     // the stored channel: intensity or roughness
    else if (rblOutput == 4) v = vec3(accum.a);          // kept by the geometry pass for this view
    else if (rblOutput == 5) v = vec3(clamp(viewDistance/rblOutputScale, 0.0, 1.0));
    else if (rblOutput == 6) v = fract(position/rblOutputScale);
    else if (rblOutput == 7) v = rblHeat(color.r/rblOutputScale);
    finalColor = vec4(v, 1.0);
}
