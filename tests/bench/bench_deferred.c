// Benchmark suite "deferred": memory and frame cost of the deferred helper (GPU, headless GL).
//   G-buffer     bytes per pixel of the colour targets as allocated (RblGBufferBytesPerPixel, and each
//                target's raylib format through GetPixelDataSize), cross-checked against the bits the
//                GL reports for the textures it actually allocated (glGetTexLevelParameteriv); depth and
//                the RGBA16F accumulation target listed separately. Next to two constants (not measured
//                here): the seed pipeline's 28 bytes per pixel (as its source allocated it; that source
//                is not part of this repository, the figure is the one the project states) and raylib's
//                own deferred example (examples/shaders/shaders_deferred_rendering.c: position and
//                normal RL_PIXELFORMAT_UNCOMPRESSED_R16G16B16 = 6 + 6 bytes, albedo+specular R8G8B8A8 = 4
//                bytes; 16 bytes, depth in a renderbuffer).
//   frame cost   ms per frame at 1280x720 of a floor filling the screen (one fixed-facing RblBillboard,
//                normal +Y, seen from above at ~40 degrees) lit by 1, 16, 256 and 1024 small point
//                lights (range 0.3-0.8 world units, windowed falloff, scattered uniformly over the
//                visible floor with a fixed seed), BRDF BENCH_BRDF, through three pipelines:
//                  forward   a lit program (RblLoadLitShader) with maxLights = min(n, RBL_MAX_LIGHTS); above
//                            RBL_MAX_LIGHTS the floor is drawn again per chunk of 64 lights, each chunk set as
//                            the scene (RblSetScene): the first pass with the ambient, later passes with
//                            ambient BLACK, additive blending (ONE, ONE, ADD) and the
//                            depth test left on: raylib's default depth function is GL_LEQUAL (rlglInit),
//                            so identical geometry drawn by the same program passes it again. The forward
//                            shader writes sRGB-encoded colour, so adding passes is not physically the
//                            same as one pass over every light: only the timing of those rows matters.
//                  volumes   RblLoadGBuffer + RblSetScene (the n lights) + geometry pass (desc.deferred
//                            material; it adds the ambient) + RblDrawDeferredLights (bounded lights as instanced sphere volumes) +
//                            RblResolveGBuffer into the 1280x720 RenderTexture.
//                  naive     the same with g.naiveFullscreen = true: every light at every pixel, in
//                            full-screen passes of RBL_MAX_LIGHTS.
//                The raylib baseline is timed in the same run: the floor as a GenMeshPlane Mesh drawn by
//                DrawMesh with raylib's default material (unlit). One timed run draws every case once,
//                each right after a baseline frame (bench_lighting's scheme: a slow phase of a noisy
//                machine hits all cases alike); ratios (to the baseline, and volumes against naive)
//                are medians of per-run ratios. Each frame: glFinish, draw, glFinish.
//                Checked once, untimed: every case writes every pixel; volumes and naive agree within
//                1/255 (max channel difference over covered pixels) at every light count; forward and
//                deferred agree at 16 lights (one forward pass, so the same light sum).
//   G-buffer     ms per frame at 1280x720 of the same floor through each BRDF's G-buffer (the codec's
//   per BRDF     cost: packing in the geometry pass, unpacking in the light passes): the geometry pass
//                alone (RblBeginGBuffer, the floor, RblEndGBuffer) and the whole frame at 16 of the
//                lights (geometry, RblDrawDeferredLights, RblResolveGBuffer); each case right after a
//                baseline frame, ratios to the run's median baseline, medians over runs.
//   reference    (GPU, untimed) the deferred image against the double-precision reference
//                (tests/lighting_reference.h) in the views of the GPU test
//                test_deferred_every_brdf_matches_the_double_reference_on_8_bit_and_float_targets: a
//                tilted plane and a sphere Model (its interpolated vertex normals), perspective and
//                orthographic, a point light near the surface and a directional light, 96x96; resolved
//                into RGBA8 and into RGBA16F / RGBA32F with the display encoding and with linear output.
//                Per group (Lambert; Blinn-Phong n 2..1024 at intensities 0.03..1.5; GGX roughness
//                0.02..1 metal and dielectric; GGX metalness between codes) the worst max and mean in
//                1/255: 8-bit against the reference rounded, float against the reference itself,
//                linear values above 1 relative to the value. A previous commit's binary prints the
//                same rows for its codec (run both, alternating, for the before/after).
//   encoding     (CPU, double; no GL) what the G-buffer's quantisation alone does to the image, 0.3's
//                codec, the previous one (Blinn-Phong: normal 36 bits, shininess 11, intensity 9) and
//                this one (Blinn-Phong: normal 32, shininess 12, intensity 12): the double-precision
//                reference (tests/lighting_reference.h) shades every pixel of the GPU sweep test's two
//                scenes (test_deferred.c: an axis-aligned plane seen obliquely, a sphere of radius 1.2
//                filling a 128x128 frame; a point and a directional light, sRGB, no tonemap) once with
//                the exact surface and once with the surface each codec stores (normal, roughness,
//                metalness, shininess, intensity decoded as the shaders do); max and mean channel
//                difference in 1/255 before 8-bit rounding, and per group the worst of the previous
//                codec and this one also rounded to 8 bits and as linear output (relative above 1).
//                Normal codes over 400000 uniform sphere normals (degrees), and the first-order worst
//                case of a highlight's flank: 255 sRGB'(1) (2/alpha) x the code's worst normal error
//                (Blinn-Phong as the GGX alpha of its lobe, n = 2/alpha^2 - 2).
// Rows (suite "deferred"):
//   gbuffer: bytes_per_pixel (RblGBufferBytesPerPixel), gl_bytes_per_pixel (GL-reported bits / 8)
//   gbuffer_albedo|gbuffer_normal|gbuffer_params|gbuffer_depth|gbuffer_accum: bytes_per_pixel
//   seed_pipeline|raylib_deferred_example: bytes_per_pixel (constants, see above)
//   raylib_default_material: ms_per_frame_1280x720, spread_pct, runs
//   <forward|deferred_volumes|deferred_naive>_<n>lights: ms_per_frame_1280x720, ratio_to_raylib
//   forward_<n>lights: passes
//   deferred_volumes_<n>lights: speedup_vs_naive (median of per-run naive/volumes), speedup_vs_forward
//   deferred_vs_forward: crossover_lights (smallest tested n where volumes beat forward; 0 = none)
//   check_volumes_vs_naive_<n>lights, check_forward_vs_deferred_16lights: max_diff (1/255), pixels
//   normal_<old_12x12_rounded|30bit_nearest|32bit_nearest|36bit_nearest>: mean_deg, max_deg
//   geometry_pass_<lambert|blinn_phong|ggx>, deferred_frame_<brdf>_16lights: ms_per_frame_1280x720, ratio_to_raylib
//   reference_<lambert|blinn_phong|ggx|ggx_metal_between>_<rgba8|rgba16f|rgba32f|rgba16f_linear|rgba32f_linear>: max, mean (1/255)
//   encoding_<brdf>_<parameters>_<plane|sphere>: old_max, old_mean, prev_max, prev_mean, new_max, new_mean (1/255)
//   encoding_<lambert|blinn_phong|ggx|ggx_metal_between>_<float|8bit|linear>: prev_max, prev_mean, new_max, new_mean (1/255)
//   flank_bound_ggx_r<roughness>: old, 30bit, 32bit, new; flank_bound_blinn_phong_n<n>: prev, new (1/255,
//                first-order worst case of the normal code)
// Output: rows appended to $BENCH_CSV (see bench.h) and a summary table on stdout.
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "rlgl.h"
#include "raymath.h"
#include "harness.h"
#include "bench.h"
#include "bench_floor.h"
#include "lighting_reference.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

//----------------------------------------------------------------------------------
// Defines and Macros
//----------------------------------------------------------------------------------
#define SUITE               "deferred"
#define FRAME_W             1280
#define FRAME_H             720
#define COUNTS              4
#define MAX_N               1024
#define PIPES               3
#define CASES               (PIPES*COUNTS)     // pipe-major: [pipe*COUNTS + light count index]
#define FLOOR_SIZE          60.0f               // floor centred under the camera target
#define BENCH_BRDF          RBL_BRDF_LAMBERT    // the header's default BRDF (its cheapest: the least
                                                // favourable case for deferred against forward)
#define SEED_BYTES          28                  // seed pipeline's G-buffer (constant, see the top)
#define RAYLIB_EXAMPLE_BYTES 16                 // raylib's deferred example (constant, see the top)

// GL enums for the format cross-check (GL 3.3 core)
#define GL_TEXTURE_2D_             0x0DE1
#define GL_TEXTURE_RED_SIZE_       0x805C
#define GL_TEXTURE_GREEN_SIZE_     0x805D
#define GL_TEXTURE_BLUE_SIZE_      0x805E
#define GL_TEXTURE_ALPHA_SIZE_     0x805F
#define GL_TEXTURE_DEPTH_SIZE_     0x884A

//----------------------------------------------------------------------------------
// Types and Structures Definition
//----------------------------------------------------------------------------------
typedef enum { PIPE_FORWARD = 0, PIPE_VOLUMES, PIPE_NAIVE } Pipe;
static const char *pipeName[PIPES] = { "forward", "deferred_volumes", "deferred_naive" };

