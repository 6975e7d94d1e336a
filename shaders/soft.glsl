// Soft particles: a blended billboard fades where it meets the opaque scene behind it, by the depth
// distance between the two (RblScene.depth: a RblLoadSceneTarget's or a G-buffer's depth texture,
// the same size as the target drawn into). No depth texture in the scene: no fade.
//   RBL_SOFT_PARTICLES         compiled in (RblLitShaderDesc.softParticles)
#include "common.glsl"

#ifdef RBL_SOFT_PARTICLES
uniform sampler2D rblSceneDepth;    // texture unit RBL_SCENE_DEPTH_TEXTURE_UNIT
uniform vec4 rblSoftDepth;          // projection m10, m14, orthographic (0/1; -1 = no scene depth), fade distance (world units)
uniform vec2 rblSoftDepthTexel;     // 1/width, 1/height of the scene depth

// Distance in front of the camera of a window depth d (0..1), from the projection's depth row
float rblViewDepth(float d)
{
    float ndc = d*2.0 - 1.0;
    return (rblSoftDepth.z > 0.5)? (rblSoftDepth.y - ndc)/rblSoftDepth.x : rblSoftDepth.y/(ndc + rblSoftDepth.x);
}

// 0 where the fragment lies on or behind the scene's surface, 1 a fade distance or more in front
float rblSoftFade()
{
    if (rblSoftDepth.z < -0.5) return 1.0;
    float scene = rblViewDepth(texture(rblSceneDepth, gl_FragCoord.xy*rblSoftDepthTexel).r);
    float self = rblViewDepth(gl_FragCoord.z);
    return clamp((scene - self)/rblSoftDepth.w, 0.0, 1.0);
}
#endif
