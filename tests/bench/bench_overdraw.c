// Benchmark suite "overdraw": deferred against forward where opaque sprites overlap (issue #27
// item 7: the ambient and emission must not be paid per overdrawn layer).
//   1k and 10k opaque camera-facing sprites (instanced, solid 4x4 texture, GGX, emission) scattered
//   through a box in front of a perspective camera, 160 x 160 target, each sprite about 1/12 of the
//   view wide: mean depth complexity ~7 at 1k and ~70 at 10k. Scene: a hemisphere ambient, one
//   directional light (full-screen pass) and two bounded point lights (volumes). One run times
//   forward and deferred once each (glFinish, frame, glFinish), alternating which goes first;
//   medians over runs. Error: forward vs deferred, max and mean |difference| /255 over covered pixels.
// The file uses only the public API, so the same source builds against an older header for a
// before/after comparison (compile it with -I pointing at the other rbillboard_lit.h).
// Rows (suite "overdraw"): sprites_<1k|10k>_<forward|deferred>: ms_per_frame;
//   sprites_<n>: deferred_over_forward (ratio), max_diff, mean_diff (1/255)
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "rlgl.h"
#include "harness.h"
#include "bench.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SUITE   "overdraw"
#define FRAME   160
#define SIZES   2
static const int countOf[SIZES] = { 1000, 10000 };
static const char *const sizeName[SIZES] = { "1k", "10k" };

typedef struct Bench {
    RenderTexture2D target;
    RblGBuffer g;
    Shader fwd, geo;
    Texture2D white;
    RblInstanceBuffer buffer;
    RblInstance *instances;
    RblLight lights[3];
    Camera3D camera;
    int n, round;
} Bench;

static void SetScene(Bench *b)
{
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = b->lights; scene.lightCount = 3;
    scene.ambient = (Color){ 60, 70, 90, 255 }; scene.ambientGround = (Color){ 50, 40, 30, 255 };
    scene.ambientUp = (Vector3){ 0.0f, 1.0f, 0.0f };
    RblSetScene(&scene);
}

static Material SpriteMaterial(Bench *b, Shader s)
{
    Material m = LoadMaterialDefault();
    m.shader = s;
    m.maps[MATERIAL_MAP_ALBEDO].texture = b->white;
    m.maps[MATERIAL_MAP_ROUGHNESS].value = 0.5f;
    m.maps[MATERIAL_MAP_METALNESS].value = 0.2f;
    m.maps[MATERIAL_MAP_EMISSION].color = (Color){ 20, 8, 0, 255 };
    return m;
}

static void DrawSprites(Bench *b, Shader s)
{
    Material m = SpriteMaterial(b, s);
    RblInstancedDesc d;
    memset(&d, 0, sizeof(d));
    RblDrawInstanced(&b->buffer, b->camera, m, d, b->instances, b->n);
    MemFree(m.maps);
}

static void Forward(Bench *b)
{
    SetScene(b);
    BeginTextureMode(b->target);
    ClearBackground(BLANK);
    BeginMode3D(b->camera);
    DrawSprites(b, b->fwd);
    EndMode3D();
    EndTextureMode();
}

static bool Deferred(Bench *b)
{
    SetScene(b);
    bool ok = RblBeginGBuffer(&b->g, b->camera);
    if (ok)
    {
        DrawSprites(b, b->geo);
        RblEndGBuffer(&b->g);
        ok = RblDrawDeferredLights(&b->g);
    }
    BeginTextureMode(b->target);
    ClearBackground(BLANK);
    if (ok) RblResolveGBuffer(&b->g);
    EndTextureMode();
    return ok;
}

static double TimeFrame(Bench *b, bool deferred)
{
    rlDrawRenderBatchActive();
    rtFinish();
    double t0 = BenchNowNs();
    if (deferred) Deferred(b); else Forward(b);
    rtFinish();
    return (BenchNowNs() - t0)*1e-6;
}

static void Run(void *ctx, double *out)
{
    Bench *b = (Bench *)ctx;
    bool deferredFirst = (b->round++ & 1) != 0;
    for (int k = 0; k < 2; k++)
    {
        bool deferred = (k == 0)? deferredFirst : !deferredFirst;
        out[deferred? 1 : 0] = TimeFrame(b, deferred);
    }
}