typedef struct Scene {
    RenderTexture2D target;
    Camera3D camera;
    RblBillboard floor;             // fixed facing, normal +Y
    Mesh plane;                     // the same floor for raylib's baseline
    Matrix planeTransform;
    Material rayMat;                // raylib's default material + albedo
    Texture2D albedo;
    Shader fwd[COUNTS];             // forward: maxLights = min(n, RBL_MAX_LIGHTS)
    int fwdSlots[COUNTS];           // ... its maxLights
    Material fwdMat[COUNTS];
    Shader geo;                     // deferred geometry variant
    Material geoMat;
    RblGBuffer g;
    RblLight lights[MAX_N];
    int counts[COUNTS];
    Color ambient;
    bool ok[CASES];                 // case drew without an API refusal
    bool frameOk;                   // last frame's API calls all succeeded
    double baseMin, baseMax;        // spread of the per-run baselines
} Scene;

#define VALUES (2*CASES + COUNTS + 1)   // ms, ratios, naive/volumes speed-ups, baseline (<= BENCH_MAX_VALUES)

//----------------------------------------------------------------------------------
// Frames
//----------------------------------------------------------------------------------
static const Matrix identity = { 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f };

// The frame's scene: count lights from first, a flat ambient, nothing else (no fog, exposure 1, no shadows)
static bool SetLights(const RblLight *first, int count, Color ambient)
{
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = first;
    scene.lightCount = count;
    scene.ambient = ambient;
    return RblSetScene(&scene);
}

static void DrawBaseline(Scene *s)
{
    BeginTextureMode(s->target);
    ClearBackground(BLANK);                 // alpha 0: coverage check
    BeginMode3D(s->camera);
    DrawMesh(s->plane, s->rayMat, s->planeTransform);
    EndMode3D();
    EndTextureMode();
}

// Forward: one pass per RBL_MAX_LIGHTS lights; passes after the first add (see the top)
static int DrawForward(Scene *s, int c)
{
    int n = s->counts[c], slots = s->fwdSlots[c], passes = 0;
    s->frameOk = true;
    BeginTextureMode(s->target);
    ClearBackground(BLANK);
    BeginMode3D(s->camera);
    for (int first = 0; first < n; first += slots, passes++)
    {
        int k = (n - first < slots)? n - first : slots;
        if (passes == 1)
        {
            rlSetBlendFactors(RL_ONE, RL_ONE, RL_FUNC_ADD);
            rlSetBlendMode(BLEND_CUSTOM);
        }
        s->frameOk = SetLights(&s->lights[first], k, (passes == 0)? s->ambient : BLACK) && s->frameOk;
        RblDrawBillboard(s->camera, s->fwdMat[c], s->floor);
    }
    if (passes > 1) rlSetBlendMode(BLEND_ALPHA);
    EndMode3D();
    EndTextureMode();
    return passes;
}

static void DrawDeferred(Scene *s, int c, bool naive)
{
    s->g.naiveFullscreen = naive;
    s->frameOk = SetLights(s->lights, s->counts[c], s->ambient) && RblBeginGBuffer(&s->g, s->camera);    // the geometry pass adds the ambient
    if (s->frameOk)
    {
        RblDrawBillboard(s->camera, s->geoMat, s->floor);
        RblEndGBuffer(&s->g);
        s->frameOk = RblDrawDeferredLights(&s->g);
    }
    BeginTextureMode(s->target);
    ClearBackground(BLANK);
    if (s->frameOk) RblResolveGBuffer(&s->g);
    EndTextureMode();
}

static void DrawCase(Scene *s, int i)
{
    int pipe = i/COUNTS, c = i%COUNTS;
    if (pipe == PIPE_FORWARD) DrawForward(s, c);
    else DrawDeferred(s, c, pipe == PIPE_NAIVE);
}

// One frame: glFinish, draw, glFinish (GPU work included); milliseconds. case -1 = baseline
static double TimeFrame(void *ctx, int i)
{
    Scene *s = (Scene *)ctx;
    rtFinish();
    double t0 = BenchNowNs();
    if (i < 0) DrawBaseline(s); else DrawCase(s, i);
    rtFinish();
    return (BenchNowNs() - t0)*1e-6;
}

// One run times every case once, each right after a baseline frame. out: [0, CASES) ms,
// [CASES, 2*CASES) ratios to the run's baseline (median of its baseline frames),
// [2*CASES, 2*CASES + COUNTS) naive/volumes at each count, then the run's baseline.
static void RoundRun(void *ctx, double *out)
{
    Scene *s = (Scene *)ctx;
    double roundBase = BenchPairedRound(TimeFrame, s, s->ok, CASES, out);
    for (int c = 0; c < COUNTS; c++)
    {
        double vol = out[PIPE_VOLUMES*COUNTS + c], naive = out[PIPE_NAIVE*COUNTS + c];
        out[2*CASES + c] = (vol > 0.0)? naive/vol : 0.0;
    }
    out[2*CASES + COUNTS] = roundBase;
    if ((s->baseMin == 0.0) || (roundBase < s->baseMin)) s->baseMin = roundBase;
    if (roundBase > s->baseMax) s->baseMax = roundBase;
}

//----------------------------------------------------------------------------------
// Checks (untimed)
//----------------------------------------------------------------------------------
static int UncoveredPixels(Image img)
{
    const unsigned char *p = (const unsigned char *)img.data;
    int missing = 0;
    for (int i = 0; i < img.width*img.height; i++) missing += (p[i*4 + 3] == 0);
    return missing;
}

typedef struct Diff { int worst, pixels, coverage; } Diff;

// Max channel difference over pixels both images cover; coverage = pixels only one covers
static Diff CompareImages(Image a, Image b)
{
    Diff d = { 0, 0, 0 };
    const unsigned char *p = (const unsigned char *)a.data, *q = (const unsigned char *)b.data;
    for (int i = 0; i < a.width*a.height; i++)
    {
        const unsigned char *x = p + i*4, *y = q + i*4;
        if ((x[3] == 0) != (y[3] == 0)) { d.coverage++; continue; }
        if (x[3] == 0) continue;
        d.pixels++;
        for (int ch = 0; ch < 3; ch++) { int e = abs((int)x[ch] - (int)y[ch]); if (e > d.worst) d.worst = e; }
    }
    return d;
}

// Bytes per pixel of a texture as the GL allocated it (sum of its channel and depth bits / 8)
static double GlBytesPerPixel(unsigned int id)
{
    void (*getLevel)(unsigned int, int, unsigned int, int *) = NULL;
    void *proc = rtGlProc("glGetTexLevelParameteriv");
    if ((proc == NULL) || (id == 0)) return -1.0;
    memcpy(&getLevel, &proc, sizeof(proc));
    const unsigned int what[5] = { GL_TEXTURE_RED_SIZE_, GL_TEXTURE_GREEN_SIZE_, GL_TEXTURE_BLUE_SIZE_, GL_TEXTURE_ALPHA_SIZE_, GL_TEXTURE_DEPTH_SIZE_ };
    int bits = 0;
    rlActiveTextureSlot(0);
    rlEnableTexture(id);
    for (int k = 0; k < 5; k++) { int b = 0; getLevel(GL_TEXTURE_2D_, 0, what[k], &b); bits += b; }
    rlDisableTexture();
    return bits/8.0;
}

//----------------------------------------------------------------------------------
// Scene
//----------------------------------------------------------------------------------
//----------------------------------------------------------------------------------
// Geometry pass per BRDF (timed) and the G-buffer against the double reference (untimed)
//----------------------------------------------------------------------------------
// Each BRDF's G-buffer at the frame's size, its geometry variant and a material of middling values
typedef struct BrdfPass { RblGBuffer g; Shader geo; Material mat; bool ok; } BrdfPass;
static const char *brdfKey[3] = { "lambert", "blinn_phong", "ggx" };

static void BrdfPassLoad(BrdfPass *p, int brdf, Texture2D albedo)
{
    RblGBufferDesc gd;
    memset(&gd, 0, sizeof(gd));
    gd.width = FRAME_W; gd.height = FRAME_H;
    gd.shading.brdf = brdf;                         // point lights (the default light features), no fog, sRGB
    p->g = RblLoadGBuffer(gd);
    RblLitShaderDesc d;
    memset(&d, 0, sizeof(d));
    d.shading.brdf = brdf;
    d.deferred = true;
    p->geo = RblLoadLitShader(d);
    p->mat = LoadMaterialDefault();
    p->mat.shader = p->geo;
    p->mat.maps[MATERIAL_MAP_ALBEDO].texture = albedo;
    p->mat.maps[MATERIAL_MAP_NORMAL].value = 32.0f;                               // Blinn-Phong shininess
    p->mat.params[1] = 0.7f;                                                      // Blinn-Phong intensity
    p->mat.maps[MATERIAL_MAP_ROUGHNESS].value = 0.4f;                             // GGX
    p->ok = RblIsGBufferValid(p->g) && RblIsLitShaderValid(p->geo);
}

static void BrdfPassUnload(BrdfPass *p)
{
    if (RblIsLitShaderValid(p->geo)) RblUnloadLitShader(&p->geo);
    MemFree(p->mat.maps);
    RblUnloadGBuffer(&p->g);
}

// The geometry pass alone (frame = false) or the whole frame at 16 lights: geometry, lights, resolve
static bool DrawBrdf(Scene *s, BrdfPass *p, bool frame)
{
    bool ok = SetLights(s->lights, 16, s->ambient) && RblBeginGBuffer(&p->g, s->camera);
    if (ok)
    {
        RblDrawBillboard(s->camera, p->mat, s->floor);
        RblEndGBuffer(&p->g);
    }
    if (!frame) return ok;
    ok = ok && RblDrawDeferredLights(&p->g);
    BeginTextureMode(s->target);
    ClearBackground(BLANK);
    if (ok) RblResolveGBuffer(&p->g);
    EndTextureMode();
    return ok;
}

