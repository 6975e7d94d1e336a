/**********************************************************************************************
*
*   rbillboard_lit v0.1 - Lit billboards for raylib: normals, tangents, materials and lights
*
*   DESCRIPTION:
*       A raylib billboard (DrawBillboardPro) is two triangles with a colour and texture
*       coordinates: no normal, no tangent, no material, so it cannot take part in lighting.
*       This single header emits billboard quads that carry a per-vertex normal and tangent
*       (xyz + handedness), in every common facing mode, through its own vertex buffer (rlgl's
*       batch has no tangent attribute), and ships a forward shader that lights billboards and
*       ordinary raylib Models with the same lights, using raylib's default attribute and uniform
*       names so a Model's Material can use it unchanged.
*
*   FEATURES:
*       - Facing modes: camera plane (as raylib), camera position, locked axis (any unit axis),
*         fixed world orientation
*       - DrawBillboardPro parameters: atlas source rectangle, size, origin (pivot), rotation, tint;
*         plus atlas frames stored rotated 90 degrees and flips by negative size or source extent
*       - Per-vertex normal and tangent whose handedness stays right under every flip and rotation,
*         optional rounded (spherical / cylindrical) normals
*       - Immediate (one call per billboard), batched (one upload, one draw per material run) and
*         GPU-instanced (56 bytes per billboard, quads expanded in the vertex shader) paths
*       - Stable frames for degenerate cameras (looking straight up/down, target == position,
*         billboard at the eye); NaN/Inf input is skipped with one warning, never written to a buffer
*       - Forward lit shader: albedo with alpha cutoff, tangent-space normal map, point lights with
*         windowed inverse-square falloff, ambient term; the GLSL sources live in shaders/ and are
*         embedded below by `make shaders`
*
*   LIMITATIONS:
*       - OpenGL 3.3 core (GLSL 330) only for now; GLES2/WebGL variants are not written yet
*       - Lighting is Lambert diffuse with point lights only (directional/spot, Blinn-Phong/GGX,
*         packed material maps, the deferred helper and shadows are planned, not implemented)
*       - Billboards are not sorted: draw alpha-blended ones back to front yourself
*       - Instanced path: facing mode, up, axis and roundness are shared by all instances of a draw
*         (RblInstancedDesc); billboards needing their own FIXED orientation go through the batch
*       - rlgl's matrix stack (rlPushMatrix/rlTranslatef) is not applied to billboards: their vertices
*         are world space (matModel = identity) and face the camera in world space
*
*   DEVIATIONS FROM raylib's DrawBillboardPro (deliberate, tested):
*       - Negative size mirrors the image inside the source rectangle and keeps the quad's footprint
*         and pivot. raylib shifts the source rectangle by the world-space size (source.x -= size.x),
*         which samples the right texels only when |size| equals the source width in pixels, and
*         negates the pivot, which moves the quad.
*       - When camera.up is parallel to the view direction raylib's right vector is zero (a collapsed
*         quad); here a fallback frame is used (see DEGENERATE FRAMES).
*
*   DEGENERATE FRAMES (documented fallbacks, all deterministic):
*       - camera.target == camera.position: the view direction falls back to -Z (raylib's default).
*       - camera.up parallel to the view direction: up falls back to the world axis least aligned
*         with the view direction (-Z when looking straight down, +Z straight up), so a top-down
*         camera keeps -Z as screen-up.
*       - Camera-position mode with the billboard centre at the eye: faces the camera plane.
*       - Axis mode with the eye on the axis: faces the camera plane projected off the axis; if the
*         view looks along the axis too, the camera's up projected off the axis.
*       - Fixed mode with up parallel to the normal: up falls back as for the camera.
*
*   CONVENTIONS:
*       - Tangent = world direction of +U; cross(normal, tangent.xyz)*tangent.w = world direction
*         of +V, the same handedness raylib's GenMeshTangents() produces, so Models and billboards
*         share one shader.
*       - Normal maps: OpenGL convention (+X right, +Y up in the image as you see it).
*       - Texture slots follow raylib's Material: MATERIAL_MAP_ALBEDO -> texture0,
*         MATERIAL_MAP_NORMAL -> texture2.
*
*   CONFIGURATION:
*       #define RBILLBOARD_LIT_IMPLEMENTATION
*           Generates the implementation in the including file (exactly one translation unit).
*
*       #define RBL_MAX_LIGHTS 8
*           Light slots compiled into a lit shader at most (the variant compiles only what it asks for).
*
*       #define RBL_BATCH_DEFAULT_CAPACITY 1024
*           Billboards a batch reserves when RblLoadBatch() is given 0.
*
*       #define RBL_MALLOC / RBL_CALLOC / RBL_REALLOC / RBL_FREE
*           Custom allocator: define all four or none.
*
*       #define RBLAPI
*           Decoration for public functions; BUILD_LIBTYPE_SHARED / USE_LIBTYPE_SHARED select
*           __declspec(dllexport/dllimport) on Windows, as in raylib.
*
*   VERSIONS HISTORY:
*       0.1 (2026-11-22) First release: geometry (all facing modes, flips, rotated frames, rounded
*                        normals), immediate, batched and instanced paths, forward Lambert point lights.
*
*   DEPENDENCIES:
*       raylib 6.0 (raylib.h, rlgl.h, raymath.h), OpenGL 3.3 backend
*
*   LICENSE: zlib/libpng
*
*   Copyright (c) 2026 rbillboard_lit contributors
*
*   This software is provided "as-is", without any express or implied warranty. In no event
*   will the authors be held liable for any damages arising from the use of this software.
*
*   Permission is granted to anyone to use this software for any purpose, including commercial
*   applications, and to alter it and redistribute it freely, subject to the following restrictions:
*
*     1. The origin of this software must not be misrepresented; you must not claim that you
*     wrote the original software. If you use this software in a product, an acknowledgment
*     in the product documentation would be appreciated but is not required.
*
*     2. Altered source versions must be plainly marked as such, and must not be misrepresented
*     as being the original software.
*
*     3. This notice may not be removed or altered from any source distribution.
*
**********************************************************************************************/

#ifndef RBILLBOARD_LIT_H
#define RBILLBOARD_LIT_H

#include "raylib.h"

#define RBILLBOARD_LIT_VERSION_MAJOR 0
#define RBILLBOARD_LIT_VERSION_MINOR 1
#define RBILLBOARD_LIT_VERSION_PATCH 0
#define RBILLBOARD_LIT_VERSION "0.1.0"

// Function specifiers for a shared library build on Windows (as raylib's BUILD_LIBTYPE_SHARED)
#ifndef RBLAPI
    #if defined(_WIN32) && defined(BUILD_LIBTYPE_SHARED)
        #define RBLAPI __declspec(dllexport)     // Building the library as a Win32 shared library (.dll)
    #elif defined(_WIN32) && defined(USE_LIBTYPE_SHARED)
        #define RBLAPI __declspec(dllimport)     // Using the library as a Win32 shared library (.dll)
    #else
        #define RBLAPI                           // Functions defined as 'extern' by default (implicit specifiers)
    #endif
#endif

//----------------------------------------------------------------------------------
// Defines and Macros
//----------------------------------------------------------------------------------
#ifndef RBL_MAX_LIGHTS
    #define RBL_MAX_LIGHTS 8                    // Light slots a lit shader may compile in
#endif
#ifndef RBL_BATCH_DEFAULT_CAPACITY
    #define RBL_BATCH_DEFAULT_CAPACITY 1024     // Billboards reserved by RblLoadBatch(0)
#endif

//----------------------------------------------------------------------------------
// Types and Structures Definition
//----------------------------------------------------------------------------------
// How a billboard orients itself
typedef enum {
    RBL_FACING_CAMERA_PLANE = 0,    // Parallel to the view plane (raylib's DrawBillboard)
    RBL_FACING_CAMERA_POSITION,     // Each billboard turns toward the eye
    RBL_FACING_AXIS,                // Turns toward the eye around a locked axis (default +Y)
    RBL_FACING_FIXED                // World orientation given by normal and up
} RblFacing;

// Billboard flags
typedef enum {
    RBL_FRAME_ROTATED = 1,          // Atlas frame stored rotated 90 degrees clockwise (texture packers)
    RBL_ROUND_CYLINDER = 2          // Rounded normals bend around the up axis only (default: sphere)
} RblBillboardFlags;

// One billboard; zero fields take their defaults
typedef struct RblBillboard {
    Vector3 position;               // World position of the pivot
    Vector2 size;                   // World size; a negative component mirrors the image
    Vector2 origin;                 // Pivot, world units from the bottom-left corner (DrawBillboardPro)
    float rotation;                 // Degrees, counter-clockwise as seen from the front
    Rectangle source;               // Atlas frame in texels (zero = whole texture); negative extent mirrors
    Color tint;                     // Vertex colour (all zero = WHITE)
    int facing;                     // RblFacing
    Vector3 up;                     // CAMERA_PLANE: up vector (zero = camera up); FIXED: up (zero = +Y)
    Vector3 axis;                   // AXIS: locked axis (zero = +Y); FIXED: facing normal (zero = +Z)
    float roundness;                // 0 = flat normal, 1 = fully rounded (see RBL_ROUND_CYLINDER)
    unsigned int flags;             // RblBillboardFlags
} RblBillboard;

// Vertex layout of the batched path (attribute locations are raylib's defaults)
typedef struct RblVertex {
    float position[3];              // location 0: vertexPosition
    float texcoord[2];              // location 1: vertexTexCoord
    float normal[3];                // location 2: vertexNormal
    float tangent[4];               // location 4: vertexTangent (xyz: +U, w: handedness)
    unsigned char color[4];         // location 3: vertexColor
} RblVertex;

// Camera frame derived once per batch (degenerate cameras already resolved)
typedef struct RblView {
    Vector3 eye;                    // Camera position
    Vector3 right;                  // View matrix row 0 (unit)
    Vector3 up;                     // View matrix row 1 (unit)
    Vector3 back;                   // View matrix row 2 (unit, from target toward the eye)
} RblView;

// A run of billboards sharing one material inside a batch
typedef struct RblBatchRun {
    Material material;              // Material the run draws with
    int first;                      // First billboard
    int count;                      // Billboards in the run
} RblBatchRun;

