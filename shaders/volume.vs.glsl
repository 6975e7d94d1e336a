// Deferred light volume, vertex stage: a sphere proxy per bounded point/spot light, one instanced
// draw; the light's packed values ride along as instance attributes (as the forward uniforms).
#include "dialect.glsl"

RBL_ATTRIBUTE vec3 vertexPosition;                         // proxy that encloses the unit sphere
layout(location = 10) in vec4 rblVolumePosition; // as rblLightPosition (w = 1)
layout(location = 11) in vec4 rblVolumeColor;    // as rblLightColor (a = 1/range > 0)
layout(location = 12) in vec4 rblVolumeSpot;     // as rblLightSpot
layout(location = 13) in vec4 rblVolumeFalloff;  // xyz as rblLightAttenuation, w shadow map index + 1 (0 = none) + 8 x (relief bit + 1)
uniform mat4 mvp;                               // projection x view of the geometry pass
RBL_FLAT RBL_VARYING vec4 volumePosition;
RBL_FLAT RBL_VARYING vec4 volumeColor;
RBL_FLAT RBL_VARYING vec4 volumeSpot;
RBL_FLAT RBL_VARYING vec4 volumeFalloff;

void main()
{
    volumePosition = rblVolumePosition;
    volumeColor = rblVolumeColor;
    volumeSpot = rblVolumeSpot;
    volumeFalloff = rblVolumeFalloff;
    gl_Position = mvp*vec4(rblVolumePosition.xyz + vertexPosition/rblVolumeColor.a, 1.0);
}