typedef struct BrdfRun { Scene *s; BrdfPass *p; } BrdfRun;
#define BRDF_CASES 6                        // geometry pass x 3 BRDFs, frame x 3 BRDFs
#define BRDF_VALUES (2*BRDF_CASES + 1)      // ms, ratios, baseline

// One run: every case once, each right after a baseline frame; ratios to the run's median baseline
static void BrdfRoundRun(void *ctx, double *out)
{
    BrdfRun *r = (BrdfRun *)ctx;
    double base[BRDF_CASES];
    for (int i = 0; i < BRDF_CASES; i++)
    {
        rtFinish();
        double t0 = BenchNowNs();
        DrawBaseline(r->s);
        rtFinish();
        base[i] = (BenchNowNs() - t0)*1e-6;
        out[i] = 0.0;
        if (!r->p[i%3].ok) continue;
        t0 = BenchNowNs();
        DrawBrdf(r->s, &r->p[i%3], i >= 3);
        rtFinish();
        out[i] = (BenchNowNs() - t0)*1e-6;
    }
    double roundBase = BenchMedian(base, BRDF_CASES);
    for (int i = 0; i < BRDF_CASES; i++) out[BRDF_CASES + i] = (roundBase > 0.0)? out[i]/roundBase : 0.0;
    out[2*BRDF_CASES] = roundBase;
}

// ---- against the double reference (tests/lighting_reference.h), the GPU test's views ----------------
// A tilted plane (normal no code) and a sphere Model (interpolated vertex normals), perspective and
// orthographic, a point light near the surface and a directional light; resolved into RGBA8 (display),
// RGBA16F and RGBA32F (display encoding, unrounded) and RGBA16F / RGBA32F linear output. Errors in
// 1/255: 8-bit against the reference rounded, float against the reference, linear values above 1 relative.
#define REF_SIZE    96
#define REF_TARGETS 5
static const char *refTargetKey[REF_TARGETS] = { "rgba8", "rgba16f", "rgba32f", "rgba16f_linear", "rgba32f_linear" };
static const int refFormat[REF_TARGETS] = { PIXELFORMAT_UNCOMPRESSED_R8G8B8A8, PIXELFORMAT_UNCOMPRESSED_R16G16B16A16, PIXELFORMAT_UNCOMPRESSED_R32G32B32A32,
                                            PIXELFORMAT_UNCOMPRESSED_R16G16B16A16, PIXELFORMAT_UNCOMPRESSED_R32G32B32A32 };

typedef struct RefView { Camera3D camera; RblLight lights[2]; bool sphere; RblBillboard plane; bool hit[REF_SIZE*REF_SIZE]; D3 p[REF_SIZE*REF_SIZE], n[REF_SIZE*REF_SIZE]; } RefView;

static void RefViewLoad(RefView *v, bool sphere, bool ortho, const RefMesh *mesh)
{
    memset(v, 0, sizeof(*v));
    v->sphere = sphere;
    RblLight point, sun;
    memset(&point, 0, sizeof(point)); memset(&sun, 0, sizeof(sun));
    point.type = RBL_LIGHT_POINT; point.color = (Color){ 255, 240, 220, 255 };
    sun.type = RBL_LIGHT_DIRECTIONAL; sun.color = WHITE; sun.intensity = 0.6f;
    if (sphere)
    {
        v->camera = makeCamera((Vector3){ 0.3f, 0.5f, 4.0f }, (Vector3){ 0.0f, 0.0f, 0.0f }, (Vector3){ 0.0f, 1.0f, 0.0f });
        point.position = (Vector3){ 1.1f, 0.9f, 1.6f }; point.intensity = 3.0f; point.range = 5.0f;
        sun.direction = (Vector3){ 0.5f, -0.3f, -1.0f };
    }
    else
    {
        v->camera = makeCamera((Vector3){ 0.0f, -2.5f, 2.0f }, (Vector3){ 0.0f, 0.5f, 0.0f }, (Vector3){ 0.0f, 1.0f, 0.0f });
        point.position = (Vector3){ 0.3f, 0.5f, 0.35f }; point.intensity = 0.4f; point.range = 3.0f;
        sun.direction = (Vector3){ 0.5f, -3.7f, -2.0f };
        v->plane.size = (Vector2){ 40.0f, 40.0f }; v->plane.origin = (Vector2){ 20.0f, 20.0f };
        v->plane.facing = RBL_FACING_FIXED;
        v->plane.axis = Vector3Normalize((Vector3){ 0.21f, -0.13f, 1.0f });
        v->plane.up = Vector3Normalize(Vector3CrossProduct(v->plane.axis, (Vector3){ 1.0f, 0.0f, 0.0f }));
    }
    v->lights[0] = point; v->lights[1] = sun;
    if (ortho) { v->camera.projection = CAMERA_ORTHOGRAPHIC; v->camera.fovy = sphere? 2.9f : 3.6f; }
    static bool sees[REF_SIZE*REF_SIZE];
    D3 corners[4], normal = d3(0, 0, 1);
    if (!sphere) refQuad(v->camera, &v->plane, corners, &normal);
    for (int py = 0; py < REF_SIZE; py++)
        for (int px = 0; px < REF_SIZE; px++)
        {
            int i = py*REF_SIZE + px;
            D3 o, d;
            refPixelRay(v->camera, REF_SIZE, REF_SIZE, px, py, &o, &d);
            if (sphere) sees[i] = refMeshRay(mesh, o, d, &v->p[i], &v->n[i]);
            else { sees[i] = refPixelOnPlane(v->camera, REF_SIZE, REF_SIZE, px, py, corners[0], normal, &v->p[i]); v->n[i] = normal; }
        }
    for (int py = 1; py < REF_SIZE - 1; py++)
        for (int px = 1; px < REF_SIZE - 1; px++)
        {
            int i = py*REF_SIZE + px;
            v->hit[i] = sees[i] && sees[i - 1] && sees[i + 1] && sees[i - REF_SIZE] && sees[i + REF_SIZE];
        }
}

typedef struct RefCase { int brdf; float roughness, metalness, shininess, specular; } RefCase;
typedef struct RefErr { double max, mean; } RefErr;

// A colour target of a raylib format with a depth renderbuffer (the resolve writes depth)
static RenderTexture2D RefTarget(int format)
{
    RenderTexture2D rt;
    memset(&rt, 0, sizeof(rt));
    rt.id = rlLoadFramebuffer();
    rt.texture.id = rlLoadTexture(NULL, REF_SIZE, REF_SIZE, format, 1);
    rt.texture.width = REF_SIZE; rt.texture.height = REF_SIZE; rt.texture.mipmaps = 1; rt.texture.format = format;
    rt.depth.id = rlLoadTextureDepth(REF_SIZE, REF_SIZE, true);
    rlFramebufferAttach(rt.id, rt.texture.id, RL_ATTACHMENT_COLOR_CHANNEL0, RL_ATTACHMENT_TEXTURE2D, 0);
    rlFramebufferAttach(rt.id, rt.depth.id, RL_ATTACHMENT_DEPTH, RL_ATTACHMENT_RENDERBUFFER, 0);
    return rt;
}