// Batched billboards: CPU vertices, one GPU upload per RblEndBatch(), one draw per material run
typedef struct RblBatch {
    RblVertex *vertices;            // 4 per billboard
    int capacity;                   // Billboards reserved (CPU and GPU)
    int count;                      // Billboards added since RblBeginBatch()
    RblBatchRun *runs;              // Material runs
    int runCount;                   // Runs used
    int runCapacity;                // Runs reserved
    int gpuCapacity;                // Billboards the GPU buffer holds
    unsigned int vaoId;             // Vertex array
    unsigned int vboId;             // Vertex buffer
    unsigned int eboId;             // Index buffer (quads share 16-bit indices in chunks)
    RblView view;                   // Frame of the current camera
    int skipped;                    // Billboards skipped for bad input since RblBeginBatch()
    bool begun;                     // Between RblBeginBatch() and RblEndBatch()
} RblBatch;

// One instance of the instanced path: per-instance data only (56 bytes), the quad is expanded
// on the GPU with the same math as RblBillboardVertices()
typedef struct RblInstance {
    Vector3 position;               // World position of the pivot
    float rotation;                 // Degrees, counter-clockwise as seen from the front
    Vector2 size;                   // World size; a negative component mirrors the image
    Vector2 origin;                 // Pivot, world units from the bottom-left corner
    Rectangle source;               // Atlas frame in texels (zero = whole texture); negative extent mirrors
    Color tint;                     // Vertex colour (all zero = WHITE)
    unsigned int flags;             // RblBillboardFlags
} RblInstance;

// What one instanced draw shares across its instances; zero means default
typedef struct RblInstancedDesc {
    int facing;                     // RblFacing for every instance
    Vector3 up;                     // As RblBillboard.up
    Vector3 axis;                   // As RblBillboard.axis
    float roundness;                // As RblBillboard.roundness
} RblInstancedDesc;

// GPU instance buffer plus a staging copy (validated) and the instanced uniforms of the last shader
typedef struct RblInstanceBuffer {
    RblInstance *staging;           // Validated copy of the caller's instances
    int capacity;                   // Instances reserved
    unsigned int vaoId;             // Vertex array (instance attributes only)
    unsigned int vboId;             // Instance buffer
    unsigned int shaderId;          // Shader the cached locations belong to
    int locs[10];                   // Instanced uniform locations (looked up once per shader)
    int skipped;                    // Instances skipped for bad input in the last draw
} RblInstanceBuffer;

// Normal encodings (packed material texture, or a plain normal map)
typedef enum {
    RBL_NORMAL_NONE = 0,            // No normal map: the geometry normal, nothing sampled
    RBL_NORMAL_HEMIOCT,             // Hemi-octahedral in two 8-bit channels, precise encoder (packing default)
    RBL_NORMAL_XY,                  // X and Y in two 8-bit channels, Z rebuilt as sqrt(max(0, 1 - x*x - y*y))
    RBL_NORMAL_RGB                  // Plain RGB tangent-space map (raylib's MATERIAL_MAP_NORMAL as authored)
} RblNormalEncoding;

// Emissive representations of a packed material
typedef enum {
    RBL_EMISSIVE_NONE = 0,          // No emission, nothing sampled
    RBL_EMISSIVE_MASK,              // 8-bit grey mask (1 byte/texel): emission = mask x albedo colour
    RBL_EMISSIVE_RGB                // Own colour (sRGB RGBA8, 4 bytes/texel)
} RblEmissiveLayout;

// What a packed material holds; it also selects the lit shader variant (absent maps are never sampled)
typedef struct RblMaterialLayout {
    int normalEncoding;             // RblNormalEncoding of the material texture's RG (RGB for RBL_NORMAL_RGB)
    bool specular;                  // Material texture B: specular intensity (or roughness), linear
    bool occlusion;                 // Material texture A: ambient occlusion, linear
    int emissive;                   // RblEmissiveLayout of the emissive texture
} RblMaterialLayout;

// Packing input: raylib Images of one size (any format raylib converts); data == NULL = absent
typedef struct RblMaterialSource {
    Image albedo;                   // Required: colour (sRGB) with alpha
    Image normal;                   // Tangent-space normal map (RGB, OpenGL convention unless normalDirectX)
    Image specular;                 // Specular intensity or roughness (grey; red channel of a colour image)
    Image occlusion;                // Ambient occlusion (grey)
    Image emissive;                 // Emission: colour (sRGB), or grey = a mask
    bool normalDirectX;             // Normal map is DirectX convention (+Y down): flipped on packing
    int normalEncoding;             // RblNormalEncoding to pack into (0 = RBL_NORMAL_HEMIOCT)
    const Rectangle *frames;        // Atlas frames whose edge texels are dilated into the gutters (NULL = none)
    int frameCount;                 // Number of frames
    bool mipmaps;                   // Build mip chains (normals renormalised, colour averaged in linear light)
} RblMaterialSource;

// Packing output (CPU Images; upload with LoadTextureFromImage or RblLoadPackedMaterial)
typedef struct RblPackedMaterial {
    Image albedo;                   // RGBA8 sRGB, gutters dilated
    Image material;                 // RGBA8: RG normal, B specular, A occlusion (data == NULL if nothing to store)
    Image emissive;                 // R8 mask or RGBA8 sRGB (data == NULL if none)
    RblMaterialLayout layout;       // What is stored where
} RblPackedMaterial;

// Angular error of a normal encoding, in degrees
typedef struct RblNormalErrorStats {
    double mean;                    // Mean angular error
    double p99;                     // 99th percentile
    double max;                     // Maximum
    int count;                      // Normals measured
} RblNormalErrorStats;

// Point light (linear colour; range 0 = unbounded inverse square)
typedef struct RblLight {
    Vector3 position;               // World position
    Color color;                    // Colour (linear, /255)
    float intensity;                // Scale of color; >= 0
    float range;                    // Distance where the light fades to zero (0 = no window)
} RblLight;

// Lit shader variant request; zero means default
typedef struct RblLitShaderDesc {
    int maxLights;                  // Light slots compiled in (0 = 1, at most RBL_MAX_LIGHTS)
    bool normalMap;                 // Sample a tangent-space normal map from MATERIAL_MAP_NORMAL
    float alphaCutoff;              // Discard fragments below this alpha (0 = 0.5; negative = never)
    bool instanced;                 // Vertex stage for RblDrawInstanced() instead of vertex buffers
} RblLitShaderDesc;

// Lit shader: a raylib Shader plus its uniform locations (looked up once)
typedef struct RblLitShader {
    Shader shader;                  // Use as Material.shader for billboards and Models
    int maxLights;                  // Light slots compiled in
    bool normalMap;                 // Variant samples a normal map
    bool instanced;                 // Variant expands RblInstance data
    int locLightCount;              // Uniform locations
    int locLightPosition;
    int locLightColor;
    int locLightInvRange;
    int locAmbient;
    int locAlphaCutoff;
} RblLitShader;

#if defined(__cplusplus)
extern "C" {            // Prevents name mangling of functions
#endif

//----------------------------------------------------------------------------------
// Module Functions Declaration
//----------------------------------------------------------------------------------
// Geometry (CPU, no GL needed)
RBLAPI RblView RblGetView(Camera3D camera);                                   // Camera frame with degenerate cases resolved
RBLAPI bool RblBillboardVertices(const RblView *view, int textureWidth, int textureHeight, const RblBillboard *billboard, RblVertex out[4]); // Emit a quad (bottom-left, bottom-right, top-right, top-left); false = skipped, out untouched

// Batched and immediate paths (GL)
RBLAPI RblBatch RblLoadBatch(int capacity);                                   // Load a batch reserving capacity billboards (0 = default)
RBLAPI bool RblIsBatchValid(RblBatch batch);                                  // Check the batch owns its GPU buffers
RBLAPI void RblUnloadBatch(RblBatch *batch);                                  // Unload batch buffers
RBLAPI void RblBeginBatch(RblBatch *batch, Camera3D camera);                  // Start collecting billboards seen by camera
RBLAPI bool RblBatchAdd(RblBatch *batch, Material material, const RblBillboard *billboard); // Add one billboard; false = skipped (bad input)
RBLAPI void RblEndBatch(RblBatch *batch);                                     // Upload once and draw each material run
RBLAPI void RblDrawBillboard(Camera3D camera, Material material, RblBillboard billboard); // Draw one billboard now (immediate path)
RBLAPI void RblClose(void);                                                   // Release the immediate path's buffers (before CloseWindow)

// Instanced path (GL): per-instance data only, quads expanded in the vertex shader
RBLAPI RblInstanceBuffer RblLoadInstanceBuffer(int capacity);                 // Load an instance buffer (0 = default capacity)
RBLAPI bool RblIsInstanceBufferValid(RblInstanceBuffer buffer);               // Check the buffer owns its GPU objects
RBLAPI void RblUnloadInstanceBuffer(RblInstanceBuffer *buffer);               // Unload an instance buffer
RBLAPI int RblDrawInstanced(RblInstanceBuffer *buffer, Camera3D camera, Material material, RblInstancedDesc desc, const RblInstance *instances, int count); // Draw with one instanced call (material.shader: an instanced lit variant); returns instances drawn

// Material maps (CPU, no GL needed): packing, encodings, authoring help
RBLAPI bool RblPackMaterial(const RblMaterialSource *source, RblPackedMaterial *packed); // Pack an atlas's maps; false = invalid input (logged), packed untouched
RBLAPI void RblUnloadPackedMaterial(RblPackedMaterial *packed);               // Free packed Images
RBLAPI void RblEncodeNormal(Vector3 normal, int encoding, unsigned char out[3]); // Encode a unit tangent-space normal (RG used; RGB for RBL_NORMAL_RGB)
RBLAPI Vector3 RblDecodeNormal(const unsigned char in[3], int encoding);     // Decode as the shaders do (unit length, never NaN)
RBLAPI RblNormalErrorStats RblMeasureNormalEncoding(int encoding, const Vector3 *normals, int count); // Angular error of encode+decode over unit normals
RBLAPI Image RblGenNormalMapFromHeight(Image height, float strength, bool wrap); // Tangent-space normal map (OpenGL convention) from a height map (grey)
RBLAPI Image RblGenHeightFromLuminance(Image albedo);                         // Height (grey) from albedo luminance, for RblGenNormalMapFromHeight
RBLAPI Image RblGenOcclusionFromHeight(Image height, int radius, float strength); // Cavity occlusion (grey) from a height map

// Lights and the forward lit shader
RBLAPI RblLitShader RblLoadLitShader(RblLitShaderDesc desc);                  // Compile a lit shader variant
RBLAPI bool RblIsLitShaderValid(RblLitShader shader);                         // Check it compiled (not raylib's fallback)
RBLAPI void RblUnloadLitShader(RblLitShader shader);                          // Unload a lit shader
RBLAPI bool RblSetLights(RblLitShader *shader, const RblLight *lights, int count, Color ambient); // Upload lights; false = rejected, nothing changed

#if defined(__cplusplus)
}
#endif

