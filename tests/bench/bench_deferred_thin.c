// Benchmark suite "deferred_thin": what each thin-sprite term costs deferred, beside forward (issue
// #26 item 6), GPU, headless GL. 400 x 400 target, one card filling the view (fixed facing, Lambert,
// one directional light, flat ambient), four pipelines per feature, timed in rotating order within
// each run (glFinish, frame, glFinish; medians over runs):
//   forward_off / forward_on     the lit program without / with the term
//   deferred_off / deferred_on   a G-buffer (and geometry variant) without / with it, lights, resolve
//   transmission  light 30 degrees off the card's back normal, material value 0.6, thickness none
//   relief        the dome of tests/relief_reference.h (32 x 32 texels, height 6), 16 steps, light
//                 from +X 40 degrees up
//   tint          the card as a floor under a red glass caster (RblBeginShadowBlend) of a 1024 map
//                 with a transmittance target; off = receivers that do not read it
// Error: forward_on vs deferred_on, max |difference| /255 over the target.
// Rows (suite "deferred_thin"): <feature>_<pipeline>: ms_per_frame; <feature>: deferred_on_over_off,
//   forward_on_over_off, deferred_over_forward (on), max_diff (1/255)
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "rlgl.h"
#include "harness.h"
#include "bench.h"
#include "relief_reference.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SUITE   "deferred_thin"
#define FRAME   400
#define FEATURES 3
#define PIPES   4
enum { FORWARD_OFF = 0, FORWARD_ON, DEFERRED_OFF, DEFERRED_ON };
static const char *const featureName[FEATURES] = { "transmission", "relief", "tint" };
static const char *const pipeName[PIPES] = { "forward_off", "forward_on", "deferred_off", "deferred_on" };

typedef struct Bench {
    RenderTexture2D target;
    Shader shader[FEATURES][PIPES];
    RblGBuffer g[FEATURES][2];
    Texture2D albedo, material, white, glass;
    RblLight light[FEATURES];
    RblShadowMap map;
    int feature, round;
} Bench;

static Camera3D CardCamera(void)
{
    Camera3D c;
    memset(&c, 0, sizeof(c));
    c.position = (Vector3){ 0.0f, 0.0f, 4.0f };
    c.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    c.fovy = THIN_CARD;
    c.projection = CAMERA_ORTHOGRAPHIC;
    return c;
}

static RblBillboard Card(float z, float size)
{
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.position = (Vector3){ 0.0f, 0.0f, z };
    b.size = (Vector2){ size, size };
    b.origin = (Vector2){ size*0.5f, size*0.5f };
    b.facing = RBL_FACING_FIXED;
    b.axis = (Vector3){ 0.0f, 0.0f, 1.0f };
    b.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    return b;
}

static void SetScene(Bench *b, int f)
{
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = &b->light[f]; scene.lightCount = 1; scene.ambient = (Color){ 40, 40, 40, 255 };
    if (f == 2) { scene.shadowMaps = &b->map; scene.shadowMapCount = 1; }
    RblSetScene(&scene);
}

static void DrawCard(Bench *b, int f, Shader s)
{
    Material m = LoadMaterialDefault();
    m.shader = s;
    m.maps[MATERIAL_MAP_ALBEDO].texture = (f == 2)? b->white : b->albedo;
    if (f == 1) m.maps[MATERIAL_MAP_NORMAL].texture = b->material;
    m.maps[MATERIAL_MAP_HEIGHT].value = 6.0f;
    m.params[RBL_PARAM_TRANSMISSION] = 0.6f;
    RblDrawBillboard(CardCamera(), m, Card(0.0f, THIN_CARD));
    MemFree(m.maps);
}

static void Frame(Bench *b, int f, int pipe)
{
    SetScene(b, f);
    Shader s = b->shader[f][pipe];
    if (pipe < DEFERRED_OFF)
    {
        BeginTextureMode(b->target);
        ClearBackground(BLANK);
        BeginMode3D(CardCamera());
        DrawCard(b, f, s);
        EndMode3D();
        EndTextureMode();
        return;
    }
    RblGBuffer *g = &b->g[f][pipe - DEFERRED_OFF];
    bool ok = RblBeginGBuffer(g, CardCamera());
    if (ok) { DrawCard(b, f, s); RblEndGBuffer(g); ok = RblDrawDeferredLights(g); }
    BeginTextureMode(b->target);
    ClearBackground(BLANK);
    if (ok) RblResolveGBuffer(g);
    EndTextureMode();
}

