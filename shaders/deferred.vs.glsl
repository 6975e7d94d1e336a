// Deferred lighting passes, vertex stage. The loader prepends "#version 330" and the defines:
//   RBL_PASS 1  full-screen triangle from gl_VertexID (ambient + unbounded lights, resolve)
//   RBL_PASS 2  light volume: a sphere proxy per bounded point/spot light, one instanced draw

out vec2 fragUv;                        // G-buffer coordinate of this pixel (0..1)

#if RBL_PASS == 2
in vec3 vertexPosition;                         // proxy that encloses the unit sphere
layout(location = 10) in vec4 rblVolumePosition; // as rblLightPosition (w = 1)
layout(location = 11) in vec4 rblVolumeColor;    // as rblLightColor (a = 1/range > 0)
layout(location = 12) in vec4 rblVolumeSpot;     // as rblLightSpot
layout(location = 13) in vec4 rblVolumeFalloff;  // xyz as rblLightAttenuation, w shadow map index + 1 (0 = none)
uniform mat4 mvp;                               // projection x view of the geometry pass
flat out vec4 volumePosition;
flat out vec4 volumeColor;
flat out vec4 volumeSpot;
flat out vec4 volumeFalloff;

void main()
{
    volumePosition = rblVolumePosition;
    volumeColor = rblVolumeColor;
    volumeSpot = rblVolumeSpot;
    volumeFalloff = rblVolumeFalloff;
    gl_Position = mvp*vec4(rblVolumePosition.xyz + vertexPosition/rblVolumeColor.a, 1.0);
    fragUv = (gl_Position.xy/gl_Position.w)*0.5 + 0.5;     // unused: the fragment stage uses gl_FragCoord
}
#else
void main()
{
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));     // (0,0) (2,0) (0,2)
    fragUv = p;
    gl_Position = vec4(p*2.0 - 1.0, 0.0, 1.0);
}
#endif