#endif // RBILLBOARD_LIT_H

/***********************************************************************************
*
*   RBILLBOARD_LIT IMPLEMENTATION
*
************************************************************************************/
#if defined(RBILLBOARD_LIT_IMPLEMENTATION)

#include "rlgl.h"
#include <math.h>       // sqrtf, sinf, cosf, fabsf
#include <string.h>     // memcpy, memset, strlen
#include <stdio.h>      // snprintf
#include <stddef.h>     // offsetof

#if defined(RBL_MALLOC) || defined(RBL_CALLOC) || defined(RBL_REALLOC) || defined(RBL_FREE)
    #if !defined(RBL_MALLOC) || !defined(RBL_CALLOC) || !defined(RBL_REALLOC) || !defined(RBL_FREE)
        #error "rbillboard_lit: define all of RBL_MALLOC, RBL_CALLOC, RBL_REALLOC and RBL_FREE, or none"
    #endif
#else
    #include <stdlib.h>
    #define RBL_MALLOC(sz)       malloc(sz)
    #define RBL_CALLOC(n,sz)     calloc(n,sz)
    #define RBL_REALLOC(ptr,sz)  realloc(ptr,sz)
    #define RBL_FREE(ptr)        free(ptr)
#endif

// Quads per indexed draw: 16-bit indices (rlDrawVertexArrayElements) address 65536 vertices
#define RBL__QUADS_PER_CHUNK 16384

//----------------------------------------------------------------------------------
// Embedded shaders (generated from the .glsl files in shaders/ by `make shaders`; do not edit by hand)
//----------------------------------------------------------------------------------
// RBL-SHADERS-BEGIN
static const char *const rbl__shader_lit_fs[] = {
    "// Forward lit fragment shader: albedo (texture0 x colDiffuse x vertex colour) with an alpha cutoff,\n",
    "// optional tangent-space normal map (texture2, OpenGL convention: +X = +U, +Y = image up),\n",
    "// Lambert diffuse from RBL_LIGHTS point lights plus a flat ambient term.\n",
    "// Variant defines (prepended by the loader): RBL_LIGHTS (slots compiled in), RBL_NORMAL_MAP.\n",
    "\n",
    "in vec3 fragPosition;\n",
    "in vec2 fragTexCoord;\n",
    "in vec4 fragColor;\n",
    "in vec3 fragNormal;\n",
    "in vec4 fragTangent;\n",
    "\n",
    "uniform sampler2D texture0;     // albedo\n",
    "#ifdef RBL_NORMAL_MAP\n",
    "uniform sampler2D texture2;     // tangent-space normal map (raylib's MATERIAL_MAP_NORMAL slot)\n",
    "#endif\n",
    "uniform vec4 colDiffuse;\n",
    "uniform float rblAlphaCutoff;\n",
    "uniform vec3 rblAmbient;        // linear ambient radiance\n",
    "#if RBL_LIGHTS > 0\n",
    "uniform int rblLightCount;\n",
    "uniform vec3 rblLightPosition[RBL_LIGHTS];\n",
    "uniform vec3 rblLightColor[RBL_LIGHTS];     // linear colour x intensity\n",
    "uniform float rblLightInvRange[RBL_LIGHTS]; // 1/range, 0 = no range window\n",
    "#endif\n",
    "\n",
    "out vec4 finalColor;\n",
    "\n",
    "// normalize() of a zero vector is undefined (NaN on most GPUs): fall back instead.\n",
    "vec3 rblSafeNormalize(vec3 v, vec3 fallback)\n",
    "{\n",
    "    float len2 = dot(v, v);\n",
    "    return (len2 > 1e-20)? v*inversesqrt(len2) : fallback;\n",
    "}\n",
    "\n",
    "void main()\n",
    "{\n",
    "    vec4 albedo = texture(texture0, fragTexCoord)*colDiffuse*fragColor;\n",
    "    if (albedo.a < rblAlphaCutoff) discard;\n",
    "\n",
    "    vec3 n = rblSafeNormalize(fragNormal, vec3(0.0, 0.0, 1.0));\n",
    "#ifdef RBL_NORMAL_MAP\n",
    "    // Re-orthogonalise the interpolated tangent; cross(N,T)*w is the +V direction (raylib's\n",
    "    // GenMeshTangents convention), and +V runs down the image, so the map's +Y is -B.\n",
    "    vec3 t = fragTangent.xyz - n*dot(n, fragTangent.xyz);\n",
    "    vec3 anyPerp = (abs(n.z) < 0.9)? vec3(-n.y, n.x, 0.0) : vec3(0.0, -n.z, n.y);\n",
    "    t = rblSafeNormalize(t, rblSafeNormalize(anyPerp, vec3(1.0, 0.0, 0.0)));\n",
    "    vec3 b = cross(n, t)*((fragTangent.w < 0.0)? -1.0 : 1.0);\n",
    "    vec3 m = texture(texture2, fragTexCoord).xyz*2.0 - 1.0;\n",
    "    n = rblSafeNormalize(t*m.x - b*m.y + n*m.z, n);\n",
    "#endif\n",
    "\n",
    "    vec3 irradiance = rblAmbient;\n",
    "#if RBL_LIGHTS > 0\n",
    "    for (int i = 0; i < RBL_LIGHTS; i++)\n",
    "    {\n",
    "        if (i >= rblLightCount) break;\n",
    "        vec3 toLight = rblLightPosition[i] - fragPosition;\n",
    "        float d2 = dot(toLight, toLight);\n",
    "        vec3 l = rblSafeNormalize(toLight, n);      // a light on the surface lights it head-on\n",
    "        // Windowed inverse square (UE4/Filament): I*saturate(1-(d/r)^4)^2/max(d^2, eps).\n",
    "        float x2 = d2*rblLightInvRange[i]*rblLightInvRange[i];\n",
    "        float window = clamp(1.0 - x2*x2, 0.0, 1.0);\n",
    "        float falloff = window*window/max(d2, 1e-4);\n",
    "        irradiance += rblLightColor[i]*(max(dot(n, l), 0.0)*falloff);\n",
    "    }\n",
    "#endif\n",
    "    finalColor = vec4(albedo.rgb*irradiance, albedo.a);\n",
    "}\n",
    NULL };
static const char *const rbl__shader_lit_vs[] = {
    "// Forward lit vertex shader: billboards (world-space vertices, matModel = identity) and raylib\n",
    "// Models (matModel = the model transform) go through the same code.\n",
    "// The loader prepends \"#version 330\" and the variant's #defines.\n",
    "\n",
    "in vec3 vertexPosition;\n",
    "in vec2 vertexTexCoord;\n",
    "in vec3 vertexNormal;\n",
    "in vec4 vertexColor;\n",
    "in vec4 vertexTangent;      // xyz: world +U direction, w: handedness (cross(N,T)*w = +V)\n",
    "\n",
    "uniform mat4 mvp;\n",
    "uniform mat4 matModel;\n",
    "uniform mat4 matNormal;\n",
    "\n",
    "out vec3 fragPosition;\n",
    "out vec2 fragTexCoord;\n",
    "out vec4 fragColor;\n",
    "out vec3 fragNormal;\n",
    "out vec4 fragTangent;\n",
    "\n",
    "void main()\n",
    "{\n",
    "    fragPosition = vec3(matModel*vec4(vertexPosition, 1.0));\n",
    "    fragTexCoord = vertexTexCoord;\n",
    "    fragColor = vertexColor;\n",
    "    fragNormal = mat3(matNormal)*vertexNormal;\n",
    "    // Tangents transform with the model matrix (they lie in the surface), normals with its inverse transpose.\n",
    "    fragTangent = vec4(mat3(matModel)*vertexTangent.xyz, vertexTangent.w);\n",
    "    gl_Position = mvp*vec4(vertexPosition, 1.0);\n",
    "}\n",
    NULL };