int main(void)
{
    SetTraceLogLevel(LOG_WARNING);
    const char *backend = rtInitContext(FRAME, FRAME);
    if (backend == NULL) { printf("bench_overdraw: no headless GL context, skipped\n"); return 0; }
    static Bench bench;
    Bench *b = &bench;
    memset(b, 0, sizeof(*b));
    b->target = LoadRenderTexture(FRAME, FRAME);
    Image white = GenImageColor(4, 4, (Color){ 200, 190, 170, 255 });
    b->white = LoadTextureFromImage(white);
    UnloadImage(white);
    b->camera.position = (Vector3){ 0.0f, 0.0f, 10.0f };
    b->camera.target = (Vector3){ 0.0f, 0.0f, 0.0f };
    b->camera.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    b->camera.fovy = 45.0f;
    b->camera.projection = CAMERA_PERSPECTIVE;
    RblLight *l = b->lights;
    l[0].type = RBL_LIGHT_DIRECTIONAL; l[0].direction = (Vector3){ -0.3f, -0.5f, -0.8f }; l[0].color = WHITE; l[0].intensity = 1.5f;
    l[1].type = RBL_LIGHT_POINT; l[1].position = (Vector3){ 1.5f, 1.0f, 3.0f }; l[1].color = (Color){ 255, 200, 150, 255 }; l[1].intensity = 4.0f; l[1].range = 6.0f;
    l[2].type = RBL_LIGHT_POINT; l[2].position = (Vector3){ -2.0f, -1.0f, 2.0f }; l[2].color = (Color){ 150, 200, 255, 255 }; l[2].intensity = 3.0f; l[2].range = 5.0f;
    RblLitShaderDesc d;
    memset(&d, 0, sizeof(d));
    d.maxLights = 3; d.shading.lightFeatures = RblGetLightFeatures(l, 3); d.shading.brdf = RBL_BRDF_GGX; d.instanced = true;
    b->fwd = RblLoadLitShader(d);
    d.deferred = true;
    b->geo = RblLoadLitShader(d);
    RblGBufferDesc gd;
    memset(&gd, 0, sizeof(gd));
    gd.width = FRAME; gd.height = FRAME; gd.shading.brdf = RBL_BRDF_GGX; gd.shading.lightFeatures = d.shading.lightFeatures;
    b->g = RblLoadGBuffer(gd);
    b->buffer = RblLoadInstanceBuffer(countOf[SIZES - 1]);
    b->instances = (RblInstance *)calloc((size_t)countOf[SIZES - 1], sizeof(RblInstance));
    if (!RblIsLitShaderValid(b->fwd) || !RblIsLitShaderValid(b->geo) || !RblIsGBufferValid(b->g) || (b->instances == NULL))
    {
        printf("bench_overdraw: a program or the G-buffer failed to load\n");
        rtCloseContext();
        return 1;
    }
    unsigned int seed = 12345u;
    for (int i = 0; i < countOf[SIZES - 1]; i++)
    {
        float r[3];
        for (int k = 0; k < 3; k++) { seed = seed*1664525u + 1013904223u; r[k] = (float)(seed >> 8)/16777216.0f; }
        RblInstance *in = &b->instances[i];
        in->position = (Vector3){ (r[0] - 0.5f)*6.0f, (r[1] - 0.5f)*6.0f, (r[2] - 0.5f)*4.0f };
        in->size = (Vector2){ 0.7f, 0.7f }; in->origin = (Vector2){ 0.35f, 0.35f };
    }
    const BenchTiming timing = { 1, 5, 11, 6e9 };
    printf("  context: %s; %dx%d target, GGX + emission, hemisphere ambient, 1 directional + 2 point lights\n", backend, FRAME, FRAME);
    printf("  %-8s %12s %12s %10s %10s %10s %6s\n", "sprites", "forward ms", "deferred ms", "def/fwd", "max /255", "mean /255", "runs");
    for (int s = 0; s < SIZES; s++)
    {
        b->n = countOf[s];
        b->round = 0;
        double ms[2];
        int runs = BenchMedianOfRuns(Run, b, 2, timing, ms);
        Forward(b);
        Image f = rtReadTarget(b->target);
        Deferred(b);
        Image g = rtReadTarget(b->target);
        int worst = 0;
        long covered = 0;
        double sum = 0.0;
        for (int i = 0; i < FRAME*FRAME; i++)
        {
            Color p = ((Color *)f.data)[i], q = ((Color *)g.data)[i];
            if ((p.a == 0) && (q.a == 0)) continue;
            covered++;
            int e[3] = { abs(p.r - q.r), abs(p.g - q.g), abs(p.b - q.b) };
            for (int c = 0; c < 3; c++) { if (e[c] > worst) worst = e[c]; sum += e[c]/3.0; }
        }
        UnloadImage(f); UnloadImage(g);
        double mean = (covered > 0)? sum/(double)covered : 0.0;
        printf("  %-8s %12.3f %12.3f %10.3f %10d %10.4f %6d\n", sizeName[s], ms[0], ms[1], ms[1]/ms[0], worst, mean, runs);
        char name[48];
        snprintf(name, sizeof(name), "sprites_%s_forward", sizeName[s]);
        BenchCsvRow(SUITE, name, "ms_per_frame", ms[0], "ms");
        snprintf(name, sizeof(name), "sprites_%s_deferred", sizeName[s]);
        BenchCsvRow(SUITE, name, "ms_per_frame", ms[1], "ms");
        snprintf(name, sizeof(name), "sprites_%s", sizeName[s]);
        BenchCsvRow(SUITE, name, "deferred_over_forward", ms[1]/ms[0], "ratio");
        BenchCsvRow(SUITE, name, "max_diff", (double)worst, "1/255");
        BenchCsvRow(SUITE, name, "mean_diff", mean, "1/255");
    }
    free(b->instances);
    RblUnloadInstanceBuffer(&b->buffer);
    RblUnloadGBuffer(&b->g);
    RblUnloadLitShader(&b->fwd); RblUnloadLitShader(&b->geo);
    UnloadTexture(b->white);
    UnloadRenderTexture(b->target);
    RblClose();
    rtCloseContext();
    return 0;
}
