// The opaque world drawn between RblBeginSceneDepth and RblEndSceneDepth, shown on the caller's target
// with its depth, so later draws are depth tested against it (soft particles also read that depth as a
// texture). Where nothing was drawn the caller's target shows through. GLSL ES 1.00 writes depth only
// with EXT_frag_depth (the loader enables it where it exists).
#include "dialect.glsl"

uniform sampler2D texture0;             // the scene target's colour
uniform sampler2D rblSceneDepthMap;     // its depth
RBL_VARYING vec2 fragUv;
#if RBL_GLSL >= 300
out vec4 finalColor;
#else
#define finalColor gl_FragColor
#endif

void main()
{
    float depth = texture(rblSceneDepthMap, fragUv).r;
    if (depth >= 1.0) discard;
    finalColor = vec4(texture(texture0, fragUv).rgb, 1.0);
#if RBL_GLSL >= 120
    gl_FragDepth = depth;
#elif defined(GL_EXT_frag_depth)
    gl_FragDepthEXT = depth;
#endif
}