static const char *const rbl__shader_lit_instanced_vs[] = {
    "// Instanced billboard vertex shader: expands one quad per instance (6 vertices, gl_VertexID 0..5)\n",
    "// from per-instance data, with the same math and degenerate-frame fallbacks as the CPU path\n",
    "// (RblBillboardVertices), so all three paths emit the same vertices. Pairs with lit.fs.glsl.\n",
    "// The loader prepends \"#version 330\" and the variant's #defines.\n",
    "\n",
    "layout(location = 10) in vec4 rblInstancePosition;  // xyz: pivot, w: rotation in degrees\n",
    "layout(location = 11) in vec4 rblInstanceSize;      // xy: size (negative mirrors), zw: origin\n",
    "layout(location = 12) in vec4 rblInstanceSource;    // x, y, width, height in texels (all zero = whole texture)\n",
    "layout(location = 13) in vec4 rblInstanceTint;      // normalised bytes (all zero = white)\n",
    "layout(location = 14) in float rblInstanceFlags;    // RblBillboardFlags\n",
    "\n",
    "uniform mat4 mvp;\n",
    "uniform vec3 rblViewEye;\n",
    "uniform vec3 rblViewRight;\n",
    "uniform vec3 rblViewUp;\n",
    "uniform vec3 rblViewBack;\n",
    "uniform int rblFacing;          // RblFacing\n",
    "uniform vec3 rblFacingUp;       // CAMERA_PLANE: caller up (zero = camera up); FIXED: up (zero = +Y)\n",
    "uniform vec3 rblFacingAxis;     // AXIS: locked axis (zero = +Y); FIXED: normal (zero = +Z)\n",
    "uniform float rblRoundness;\n",
    "uniform vec2 rblTextureSize;\n",
    "\n",
    "out vec3 fragPosition;\n",
    "out vec2 fragTexCoord;\n",
    "out vec4 fragColor;\n",
    "out vec3 fragNormal;\n",
    "out vec4 fragTangent;\n",
    "\n",
    "bool rblNormalizeTo(vec3 v, out vec3 o)\n",
    "{\n",
    "    float l2 = dot(v, v);\n",
    "    o = v;\n",
    "    if (!(l2 > 1e-24)) return false;\n",
    "    o = v*inversesqrt(l2);\n",
    "    return true;\n",
    "}\n",
    "\n",
    "// Unit component of v perpendicular to unit n (relative threshold, as on the CPU)\n",
    "bool rblPerpendicular(vec3 v, vec3 n, out vec3 o)\n",
    "{\n",
    "    vec3 p = v - n*dot(v, n);\n",
    "    o = p;\n",
    "    if (!(dot(p, p) > 1e-10*dot(v, v))) return false;\n",
    "    return rblNormalizeTo(p, o);\n",
    "}\n",
    "\n",
    "vec3 rblFallbackUp(vec3 d)\n",
    "{\n",
    "    vec3 a = abs(d);\n",
    "    if ((a.z <= a.x) && (a.z <= a.y)) return vec3(0.0, 0.0, (d.y > 0.0)? -1.0 : 1.0);\n",
    "    if (a.y <= a.x) return vec3(0.0, 1.0, 0.0);\n",
    "    return vec3(1.0, 0.0, 0.0);\n",
    "}\n",
    "\n",
    "void main()\n",
    "{\n",
    "    const int cornerOf[6] = int[6](0, 1, 2, 0, 2, 3);\n",
    "    int corner = cornerOf[gl_VertexID % 6];\n",
    "    vec3 position = rblInstancePosition.xyz;\n",
    "    int flags = int(rblInstanceFlags + 0.5);\n",
    "\n",
    "    // Facing basis (right r, up u, normal n)\n",
    "    vec3 r = rblViewRight, u = rblViewUp, n = rblViewBack;\n",
    "    if (rblFacing == 0)\n",
    "    {\n",
    "        vec3 nn;\n",
    "        if ((dot(rblFacingUp, rblFacingUp) > 0.0) && rblNormalizeTo(cross(r, rblFacingUp), nn)) { u = rblFacingUp; n = nn; }\n",
    "    }\n",
    "    else if (rblFacing == 1)\n",
    "    {\n",
    "        vec3 toEye;\n",
    "        if (rblNormalizeTo(rblViewEye - position, toEye))\n",
    "        {\n",
    "            n = toEye;\n",
    "            vec3 rr;\n",
    "            if (rblNormalizeTo(cross(rblViewUp, n), rr)) { r = rr; u = cross(n, r); }\n",
    "            else { r = rblViewRight; u = cross(n, r); rblNormalizeTo(u, u); r = cross(u, n); }\n",
    "        }\n",
    "    }\n",
    "    else if (rblFacing == 2)\n",
    "    {\n",
    "        vec3 a = vec3(0.0, 1.0, 0.0);\n",
    "        if (dot(rblFacingAxis, rblFacingAxis) > 0.0) rblNormalizeTo(rblFacingAxis, a);\n",
    "        vec3 nn;\n",
    "        if (!rblPerpendicular(rblViewEye - position, a, nn) && !rblPerpendicular(rblViewBack, a, nn) &&\n",
    "            !rblPerpendicular(rblViewUp, a, nn)) nn = rblViewBack;\n",
    "        u = a; n = nn; r = cross(u, n);\n",
    "    }\n",
    "    else\n",
    "    {\n",
    "        vec3 nn = vec3(0.0, 0.0, 1.0);\n",
    "        if (dot(rblFacingAxis, rblFacingAxis) > 0.0) rblNormalizeTo(rblFacingAxis, nn);\n",
    "        vec3 uu = (dot(rblFacingUp, rblFacingUp) > 0.0)? rblFacingUp : vec3(0.0, 1.0, 0.0);\n",
    "        if (!rblPerpendicular(uu, nn, uu)) rblPerpendicular(rblFallbackUp(nn), nn, uu);\n",
    "        n = nn; u = uu; r = cross(u, n);\n",
    "    }\n",
    "\n",
    "    float rotation = rblInstancePosition.w;\n",
    "    if (rotation != 0.0)\n",
    "    {\n",
    "        float ang = rotation*(3.14159265358979323846/180.0), c = cos(ang), s = sin(ang);\n",
    "        vec3 nr = cross(n, r), nu = cross(n, u);\n",
    "        r = r*c + nr*s;\n",
    "        u = u*c + nu*s;\n",
    "    }\n",
    "\n",
    "    vec2 size = rblInstanceSize.xy, origin = rblInstanceSize.zw;\n",
    "    float sx = abs(size.x), sy = abs(size.y);\n",
    "    vec3 un = u;\n",
    "    rblNormalizeTo(u, un);\n",
    "    float ulen = length(u);\n",
    "    float cs = (corner == 1 || corner == 2)? 1.0 : 0.0;     // sprite-space s (right)\n",
    "    float ct = (corner < 2)? 1.0 : 0.0;                      // sprite-space t (down)\n",
    "    float x = (cs > 0.5)? sx - origin.x : -origin.x;\n",
    "    float y = (ct < 0.5)? sy*ulen - origin.y : -origin.y;\n",
    "    vec3 p = position + r*x + un*y;\n",
    "\n",
    "    vec4 src = rblInstanceSource;\n",
    "    if (src == vec4(0.0)) src = vec4(0.0, 0.0, rblTextureSize);\n",
    "    bool flipU = (size.x < 0.0) != (src.z < 0.0);\n",
    "    bool flipV = (size.y < 0.0) != (src.w < 0.0);\n",
    "    bool rotated = (flags & 1) != 0;\n",
    "    float s = flipU? 1.0 - cs : cs;\n",
    "    float t = flipV? 1.0 - ct : ct;\n",
    "    vec2 frame = rotated? vec2(1.0 - t, s) : vec2(s, t);\n",
    "    fragTexCoord = (src.xy + frame*abs(src.zw))/rblTextureSize;\n",
    "\n",
    "    vec3 T, V;\n",
    "    if (!rotated) { T = flipU? -r : r; V = flipV? un : -un; }\n",
    "    else { T = flipV? -un : un; V = flipU? -r : r; }\n",
    "    float w = (dot(cross(n, T), V) < 0.0)? -1.0 : 1.0;\n",
    "\n",
    "    vec3 nv = n, tv = T;\n",
    "    float round = clamp(rblRoundness, 0.0, 1.0);\n",
    "    if (round > 0.0)\n",
    "    {\n",
    "        float dx = (cs < 0.5)? -1.0 : 1.0;\n",
    "        float dy = ((flags & 2) != 0)? 0.0 : ((ct > 0.5)? -1.0 : 1.0);\n",
    "        rblNormalizeTo(n + (r*dx + un*dy)*round, nv);\n",
    "        if (!rblPerpendicular(T, nv, tv)) tv = T;\n",
    "    }\n",
    "\n",
    "    fragPosition = p;\n",
    "    fragColor = (rblInstanceTint == vec4(0.0))? vec4(1.0) : rblInstanceTint;\n",
    "    fragNormal = nv;\n",
    "    fragTangent = vec4(tv, w);\n",
    "    gl_Position = mvp*vec4(p, 1.0);\n",
    "}\n",
    NULL };
// Every embedded shader by file name (tests compare these with shaders/*.glsl)
static const struct { const char *file; const char *const *source; } rbl__shaderFiles[] = {
    { "lit.fs.glsl", rbl__shader_lit_fs },
    { "lit.vs.glsl", rbl__shader_lit_vs },
    { "lit_instanced.vs.glsl", rbl__shader_lit_instanced_vs },
};
// RBL-SHADERS-END

