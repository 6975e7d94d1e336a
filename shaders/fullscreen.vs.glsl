// Full-screen triangle from gl_VertexID (deferred ambient/unbounded-light pass and resolve); no
// vertex buffer.
#include "dialect.glsl"

RBL_VARYING vec2 fragUv;                        // G-buffer coordinate of this pixel (0..1)

void main()
{
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));     // (0,0) (2,0) (0,2)
    fragUv = p;
    gl_Position = vec4(p*2.0 - 1.0, 0.0, 1.0);
}
