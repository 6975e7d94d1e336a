// Full-screen triangle from a vertex buffer (GLSL 1 has no gl_VertexID): RblEndSceneDepth shows the
// scene target on the caller's target. Pairs with scene_composite.fs.glsl.
#include "dialect.glsl"

RBL_ATTRIBUTE vec3 vertexPosition;      // (-1,-1) (3,-1) (-1,3)
RBL_VARYING vec2 fragUv;                // scene target coordinate of this pixel (0..1)

void main()
{
    fragUv = vertexPosition.xy*0.5 + 0.5;
    gl_Position = vec4(vertexPosition.xy, 0.0, 1.0);
}