//----------------------------------------------------------------------------------
// Module Internal Functions: small vector helpers (C and C++ without compound literals)
//----------------------------------------------------------------------------------
static inline Vector3 rbl__v3(float x, float y, float z) { Vector3 v; v.x = x; v.y = y; v.z = z; return v; }
static inline bool rbl__finite(float x) { return (x == x) && (x - x == 0.0f); }    // false for NaN and +-Inf
static inline bool rbl__finite3(Vector3 v) { return rbl__finite(v.x) && rbl__finite(v.y) && rbl__finite(v.z); }
static inline float rbl__len2(Vector3 v) { return v.x*v.x + v.y*v.y + v.z*v.z; }
static inline float rbl__dot(Vector3 a, Vector3 b) { return a.x*b.x + a.y*b.y + a.z*b.z; }
static inline Vector3 rbl__sub(Vector3 a, Vector3 b) { return rbl__v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline Vector3 rbl__neg(Vector3 a) { return rbl__v3(-a.x, -a.y, -a.z); }
static inline Vector3 rbl__cross(Vector3 a, Vector3 b) { return rbl__v3(a.y*b.z - a.z*b.y, a.z*b.x - a.x*b.z, a.x*b.y - a.y*b.x); }

// a*b exactly as raymath's MatrixMultiply (raymath is not included: it does not compile
// warning-free as C++ with -Wextra). Matrix fields are named m0..m15 but stored row by row.
static void rbl__matToArray(Matrix m, float a[16])
{
    a[0] = m.m0; a[1] = m.m1; a[2] = m.m2; a[3] = m.m3; a[4] = m.m4; a[5] = m.m5; a[6] = m.m6; a[7] = m.m7;
    a[8] = m.m8; a[9] = m.m9; a[10] = m.m10; a[11] = m.m11; a[12] = m.m12; a[13] = m.m13; a[14] = m.m14; a[15] = m.m15;
}

static Matrix rbl__matMul(Matrix left, Matrix right)
{
    float a[16], b[16], r[16];
    rbl__matToArray(left, a);
    rbl__matToArray(right, b);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            r[i*4 + j] = a[i*4 + 0]*b[0*4 + j] + a[i*4 + 1]*b[1*4 + j] + a[i*4 + 2]*b[2*4 + j] + a[i*4 + 3]*b[3*4 + j];
    Matrix m;
    m.m0 = r[0]; m.m1 = r[1]; m.m2 = r[2]; m.m3 = r[3]; m.m4 = r[4]; m.m5 = r[5]; m.m6 = r[6]; m.m7 = r[7];
    m.m8 = r[8]; m.m9 = r[9]; m.m10 = r[10]; m.m11 = r[11]; m.m12 = r[12]; m.m13 = r[13]; m.m14 = r[14]; m.m15 = r[15];
    return m;
}

static Matrix rbl__identity(void)
{
    Matrix m;
    memset(&m, 0, sizeof(m));
    m.m0 = m.m5 = m.m10 = m.m15 = 1.0f;
    return m;
}

// Unit vector or false when v is too short to give a direction
static inline bool rbl__normalizeTo(Vector3 v, Vector3 *out)
{
    float l2 = rbl__len2(v);
    if (!(l2 > 1e-24f) || !rbl__finite(l2)) return false;
    float inv = 1.0f/sqrtf(l2);
    *out = rbl__v3(v.x*inv, v.y*inv, v.z*inv);
    return true;
}

// World axis least aligned with d: the stable substitute for an up vector parallel to d.
// Ties prefer Z; d is the view's back vector, so a camera looking straight down (back = +Y)
// gets -Z (raylib's forward, "north") as screen-up, and one looking straight up gets +Z.
static Vector3 rbl__fallbackUp(Vector3 d)
{
    float ax = fabsf(d.x), ay = fabsf(d.y), az = fabsf(d.z);
    if ((az <= ax) && (az <= ay)) return rbl__v3(0.0f, 0.0f, (d.y > 0.0f)? -1.0f : 1.0f);
    if (ay <= ax) return rbl__v3(0.0f, 1.0f, 0.0f);
    return rbl__v3(1.0f, 0.0f, 0.0f);
}

// Unit component of v perpendicular to unit n; false if v is (nearly) parallel to n
static inline bool rbl__perpendicular(Vector3 v, Vector3 n, Vector3 *out)
{
    float d = rbl__dot(v, n);
    Vector3 p = rbl__v3(v.x - n.x*d, v.y - n.y*d, v.z - n.z*d);
    float l2v = rbl__len2(v);
    if (!(rbl__len2(p) > 1e-10f*l2v)) return false;     // relative test: scale-free
    return rbl__normalizeTo(p, out);
}

//----------------------------------------------------------------------------------
// Module Functions Definition: geometry
//----------------------------------------------------------------------------------
// Camera frame, computed in the same operation order as raymath's MatrixLookAt (parity with raylib)
RblView RblGetView(Camera3D camera)
{
    RblView view;
    view.eye = camera.position;
    Vector3 back;
    if (!rbl__normalizeTo(rbl__sub(camera.position, camera.target), &back)) back = rbl__v3(0.0f, 0.0f, 1.0f);
    Vector3 up = camera.up;
    Vector3 right = rbl__v3(1.0f, 0.0f, 0.0f);     // overwritten: the fallback up is never parallel to back
    if (!rbl__finite3(up) || !rbl__normalizeTo(rbl__cross(up, back), &right) ||
        (rbl__len2(rbl__cross(up, back)) < 1e-12f*rbl__len2(up)))
    {
        up = rbl__fallbackUp(back);
        rbl__normalizeTo(rbl__cross(up, back), &right);
    }
    view.right = right;
    view.up = rbl__cross(back, right);
    view.back = back;
    return view;
}

// Right, up (both scaled to unit length except CAMERA_PLANE's caller up) and unit normal
static void rbl__facingBasis(const RblView *view, const RblBillboard *b, Vector3 *right, Vector3 *up, Vector3 *normal)
{
    Vector3 r = view->right, u = view->up, n = view->back;
    switch (b->facing)
    {
        case RBL_FACING_CAMERA_PLANE:
        {
            // raylib scales the caller's up as given (not normalised): keep that for parity
            if (rbl__len2(b->up) > 0.0f)
            {
                Vector3 nn;
                if (rbl__normalizeTo(rbl__cross(r, b->up), &nn)) { u = b->up; n = nn; }
            }
        } break;
        case RBL_FACING_CAMERA_POSITION:
        {
            Vector3 toEye;
            if (rbl__normalizeTo(rbl__sub(view->eye, b->position), &toEye))
            {
                n = toEye;
                Vector3 rr;
                if (rbl__normalizeTo(rbl__cross(view->up, n), &rr)) { r = rr; u = rbl__cross(n, r); }
                else { r = view->right; u = rbl__cross(n, r); rbl__normalizeTo(u, &u); r = rbl__cross(u, n); }
            }
        } break;
        case RBL_FACING_AXIS:
        {
            Vector3 a = rbl__v3(0.0f, 1.0f, 0.0f);
            if (rbl__len2(b->axis) > 0.0f) rbl__normalizeTo(b->axis, &a);
            Vector3 nn;
            if (!rbl__perpendicular(rbl__sub(view->eye, b->position), a, &nn) &&
                !rbl__perpendicular(view->back, a, &nn) &&
                !rbl__perpendicular(view->up, a, &nn)) nn = view->back;    // unreachable: up and back can't both be parallel to a
            u = a; n = nn; r = rbl__cross(u, n);
        } break;
        case RBL_FACING_FIXED:
        {
            Vector3 nn = rbl__v3(0.0f, 0.0f, 1.0f);
            if (rbl__len2(b->axis) > 0.0f) rbl__normalizeTo(b->axis, &nn);
            Vector3 uu = (rbl__len2(b->up) > 0.0f)? b->up : rbl__v3(0.0f, 1.0f, 0.0f);
            if (!rbl__perpendicular(uu, nn, &uu)) rbl__perpendicular(rbl__fallbackUp(nn), nn, &uu);
            n = nn; u = uu; r = rbl__cross(u, n);
        } break;
        default: break;
    }
    *right = r; *up = u; *normal = n;
}

bool RblBillboardVertices(const RblView *view, int textureWidth, int textureHeight, const RblBillboard *b, RblVertex out[4])
{
    if ((view == NULL) || (b == NULL) || (out == NULL)) return false;
    if ((textureWidth <= 0) || (textureHeight <= 0)) return false;
    if (!rbl__finite3(b->position) || !rbl__finite(b->size.x) || !rbl__finite(b->size.y) ||
        !rbl__finite(b->origin.x) || !rbl__finite(b->origin.y) || !rbl__finite(b->rotation) ||
        !rbl__finite(b->source.x) || !rbl__finite(b->source.y) || !rbl__finite(b->source.width) ||
        !rbl__finite(b->source.height) || !rbl__finite3(b->up) || !rbl__finite3(b->axis) ||
        !rbl__finite(b->roundness)) return false;
    if ((b->facing < RBL_FACING_CAMERA_PLANE) || (b->facing > RBL_FACING_FIXED)) return false;

    Vector3 R, U, N;
    rbl__facingBasis(view, b, &R, &U, &N);

    // Rotate the basis around the normal (raylib rotates the corners; same result, fewer ops)
    if (b->rotation != 0.0f)
    {
        float a = b->rotation*(PI/180.0f), c = cosf(a), s = sinf(a);
        Vector3 nr = rbl__cross(N, R), nu = rbl__cross(N, U);
        R = rbl__v3(R.x*c + nr.x*s, R.y*c + nr.y*s, R.z*c + nr.z*s);
        U = rbl__v3(U.x*c + nu.x*s, U.y*c + nu.y*s, U.z*c + nu.z*s);
    }

    // Footprint: |size| with the pivot measured from the bottom-left, whatever the flips. R is unit;
    // U too, except CAMERA_PLANE with a caller up, which raylib scales as given (not normalised).
    float ulen = 1.0f;
    if ((b->facing == RBL_FACING_CAMERA_PLANE) && (rbl__len2(b->up) > 0.0f))
    {
        ulen = sqrtf(rbl__len2(U));
        if (ulen > 0.0f) U = rbl__v3(U.x/ulen, U.y/ulen, U.z/ulen);
    }
    float sx = fabsf(b->size.x), sy = fabsf(b->size.y);
    float x0 = -b->origin.x, x1 = sx - b->origin.x;
    float y0 = -b->origin.y, y1 = sy*ulen - b->origin.y;
    const Vector3 P = b->position;
    Vector3 p[4];
    p[0] = rbl__v3(P.x + R.x*x0 + U.x*y0, P.y + R.y*x0 + U.y*y0, P.z + R.z*x0 + U.z*y0);
    p[1] = rbl__v3(P.x + R.x*x1 + U.x*y0, P.y + R.y*x1 + U.y*y0, P.z + R.z*x1 + U.z*y0);
    p[2] = rbl__v3(P.x + R.x*x1 + U.x*y1, P.y + R.y*x1 + U.y*y1, P.z + R.z*x1 + U.z*y1);
    p[3] = rbl__v3(P.x + R.x*x0 + U.x*y1, P.y + R.y*x0 + U.y*y1, P.z + R.z*x0 + U.z*y1);
    // Huge sizes overflowing float: skip, never write Inf (the output stays untouched)
    if (!rbl__finite3(p[0]) || !rbl__finite3(p[1]) || !rbl__finite3(p[2]) || !rbl__finite3(p[3])) return false;

    // Source frame (zero = whole texture); flips mirror inside it. As raylib's DrawTexturePro, a
    // negative extent flips and the rectangle still starts at (x, y).
    Rectangle src = b->source;
    if ((src.x == 0.0f) && (src.y == 0.0f) && (src.width == 0.0f) && (src.height == 0.0f))
    {
        src.width = (float)textureWidth; src.height = (float)textureHeight;
    }
    bool flipU = (b->size.x < 0.0f) != (src.width < 0.0f);
    bool flipV = (b->size.y < 0.0f) != (src.height < 0.0f);
    bool rotated = (b->flags & RBL_FRAME_ROTATED) != 0;
    float invW = 1.0f/(float)textureWidth, invH = 1.0f/(float)textureHeight;
    float fu0 = src.x*invW, fu1 = (src.x + fabsf(src.width))*invW;     // frame edges in texture space
    float fv0 = src.y*invH, fv1 = (src.y + fabsf(src.height))*invH;
    // Corners in sprite space (s right, t down): BL (0,1), BR (1,1), TR (1,0), TL (0,0); a mirror
    // swaps the ends of its sprite axis. A rotated frame holds the sprite turned 90 degrees
    // clockwise, sprite (s,t) at frame (1-t, s): u then runs along sprite t and v along sprite s.
    float uv[4][2];
    if (!rotated)
    {
        float sl = flipU? fu1 : fu0, sr = flipU? fu0 : fu1;      // u at sprite left / right
        float tt = flipV? fv1 : fv0, tb = flipV? fv0 : fv1;      // v at sprite top / bottom
        uv[0][0] = sl; uv[0][1] = tb; uv[1][0] = sr; uv[1][1] = tb;
        uv[2][0] = sr; uv[2][1] = tt; uv[3][0] = sl; uv[3][1] = tt;
    }
    else
    {
        float tt = flipV? fu0 : fu1, tb = flipV? fu1 : fu0;      // u at sprite top / bottom
        float sl = flipU? fv1 : fv0, sr = flipU? fv0 : fv1;      // v at sprite left / right
        uv[0][0] = tb; uv[0][1] = sl; uv[1][0] = tb; uv[1][1] = sr;
        uv[2][0] = tt; uv[2][1] = sr; uv[3][0] = tt; uv[3][1] = sl;
    }

    // Tangent (+U) and handedness. In the right-handed frame (R x U = N), +V = -U unflipped, so
    // cross(N, T)*w = +V needs w = -1; each mirror flips w, a rotated frame keeps it.
    Vector3 T;
    if (!rotated) T = flipU? rbl__neg(R) : R;
    else T = flipV? rbl__neg(U) : U;
    float w = (flipU != flipV)? 1.0f : -1.0f;

    unsigned char col[4] = { b->tint.r, b->tint.g, b->tint.b, b->tint.a };
    if ((col[0] | col[1] | col[2] | col[3]) == 0) { col[0] = col[1] = col[2] = col[3] = 255; }

    float round = b->roundness;
    if (round < 0.0f) round = 0.0f;
    if (round > 1.0f) round = 1.0f;
    bool cylinder = (b->flags & RBL_ROUND_CYLINDER) != 0;
    static const float dxs[4] = { -1.0f, 1.0f, 1.0f, -1.0f }, dys[4] = { -1.0f, -1.0f, 1.0f, 1.0f };

    for (int i = 0; i < 4; i++)
    {
        RblVertex *v = &out[i];
        v->position[0] = p[i].x; v->position[1] = p[i].y; v->position[2] = p[i].z;
        v->texcoord[0] = uv[i][0]; v->texcoord[1] = uv[i][1];
        Vector3 n = N, tg = T;
        if (round > 0.0f)
        {
            // Corner normals lean outward from the quad centre: 45 degrees for a cylinder, 54.7 for a
            // sphere at full roundness; their interpolated mean stays the flat normal, never zero.
            float dx = dxs[i]*round, dy = cylinder? 0.0f : dys[i]*round;
            rbl__normalizeTo(rbl__v3(N.x + R.x*dx + U.x*dy, N.y + R.y*dx + U.y*dy, N.z + R.z*dx + U.z*dy), &n);
            if (!rbl__perpendicular(T, n, &tg)) tg = T;
        }
        v->normal[0] = n.x; v->normal[1] = n.y; v->normal[2] = n.z;
        v->tangent[0] = tg.x; v->tangent[1] = tg.y; v->tangent[2] = tg.z; v->tangent[3] = w;
        memcpy(v->color, col, 4);
    }
    return true;
}

//----------------------------------------------------------------------------------
// Module Functions Definition: batched and immediate paths
//----------------------------------------------------------------------------------
static void rbl__loadBatchGpu(RblBatch *batch)
{
    int quads = batch->capacity;
    batch->vaoId = rlLoadVertexArray();
    rlEnableVertexArray(batch->vaoId);
    batch->vboId = rlLoadVertexBuffer(NULL, quads*4*(int)sizeof(RblVertex), true);

    int chunkQuads = (quads < RBL__QUADS_PER_CHUNK)? quads : RBL__QUADS_PER_CHUNK;
    unsigned short *indices = (unsigned short *)RBL_MALLOC((size_t)chunkQuads*6*sizeof(unsigned short));
    if (indices != NULL)
    {
        for (int q = 0; q < chunkQuads; q++)
        {
            unsigned short b = (unsigned short)(q*4);
            unsigned short *ix = indices + q*6;
            ix[0] = b; ix[1] = (unsigned short)(b + 1); ix[2] = (unsigned short)(b + 2);
            ix[3] = b; ix[4] = (unsigned short)(b + 2); ix[5] = (unsigned short)(b + 3);
        }
        batch->eboId = rlLoadVertexBufferElement(indices, chunkQuads*6*(int)sizeof(unsigned short), false);
        RBL_FREE(indices);
    }
    rlDisableVertexArray();
    batch->gpuCapacity = quads;
}

static void rbl__unloadBatchGpu(RblBatch *batch)
{
    if (batch->vaoId != 0) rlUnloadVertexArray(batch->vaoId);
    if (batch->vboId != 0) rlUnloadVertexBuffer(batch->vboId);
    if (batch->eboId != 0) rlUnloadVertexBuffer(batch->eboId);
    batch->vaoId = batch->vboId = batch->eboId = 0;
    batch->gpuCapacity = 0;
}

RblBatch RblLoadBatch(int capacity)
{
    RblBatch batch;
    memset(&batch, 0, sizeof(batch));
    if (capacity < 0) { TraceLog(LOG_WARNING, "RBL: RblLoadBatch: negative capacity %i", capacity); return batch; }
    if (capacity == 0) capacity = RBL_BATCH_DEFAULT_CAPACITY;
    batch.vertices = (RblVertex *)RBL_MALLOC((size_t)capacity*4*sizeof(RblVertex));
    batch.runCapacity = 16;
    batch.runs = (RblBatchRun *)RBL_MALLOC((size_t)batch.runCapacity*sizeof(RblBatchRun));
    if ((batch.vertices == NULL) || (batch.runs == NULL))
    {
        TraceLog(LOG_WARNING, "RBL: RblLoadBatch: out of memory for %i billboards", capacity);
        RBL_FREE(batch.vertices); RBL_FREE(batch.runs);
        memset(&batch, 0, sizeof(batch));
        return batch;
    }
    batch.capacity = capacity;
    rbl__loadBatchGpu(&batch);
    if ((batch.vaoId == 0) || (batch.vboId == 0) || (batch.eboId == 0))
    {
        TraceLog(LOG_WARNING, "RBL: RblLoadBatch: GPU buffers could not be created (no GL context?)");
        RblUnloadBatch(&batch);
    }
    return batch;
}

bool RblIsBatchValid(RblBatch batch)
{
    return (batch.vertices != NULL) && (batch.vaoId != 0) && (batch.vboId != 0) && (batch.eboId != 0);
}

void RblUnloadBatch(RblBatch *batch)
{
    if (batch == NULL) return;
    rbl__unloadBatchGpu(batch);
    RBL_FREE(batch->vertices);
    RBL_FREE(batch->runs);
    memset(batch, 0, sizeof(*batch));
}

void RblBeginBatch(RblBatch *batch, Camera3D camera)
{
    if (batch == NULL) return;
    batch->view = RblGetView(camera);
    batch->count = 0;
    batch->runCount = 0;
    batch->skipped = 0;
    batch->begun = true;
}

static bool rbl__sameMaterial(const Material *a, const Material *b)
{
    if ((a->shader.id != b->shader.id) || (a->maps != b->maps)) return false;
    if (a->maps == NULL) return true;
    return (a->maps[MATERIAL_MAP_ALBEDO].texture.id == b->maps[MATERIAL_MAP_ALBEDO].texture.id) &&
           (a->maps[MATERIAL_MAP_METALNESS].texture.id == b->maps[MATERIAL_MAP_METALNESS].texture.id) &&
           (a->maps[MATERIAL_MAP_NORMAL].texture.id == b->maps[MATERIAL_MAP_NORMAL].texture.id) &&
           (memcmp(&a->maps[MATERIAL_MAP_ALBEDO].color, &b->maps[MATERIAL_MAP_ALBEDO].color, sizeof(Color)) == 0);
}

// Grow CPU storage by doubling; the GPU buffer follows at the next RblEndBatch()
static bool rbl__growBatch(RblBatch *batch)
{
    int newCapacity = (batch->capacity > 0)? batch->capacity*2 : RBL_BATCH_DEFAULT_CAPACITY;
    RblVertex *vertices = (RblVertex *)RBL_REALLOC(batch->vertices, (size_t)newCapacity*4*sizeof(RblVertex));
    if (vertices == NULL) { TraceLog(LOG_WARNING, "RBL: batch: out of memory growing to %i billboards", newCapacity); return false; }
    TraceLog(LOG_INFO, "RBL: batch grown from %i to %i billboards (reserve more in RblLoadBatch)", batch->capacity, newCapacity);
    batch->vertices = vertices;
    batch->capacity = newCapacity;
    return true;
}

bool RblBatchAdd(RblBatch *batch, Material material, const RblBillboard *billboard)
{
    if ((batch == NULL) || !batch->begun || (batch->vertices == NULL)) return false;
    if ((batch->count == batch->capacity) && !rbl__growBatch(batch)) return false;

    // An albedo slot without a texture draws raylib's 1x1 default texture
    int texW = 1, texH = 1;
    if ((material.maps != NULL) && (material.maps[MATERIAL_MAP_ALBEDO].texture.id != 0))
    {
        texW = material.maps[MATERIAL_MAP_ALBEDO].texture.width;
        texH = material.maps[MATERIAL_MAP_ALBEDO].texture.height;
    }
    if (!RblBillboardVertices(&batch->view, texW, texH, billboard, batch->vertices + (size_t)batch->count*4))
    {
        if (batch->skipped++ == 0) TraceLog(LOG_WARNING, "RBL: batch: billboard skipped (NaN/Inf input, bad facing or texture size %ix%i); further skips this batch are not logged", texW, texH);
        return false;
    }

    RblBatchRun *run = (batch->runCount > 0)? &batch->runs[batch->runCount - 1] : NULL;
    if ((run == NULL) || !rbl__sameMaterial(&run->material, &material))
    {
        if (batch->runCount == batch->runCapacity)
        {
            RblBatchRun *runs = (RblBatchRun *)RBL_REALLOC(batch->runs, (size_t)batch->runCapacity*2*sizeof(RblBatchRun));
            if (runs == NULL) { TraceLog(LOG_WARNING, "RBL: batch: out of memory for material runs"); return false; }
            batch->runs = runs;
            batch->runCapacity *= 2;
        }
        run = &batch->runs[batch->runCount++];
        run->material = material;
        run->first = batch->count;
        run->count = 0;
    }
    run->count++;
    batch->count++;
    return true;
}

// Bind the material the way raylib's DrawMesh does (same uniform names and texture slots)
static void rbl__bindMaterial(const Material *material)
{
    Shader sh = material->shader;
    rlEnableShader(sh.id);
    Matrix view = rlGetMatrixModelview(), proj = rlGetMatrixProjection();
    // Billboard vertices are already in world space: model = identity (the seed applied it twice)
    if (sh.locs[SHADER_LOC_MATRIX_MVP] != -1) rlSetUniformMatrix(sh.locs[SHADER_LOC_MATRIX_MVP], rbl__matMul(view, proj));
    if (sh.locs[SHADER_LOC_MATRIX_MODEL] != -1) rlSetUniformMatrix(sh.locs[SHADER_LOC_MATRIX_MODEL], rbl__identity());
    if (sh.locs[SHADER_LOC_MATRIX_NORMAL] != -1) rlSetUniformMatrix(sh.locs[SHADER_LOC_MATRIX_NORMAL], rbl__identity());
    if (sh.locs[SHADER_LOC_MATRIX_VIEW] != -1) rlSetUniformMatrix(sh.locs[SHADER_LOC_MATRIX_VIEW], view);
    if (sh.locs[SHADER_LOC_MATRIX_PROJECTION] != -1) rlSetUniformMatrix(sh.locs[SHADER_LOC_MATRIX_PROJECTION], proj);
    if (material->maps == NULL)
    {
        rlActiveTextureSlot(0); rlEnableTexture(rlGetTextureIdDefault());
        return;
    }
    if (sh.locs[SHADER_LOC_COLOR_DIFFUSE] != -1)
    {
        Color c = material->maps[MATERIAL_MAP_ALBEDO].color;
        float v[4] = { c.r/255.0f, c.g/255.0f, c.b/255.0f, c.a/255.0f };
        rlSetUniform(sh.locs[SHADER_LOC_COLOR_DIFFUSE], v, SHADER_UNIFORM_VEC4, 1);
    }
    // Slots 0..2 (albedo, metalness/specular, normal): only maps the shader samples are bound
    for (int i = MATERIAL_MAP_ALBEDO; i <= MATERIAL_MAP_NORMAL; i++)
    {
        int loc = sh.locs[SHADER_LOC_MAP_DIFFUSE + i];
        unsigned int id = material->maps[i].texture.id;
        if ((i == MATERIAL_MAP_ALBEDO) && (id == 0)) id = rlGetTextureIdDefault();
        if ((id == 0) || (loc == -1)) continue;
        rlActiveTextureSlot(i);
        rlEnableTexture(id);
        rlSetUniform(loc, &i, SHADER_UNIFORM_INT, 1);
    }
}

static void rbl__unbindMaterial(void)
{
    for (int i = MATERIAL_MAP_NORMAL; i >= MATERIAL_MAP_ALBEDO; i--) { rlActiveTextureSlot(i); rlDisableTexture(); }
    rlDisableShader();
}

static void rbl__setVertexLayout(size_t baseOffset)
{
    const int stride = (int)sizeof(RblVertex);
    rlSetVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_POSITION, 3, RL_FLOAT, false, stride, (int)(baseOffset + offsetof(RblVertex, position)));
    rlSetVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_TEXCOORD, 2, RL_FLOAT, false, stride, (int)(baseOffset + offsetof(RblVertex, texcoord)));
    rlSetVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_NORMAL, 3, RL_FLOAT, false, stride, (int)(baseOffset + offsetof(RblVertex, normal)));
    rlSetVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_TANGENT, 4, RL_FLOAT, false, stride, (int)(baseOffset + offsetof(RblVertex, tangent)));
    rlSetVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_COLOR, 4, RL_UNSIGNED_BYTE, true, stride, (int)(baseOffset + offsetof(RblVertex, color)));
    rlEnableVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_POSITION);
    rlEnableVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_TEXCOORD);
    rlEnableVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_NORMAL);
    rlEnableVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_TANGENT);
    rlEnableVertexAttribute(RL_DEFAULT_SHADER_ATTRIB_LOCATION_COLOR);
}

