// Benchmark suite "thin": cost and error of the thin-sprite terms (GPU, headless GL).
//   relief       ms per frame at 720x720 of one card filling the view (fixed facing, Lambert, one
//                directional light 40 degrees up, flat ambient), its material texture the dome of
//                tests/relief_reference.h (32 x 32 texels, height 6 texels, A channel), for
//                desc.relief off (the same material and height channel: the baseline) and
//                reliefSteps 4, 8, 16, 32, 64. One run times every variant once, in rotating order
//                (glFinish, draw, glFinish); medians over runs. ns_per_pixel_step = (frame - baseline)/
//                (pixels x steps), pixels = the card's. Error: the share of the card's pixels whose
//                lit/shadowed decision differs from the continuous ray (8192 samples; the double march
//                of relief_reference.h) at every 4th pixel of every 4th row, over 4 light directions.
//   transmission ms per frame of the same card lit from behind (light 30 degrees off the card's back
//                normal) for the program without transmission, with it at a material value of 0, and
//                with it at 0.6: what compiling the term costs a material that does not use it.
// Rows (suite "thin"):
//   relief_<off|steps_N>: ms_per_frame, ratio_to_off, ns_per_pixel_step, continuous_mismatch_fraction
//   transmission_<off|zero|on>: ms_per_frame, ratio_to_off
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

#define SUITE       "thin"
#define FRAME       720
#define VARIANTS    6
#define TX_VARIANTS 3
static const int stepsOf[VARIANTS] = { 0, 4, 8, 16, 32, 64 };
static const char *const txName[TX_VARIANTS] = { "off", "zero", "on" };