// One case in one view, each target against the reference (e per target); false when refused
static bool RefRender(const RefView *v, RefCase c, Model *sphere, Texture2D albedo, RblGBuffer g[2], RefErr e[REF_TARGETS])
{
    RblLitShaderDesc d;
    memset(&d, 0, sizeof(d));
    d.shading.brdf = c.brdf; d.maxLights = 2; d.shading.lightFeatures = RblGetLightFeatures(v->lights, 2); d.deferred = true;
    Shader geo = RblLoadLitShader(d);
    Material m = LoadMaterialDefault();
    m.shader = geo;
    m.maps[MATERIAL_MAP_ALBEDO].texture = albedo;
    m.maps[MATERIAL_MAP_NORMAL].value = c.shininess;
    m.maps[MATERIAL_MAP_ROUGHNESS].value = c.roughness;
    m.maps[MATERIAL_MAP_METALNESS].value = c.metalness;
    m.params[1] = c.specular;
    const Color ambient = { 20, 22, 28, 255 };
    bool ok = RblIsLitShaderValid(geo) && SetLights(v->lights, 2, ambient);
    for (int k = 0; k < 2; k++)
    {
        ok = ok && RblBeginGBuffer(&g[k], v->camera);
        if (!ok) break;
        if (v->sphere)
        {
            Material keep = sphere->materials[0];
            sphere->materials[0] = m;
            RblDrawModel(*sphere, (Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f, WHITE);
            sphere->materials[0] = keep;
        }
        else RblDrawBillboard(v->camera, m, v->plane);
        RblEndGBuffer(&g[k]);
        ok = RblDrawDeferredLights(&g[k]);
    }
    RefParams rp;
    memset(&rp, 0, sizeof(rp));
    rp.brdf = c.brdf; rp.roughness = c.roughness; rp.metalness = c.metalness; rp.shininess = c.shininess; rp.specular = c.specular;
    RefEnvironment env;
    memset(&env, 0, sizeof(env));
    env.ambient = ambient;
    const Color albedoColor = { 200, 160, 120, 255 };
    for (int t = 0; ok && (t < REF_TARGETS); t++)
    {
        bool linear = (t >= 3);
        RenderTexture2D rt = RefTarget(refFormat[t]);
        BeginTextureMode(rt); ClearBackground(BLANK); RblResolveGBuffer(&g[linear? 1 : 0]); EndTextureMode();
        float *px = rtReadFloatPixels(rt.texture.id, REF_SIZE, REF_SIZE);          // GL rows: bottom first
        rlUnloadTexture(rt.texture.id);
        rlUnloadFramebuffer(rt.id);
        if (px == NULL) { ok = false; break; }
        rp.linearOutput = linear;
        double sum = 0.0;
        int pixels = 0;
        e[t].max = 0.0;
        for (int py = 0; py < REF_SIZE; py++)
            for (int x = 0; x < REF_SIZE; x++)
            {
                int i = py*REF_SIZE + x;
                const float *q = &px[((REF_SIZE - 1 - py)*REF_SIZE + x)*4];
                if (!v->hit[i] || (q[3] <= 0.0f)) continue;
                RefSurface s;
                memset(&s, 0, sizeof(s));
                s.position = v->p[i]; s.normal = v->n[i]; s.albedo = refLinear(albedoColor); s.specularMap = -1.0; s.occlusion = 1.0;
                RefRgb ref = refFinishAt(&rp, refShadeView(&rp, v->lights, 2, &env, &s, refViewVector(v->camera, s.position)), refViewDistance(v->camera, s.position));
                const double want[3] = { ref.r, ref.g, ref.b };
                for (int ch = 0; ch < 3; ch++)
                {
                    double err = (t == 0)? fabs(floor(q[ch]*255.0 + 0.5) - floor(want[ch]*255.0 + 0.5)) : fabs(q[ch] - want[ch])*255.0/fmax(1.0, want[ch]);
                    e[t].max = fmax(e[t].max, err);
                    sum += err;
                }
                pixels++;
            }
        e[t].mean = (pixels > 0)? sum/(3.0*pixels) : 0.0;
        free(px);
    }
    MemFree(m.maps);
    if (RblIsLitShaderValid(geo)) RblUnloadLitShader(&geo);
    return ok;
}

// Worst max and mean per BRDF group (Lambert, Blinn-Phong, GGX metal/dielectric, GGX metalness between
// codes) and target over its cases and the 4 views; rows reference_<group>_<target>
#define REF_GROUPS 4
static const char *refGroupKey[REF_GROUPS] = { "lambert", "blinn_phong", "ggx", "ggx_metal_between" };

static bool ReferenceErrors(RefErr worst[REF_GROUPS][REF_TARGETS])
{
    static const RefCase cases[] = {
        { RBL_BRDF_LAMBERT, 0, 0, 0, 0 },
        { RBL_BRDF_BLINN_PHONG, 0, 0, 2.0f, 0.7f }, { RBL_BRDF_BLINN_PHONG, 0, 0, 32.0f, 0.7f }, { RBL_BRDF_BLINN_PHONG, 0, 0, 64.0f, 1.5f },
        { RBL_BRDF_BLINN_PHONG, 0, 0, 300.0f, 0.7f }, { RBL_BRDF_BLINN_PHONG, 0, 0, 1024.0f, 1.2f }, { RBL_BRDF_BLINN_PHONG, 0, 0, 1024.0f, 0.03f },
        { RBL_BRDF_GGX, 0.02f, 0, 0, 0 }, { RBL_BRDF_GGX, 0.1f, 0, 0, 0 }, { RBL_BRDF_GGX, 0.3f, 0, 0, 0 }, { RBL_BRDF_GGX, 1.0f, 0, 0, 0 },
        { RBL_BRDF_GGX, 0.02f, 1, 0, 0 }, { RBL_BRDF_GGX, 0.05f, 1, 0, 0 }, { RBL_BRDF_GGX, 0.3f, 1, 0, 0 }, { RBL_BRDF_GGX, 1.0f, 1, 0, 0 },
        { RBL_BRDF_GGX, 0.1f, 0.5f, 0, 0 }, { RBL_BRDF_GGX, 0.4f, 0.3f, 0, 0 },
    };
    memset(worst, 0, sizeof(RefErr)*REF_GROUPS*REF_TARGETS);
    Model sphere = LoadModelFromMesh(GenMeshSphere(1.2f, 32, 32));
    RefMesh mesh = refMeshOf(sphere.meshes[0], d3(0, 0, 0));
    Image a = GenImageColor(1, 1, (Color){ 200, 160, 120, 255 });
    Texture2D albedo = LoadTextureFromImage(a);
    UnloadImage(a);
    static RefView views[4];
    for (int k = 0; k < 4; k++) RefViewLoad(&views[k], k >= 2, (k & 1) != 0, &mesh);
    RblGBuffer g[3][2];
    bool ok = true;
    for (int b = 0; b < 3; b++)
        for (int k = 0; k < 2; k++)
        {
            RblGBufferDesc gd;
            memset(&gd, 0, sizeof(gd));
            gd.width = REF_SIZE; gd.height = REF_SIZE; gd.shading.brdf = b;
            gd.shading.lightFeatures = RBL_LIGHT_FEATURE_POINT | RBL_LIGHT_FEATURE_DIRECTIONAL;
            gd.shading.linearOutput = (k == 1);
            g[b][k] = RblLoadGBuffer(gd);
            ok = ok && RblIsGBufferValid(g[b][k]);
        }
    for (int i = 0; ok && (i < (int)(sizeof(cases)/sizeof(cases[0]))); i++)
    {
        RefCase c = cases[i];
        int group = (c.brdf == RBL_BRDF_GGX)? (((c.metalness > 0.0f) && (c.metalness < 1.0f))? 3 : 2) : c.brdf;
        for (int k = 0; ok && (k < 4); k++)
        {
            RefErr e[REF_TARGETS];
            ok = RefRender(&views[k], c, &sphere, albedo, g[c.brdf], e);
            for (int t = 0; ok && (t < REF_TARGETS); t++)
            {
                worst[group][t].max = fmax(worst[group][t].max, e[t].max);
                worst[group][t].mean = fmax(worst[group][t].mean, e[t].mean);
            }
        }
    }
    for (int b = 0; b < 3; b++) { RblUnloadGBuffer(&g[b][0]); RblUnloadGBuffer(&g[b][1]); }
    refMeshFree(&mesh);
    UnloadTexture(albedo);
    UnloadModel(sphere);
    return ok;
}

//----------------------------------------------------------------------------------
// Encoding error (CPU, double): 0.3's G-buffer codec, the previous one and this one, mirrored from
// their layouts (previous: every BRDF's normal 18 + 18 bits, Blinn-Phong shininess 11 and intensity
// 9; this one: Blinn-Phong normal 16 + 16, shininess 12, intensity 12)
//----------------------------------------------------------------------------------
typedef enum { CODEC_OLD = 0, CODEC_PREV, CODEC_NEW } Codec;

// Octahedral code q in 0..levels-1 stands for e = q/(levels - 1)*2 - 1 (Cigolle et al. 2014)
static D3 OctDecode(int qx, int qy, int levels)
{
    double h = (levels - 1)*0.5, ex = (qx - h)/h, ey = (qy - h)/h;
    D3 r = d3(ex, ey, 1.0 - fabs(ex) - fabs(ey));
    double t = fmax(-r.z, 0.0);
    r.x += (r.x >= 0.0)? -t : t;
    r.y += (r.y >= 0.0)? -t : t;
    return dNorm(r);
}

// Rounded per coordinate (0.3: 4096 levels) or the nearest of the 4 neighbouring codes (the G-buffer now)
static D3 OctRoundTrip(D3 n, int levels, bool nearest)
{
    double s = fabs(n.x) + fabs(n.y) + fabs(n.z), ex = n.x/s, ey = n.y/s;
    if (n.z < 0.0) { double tx = (1.0 - fabs(ey))*((ex >= 0.0)? 1.0 : -1.0), ty = (1.0 - fabs(ex))*((ey >= 0.0)? 1.0 : -1.0); ex = tx; ey = ty; }
    double h = (levels - 1)*0.5, fx = ex*h + h, fy = ey*h + h;
    if (!nearest) return OctDecode((int)floor(fx + 0.5), (int)floor(fy + 0.5), levels);
    D3 best = n;
    double cosBest = -2.0;
    for (int k = 0; k < 4; k++)
    {
        int qx = (int)floor(fx) + (k & 1), qy = (int)floor(fy) + (k >> 1);
        D3 d = OctDecode((qx < levels)? qx : levels - 1, (qy < levels)? qy : levels - 1, levels);
        if (dDot(d, n) > cosBest) { cosBest = dDot(d, n); best = d; }
    }
    return best;
}

static double Quantize(double t, int bits) { double m = (double)((1 << bits) - 1); return floor(fmin(fmax(t, 0.0), 1.0)*m + 0.5)/m; }

// The material values a codec hands the lighting passes (RefParams: what the reference reads)
static RefParams StoredParams(RefParams p, Codec c)
{
    RefParams q = p;
    if (c == CODEC_OLD)
    {
        q.roughness = (float)Quantize(p.roughness, 8);                                  // RT1.a, linear
        q.metalness = (float)Quantize(p.metalness, 8);
        q.shininess = (float)exp2(Quantize(log2(fmax(p.shininess, 1.0))/11.0, 16)*11.0);
        q.specular = (float)Quantize(p.specular, 8);                                    // RT1.a, linear, clamped to 1
    }
    else
    {
        double lo = log2(0.045);
        q.roughness = (float)exp2(lo*(1.0 - Quantize(1.0 - log2(fmin(fmax(p.roughness, 0.045), 1.0))/lo, 12)));
        q.metalness = (float)Quantize(p.metalness, 8);
        int bits = (c == CODEC_PREV)? 11 : 12;
        q.shininess = (float)exp2(Quantize(log2(fmax(p.shininess, 1.0))/11.0, bits)*11.0);
        bits = (c == CODEC_PREV)? 9 : 12;
        q.specular = (float)((exp2(Quantize(log2(1.0 + 256.0*p.specular)/9.0, bits)*9.0) - 1.0)/256.0);
    }
    return q;
}

static D3 StoredNormal(D3 n, int brdf, Codec c)
{
    if (c == CODEC_OLD) return OctRoundTrip(n, 4096, false);
    if ((c == CODEC_NEW) && (brdf == RBL_BRDF_BLINN_PHONG)) return OctRoundTrip(n, 65535, true);     // 2^16 - 1 levels
    return OctRoundTrip(n, 262143, true);       // 2^18 - 1 levels per coordinate
}

// Per target: the display encoding unrounded (a float target), rounded to 8 bits on both sides, and
// linear output (values above 1 relative)
enum { ENC_FLOAT = 0, ENC_8BIT, ENC_LINEAR, ENC_TARGETS };
static const char *encTargetKey[ENC_TARGETS] = { "float", "8bit", "linear" };
typedef struct EncError { double max, mean; } EncError;

// The GPU sweep test's scenes (tests/test_deferred.c, defSweepScene), shaded in double at each pixel centre
static void EncodingError(RefParams p, bool sphere, Codec c, EncError out[ENC_TARGETS])
{
    const int size = 128;
    Camera3D cam;
    memset(&cam, 0, sizeof(cam));
    RblLight lights[2];
    memset(lights, 0, sizeof(lights));
    lights[0].type = RBL_LIGHT_POINT; lights[0].color = (Color){ 255, 240, 220, 255 };
    lights[1].type = RBL_LIGHT_DIRECTIONAL; lights[1].color = WHITE;
    if (sphere)
    {
        cam = makeCamera((Vector3){ 0.0f, 0.0f, 4.0f }, (Vector3){ 0.0f, 0.0f, 0.0f }, (Vector3){ 0.0f, 1.0f, 0.0f });
        lights[0].position = (Vector3){ 1.6f, 1.2f, 2.4f }; lights[0].intensity = 4.0f; lights[0].range = 8.0f;
        lights[1].direction = (Vector3){ 0.5f, -0.3f, -1.0f }; lights[1].intensity = 0.6f;
    }
    else
    {
        cam = makeCamera((Vector3){ 0.0f, -2.5f, 2.0f }, (Vector3){ 0.0f, 0.5f, 0.0f }, (Vector3){ 0.0f, 1.0f, 0.0f });
        lights[0].position = (Vector3){ 0.3f, 0.8f, 0.6f }; lights[0].intensity = 0.5f; lights[0].range = 4.0f;
        lights[1].direction = (Vector3){ 0.5f, -3.7f, -2.0f }; lights[1].intensity = 0.6f;
    }
    RefEnvironment env;
    memset(&env, 0, sizeof(env));
    env.ambient = (Color){ 20, 22, 28, 255 };
    env.up = d3(0, 1, 0);
    RefParams q = StoredParams(p, c);
    D3 eye = d3f(cam.position), f = dNorm(dSub(d3f(cam.target), eye));
    D3 right = dNorm(dCross(f, d3f(cam.up))), up = dCross(right, f);
    double t = tan(cam.fovy*PI/360.0), sum[ENC_TARGETS] = { 0.0, 0.0, 0.0 };
    for (int k = 0; k < ENC_TARGETS; k++) out[k].max = out[k].mean = 0.0;
    RefParams pl = p, ql = q;
    pl.linearOutput = true; ql.linearOutput = true;
    int pixels = 0;
    for (int py = 0; py < size; py++)
        for (int px = 0; px < size; px++)
        {
            D3 dir = dNorm(dAdd(f, dAdd(dScale(right, (((px + 0.5)/size)*2.0 - 1.0)*t), dScale(up, (1.0 - ((py + 0.5)/size)*2.0)*t))));
            RefSurface s;
            memset(&s, 0, sizeof(s));
            if (sphere)
            {
                double b = dDot(eye, dir), disc = b*b - (dDot(eye, eye) - 1.44);
                if (disc < 0.0) continue;
                s.position = dAdd(eye, dScale(dir, -b - sqrt(disc)));
                s.normal = dNorm(s.position);
            }
            else
            {
                if (dir.z >= 0.0) continue;
                s.position = dAdd(eye, dScale(dir, -eye.z/dir.z));
                s.normal = d3(0, 0, 1);
            }
            s.albedo = refLinear((Color){ 200, 160, 120, 255 });
            s.specularMap = -1.0;
            s.occlusion = 1.0;
            RefSurface stored = s;
            stored.normal = StoredNormal(s.normal, p.brdf, c);
            RefRgb ea = refShade(&p, lights, 2, &env, &s, eye), eb = refShade(&q, lights, 2, &env, &stored, eye);
            RefRgb a = refFinish(&p, ea, s.position, eye), b = refFinish(&q, eb, s.position, eye);
            RefRgb la = refFinish(&pl, ea, s.position, eye), lb = refFinish(&ql, eb, s.position, eye);
            const double av[3] = { a.r, a.g, a.b }, bv[3] = { b.r, b.g, b.b }, lav[3] = { la.r, la.g, la.b }, lbv[3] = { lb.r, lb.g, lb.b };
            for (int k = 0; k < 3; k++)
            {
                double d[ENC_TARGETS] = { fabs(av[k] - bv[k])*255.0, fabs(floor(av[k]*255.0 + 0.5) - floor(bv[k]*255.0 + 0.5)),
                                          fabs(lav[k] - lbv[k])*255.0/fmax(1.0, lav[k]) };
                for (int e = 0; e < ENC_TARGETS; e++) { out[e].max = fmax(out[e].max, d[e]); sum[e] += d[e]; }
            }
            pixels++;
        }
    for (int e = 0; e < ENC_TARGETS; e++) out[e].mean = (pixels > 0)? sum[e]/(3.0*pixels) : 0.0;
}

// Worst and mean angle (degrees) of a normal code over a uniform sphere sample
static void NormalCodeError(int levels, bool nearest, double *mean, double *worst)
{
    unsigned int seed = 2024u;
    const int count = 400000;
    *mean = 0.0; *worst = 0.0;
    for (int i = 0; i < count; i++)
    {
        double z = rtRandomRange(&seed, -1.0f, 1.0f), phi = rtRandomRange(&seed, 0.0f, (float)(2.0*PI)), r = sqrt(fmax(0.0, 1.0 - z*z));
        D3 n = d3(r*cos(phi), r*sin(phi), z), q = OctRoundTrip(n, levels, nearest);
        double e = atan2(dLen(dCross(n, q)), dDot(n, q))*180.0/PI;
        *mean += e/count;
        *worst = fmax(*worst, e);
    }
}

static void EncodingRows(void)
{
    const char *normalName[4] = { "old_12x12_rounded", "30bit_nearest", "32bit_nearest", "36bit_nearest" };   // 0.3, a 30-bit word's, Blinn-Phong's, GGX's
    const int normalLevels[4] = { 4096, 32767, 65535, 262143 };
    double nMean[4], nMax[4];
    printf("\ndeferred: G-buffer encoding error (CPU, double reference; no GL), 0.3's codec, the previous one, this one\n");
    printf("  normal codes over 400000 uniform sphere normals (degrees):\n");
    for (int k = 0; k < 4; k++)
    {
        NormalCodeError(normalLevels[k], k > 0, &nMean[k], &nMax[k]);
        char name[64];
        snprintf(name, sizeof(name), "normal_%s", normalName[k]);
        BenchCsvRow(SUITE, name, "mean_deg", nMean[k], "deg");
        BenchCsvRow(SUITE, name, "max_deg", nMax[k], "deg");
        printf("    %-22s %6d levels per coordinate: mean %.6f  max %.6f\n", normalName[k], normalLevels[k], nMean[k], nMax[k]);
    }
    printf("  image error from the stored surface alone, 1/255 before 8-bit rounding (the GPU sweep test's scenes), max/mean:\n");
    printf("    %-40s %30s %30s\n", "", "plane old / prev / new", "sphere old / prev / new");
    typedef struct { int brdf; float roughness, metalness, shininess, specular; } Case;
    Case cases[32];
    int n = 0;
    cases[n++] = (Case){ RBL_BRDF_LAMBERT, 0, 0, 0, 0 };
    const float shininess[6] = { 4.0f, 16.0f, 64.0f, 256.0f, 600.0f, 1024.0f };
    for (int i = 0; i < 6; i++) cases[n++] = (Case){ RBL_BRDF_BLINN_PHONG, 0, 0, shininess[i], 0.5f };
    cases[n++] = (Case){ RBL_BRDF_BLINN_PHONG, 0, 0, 1024.0f, 0.03f };
    // Values between two codes of the previous codec (the GPU reference test's)
    const float between[6][2] = { { 2.0f, 0.7f }, { 32.0f, 0.7f }, { 64.0f, 0.8f }, { 64.0f, 1.5f }, { 300.0f, 0.7f }, { 1024.0f, 1.2f } };
    for (int i = 0; i < 6; i++) cases[n++] = (Case){ RBL_BRDF_BLINN_PHONG, 0, 0, between[i][0], between[i][1] };
    const float roughness[6] = { 0.02f, 0.05f, 0.1f, 0.3f, 0.6f, 1.0f };
    for (int metal = 0; metal < 2; metal++)
        for (int i = 0; i < 6; i++) cases[n++] = (Case){ RBL_BRDF_GGX, roughness[i], (float)metal, 0, 0 };
    cases[n++] = (Case){ RBL_BRDF_GGX, 0.1f, 0.5f, 0, 0 };
    cases[n++] = (Case){ RBL_BRDF_GGX, 0.4f, 0.3f, 0, 0 };
    // Worst per group (Lambert, Blinn-Phong, GGX metal/dielectric, GGX metalness between) and target
    const char *groupKey[4] = { "lambert", "blinn_phong", "ggx", "ggx_metal_between" };
    EncError worst[4][2][ENC_TARGETS];          // [group][prev, new][target]
    memset(worst, 0, sizeof(worst));
    for (int i = 0; i < n; i++)
    {
        RefParams p;
        memset(&p, 0, sizeof(p));
        p.brdf = cases[i].brdf; p.roughness = cases[i].roughness; p.metalness = cases[i].metalness;
        p.shininess = cases[i].shininess; p.specular = cases[i].specular;
        int group = (p.brdf == RBL_BRDF_GGX)? (((p.metalness > 0.0f) && (p.metalness < 1.0f))? 3 : 2) : p.brdf;
        char label[64], key[64];
        if (p.brdf == RBL_BRDF_GGX)
        {
            snprintf(label, sizeof(label), "GGX roughness %.2f metalness %.1f", p.roughness, p.metalness);
            if ((p.metalness == 0.0f) || (p.metalness == 1.0f)) snprintf(key, sizeof(key), "ggx_r%.2f_%s", p.roughness, (p.metalness > 0.5f)? "metal" : "dielectric");
            else snprintf(key, sizeof(key), "ggx_r%.2f_m%.2f", p.roughness, p.metalness);
        }
        else if (p.brdf == RBL_BRDF_BLINN_PHONG)
        {
            snprintf(label, sizeof(label), "Blinn-Phong shininess %.0f, spec %.2f", p.shininess, p.specular);
            snprintf(key, sizeof(key), "blinn_phong_n%.0f_s%.2f", p.shininess, p.specular);
        }
        else { snprintf(label, sizeof(label), "Lambert"); snprintf(key, sizeof(key), "lambert"); }
        printf("    %-40s", label);
        for (int surface = 0; surface < 2; surface++)
        {
            EncError e[3][ENC_TARGETS];
            for (int c = 0; c < 3; c++) EncodingError(p, surface == 1, (Codec)c, e[c]);
            char name[96];
            snprintf(name, sizeof(name), "encoding_%s_%s", key, surface? "sphere" : "plane");
            BenchCsvRow(SUITE, name, "old_max", e[CODEC_OLD][ENC_FLOAT].max, "1/255");
            BenchCsvRow(SUITE, name, "old_mean", e[CODEC_OLD][ENC_FLOAT].mean, "1/255");
            BenchCsvRow(SUITE, name, "prev_max", e[CODEC_PREV][ENC_FLOAT].max, "1/255");
            BenchCsvRow(SUITE, name, "prev_mean", e[CODEC_PREV][ENC_FLOAT].mean, "1/255");
            BenchCsvRow(SUITE, name, "new_max", e[CODEC_NEW][ENC_FLOAT].max, "1/255");
            BenchCsvRow(SUITE, name, "new_mean", e[CODEC_NEW][ENC_FLOAT].mean, "1/255");
            printf("  %5.2f/%5.3f %4.2f/%5.3f %4.2f/%5.3f", e[CODEC_OLD][ENC_FLOAT].max, e[CODEC_OLD][ENC_FLOAT].mean, e[CODEC_PREV][ENC_FLOAT].max,
                   e[CODEC_PREV][ENC_FLOAT].mean, e[CODEC_NEW][ENC_FLOAT].max, e[CODEC_NEW][ENC_FLOAT].mean);
            for (int c = 0; c < 2; c++)
                for (int t = 0; t < ENC_TARGETS; t++)
                {
                    worst[group][c][t].max = fmax(worst[group][c][t].max, e[CODEC_PREV + c][t].max);
                    worst[group][c][t].mean = fmax(worst[group][c][t].mean, e[CODEC_PREV + c][t].mean);
                }
        }
        printf("\n");
    }
    printf("  worst per group, previous codec -> this one, max/mean 1/255 (float: display encoding unrounded; 8bit: both\n");
    printf("  rounded; linear: linear output, relative above 1):\n");
    for (int g = 0; g < 4; g++)
    {
        printf("    %-20s", groupKey[g]);
        for (int t = 0; t < ENC_TARGETS; t++)
        {
            char name[64];
            snprintf(name, sizeof(name), "encoding_%s_%s", groupKey[g], encTargetKey[t]);
            BenchCsvRow(SUITE, name, "prev_max", worst[g][0][t].max, "1/255");
            BenchCsvRow(SUITE, name, "prev_mean", worst[g][0][t].mean, "1/255");
            BenchCsvRow(SUITE, name, "new_max", worst[g][1][t].max, "1/255");
            BenchCsvRow(SUITE, name, "new_mean", worst[g][1][t].mean, "1/255");
            printf("  %s %4.2f/%5.3f -> %4.2f/%5.3f", encTargetKey[t], worst[g][0][t].max, worst[g][0][t].mean, worst[g][1][t].max, worst[g][1][t].mean);
        }
        printf("\n");
    }
    printf("  first-order worst case on a highlight's flank, 255 sRGB'(1) (2/alpha) x worst normal error (GGX;\n");
    printf("  first order holds while that error is small beside alpha: 0.3's figures at 0.045-0.05 only say 'far off'):\n");
    const float flank[4] = { 0.045f, 0.05f, 0.1f, 0.3f };
    for (int i = 0; i < 4; i++)
    {
        double alpha = (double)flank[i]*flank[i], k = 255.0*(1.055/2.4)*2.0/alpha*PI/180.0;
        char name[64];
        snprintf(name, sizeof(name), "flank_bound_ggx_r%.3f", flank[i]);
        BenchCsvRow(SUITE, name, "old", k*nMax[0], "1/255");
        BenchCsvRow(SUITE, name, "30bit", k*nMax[1], "1/255");
        BenchCsvRow(SUITE, name, "32bit", k*nMax[2], "1/255");
        BenchCsvRow(SUITE, name, "new", k*nMax[3], "1/255");
        printf("    roughness %.3f: 0.3's codec %6.1f/255, a 30-bit normal %5.1f/255, 32-bit %5.2f/255, GGX's 36 bits %5.2f/255\n", flank[i], k*nMax[0], k*nMax[1], k*nMax[2], k*nMax[3]);
    }
    // Blinn-Phong's lobe as a GGX alpha (Walter et al. 2007: n = 2/alpha^2 - 2): its sharpest (n = 2048)
    // is a GGX roughness of 0.177, where 32 bits keep the bound GGX's 36 keep at 0.045-0.05 twice over
    const float blinn[2] = { 1024.0f, 2048.0f };
    for (int i = 0; i < 2; i++)
    {
        double alpha = sqrt(2.0/(blinn[i] + 2.0)), k = 255.0*(1.055/2.4)*2.0/alpha*PI/180.0;
        char name[64];
        snprintf(name, sizeof(name), "flank_bound_blinn_phong_n%.0f", blinn[i]);
        BenchCsvRow(SUITE, name, "prev", k*nMax[3], "1/255");
        BenchCsvRow(SUITE, name, "new", k*nMax[2], "1/255");
        printf("    Blinn-Phong n %4.0f (GGX alpha %.4f): previous 36 bits %5.2f/255, this one (32 bits) %5.2f/255\n", blinn[i], alpha, k*nMax[3], k*nMax[2]);
    }
}

//----------------------------------------------------------------------------------
// Main
//----------------------------------------------------------------------------------
int main(void)
{
    double benchStart = BenchNowNs();
    SetTraceLogLevel(LOG_WARNING);
    const char *backend = rtInitContext(FRAME_W, FRAME_H);
    if (backend == NULL) { printf("bench_deferred: no headless GL context, GL rows skipped\n"); EncodingRows(); return 0; }
    int problems = 0;

    static Scene sc;
    Scene *s = &sc;
    memset(s, 0, sizeof(*s));
    const int counts[COUNTS] = { 1, 16, 256, 1024 };
    memcpy(s->counts, counts, sizeof(counts));
    s->ambient = (Color){ 20, 20, 24, 255 };
    s->camera.position = (Vector3){ 0.0f, 4.0f, 4.0f };
    s->camera.target = (Vector3){ 0.0f, 0.0f, -1.0f };
    s->camera.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    s->camera.fovy = 45.0f;
    s->camera.projection = CAMERA_PERSPECTIVE;
    s->target = LoadRenderTexture(FRAME_W, FRAME_H);
    s->floor.position = s->camera.target;
    s->floor.size = (Vector2){ FLOOR_SIZE, FLOOR_SIZE };
    s->floor.origin = (Vector2){ FLOOR_SIZE*0.5f, FLOOR_SIZE*0.5f };
    s->floor.facing = RBL_FACING_FIXED;
    s->floor.axis = (Vector3){ 0.0f, 1.0f, 0.0f };
    s->floor.up = (Vector3){ 0.0f, 0.0f, -1.0f };
    if (!benchScatterFloorLights(s->camera, FRAME_W, FRAME_H, s->lights, MAX_N)) { printf("bench_deferred: a screen corner misses the floor\n"); rtCloseContext(); return 1; }

    Image albedoImg = GenImageColor(4, 4, (Color){ 200, 160, 120, 255 });
    s->albedo = LoadTextureFromImage(albedoImg);
    UnloadImage(albedoImg);
    s->plane = GenMeshPlane(FLOOR_SIZE, FLOOR_SIZE, 1, 1);
    s->planeTransform = identity;
    s->planeTransform.m12 = s->camera.target.x; s->planeTransform.m14 = s->camera.target.z;  // under the floor billboard
    s->rayMat = LoadMaterialDefault();
    s->rayMat.maps[MATERIAL_MAP_ALBEDO].texture = s->albedo;

    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.shading.brdf = BENCH_BRDF;
    for (int c = 0; c < COUNTS; c++)
    {
        RblLitShaderDesc d = desc;
        d.maxLights = (counts[c] < RBL_MAX_LIGHTS)? counts[c] : RBL_MAX_LIGHTS;
        s->fwdSlots[c] = d.maxLights;
        s->fwd[c] = RblLoadLitShader(d);
        s->fwdMat[c] = LoadMaterialDefault();
        s->fwdMat[c].shader = s->fwd[c];
        s->fwdMat[c].maps[MATERIAL_MAP_ALBEDO].texture = s->albedo;
        s->ok[PIPE_FORWARD*COUNTS + c] = RblIsLitShaderValid(s->fwd[c]);
    }
    RblLitShaderDesc gd = desc;
    gd.deferred = true;
    s->geo = RblLoadLitShader(gd);
    s->geoMat = LoadMaterialDefault();
    s->geoMat.shader = s->geo;
    s->geoMat.maps[MATERIAL_MAP_ALBEDO].texture = s->albedo;
    RblGBufferDesc gbufferDesc;
    memset(&gbufferDesc, 0, sizeof(gbufferDesc));
    gbufferDesc.width = FRAME_W; gbufferDesc.height = FRAME_H;
    gbufferDesc.shading.brdf = BENCH_BRDF;          // point lights (the default light features), no fog, sRGB
    s->g = RblLoadGBuffer(gbufferDesc);
    bool deferredOk = RblIsGBufferValid(s->g) && RblIsLitShaderValid(s->geo);
    if (!deferredOk) { printf("bench_deferred: G-buffer or geometry variant failed to load: deferred rows skipped\n"); problems++; }
    for (int c = 0; c < COUNTS; c++) s->ok[PIPE_VOLUMES*COUNTS + c] = s->ok[PIPE_NAIVE*COUNTS + c] = deferredOk;

    // ---- G-buffer bytes per pixel, from the allocated formats ----------------------------------------
    int bpp = RblGBufferBytesPerPixel(&s->g);
    int albedoB = GetPixelDataSize(1, 1, s->g.albedo.format), normalB = GetPixelDataSize(1, 1, s->g.normal.format);
    int paramsB = GetPixelDataSize(1, 1, s->g.params.format), accumB = GetPixelDataSize(1, 1, s->g.accum.format);
    double glAlbedo = GlBytesPerPixel(s->g.albedo.id), glNormal = GlBytesPerPixel(s->g.normal.id), glParams = GlBytesPerPixel(s->g.params.id);
    double glDepth = GlBytesPerPixel(s->g.depth.id), glAccum = GlBytesPerPixel(s->g.accum.id);
    double glColour = glAlbedo + glNormal + glParams;
    if (deferredOk && (fabs(glColour - bpp) > 1e-9))
    {
        printf("bench_deferred: RblGBufferBytesPerPixel says %d, the GL allocated %.2f bytes per pixel of colour targets\n", bpp, glColour);
        problems++;
    }

    // ---- checks (untimed; also warm every pipeline up: shader compiles, buffer growth) --------------
    DrawBaseline(s);
    Image img = rtReadTarget(s->target);
    int missing = UncoveredPixels(img);
    UnloadImage(img);
    if (missing > 0) { printf("bench_deferred: raylib baseline leaves %d pixels unwritten\n", missing); problems++; }
    int passes[COUNTS];
    for (int c = 0; c < COUNTS; c++)
    {
        int i = PIPE_FORWARD*COUNTS + c;
        if (!s->ok[i]) { printf("bench_deferred: forward variant for %d lights failed to load\n", counts[c]); problems++; passes[c] = 0; continue; }
        passes[c] = DrawForward(s, c);
        s->ok[i] = s->frameOk;
        img = rtReadTarget(s->target);
        missing = UncoveredPixels(img);
        UnloadImage(img);
        if (!s->frameOk) { printf("bench_deferred: forward_%dlights: lights rejected\n", counts[c]); problems++; }
        if (missing > 0) { printf("bench_deferred: forward_%dlights leaves %d pixels unwritten\n", counts[c], missing); problems++; }
    }
    Diff agree[COUNTS];
    Diff fwdVsDef = { -1, 0, 0 };
    memset(agree, 0, sizeof(agree));
    int volumeLights[COUNTS] = { 0 }, naiveLights[COUNTS] = { 0 };
    for (int c = 0; deferredOk && (c < COUNTS); c++)
    {
        Image pair[2];
        for (int naive = 0; naive < 2; naive++)
        {
            int i = (naive? PIPE_NAIVE : PIPE_VOLUMES)*COUNTS + c;
            DrawDeferred(s, c, naive);
            s->ok[i] = s->frameOk;
            if (naive) naiveLights[c] = s->g.lightsFullscreen; else volumeLights[c] = s->g.lightsInVolumes;
            pair[naive] = rtReadTarget(s->target);
            missing = UncoveredPixels(pair[naive]);
            if (!s->frameOk) { printf("bench_deferred: %s_%dlights: refused\n", pipeName[i/COUNTS], counts[c]); problems++; }
            if (missing > 0) { printf("bench_deferred: %s_%dlights leaves %d pixels unwritten\n", pipeName[i/COUNTS], counts[c], missing); problems++; }
        }
        agree[c] = CompareImages(pair[0], pair[1]);
        if ((agree[c].worst > 1) || (agree[c].coverage > 0))
        {
            printf("bench_deferred: volumes and naive differ by %d/255 at %d lights (coverage differs in %d pixels)\n", agree[c].worst, counts[c], agree[c].coverage);
            problems++;
        }
        if ((volumeLights[c] != counts[c]) || (naiveLights[c] != counts[c]))
        {
            printf("bench_deferred: %d lights: %d drawn as volumes, %d in the naive loop\n", counts[c], volumeLights[c], naiveLights[c]);
            problems++;
        }
        if ((counts[c] == 16) && s->ok[PIPE_FORWARD*COUNTS + c])
        {
            DrawForward(s, c);
            Image fwd = rtReadTarget(s->target);
            fwdVsDef = CompareImages(fwd, pair[0]);
            UnloadImage(fwd);
        }
        UnloadImage(pair[0]);
        UnloadImage(pair[1]);
    }

    // ---- frame cost ----------------------------------------------------------------------------------
    // llvmpipe, 2 cores: one run (every case once) takes ~5 s, dominated by forward and naive at 1024
    const BenchTiming timing = { 0, 3, 7, 12e9 };
    double med[VALUES];
    int runs = BenchMedianOfRuns(RoundRun, s, VALUES, timing, med);
    double base = med[2*CASES + COUNTS];
    double spread = (base > 0.0)? 100.0*(s->baseMax - s->baseMin)/base : 0.0;
    double ms[PIPES][COUNTS], ratio[PIPES][COUNTS], speedup[COUNTS], vsForward[COUNTS];
    int crossover = 0;
    for (int i = 0; i < CASES; i++)
    {
        ms[i/COUNTS][i%COUNTS] = s->ok[i]? med[i] : -1.0;
        ratio[i/COUNTS][i%COUNTS] = med[CASES + i];
    }
    for (int c = 0; c < COUNTS; c++)
    {
        speedup[c] = med[2*CASES + c];
        vsForward[c] = ((ms[PIPE_VOLUMES][c] > 0.0) && (ms[PIPE_FORWARD][c] > 0.0))? ms[PIPE_FORWARD][c]/ms[PIPE_VOLUMES][c] : 0.0;
        if ((crossover == 0) && (vsForward[c] > 1.0)) crossover = counts[c];
    }

    // ---- geometry pass and frame per BRDF (the G-buffer codec's cost), then the reference errors -----
    static BrdfPass brdfPass[3];
    BrdfRun brdfRun = { s, brdfPass };
    double brdfMed[BRDF_VALUES];
    int brdfRuns = 0;
    for (int b = 0; b < 3; b++)
    {
        BrdfPassLoad(&brdfPass[b], b, s->albedo);
        brdfPass[b].ok = brdfPass[b].ok && DrawBrdf(s, &brdfPass[b], true);      // also the warm-up
        if (!brdfPass[b].ok) { printf("bench_deferred: %s G-buffer pass refused\n", brdfKey[b]); problems++; }
    }
    const BenchTiming brdfTiming = { 1, 5, 15, 6e9 };
    brdfRuns = BenchMedianOfRuns(BrdfRoundRun, &brdfRun, BRDF_VALUES, brdfTiming, brdfMed);
    for (int b = 0; b < 3; b++) BrdfPassUnload(&brdfPass[b]);

    // Its 6 G-buffers' passes need the program registry's room: the frame-cost scene's programs first go
    for (int c = 0; c < COUNTS; c++) if (RblIsLitShaderValid(s->fwd[c])) RblUnloadLitShader(&s->fwd[c]);
    if (RblIsLitShaderValid(s->geo)) RblUnloadLitShader(&s->geo);
    RblUnloadGBuffer(&s->g);
    RefErr refWorst[REF_GROUPS][REF_TARGETS];
    bool refOk = ReferenceErrors(refWorst);
    if (!refOk) { printf("bench_deferred: the reference views were refused\n"); problems++; }

    // ---- rows ----------------------------------------------------------------------------------------
    for (int i = 0; i < BRDF_CASES; i++)
    {
        char name[64];
        snprintf(name, sizeof(name), (i < 3)? "geometry_pass_%s" : "deferred_frame_%s_16lights", brdfKey[i%3]);
        BenchCsvRow(SUITE, name, "ms_per_frame_1280x720", brdfMed[i], "ms");
        BenchCsvRow(SUITE, name, "ratio_to_raylib", brdfMed[BRDF_CASES + i], "x");
    }
    for (int grp = 0; refOk && (grp < REF_GROUPS); grp++)
        for (int t = 0; t < REF_TARGETS; t++)
        {
            char name[64];
            snprintf(name, sizeof(name), "reference_%s_%s", refGroupKey[grp], refTargetKey[t]);
            BenchCsvRow(SUITE, name, "max", refWorst[grp][t].max, "1/255");
            BenchCsvRow(SUITE, name, "mean", refWorst[grp][t].mean, "1/255");
        }
    BenchCsvRow(SUITE, "gbuffer", "bytes_per_pixel", bpp, "B");
    BenchCsvRow(SUITE, "gbuffer", "gl_bytes_per_pixel", glColour, "B");
    BenchCsvRow(SUITE, "gbuffer_albedo", "bytes_per_pixel", albedoB, "B");
    BenchCsvRow(SUITE, "gbuffer_normal", "bytes_per_pixel", normalB, "B");
    BenchCsvRow(SUITE, "gbuffer_params", "bytes_per_pixel", paramsB, "B");
    BenchCsvRow(SUITE, "gbuffer_depth", "bytes_per_pixel", glDepth, "B");
    BenchCsvRow(SUITE, "gbuffer_accum", "bytes_per_pixel", accumB, "B");
    BenchCsvRow(SUITE, "seed_pipeline", "bytes_per_pixel", SEED_BYTES, "B");
    BenchCsvRow(SUITE, "raylib_deferred_example", "bytes_per_pixel", RAYLIB_EXAMPLE_BYTES, "B");
    BenchCsvRow(SUITE, "raylib_default_material", "ms_per_frame_1280x720", base, "ms");
    BenchCsvRow(SUITE, "raylib_default_material", "spread_pct", spread, "%");
    BenchCsvRow(SUITE, "raylib_default_material", "runs", runs, "runs");
    for (int p = 0; p < PIPES; p++)
        for (int c = 0; c < COUNTS; c++)
        {
            if (ms[p][c] < 0.0) continue;
            char name[64];
            snprintf(name, sizeof(name), "%s_%dlights", pipeName[p], counts[c]);
            BenchCsvRow(SUITE, name, "ms_per_frame_1280x720", ms[p][c], "ms");
            BenchCsvRow(SUITE, name, "ratio_to_raylib", ratio[p][c], "x");
            if (p == PIPE_FORWARD) BenchCsvRow(SUITE, name, "passes", passes[c], "passes");
            if (p == PIPE_VOLUMES)
            {
                BenchCsvRow(SUITE, name, "speedup_vs_naive", speedup[c], "x");
                BenchCsvRow(SUITE, name, "speedup_vs_forward", vsForward[c], "x");
            }
        }
    if (deferredOk)
    {
        BenchCsvRow(SUITE, "deferred_vs_forward", "crossover_lights", crossover, "lights");
        for (int c = 0; c < COUNTS; c++)
        {
            char name[64];
            snprintf(name, sizeof(name), "check_volumes_vs_naive_%dlights", counts[c]);
            BenchCsvRow(SUITE, name, "max_diff", agree[c].worst, "1/255");
            BenchCsvRow(SUITE, name, "pixels", agree[c].pixels, "pixels");
        }
        if (fwdVsDef.worst >= 0)
        {
            BenchCsvRow(SUITE, "check_forward_vs_deferred_16lights", "max_diff", fwdVsDef.worst, "1/255");
            BenchCsvRow(SUITE, "check_forward_vs_deferred_16lights", "pixels", fwdVsDef.pixels, "pixels");
        }
    }

    // ---- release -------------------------------------------------------------------------------------
    for (int c = 0; c < COUNTS; c++) MemFree(s->fwdMat[c].maps);
    MemFree(s->geoMat.maps);
    MemFree(s->rayMat.maps);
    UnloadMesh(s->plane);
    UnloadTexture(s->albedo);
    UnloadRenderTexture(s->target);
    RblClose();
    rtCloseContext();

    // ---- summary -------------------------------------------------------------------------------------
    printf("deferred: G-buffer bytes per pixel (colour targets, from the allocated formats)\n");
    printf("  RblGBufferBytesPerPixel %d = albedo %d + normal %d + params %d (GL reports %.0f + %.0f + %.0f = %.0f)\n",
           bpp, albedoB, normalB, paramsB, glAlbedo, glNormal, glParams, glColour);
    printf("  not counted: depth %.0f (GL depth bits %.0f) and accumulation RGBA16F %d (GL %.0f)\n", glDepth, glDepth*8.0, accumB, glAccum);
    if (fabs(glDepth*8.0 - 32.0) > 1e-9)
        printf("  note: the G-buffer asks for a 32-bit float depth texture; this context kept the driver's %.0f-bit format\n", glDepth*8.0);
    printf("  for comparison (constants from their sources): seed pipeline %d, raylib's deferred example %d\n", SEED_BYTES, RAYLIB_EXAMPLE_BYTES);

    printf("\ndeferred: ms per frame, %dx%d, a floor filling the screen, n point lights of range 0.3-0.8 (%s BRDF); %s context\n",
           FRAME_W, FRAME_H, (BENCH_BRDF == RBL_BRDF_LAMBERT)? "Lambert" : (BENCH_BRDF == RBL_BRDF_GGX)? "GGX" : "Blinn-Phong", backend);
    printf("  raylib default material (DrawMesh, unlit) %8.2f ms  (baseline 1.00x; per-run baselines spread %.0f%%)\n", base, spread);
    printf("  median of %d runs, each timing every case once, each right after a baseline frame\n", runs);
    printf("  %-18s", "lights");
    for (int c = 0; c < COUNTS; c++) printf(" %9d ms %7s", counts[c], "ratio");
    printf("\n");
    for (int p = 0; p < PIPES; p++)
    {
        printf("  %-18s", pipeName[p]);
        for (int c = 0; c < COUNTS; c++)
        {
            if (ms[p][c] < 0.0) printf(" %12s %7s", "-", "-");
            else printf(" %12.2f %6.1fx", ms[p][c], ratio[p][c]);
        }
        printf("\n");
    }
    printf("  %-18s", "forward passes");
    for (int c = 0; c < COUNTS; c++) printf(" %12d %7s", passes[c], "");
    printf("\n  %-18s", "volumes vs naive");
    for (int c = 0; c < COUNTS; c++) printf(" %11.2fx %7s", speedup[c], "");
    printf("\n  %-18s", "volumes vs forward");
    for (int c = 0; c < COUNTS; c++) printf(" %11.2fx %7s", vsForward[c], "");
    printf("\n");
    int last = COUNTS - 1;
    printf("  deferred volumes vs naive at %d lights: %.1fx (target >= 5x: %s)\n", counts[last], speedup[last], (speedup[last] >= 5.0)? "met" : "NOT met");
    if (crossover > 0) printf("  forward/deferred crossover: deferred volumes first beat forward at %d lights (of 1, 16, 256, 1024)\n", crossover);
    else printf("  forward/deferred crossover: deferred volumes beat forward at none of the tested counts\n");
    printf("  forward above %d lights: extra additive passes on sRGB-encoded output (timing only, not the same image)\n", RBL_MAX_LIGHTS);
    if (deferredOk)
    {
        printf("  check: volumes vs naive max channel difference");
        for (int c = 0; c < COUNTS; c++) printf("%s %d lights %d/255", (c > 0)? "," : "", counts[c], agree[c].worst);
        bool agreeOk = true;
        for (int c = 0; c < COUNTS; c++) agreeOk = agreeOk && (agree[c].worst <= 1) && (agree[c].coverage == 0);
        printf(" over %d covered pixels (limit 1/255: %s)\n", agree[last].pixels, agreeOk? "ok" : "EXCEEDED");
        if (fwdVsDef.worst >= 0) printf("  check: forward vs deferred at 16 lights (one forward pass) max %d/255 over %d pixels\n", fwdVsDef.worst, fwdVsDef.pixels);
    }
    printf("\ndeferred: G-buffer pass per BRDF, ms per frame %dx%d (the floor; median of %d runs, each case right after a baseline frame)\n", FRAME_W, FRAME_H, brdfRuns);
    printf("  %-12s %16s %16s\n", "", "geometry pass", "frame, 16 lights");
    for (int b = 0; b < 3; b++)
        printf("  %-12s %9.2f %5.2fx %9.2f %5.2fx\n", brdfKey[b], brdfMed[b], brdfMed[BRDF_CASES + b], brdfMed[3 + b], brdfMed[BRDF_CASES + 3 + b]);
    if (refOk)
    {
        printf("\ndeferred: against the double reference (GPU; tilted plane and sphere Model, perspective and orthographic),\n");
        printf("  worst max / mean in 1/255 per group (linear: relative above 1)\n  %-20s", "");
        for (int t = 0; t < REF_TARGETS; t++) printf(" %15s", refTargetKey[t]);
        printf("\n");
        for (int grp = 0; grp < REF_GROUPS; grp++)
        {
            printf("  %-20s", refGroupKey[grp]);
            for (int t = 0; t < REF_TARGETS; t++) printf("    %5.2f %5.3f", refWorst[grp][t].max, refWorst[grp][t].mean);
            printf("\n");
        }
    }
    EncodingRows();
    printf("bench_deferred: done in %.1f s, rows in %s%s\n", (BenchNowNs() - benchStart)*1e-9, BenchCsvPath(), problems? " (with problems, see above)" : "");
    return 0;
}