void RblEndBatch(RblBatch *batch)
{
    if ((batch == NULL) || !batch->begun) return;
    batch->begun = false;
    if (batch->count == 0) return;
    if (batch->capacity > batch->gpuCapacity)
    {
        rbl__unloadBatchGpu(batch);
        rbl__loadBatchGpu(batch);
    }
    if (batch->vboId == 0) return;

    rlDrawRenderBatchActive();      // keep draw order with raylib's own pending geometry
    rlEnableVertexArray(batch->vaoId);
    rlUpdateVertexBuffer(batch->vboId, batch->vertices, batch->count*4*(int)sizeof(RblVertex), 0);
    rlEnableVertexBufferElement(batch->eboId);
    for (int r = 0; r < batch->runCount; r++)
    {
        const RblBatchRun *run = &batch->runs[r];
        rbl__bindMaterial(&run->material);
        for (int q = 0; q < run->count; q += RBL__QUADS_PER_CHUNK)
        {
            int n = run->count - q;
            if (n > RBL__QUADS_PER_CHUNK) n = RBL__QUADS_PER_CHUNK;
            rbl__setVertexLayout((size_t)(run->first + q)*4*sizeof(RblVertex));
            rlDrawVertexArrayElements(0, n*6, 0);
        }
    }
    rbl__unbindMaterial();
    rlDisableVertexArray();
}