typedef struct Bench {
    RenderTexture2D target;
    Shader relief[VARIANTS], tx[TX_VARIANTS];
    Texture2D albedo, material;
    RblLight light, back;
    int round;
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

static void DrawCard(Bench *b, Shader s, float transmission)
{
    Material m = LoadMaterialDefault();
    m.shader = s;
    m.maps[MATERIAL_MAP_ALBEDO].texture = b->albedo;
    m.maps[MATERIAL_MAP_NORMAL].texture = b->material;
    m.maps[MATERIAL_MAP_HEIGHT].value = 6.0f;
    m.params[RBL_PARAM_TRANSMISSION] = transmission;
    RblBillboard card;
    memset(&card, 0, sizeof(card));
    card.size = (Vector2){ THIN_CARD, THIN_CARD };
    card.origin = (Vector2){ THIN_CARD*0.5f, THIN_CARD*0.5f };
    card.facing = RBL_FACING_FIXED;
    card.axis = (Vector3){ 0.0f, 0.0f, 1.0f };
    card.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    BeginTextureMode(b->target);
    ClearBackground(BLANK);
    BeginMode3D(CardCamera());
    RblDrawBillboard(CardCamera(), m, card);
    EndMode3D();
    EndTextureMode();
    MemFree(m.maps);
}

static void SetLight(const RblLight *l)
{
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = l; scene.lightCount = 1; scene.ambient = (Color){ 40, 40, 40, 255 };
    RblSetScene(&scene);
}

static double TimeDraw(Bench *b, Shader s, float transmission)
{
    rlDrawRenderBatchActive();
    rtFinish();
    double t0 = BenchNowNs();
    DrawCard(b, s, transmission);
    rtFinish();
    return (BenchNowNs() - t0)*1e-6;
}

static void ReliefRun(void *ctx, double *out)
{
    Bench *b = (Bench *)ctx;
    SetLight(&b->light);
    for (int k = 0; k < VARIANTS; k++) { int v = (k + b->round)%VARIANTS; out[v] = TimeDraw(b, b->relief[v], 0.0f); }
    b->round++;
}

static void TransmissionRun(void *ctx, double *out)
{
    Bench *b = (Bench *)ctx;
    SetLight(&b->back);
    for (int k = 0; k < TX_VARIANTS; k++) { int v = (k + b->round)%TX_VARIANTS; out[v] = TimeDraw(b, b->tx[v], (v == 2)? 0.6f : 0.0f); }
    b->round++;
}

// Share of the card's pixels (every 4th row and column) deciding unlike the continuous ray, for
// light direction dir; exact[] caches the continuous ray's decisions (computed when *known is false)
#define PROBE 4
static double ReliefMismatch(Bench *b, int v, Vector3 dir, bool *exactLit, bool *known)
{
    RblLight l = b->light;
    l.direction = dir;
    SetLight(&l);
    DrawCard(b, b->relief[v], 0.0f);
    Image img = rtReadTarget(b->target);
    D3 t = dNorm(dScale(d3f(dir), -1.0));
    D3 d = d3(t.x, -t.y, t.z);
    double albedo = srgbDecode(200/255.0), ambient = srgbDecode(40/255.0);
    double litValue = srgbEncode(albedo*(ambient + t.z))*255.0, darkValue = srgbEncode(albedo*ambient)*255.0;
    long n = 0, bad = 0;
    Color *px = (Color *)img.data;
    for (int y = PROBE/2; y < FRAME; y += PROBE)
        for (int x = PROBE/2; x < FRAME; x += PROBE)
        {
            double u = (x + 0.5)/FRAME, vv = (y + 0.5)/FRAME;
            Color c = px[y*FRAME + x];
            bool lit = fabs(c.g - litValue) < fabs(c.g - darkValue);
            if (!*known) exactLit[n] = thinMarch(THIN_DOME, u*THIN_TEXELS, vv*THIN_TEXELS, d, 6.0, 0).lit;
            bad += (lit != exactLit[n]);
            n++;
        }
    *known = true;
    UnloadImage(img);
    return (double)bad/(double)n;
}

int main(void)
{
    SetTraceLogLevel(LOG_WARNING);
    const char *backend = rtInitContext(FRAME, FRAME);
    if (backend == NULL) { printf("bench_thin: no headless GL context, skipped\n"); return 0; }
    static Bench bench;
    Bench *b = &bench;
    memset(b, 0, sizeof(*b));
    b->target = LoadRenderTexture(FRAME, FRAME);
    b->material = thinHeightTexture(THIN_DOME);
    Image white = GenImageColor(4, 4, (Color){ 200, 200, 200, 255 });
    b->albedo = LoadTextureFromImage(white);
    UnloadImage(white);
    b->light.type = RBL_LIGHT_DIRECTIONAL; b->light.color = WHITE; b->light.intensity = 1.0f;
    b->light.direction = (Vector3){ -0.7660f, 0.0f, -0.6428f };             // from +X, 40 degrees above the card
    b->back = b->light;
    b->back.direction = (Vector3){ 0.5f, 0.0f, 0.866f };                        // behind the card, 30 degrees off its back normal
    bool ok = true;
    for (int v = 0; v < VARIANTS; v++)
    {
        RblLitShaderDesc d;
        memset(&d, 0, sizeof(d));
        d.maxLights = 1; d.shading.lightFeatures = RBL_LIGHT_FEATURE_DIRECTIONAL;
        d.material.height = RBL_CHANNEL_A;
        d.relief = stepsOf[v] > 0; d.reliefSteps = stepsOf[v];
        b->relief[v] = RblLoadLitShader(d);
        ok = ok && RblIsLitShaderValid(b->relief[v]);
    }
    for (int v = 0; v < TX_VARIANTS; v++)
    {
        RblLitShaderDesc d;
        memset(&d, 0, sizeof(d));
        d.maxLights = 1; d.shading.lightFeatures = RBL_LIGHT_FEATURE_DIRECTIONAL;
        d.transmission = v > 0;
        b->tx[v] = RblLoadLitShader(d);
        ok = ok && RblIsLitShaderValid(b->tx[v]);
    }
    if (!ok) { printf("bench_thin: a variant failed to load\n"); rtCloseContext(); return 1; }
    const BenchTiming timing = { 1, 5, 15, 3e9 };
    double relief[VARIANTS], tx[TX_VARIANTS];
    int runs = BenchMedianOfRuns(ReliefRun, b, VARIANTS, timing, relief);
    b->round = 0;
    int txRuns = BenchMedianOfRuns(TransmissionRun, b, TX_VARIANTS, timing, tx);
    static bool exactLit[4][(FRAME/PROBE)*(FRAME/PROBE)];
    bool known[4] = { false, false, false, false };
    const Vector3 dirs[4] = { { -1.0f, 0.0f, -1.0f }, { 0.0f, 1.0f, -0.6f }, { 0.7f, -0.5f, -0.9f }, { -0.3f, -1.0f, -0.5f } };
    printf("  context: %s; %d relief runs, %d transmission runs, %dx%d card pixels\n", backend, runs, txRuns, FRAME, FRAME);
    printf("  %-16s %12s %12s %18s %22s\n", "case", "ms/frame", "ratio_off", "ns/pixel/step", "vs continuous ray");
    for (int v = 0; v < VARIANTS; v++)
    {
        char name[32];
        if (stepsOf[v] == 0) snprintf(name, sizeof(name), "relief_off"); else snprintf(name, sizeof(name), "relief_steps_%d", stepsOf[v]);
        double perStep = (stepsOf[v] > 0)? (relief[v] - relief[0])*1e6/((double)FRAME*FRAME*stepsOf[v]) : 0.0;
        double mismatch = 0.0;
        for (int k = 0; k < 4; k++) mismatch += ReliefMismatch(b, v, dirs[k], exactLit[k], &known[k])/4.0;
        printf("  %-16s %12.3f %12.3f %18.4f %21.4f%%\n", name, relief[v], relief[v]/relief[0], perStep, mismatch*100.0);
        BenchCsvRow(SUITE, name, "ms_per_frame", relief[v], "ms");
        BenchCsvRow(SUITE, name, "ratio_to_off", relief[v]/relief[0], "ratio");
        if (stepsOf[v] > 0) BenchCsvRow(SUITE, name, "ns_per_pixel_step", perStep, "ns");
        BenchCsvRow(SUITE, name, "continuous_mismatch_fraction", mismatch, "fraction");
    }
    for (int v = 0; v < TX_VARIANTS; v++)
    {
        char name[32];
        snprintf(name, sizeof(name), "transmission_%s", txName[v]);
        printf("  %-16s %12.3f %12.3f\n", name, tx[v], tx[v]/tx[0]);
        BenchCsvRow(SUITE, name, "ms_per_frame", tx[v], "ms");
        BenchCsvRow(SUITE, name, "ratio_to_off", tx[v]/tx[0], "ratio");
    }
    for (int v = 0; v < VARIANTS; v++) RblUnloadLitShader(&b->relief[v]);
    for (int v = 0; v < TX_VARIANTS; v++) RblUnloadLitShader(&b->tx[v]);
    UnloadTexture(b->material); UnloadTexture(b->albedo);
    UnloadRenderTexture(b->target);
    RblClose();
    rtCloseContext();
    return 0;
}
