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
//                  volumes   RblLoadGBuffer + geometry pass (desc.deferred material) + RblSetScene (the n
//                            lights) + RblDrawDeferredLights (bounded lights as instanced sphere volumes) +
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
// Output: rows appended to $BENCH_CSV (see bench.h) and a summary table on stdout.
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "rlgl.h"
#include "harness.h"
#include "bench.h"

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
    s->frameOk = RblBeginGBuffer(&s->g, s->camera);
    if (s->frameOk)
    {
        RblDrawBillboard(s->camera, s->geoMat, s->floor);
        RblEndGBuffer(&s->g);
        s->frameOk = SetLights(s->lights, s->counts[c], s->ambient) && RblDrawDeferredLights(&s->g);
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
static double TimeFrame(Scene *s, int i)
{
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
    double base[CASES];
    int nb = 0;
    for (int i = 0; i < CASES; i++)
    {
        out[i] = 0.0;
        if (!s->ok[i]) continue;
        base[nb++] = TimeFrame(s, -1);
        out[i] = TimeFrame(s, i);
    }
    double roundBase = (nb > 0)? BenchMedian(base, nb) : TimeFrame(s, -1);
    for (int i = 0; i < CASES; i++) out[CASES + i] = (roundBase > 0.0)? out[i]/roundBase : 0.0;
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
// Where the screen pixel's ray meets the floor y = 0 (false: it misses)
static bool FloorHit(Camera3D camera, float x, float y, Vector2 *out)
{
    Ray r = GetScreenToWorldRayEx((Vector2){ x, y }, camera, FRAME_W, FRAME_H);
    if (!(r.direction.y < -1e-6f)) return false;
    float t = -r.position.y/r.direction.y;
    *out = (Vector2){ r.position.x + t*r.direction.x, r.position.z + t*r.direction.z };
    return true;
}

static float Cross2(Vector2 a, Vector2 b, Vector2 p) { return (b.x - a.x)*(p.y - a.y) - (b.y - a.y)*(p.x - a.x); }

// n lights uniformly over the visible floor (the screen corners' floor quad; rejection sampling),
// range 0.3-0.8, 10-60% of the range above the floor, so every light reaches the floor
static bool ScatterLights(Scene *s, int n)
{
    Vector2 q[4];
    const float corner[4][2] = { { 0.0f, 0.0f }, { FRAME_W, 0.0f }, { FRAME_W, FRAME_H }, { 0.0f, FRAME_H } };
    for (int k = 0; k < 4; k++) if (!FloorHit(s->camera, corner[k][0], corner[k][1], &q[k])) return false;
    float lo[2] = { q[0].x, q[0].y }, hi[2] = { q[0].x, q[0].y };
    for (int k = 1; k < 4; k++)
    {
        lo[0] = fminf(lo[0], q[k].x); hi[0] = fmaxf(hi[0], q[k].x);
        lo[1] = fminf(lo[1], q[k].y); hi[1] = fmaxf(hi[1], q[k].y);
    }
    float orient = Cross2(q[0], q[1], q[2]);
    unsigned int seed = 20240601u;
    for (int i = 0; i < n; )
    {
        Vector2 p = { rtRandomRange(&seed, lo[0], hi[0]), rtRandomRange(&seed, lo[1], hi[1]) };
        bool inside = true;
        for (int k = 0; k < 4; k++) inside = inside && (Cross2(q[k], q[(k + 1)%4], p)*orient >= 0.0f);
        if (!inside) continue;
        RblLight l;
        memset(&l, 0, sizeof(l));
        l.type = RBL_LIGHT_POINT;
        l.range = rtRandomRange(&seed, 0.3f, 0.8f);
        l.position = (Vector3){ p.x, l.range*rtRandomRange(&seed, 0.1f, 0.6f), p.y };
        l.color = (Color){ (unsigned char)(96 + rtRandom(&seed)%160), (unsigned char)(96 + rtRandom(&seed)%160), (unsigned char)(96 + rtRandom(&seed)%160), 255 };
        l.intensity = rtRandomRange(&seed, 0.01f, 0.04f);
        s->lights[i++] = l;
    }
    return true;
}

//----------------------------------------------------------------------------------
// Main
//----------------------------------------------------------------------------------
int main(void)
{
    double benchStart = BenchNowNs();
    SetTraceLogLevel(LOG_WARNING);
    const char *backend = rtInitContext(FRAME_W, FRAME_H);
    if (backend == NULL) { printf("bench_deferred: no headless GL context, skipped\n"); return 0; }
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
    if (!ScatterLights(s, MAX_N)) { printf("bench_deferred: a screen corner misses the floor\n"); rtCloseContext(); return 1; }

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
    desc.brdf = BENCH_BRDF;
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
    gbufferDesc.brdf = BENCH_BRDF;          // point lights (the default light features), no fog, sRGB
    s->g = RblLoadGBuffer(gbufferDesc);
    bool deferredOk = RblIsGBufferValid(&s->g) && RblIsLitShaderValid(s->geo);
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

    // ---- rows ----------------------------------------------------------------------------------------
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
    for (int c = 0; c < COUNTS; c++)
    {
        if (RblIsLitShaderValid(s->fwd[c])) RblUnloadLitShader(&s->fwd[c]);
        MemFree(s->fwdMat[c].maps);
    }
    if (RblIsLitShaderValid(s->geo)) RblUnloadLitShader(&s->geo);
    MemFree(s->geoMat.maps);
    MemFree(s->rayMat.maps);
    RblUnloadGBuffer(&s->g);
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
    if (fabs(glDepth*8.0 - 24.0) > 1e-9)
        printf("  note: the header documents a 24-bit depth texture; rlLoadTextureDepth asks desktop GL for unsized GL_DEPTH_COMPONENT and this driver allocated %.0f bits\n", glDepth*8.0);
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
    printf("bench_deferred: done in %.1f s, rows in %s%s\n", (BenchNowNs() - benchStart)*1e-9, BenchCsvPath(), problems? " (with problems, see above)" : "");
    return 0;
}