static RblBatch rbl__immediate;     // zero-initialised; the immediate path's one-quad batch

void RblDrawBillboard(Camera3D camera, Material material, RblBillboard billboard)
{
    if (rbl__immediate.vertices == NULL)
    {
        rbl__immediate = RblLoadBatch(1);     // created on first use, released by RblClose()
        if (!RblIsBatchValid(rbl__immediate)) return;
    }
    RblBeginBatch(&rbl__immediate, camera);
    RblBatchAdd(&rbl__immediate, material, &billboard);
    RblEndBatch(&rbl__immediate);
}

void RblClose(void)
{
    RblUnloadBatch(&rbl__immediate);
}

//----------------------------------------------------------------------------------
// Module Functions Definition: instanced path
//----------------------------------------------------------------------------------
// Instance attribute locations: above raylib's defaults (0..9), declared in lit_instanced.vs.glsl
#define RBL__INSTANCE_LOCATION 10
// Coordinates beyond this could overflow float once the GPU combines them: rejected like NaN
#define RBL__INSTANCE_MAX_COORD 1e36f

enum { RBL__LOC_EYE = 0, RBL__LOC_RIGHT, RBL__LOC_UP, RBL__LOC_BACK, RBL__LOC_FACING, RBL__LOC_FACING_UP,
       RBL__LOC_FACING_AXIS, RBL__LOC_ROUNDNESS, RBL__LOC_TEXTURE_SIZE, RBL__LOC_COUNT };

static void rbl__loadInstanceGpu(RblInstanceBuffer *buffer)
{
    const int stride = (int)sizeof(RblInstance);
    buffer->vaoId = rlLoadVertexArray();
    rlEnableVertexArray(buffer->vaoId);
    buffer->vboId = rlLoadVertexBuffer(NULL, buffer->capacity*stride, true);
    const unsigned int loc = RBL__INSTANCE_LOCATION;
    rlSetVertexAttribute(loc + 0, 4, RL_FLOAT, false, stride, (int)offsetof(RblInstance, position));
    rlSetVertexAttribute(loc + 1, 4, RL_FLOAT, false, stride, (int)offsetof(RblInstance, size));
    rlSetVertexAttribute(loc + 2, 4, RL_FLOAT, false, stride, (int)offsetof(RblInstance, source));
    rlSetVertexAttribute(loc + 3, 4, RL_UNSIGNED_BYTE, true, stride, (int)offsetof(RblInstance, tint));
    rlSetVertexAttribute(loc + 4, 1, 0x1405 /* GL_UNSIGNED_INT, converted to float */, false, stride, (int)offsetof(RblInstance, flags));
    for (unsigned int i = 0; i < 5; i++) { rlEnableVertexAttribute(loc + i); rlSetVertexAttributeDivisor(loc + i, 1); }
    rlDisableVertexArray();
}

RblInstanceBuffer RblLoadInstanceBuffer(int capacity)
{
    RblInstanceBuffer buffer;
    memset(&buffer, 0, sizeof(buffer));
    if (capacity < 0) { TraceLog(LOG_WARNING, "RBL: RblLoadInstanceBuffer: negative capacity %i", capacity); return buffer; }
    if (capacity == 0) capacity = RBL_BATCH_DEFAULT_CAPACITY;
    buffer.staging = (RblInstance *)RBL_MALLOC((size_t)capacity*sizeof(RblInstance));
    if (buffer.staging == NULL) { TraceLog(LOG_WARNING, "RBL: RblLoadInstanceBuffer: out of memory for %i instances", capacity); return buffer; }
    buffer.capacity = capacity;
    rbl__loadInstanceGpu(&buffer);
    if ((buffer.vaoId == 0) || (buffer.vboId == 0))
    {
        TraceLog(LOG_WARNING, "RBL: RblLoadInstanceBuffer: GPU buffers could not be created (no GL context?)");
        RblUnloadInstanceBuffer(&buffer);
    }
    return buffer;
}

bool RblIsInstanceBufferValid(RblInstanceBuffer buffer)
{
    return (buffer.staging != NULL) && (buffer.vaoId != 0) && (buffer.vboId != 0);
}

void RblUnloadInstanceBuffer(RblInstanceBuffer *buffer)
{
    if (buffer == NULL) return;
    if (buffer->vaoId != 0) rlUnloadVertexArray(buffer->vaoId);
    if (buffer->vboId != 0) rlUnloadVertexBuffer(buffer->vboId);
    RBL_FREE(buffer->staging);
    memset(buffer, 0, sizeof(*buffer));
}

static bool rbl__instanceOk(const RblInstance *in)
{
    // One bound test per float rejects NaN, Inf and magnitudes that could overflow on the GPU
    const float *f = &in->position.x;
    for (int i = 0; i < 12; i++) if (!(fabsf(f[i]) <= RBL__INSTANCE_MAX_COORD)) return false;
    return true;
}

