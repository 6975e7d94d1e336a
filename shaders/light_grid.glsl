// Light grid: every light of the scene for programs compiled with RblLitShaderDesc.clustered (GLSL 3:
// GL 3.3, ES 3, WebGL2). RblSetScene packs the lights into one texture and builds one world-space grid
// over the spheres of the bounded lights: each cell lists the lights that reach it. Unbounded lights
// (directional, range 0, or a range as large as the light set) are listed once and lit everywhere. A
// world grid serves every camera, target and pass of the frame, and needs no camera to build.
//   RBL_LIGHT_GRID            the grid replaces the light slots (RBL_LIGHTS is 0)
// Mirrors of the C side (rbl__LightGrid): RBL_LIGHT_GRID_WIDTH entries per row of rblLightGrid,
// RBL_LIGHT_DATA_LIGHTS lights of 4 texels per row of rblLightData.
#include "common.glsl"

#ifdef RBL_LIGHT_GRID
#define RBL_LIGHT_GRID_WIDTH 2048           // power of two: row = i >> 11
#define RBL_LIGHT_DATA_LIGHTS 256           // power of two: row = light >> 8
uniform highp sampler2D rblLightData;       // RGBA32F, unit RBL_LIGHT_GRID_TEXTURE_UNIT; per light: position (w: its RblLightFeature bits), colour (a: 1/range), spot, falloff
uniform highp sampler2D rblLightGrid;       // R32F, unit RBL_LIGHT_GRID_TEXTURE_UNIT + 1: the unbounded lights, the cells' starts (cells + 1), then each cell's lights
uniform vec4 rblGridOrigin;                 // xyz world corner of cell (0, 0, 0), w 1/cell size
uniform ivec4 rblGridDims;                  // cells along x, y, z (0: no bounded light); w the unbounded lights (the first entries)

// Light types this program leaves out, as the slots do (point lights are always compiled)
#ifdef RBL_LIGHT_DIRECTIONAL
#define RBL_GRID_NO_DIRECTIONAL 0
#else
#define RBL_GRID_NO_DIRECTIONAL 2
#endif
#ifdef RBL_LIGHT_SPOT
#define RBL_GRID_NO_SPOT 0
#else
#define RBL_GRID_NO_SPOT 4
#endif
#ifdef RBL_LIGHT_CLASSIC
#define RBL_GRID_NO_CLASSIC 0
#else
#define RBL_GRID_NO_CLASSIC 8
#endif
#define RBL_GRID_SKIPPED (RBL_GRID_NO_DIRECTIONAL + RBL_GRID_NO_SPOT + RBL_GRID_NO_CLASSIC)

// Entry i of the grid list (a light index, or a cell's first entry)
int rblGridEntry(int i)
{
    return int(texelFetch(rblLightGrid, ivec2(i & (RBL_LIGHT_GRID_WIDTH - 1), i >> 11), 0).r);
}

// Texel t (0 position, 1 colour, 2 spot, 3 falloff) of light i
vec4 rblGridLightTexel(int i, int t)
{
    return texelFetch(rblLightData, ivec2(((i & (RBL_LIGHT_DATA_LIGHTS - 1)) << 2) + t, i >> 8), 0);
}

// Entries [x, y) listing the bounded lights that may reach world point p (empty outside the grid;
// compared as floats first, so a far or NaN position never converts to an out-of-range int)
ivec2 rblGridCell(vec3 p)
{
    vec3 g = floor((p - rblGridOrigin.xyz)*rblGridOrigin.w);
    if (!(all(greaterThanEqual(g, vec3(0.0))) && all(lessThan(g, vec3(rblGridDims.xyz))))) return ivec2(0);
    ivec3 c = ivec3(g);
    int cell = rblGridDims.w + (c.z*rblGridDims.y + c.y)*rblGridDims.x + c.x;
    return ivec2(rblGridEntry(cell), rblGridEntry(cell + 1));
}
#endif