static double TimeFrame(Bench *b, int f, int pipe)
{
    rlDrawRenderBatchActive();
    rtFinish();
    double t0 = BenchNowNs();
    Frame(b, f, pipe);
    rtFinish();
    return (BenchNowNs() - t0)*1e-6;
}

static void Run(void *ctx, double *out)
{
    Bench *b = (Bench *)ctx;
    for (int k = 0; k < PIPES; k++) { int p = (k + b->round)%PIPES; out[p] = TimeFrame(b, b->feature, p); }
    b->round++;
}

int main(void)
{
    SetTraceLogLevel(LOG_WARNING);
    const char *backend = rtInitContext(FRAME, FRAME);
    if (backend == NULL) { printf("bench_deferred_thin: no headless GL context, skipped\n"); return 0; }
    static Bench bench;
    Bench *b = &bench;
    memset(b, 0, sizeof(*b));
    b->target = LoadRenderTexture(FRAME, FRAME);
    b->material = thinHeightTexture(THIN_DOME);
    Image img = GenImageColor(4, 4, (Color){ 200, 200, 200, 255 });
    b->albedo = LoadTextureFromImage(img);
    UnloadImage(img);
    img = GenImageColor(4, 4, WHITE);
    b->white = LoadTextureFromImage(img);
    UnloadImage(img);
    img = GenImageColor(4, 4, (Color){ 255, 40, 40, 128 });
    b->glass = LoadTextureFromImage(img);
    UnloadImage(img);
    for (int f = 0; f < FEATURES; f++) { b->light[f].type = RBL_LIGHT_DIRECTIONAL; b->light[f].color = WHITE; b->light[f].intensity = 1.0f; }
    b->light[0].direction = (Vector3){ 0.5f, 0.0f, 0.866f };            // behind the card
    b->light[1].direction = (Vector3){ -0.7660f, 0.0f, -0.6428f };      // from +X, 40 degrees up
    b->light[2].direction = (Vector3){ 0.3f, 0.2f, -1.0f };
    bool ok = true;
    for (int f = 0; f < FEATURES; f++)
        for (int on = 0; on < 2; on++)
        {
            RblLitShaderDesc d;
            memset(&d, 0, sizeof(d));
            d.maxLights = 1; d.shading.lightFeatures = RBL_LIGHT_FEATURE_DIRECTIONAL;
            if (f == 0) d.transmission = on;
            if (f == 1) { d.material.height = RBL_CHANNEL_A; d.relief = on; }
            if (f == 2) { d.shading.shadowMaps = 1; d.shadowTransmittance = on; }
            b->shader[f][on] = RblLoadLitShader(d);
            RblGBufferDesc gd;
            memset(&gd, 0, sizeof(gd));
            gd.width = FRAME; gd.height = FRAME; gd.shading.lightFeatures = d.shading.lightFeatures; gd.shading.shadowMaps = d.shading.shadowMaps;
            gd.transmission = d.transmission; gd.relief = d.relief; gd.shadowTransmittance = d.shadowTransmittance;
            b->g[f][on] = RblLoadGBuffer(gd);
            d.shadowTransmittance = false; d.deferred = true;
            b->shader[f][DEFERRED_OFF + on] = RblLoadLitShader(d);
            ok = ok && RblIsLitShaderValid(b->shader[f][on]) && RblIsLitShaderValid(b->shader[f][DEFERRED_OFF + on]) && RblIsGBufferValid(b->g[f][on]);
        }
    RblShadowDesc sd;
    memset(&sd, 0, sizeof(sd));
    sd.transmittance = true;
    b->map = RblLoadShadowMap(sd);
    ok = ok && RblIsShadowMapValid(b->map);
    if (!ok) { printf("bench_deferred_thin: a variant, G-buffer or map failed to load\n"); rtCloseContext(); return 1; }
    // The tint's map: a red glass card above the floor card, drawn once
    Material glassMat = LoadMaterialDefault();
    glassMat.shader = b->shader[2][FORWARD_OFF];
    glassMat.maps[MATERIAL_MAP_ALBEDO].texture = b->glass;
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = &b->light[2]; scene.lightCount = 1;
    if (RblBeginShadowMap(&b->map, &scene, 0, (Vector3){ 0.0f, 0.0f, 0.0f }, THIN_CARD))
    {
        if (RblBeginShadowBlend(true)) { RblDrawBillboard(CardCamera(), glassMat, Card(0.8f, THIN_CARD*0.5f)); RblEndShadowBlend(); }
        RblEndShadowMap(&b->map);
    }
    MemFree(glassMat.maps);
    const BenchTiming timing = { 1, 5, 15, 4e9 };
    printf("  context: %s; %dx%d card pixels, one directional light\n", backend, FRAME, FRAME);
    printf("  %-13s %11s %11s %12s %12s %11s %11s %11s %8s\n", "feature", "fwd off ms", "fwd on ms", "def off ms", "def on ms", "fwd on/off", "def on/off", "def/fwd on", "max/255");
    for (int f = 0; f < FEATURES; f++)
    {
        b->feature = f;
        b->round = 0;
        double ms[PIPES];
        int runs = BenchMedianOfRuns(Run, b, PIPES, timing, ms);
        Frame(b, f, FORWARD_ON);
        Image fi = rtReadTarget(b->target);
        Frame(b, f, DEFERRED_ON);
        Image di = rtReadTarget(b->target);
        int worst = 0;
        for (int i = 0; i < FRAME*FRAME; i++)
        {
            Color p = ((Color *)fi.data)[i], q = ((Color *)di.data)[i];
            int e[3] = { abs(p.r - q.r), abs(p.g - q.g), abs(p.b - q.b) };
            for (int c = 0; c < 3; c++) if (e[c] > worst) worst = e[c];
        }
        UnloadImage(fi); UnloadImage(di);
        printf("  %-13s %11.3f %11.3f %12.3f %12.3f %11.3f %11.3f %11.3f %8d  (%d runs)\n", featureName[f], ms[0], ms[1], ms[2], ms[3],
               ms[FORWARD_ON]/ms[FORWARD_OFF], ms[DEFERRED_ON]/ms[DEFERRED_OFF], ms[DEFERRED_ON]/ms[FORWARD_ON], worst, runs);
        char name[48];
        for (int p = 0; p < PIPES; p++) { snprintf(name, sizeof(name), "%s_%s", featureName[f], pipeName[p]); BenchCsvRow(SUITE, name, "ms_per_frame", ms[p], "ms"); }
        BenchCsvRow(SUITE, featureName[f], "deferred_on_over_off", ms[DEFERRED_ON]/ms[DEFERRED_OFF], "ratio");
        BenchCsvRow(SUITE, featureName[f], "forward_on_over_off", ms[FORWARD_ON]/ms[FORWARD_OFF], "ratio");
        BenchCsvRow(SUITE, featureName[f], "deferred_over_forward", ms[DEFERRED_ON]/ms[FORWARD_ON], "ratio");
        BenchCsvRow(SUITE, featureName[f], "max_diff", (double)worst, "1/255");
    }
    RblSetScene(&(RblScene){ 0 });
    for (int f = 0; f < FEATURES; f++)
        for (int p = 0; p < PIPES; p++) RblUnloadLitShader(&b->shader[f][p]);
    for (int f = 0; f < FEATURES; f++) { RblUnloadGBuffer(&b->g[f][0]); RblUnloadGBuffer(&b->g[f][1]); }
    RblUnloadShadowMap(&b->map);
    UnloadTexture(b->material); UnloadTexture(b->albedo); UnloadTexture(b->white); UnloadTexture(b->glass);
    UnloadRenderTexture(b->target);
    RblClose();
    rtCloseContext();
    return 0;
}