int RblDrawInstanced(RblInstanceBuffer *buffer, Camera3D camera, Material material, RblInstancedDesc desc, const RblInstance *instances, int count)
{
    if ((buffer == NULL) || !RblIsInstanceBufferValid(*buffer)) { TraceLog(LOG_WARNING, "RBL: RblDrawInstanced: invalid instance buffer"); return 0; }
    if ((count < 0) || ((count > 0) && (instances == NULL))) { TraceLog(LOG_WARNING, "RBL: RblDrawInstanced: bad instance array (%i)", count); return 0; }
    if ((desc.facing < RBL_FACING_CAMERA_PLANE) || (desc.facing > RBL_FACING_FIXED) || !rbl__finite3(desc.up) ||
        !rbl__finite3(desc.axis) || !rbl__finite(desc.roundness))
    {
        TraceLog(LOG_WARNING, "RBL: RblDrawInstanced: bad RblInstancedDesc (facing %i or NaN/Inf vectors)", desc.facing);
        return 0;
    }
    if (count > buffer->capacity)
    {
        int newCapacity = buffer->capacity;
        while (newCapacity < count) newCapacity *= 2;
        RblInstance *staging = (RblInstance *)RBL_REALLOC(buffer->staging, (size_t)newCapacity*sizeof(RblInstance));
        if (staging == NULL) { TraceLog(LOG_WARNING, "RBL: RblDrawInstanced: out of memory for %i instances", newCapacity); return 0; }
        TraceLog(LOG_INFO, "RBL: instance buffer grown from %i to %i (reserve more in RblLoadInstanceBuffer)", buffer->capacity, newCapacity);
        buffer->staging = staging;
        buffer->capacity = newCapacity;
        rlUnloadVertexArray(buffer->vaoId);
        rlUnloadVertexBuffer(buffer->vboId);
        rbl__loadInstanceGpu(buffer);
    }

    // The small per-instance copy: validate while copying, so no NaN reaches the GPU buffer
    int n = 0;
    buffer->skipped = 0;
    for (int i = 0; i < count; i++)
    {
        if (rbl__instanceOk(&instances[i])) buffer->staging[n++] = instances[i];
        else buffer->skipped++;
    }
    if (buffer->skipped > 0) TraceLog(LOG_WARNING, "RBL: RblDrawInstanced: %i instance(s) skipped (NaN/Inf or |value| > 1e36)", buffer->skipped);
    if (n == 0) return 0;

    Shader sh = material.shader;
    if (sh.id != buffer->shaderId)
    {
        static const char *names[RBL__LOC_COUNT] = { "rblViewEye", "rblViewRight", "rblViewUp", "rblViewBack", "rblFacing",
                                                     "rblFacingUp", "rblFacingAxis", "rblRoundness", "rblTextureSize" };
        for (int i = 0; i < RBL__LOC_COUNT; i++) buffer->locs[i] = rlGetLocationUniform(sh.id, names[i]);
        buffer->shaderId = sh.id;
    }
    if (buffer->locs[RBL__LOC_RIGHT] == -1)
    {
        TraceLog(LOG_WARNING, "RBL: RblDrawInstanced: material shader %u is not an instanced lit variant (RblLitShaderDesc.instanced)", sh.id);
        return 0;
    }

    int texW = 1, texH = 1;
    if ((material.maps != NULL) && (material.maps[MATERIAL_MAP_ALBEDO].texture.id != 0))
    {
        texW = material.maps[MATERIAL_MAP_ALBEDO].texture.width;
        texH = material.maps[MATERIAL_MAP_ALBEDO].texture.height;
    }
    if ((texW <= 0) || (texH <= 0)) { TraceLog(LOG_WARNING, "RBL: RblDrawInstanced: albedo texture size %ix%i", texW, texH); return 0; }

    RblView view = RblGetView(camera);
    rlDrawRenderBatchActive();
    rbl__bindMaterial(&material);
    float texSize[2] = { (float)texW, (float)texH };
    rlSetUniform(buffer->locs[RBL__LOC_EYE], &view.eye, SHADER_UNIFORM_VEC3, 1);
    rlSetUniform(buffer->locs[RBL__LOC_RIGHT], &view.right, SHADER_UNIFORM_VEC3, 1);
    rlSetUniform(buffer->locs[RBL__LOC_UP], &view.up, SHADER_UNIFORM_VEC3, 1);
    rlSetUniform(buffer->locs[RBL__LOC_BACK], &view.back, SHADER_UNIFORM_VEC3, 1);
    rlSetUniform(buffer->locs[RBL__LOC_FACING], &desc.facing, SHADER_UNIFORM_INT, 1);
    rlSetUniform(buffer->locs[RBL__LOC_FACING_UP], &desc.up, SHADER_UNIFORM_VEC3, 1);
    rlSetUniform(buffer->locs[RBL__LOC_FACING_AXIS], &desc.axis, SHADER_UNIFORM_VEC3, 1);
    rlSetUniform(buffer->locs[RBL__LOC_ROUNDNESS], &desc.roundness, SHADER_UNIFORM_FLOAT, 1);
    rlSetUniform(buffer->locs[RBL__LOC_TEXTURE_SIZE], texSize, SHADER_UNIFORM_VEC2, 1);

    rlEnableVertexArray(buffer->vaoId);
    rlUpdateVertexBuffer(buffer->vboId, buffer->staging, n*(int)sizeof(RblInstance), 0);
    rlDrawVertexArrayInstanced(0, 6, n);
    rlDisableVertexArray();
    rbl__unbindMaterial();
    return n;
}

//----------------------------------------------------------------------------------
// Module Functions Definition: lights and the forward lit shader
//----------------------------------------------------------------------------------
// prefix + lines joined into one allocated string (the embedded sources are arrays of lines)
static char *rbl__joinSource(const char *prefix, const char *const *lines)
{
    size_t len = strlen(prefix);
    for (int i = 0; lines[i] != NULL; i++) len += strlen(lines[i]);
    char *text = (char *)RBL_MALLOC(len + 1);
    if (text == NULL) return NULL;
    size_t at = strlen(prefix);
    memcpy(text, prefix, at);
    for (int i = 0; lines[i] != NULL; i++) { size_t l = strlen(lines[i]); memcpy(text + at, lines[i], l); at += l; }
    text[at] = '\0';
    return text;
}

// Compile a variant: "#version 330", the variant's defines, then the embedded source.
// raylib substitutes its default shader when compilation fails; report that as a failure.
static Shader rbl__loadShaderVariant(const char *const *vs, const char *const *fs, const char *defines)
{
    char prefix[512];
    snprintf(prefix, sizeof(prefix), "#version 330\n%s", defines);
    char *vsFull = rbl__joinSource(prefix, vs);
    char *fsFull = rbl__joinSource(prefix, fs);
    Shader shader;
    memset(&shader, 0, sizeof(shader));
    if ((vsFull != NULL) && (fsFull != NULL)) shader = LoadShaderFromMemory(vsFull, fsFull);
    RBL_FREE(vsFull); RBL_FREE(fsFull);
    if ((shader.id == 0) || (shader.id == rlGetShaderIdDefault()))
    {
        TraceLog(LOG_WARNING, "RBL: shader variant failed to compile/link (defines: %s)", defines);
        if ((shader.id != 0) && (shader.locs != NULL) && (shader.locs != rlGetShaderLocsDefault())) MemFree(shader.locs);
        memset(&shader, 0, sizeof(shader));
    }
    return shader;
}

RblLitShader RblLoadLitShader(RblLitShaderDesc desc)
{
    RblLitShader lit;
    memset(&lit, 0, sizeof(lit));
    int maxLights = (desc.maxLights == 0)? 1 : desc.maxLights;
    if ((maxLights < 0) || (maxLights > RBL_MAX_LIGHTS))
    {
        TraceLog(LOG_WARNING, "RBL: RblLoadLitShader: maxLights %i outside 0..%i (raise RBL_MAX_LIGHTS)", desc.maxLights, RBL_MAX_LIGHTS);
        return lit;
    }
    if (!rbl__finite(desc.alphaCutoff))
    {
        TraceLog(LOG_WARNING, "RBL: RblLoadLitShader: alphaCutoff is not finite");
        return lit;
    }
    char defines[128];
    snprintf(defines, sizeof(defines), "#define RBL_LIGHTS %i\n%s", maxLights, desc.normalMap? "#define RBL_NORMAL_MAP\n" : "");
    lit.shader = rbl__loadShaderVariant(desc.instanced? rbl__shader_lit_instanced_vs : rbl__shader_lit_vs, rbl__shader_lit_fs, defines);
    if (lit.shader.id == 0) return lit;

    lit.maxLights = maxLights;
    lit.normalMap = desc.normalMap;
    lit.instanced = desc.instanced;
    lit.shader.locs[SHADER_LOC_VECTOR_VIEW] = GetShaderLocation(lit.shader, "viewPos");
    lit.shader.locs[SHADER_LOC_MAP_NORMAL] = desc.normalMap? GetShaderLocation(lit.shader, "texture2") : -1;
    lit.locLightCount = GetShaderLocation(lit.shader, "rblLightCount");
    lit.locLightPosition = GetShaderLocation(lit.shader, "rblLightPosition");
    lit.locLightColor = GetShaderLocation(lit.shader, "rblLightColor");
    lit.locLightInvRange = GetShaderLocation(lit.shader, "rblLightInvRange");
    lit.locAmbient = GetShaderLocation(lit.shader, "rblAmbient");
    lit.locAlphaCutoff = GetShaderLocation(lit.shader, "rblAlphaCutoff");

    float cutoff = (desc.alphaCutoff == 0.0f)? 0.5f : desc.alphaCutoff;
    SetShaderValue(lit.shader, lit.locAlphaCutoff, &cutoff, SHADER_UNIFORM_FLOAT);
    int zero = 0;
    SetShaderValue(lit.shader, lit.locLightCount, &zero, SHADER_UNIFORM_INT);
    return lit;
}

bool RblIsLitShaderValid(RblLitShader shader)
{
    return (shader.shader.id != 0) && (shader.shader.id != rlGetShaderIdDefault());
}

void RblUnloadLitShader(RblLitShader shader)
{
    if (RblIsLitShaderValid(shader)) UnloadShader(shader.shader);
}

bool RblSetLights(RblLitShader *shader, const RblLight *lights, int count, Color ambient)
{
    if ((shader == NULL) || !RblIsLitShaderValid(*shader)) { TraceLog(LOG_WARNING, "RBL: RblSetLights: invalid shader"); return false; }
    if ((count < 0) || (count > shader->maxLights) || ((count > 0) && (lights == NULL)))
    {
        TraceLog(LOG_WARNING, "RBL: RblSetLights: %i lights for a shader compiled with %i slots", count, shader->maxLights);
        return false;
    }
    float pos[RBL_MAX_LIGHTS*3], col[RBL_MAX_LIGHTS*3], invRange[RBL_MAX_LIGHTS];
    for (int i = 0; i < count; i++)
    {
        const RblLight *l = &lights[i];
        if (!rbl__finite3(l->position) || !rbl__finite(l->intensity) || !rbl__finite(l->range) ||
            (l->intensity < 0.0f) || (l->range < 0.0f))
        {
            TraceLog(LOG_WARNING, "RBL: RblSetLights: light %i rejected (NaN/Inf position, or negative/non-finite intensity or range)", i);
            return false;
        }
        pos[i*3 + 0] = l->position.x; pos[i*3 + 1] = l->position.y; pos[i*3 + 2] = l->position.z;
        col[i*3 + 0] = l->color.r/255.0f*l->intensity;
        col[i*3 + 1] = l->color.g/255.0f*l->intensity;
        col[i*3 + 2] = l->color.b/255.0f*l->intensity;
        invRange[i] = (l->range > 0.0f)? 1.0f/l->range : 0.0f;
        if (!rbl__finite(col[i*3]) || !rbl__finite(col[i*3 + 1]) || !rbl__finite(col[i*3 + 2]) || !rbl__finite(invRange[i]))
        {
            TraceLog(LOG_WARNING, "RBL: RblSetLights: light %i overflows float (intensity %g, range %g)", i, l->intensity, l->range);
            return false;
        }
    }
    float amb[3] = { ambient.r/255.0f, ambient.g/255.0f, ambient.b/255.0f };
    SetShaderValue(shader->shader, shader->locAmbient, amb, SHADER_UNIFORM_VEC3);
    SetShaderValue(shader->shader, shader->locLightCount, &count, SHADER_UNIFORM_INT);
    if (count > 0)
    {
        SetShaderValueV(shader->shader, shader->locLightPosition, pos, SHADER_UNIFORM_VEC3, count);
        SetShaderValueV(shader->shader, shader->locLightColor, col, SHADER_UNIFORM_VEC3, count);
        SetShaderValueV(shader->shader, shader->locLightInvRange, invRange, SHADER_UNIFORM_FLOAT, count);
    }
    return true;
}

#endif // RBILLBOARD_LIT_IMPLEMENTATION
