// Benchmark suite "clustered": frame cost of clustered forward lights (RblLitShaderDesc.clustered,
// the scene's light grid) against the fixed light slots and the deferred helper (GPU, headless GL).
//   scene        bench_deferred's: a floor filling a 1280x720 RenderTexture (one fixed-facing
//                RblBillboard, normal +Y, seen from above at ~40 degrees) lit by 16, 256 and 1024
//                small point lights (range 0.3-0.8, windowed falloff, scattered uniformly over the
//                visible floor with a fixed seed), Lambert.
//   opaque       slots      a lit program with maxLights = min(n, RBL_MAX_LIGHTS); above RBL_MAX_LIGHTS the
//                           floor is drawn again per chunk of 64 lights, added (ONE, ONE) with the ambient in
//                           the first pass only (bench_deferred's forward; the sum of sRGB-encoded passes is not
//                           one pass's image: only its time matters)
//                clustered  one clustered program, one pass, every light (its grid built in RblSetScene,
//                           which is inside the timed frame)
//                deferred   RblSetScene + geometry pass + RblDrawDeferredLights (volumes) + resolve
//   blended      smoke: the floor drawn 4 times as a blended sprite (alpha 0.35, layers 0.05 apart, so
//                every pixel shades 4 layers); clustered: every light; slots: one pass of the first
//                RBL_MAX_LIGHTS lights (what a slot program can light: additive passes cannot
//                compose alpha blending); deferred cannot light blended sprites (no rows).
//   Timing: each case right after a raylib baseline frame (the floor as a GenMeshPlane Mesh by DrawMesh
//   with raylib's default material); ratios are medians of per-run ratios. Each frame: glFinish, draw,
//   glFinish. Checked once, untimed: every case writes every pixel; clustered and slots agree at 16
//   lights (one pass: the same sum); clustered and deferred agree at every count (both light every light;
//   the G-buffer's encoding is the difference).
// Rows (suite "clustered"):
//   raylib_default_material: ms_per_frame_1280x720, spread_pct, runs
//   <slots|clustered|deferred>_<n>lights_<opaque|blended>: ms_per_frame_1280x720, ratio_to_raylib
//   clustered_<n>lights_opaque: deferred_over_clustered, slots_over_clustered (time ratios, > 1: clustered faster)
//   clustered_<n>lights_blended: slots64_over_clustered
//   grid_<n>lights: cells, entries, fullest_cell, build_us (CPU: RblSetScene with a clustered program minus without)
//   check_clustered_vs_slots_16lights, check_clustered_vs_deferred_<n>lights: max_diff (1/255), pixels
// Output: rows appended to $BENCH_CSV (see bench.h) and a summary table on stdout.

#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "rlgl.h"
#include "raymath.h"
#include "harness.h"
#include "bench.h"
#include "bench_floor.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FRAME_W     1280
#define FRAME_H     720
#define COUNTS      3
#define MAX_N       1024
#define FLOOR_SIZE  60.0f
#define LAYERS      4
enum { CASE_SLOTS = 0, CASE_CLUSTERED, CASE_DEFERRED, CASE_SLOTS_BLEND, CASE_CLUSTERED_BLEND, KINDS };
#define CASES       (KINDS*COUNTS)
#define VALUES      (2*CASES + 1)
static const char *kindName[KINDS] = { "slots", "clustered", "deferred", "slots", "clustered" };

typedef struct Scene {
    RenderTexture2D target;
    Camera3D camera;
    RblBillboard floor;
    Mesh plane;
    Matrix planeTransform;
    Material rayMat;
    Texture2D albedo, smoke;
    Shader slots[COUNTS], clustered, geo;
    Material slotMat[COUNTS], clusteredMat, geoMat, slotSmoke, clusteredSmoke;
    int slotCount[COUNTS];
    RblGBuffer g;
    RblLight lights[MAX_N];
    int counts[COUNTS];
    Color ambient;
    bool ok[CASES];
    bool frameOk;
    double baseMin, baseMax;
} Scene;

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
    ClearBackground(BLANK);
    BeginMode3D(s->camera);
    DrawMesh(s->plane, s->rayMat, s->planeTransform);
    EndMode3D();
    EndTextureMode();
}

// The smoke: the floor as LAYERS blended sprites 0.05 apart
static void DrawSmoke(Scene *s, Material m)
{
    for (int k = 0; k < LAYERS; k++)
    {
        RblBillboard b = s->floor;
        b.position.y += 0.05f*(float)k;
        RblDrawBillboard(s->camera, m, b);
    }
}

static void DrawCase(Scene *s, int i)
{
    int kind = i/COUNTS, c = i%COUNTS, n = s->counts[c];
    s->frameOk = true;
    if (kind == CASE_DEFERRED)
    {
        s->frameOk = SetLights(s->lights, n, s->ambient) && RblBeginGBuffer(&s->g, s->camera);
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
        return;
    }
    BeginTextureMode(s->target);
    ClearBackground(BLANK);
    BeginMode3D(s->camera);
    if (kind == CASE_SLOTS)
    {
        int slots = s->slotCount[c], passes = 0;
        for (int first = 0; first < n; first += slots, passes++)
        {
            int k = (n - first < slots)? n - first : slots;
            if (passes == 1) { rlSetBlendFactors(RL_ONE, RL_ONE, RL_FUNC_ADD); rlSetBlendMode(BLEND_CUSTOM); }
            s->frameOk = SetLights(&s->lights[first], k, (passes == 0)? s->ambient : BLACK) && s->frameOk;
            RblDrawBillboard(s->camera, s->slotMat[c], s->floor);
        }
        if (passes > 1) rlSetBlendMode(BLEND_ALPHA);
    }
    else if (kind == CASE_CLUSTERED)
    {
        s->frameOk = SetLights(s->lights, n, s->ambient);
        RblDrawBillboard(s->camera, s->clusteredMat, s->floor);
    }
    else if (kind == CASE_SLOTS_BLEND)
    {
        s->frameOk = SetLights(s->lights, (n < RBL_MAX_LIGHTS)? n : RBL_MAX_LIGHTS, s->ambient);
        s->slotSmoke.shader = s->slots[COUNTS - 1];        // 64 slots (16 lights: 16 of them filled)
        DrawSmoke(s, s->slotSmoke);
    }
    else
    {
        s->frameOk = SetLights(s->lights, n, s->ambient);
        DrawSmoke(s, s->clusteredSmoke);
    }
    EndMode3D();
    EndTextureMode();
}

static double TimeFrame(void *ctx, int i)
{
    Scene *s = (Scene *)ctx;
    rtFinish();
    double t0 = BenchNowNs();
    if (i < 0) DrawBaseline(s); else DrawCase(s, i);
    rtFinish();
    return (BenchNowNs() - t0)*1e-6;
}

static void RoundRun(void *ctx, double *out)
{
    Scene *s = (Scene *)ctx;
    double roundBase = BenchPairedRound(TimeFrame, s, s->ok, CASES, out);
    out[2*CASES] = roundBase;
    if ((s->baseMin == 0.0) || (roundBase < s->baseMin)) s->baseMin = roundBase;
    if (roundBase > s->baseMax) s->baseMax = roundBase;
}

static int UncoveredPixels(Image img)
{
    const unsigned char *p = (const unsigned char *)img.data;
    int missing = 0;
    for (int i = 0; i < img.width*img.height; i++) missing += (p[i*4 + 3] == 0);
    return missing;
}

// Max channel difference over pixels both cover
static int MaxDiff(Image a, Image b, int *pixels)
{
    const unsigned char *p = (const unsigned char *)a.data, *q = (const unsigned char *)b.data;
    int worst = 0;
    *pixels = 0;
    for (int i = 0; i < a.width*a.height; i++)
    {
        if ((p[i*4 + 3] == 0) || (q[i*4 + 3] == 0)) continue;
        (*pixels)++;
        for (int ch = 0; ch < 3; ch++) { int e = abs((int)p[i*4 + ch] - (int)q[i*4 + ch]); if (e > worst) worst = e; }
    }
    return worst;
}

static Material MaterialOf(Shader shader, Texture2D albedo)
{
    Material m = LoadMaterialDefault();
    m.shader = shader;
    m.maps[MATERIAL_MAP_ALBEDO].texture = albedo;
    return m;
}

int main(void)
{
    SetTraceLogLevel(LOG_WARNING);
    const char *backend = rtInitContext(FRAME_W, FRAME_H);
    if (backend == NULL) { printf("bench_clustered: no headless GL context, rows skipped\n"); return 0; }
    int problems = 0;
    static Scene sc;
    Scene *s = &sc;
    memset(s, 0, sizeof(*s));
    const int counts[COUNTS] = { 16, 256, 1024 };
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
    if (!benchScatterFloorLights(s->camera, FRAME_W, FRAME_H, s->lights, MAX_N)) { printf("bench_clustered: a screen corner misses the floor\n"); rtCloseContext(); return 1; }
    Image img = GenImageColor(4, 4, (Color){ 200, 160, 120, 255 });
    s->albedo = LoadTextureFromImage(img);
    UnloadImage(img);
    img = GenImageColor(4, 4, (Color){ 220, 220, 230, 90 });
    s->smoke = LoadTextureFromImage(img);
    UnloadImage(img);
    s->plane = GenMeshPlane(FLOOR_SIZE, FLOOR_SIZE, 1, 1);
    s->planeTransform = MatrixTranslate(s->camera.target.x, 0.0f, s->camera.target.z);
    s->rayMat = LoadMaterialDefault();
    s->rayMat.maps[MATERIAL_MAP_ALBEDO].texture = s->albedo;

    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    for (int c = 0; c < COUNTS; c++)
    {
        RblLitShaderDesc d = desc;
        d.maxLights = (counts[c] < RBL_MAX_LIGHTS)? counts[c] : RBL_MAX_LIGHTS;
        s->slotCount[c] = d.maxLights;
        s->slots[c] = RblLoadLitShader(d);
        s->slotMat[c] = MaterialOf(s->slots[c], s->albedo);
    }
    RblLitShaderDesc cd = desc;
    cd.clustered = true;
    s->clustered = RblLoadLitShader(cd);
    s->clusteredMat = MaterialOf(s->clustered, s->albedo);
    s->clusteredSmoke = MaterialOf(s->clustered, s->smoke);
    s->slotSmoke = MaterialOf(s->slots[COUNTS - 1], s->smoke);
    s->clusteredSmoke.params[RBL_PARAM_ALPHA_CUTOFF] = -1.0f;
    s->slotSmoke.params[RBL_PARAM_ALPHA_CUTOFF] = -1.0f;
    RblLitShaderDesc gd = desc;
    gd.deferred = true;
    s->geo = RblLoadLitShader(gd);
    s->geoMat = MaterialOf(s->geo, s->albedo);
    RblGBufferDesc gbufferDesc;
    memset(&gbufferDesc, 0, sizeof(gbufferDesc));
    gbufferDesc.width = FRAME_W; gbufferDesc.height = FRAME_H;
    s->g = RblLoadGBuffer(gbufferDesc);
    bool clusteredOk = RblIsLitShaderValid(s->clustered), deferredOk = RblIsGBufferValid(s->g) && RblIsLitShaderValid(s->geo);
    for (int c = 0; c < COUNTS; c++)
    {
        s->ok[CASE_SLOTS*COUNTS + c] = s->ok[CASE_SLOTS_BLEND*COUNTS + c] = RblIsLitShaderValid(s->slots[c]) && RblIsLitShaderValid(s->slots[COUNTS - 1]);
        s->ok[CASE_CLUSTERED*COUNTS + c] = s->ok[CASE_CLUSTERED_BLEND*COUNTS + c] = clusteredOk;
        s->ok[CASE_DEFERRED*COUNTS + c] = deferredOk;
    }
    if (!clusteredOk || !deferredOk) { printf("bench_clustered: clustered program or G-buffer failed to load\n"); problems++; }

    // ---- checks (untimed; also the warm-up) ----
    int diffSlots = -1, diffSlotsPx = 0, diffDeferred[COUNTS], diffDeferredPx[COUNTS];
    for (int c = 0; c < COUNTS; c++)
    {
        diffDeferred[c] = -1; diffDeferredPx[c] = 0;
        Image shot[KINDS];
        memset(shot, 0, sizeof(shot));
        for (int k = 0; k < KINDS; k++)
        {
            int i = k*COUNTS + c;
            if (!s->ok[i]) continue;
            DrawCase(s, i);
            s->ok[i] = s->frameOk;
            shot[k] = rtReadTarget(s->target);
            int missing = (k < CASE_SLOTS_BLEND)? UncoveredPixels(shot[k]) : 0;
            if (!s->frameOk || (missing > 0)) { printf("bench_clustered: %s_%dlights: refused or %d pixels unwritten\n", kindName[k], counts[c], missing); problems++; }
        }
        if ((shot[CASE_CLUSTERED].data != NULL) && (shot[CASE_DEFERRED].data != NULL)) diffDeferred[c] = MaxDiff(shot[CASE_CLUSTERED], shot[CASE_DEFERRED], &diffDeferredPx[c]);
        if ((counts[c] <= RBL_MAX_LIGHTS) && (shot[CASE_CLUSTERED].data != NULL) && (shot[CASE_SLOTS].data != NULL)) diffSlots = MaxDiff(shot[CASE_CLUSTERED], shot[CASE_SLOTS], &diffSlotsPx);
        if (c == COUNTS - 1) for (int k = 0; k < KINDS; k++) if (shot[k].data != NULL)
        {
            char path[96];
            snprintf(path, sizeof(path), "build/bench/clustered_%s%s_%d.png", kindName[k], (k >= CASE_SLOTS_BLEND)? "_blended" : "", counts[c]);
            ExportImage(shot[k], path);
        }
        for (int k = 0; k < KINDS; k++) if (shot[k].data != NULL) UnloadImage(shot[k]);
    }

    // ---- grid build cost: RblSetScene with and without a clustered program (CPU) ----
    RblLightGridStats gs[COUNTS];
    double buildUs[COUNTS];
    for (int c = 0; c < COUNTS; c++)
    {
        double with[9], without[9];
        for (int r = 0; r < 9; r++)
        {
            double t0 = BenchNowNs();
            SetLights(s->lights, counts[c], s->ambient);
            with[r] = BenchNowNs() - t0;
        }
        gs[c] = RblGetLightGridStats();
        RblUnloadLitShader(&s->clustered);
        for (int r = 0; r < 9; r++)
        {
            double t0 = BenchNowNs();
            SetLights(s->lights, counts[c], s->ambient);
            without[r] = BenchNowNs() - t0;
        }
        s->clustered = RblLoadLitShader(cd);
        s->clusteredMat.shader = s->clustered; s->clusteredSmoke.shader = s->clustered;
        buildUs[c] = (BenchMedian(with, 9) - BenchMedian(without, 9))*1e-3;
    }

    // ---- frame cost ----
    const BenchTiming timing = { 0, 3, 7, 15e9 };
    double med[VALUES];
    int runs = BenchMedianOfRuns(RoundRun, s, VALUES, timing, med);
    double base = med[2*CASES], spread = (base > 0.0)? 100.0*(s->baseMax - s->baseMin)/base : 0.0;

    printf("bench_clustered (%s, %dx%d, %d runs; raylib DrawMesh baseline %.3f ms, spread %.0f%%)\n", backend, FRAME_W, FRAME_H, runs, base, spread);
    BenchCsvRow("clustered", "raylib_default_material", "ms_per_frame_1280x720", base, "ms");
    BenchCsvRow("clustered", "raylib_default_material", "spread_pct", spread, "%");
    BenchCsvRow("clustered", "raylib_default_material", "runs", runs, "count");
    printf("  %-34s %12s %10s\n", "case", "ms/frame", "x raylib");
    for (int i = 0; i < CASES; i++)
    {
        int k = i/COUNTS, c = i%COUNTS;
        char name[64];
        snprintf(name, sizeof(name), "%s_%dlights_%s", kindName[k], counts[c], (k >= CASE_SLOTS_BLEND)? "blended" : "opaque");
        if (!s->ok[i]) { printf("  %-34s %12s\n", name, "n/a"); continue; }
        printf("  %-34s %12.3f %10.2f\n", name, med[i], med[CASES + i]);
        BenchCsvRow("clustered", name, "ms_per_frame_1280x720", med[i], "ms");
        BenchCsvRow("clustered", name, "ratio_to_raylib", med[CASES + i], "x");
    }
    for (int c = 0; c < COUNTS; c++)
    {
        char name[64];
        double cl = med[CASE_CLUSTERED*COUNTS + c], clb = med[CASE_CLUSTERED_BLEND*COUNTS + c];
        double def = (cl > 0.0)? med[CASE_DEFERRED*COUNTS + c]/cl : 0.0, slo = (cl > 0.0)? med[CASE_SLOTS*COUNTS + c]/cl : 0.0;
        double slb = (clb > 0.0)? med[CASE_SLOTS_BLEND*COUNTS + c]/clb : 0.0;
        snprintf(name, sizeof(name), "clustered_%dlights_opaque", counts[c]);
        BenchCsvRow("clustered", name, "deferred_over_clustered", def, "x");
        BenchCsvRow("clustered", name, "slots_over_clustered", slo, "x");
        snprintf(name, sizeof(name), "clustered_%dlights_blended", counts[c]);
        BenchCsvRow("clustered", name, "slots64_over_clustered", slb, "x");
        printf("  %d lights: deferred/clustered %.2f, slots (multi-pass)/clustered %.2f; blended: slots (first %d lights)/clustered %.2f\n",
               counts[c], def, slo, (counts[c] < RBL_MAX_LIGHTS)? counts[c] : RBL_MAX_LIGHTS, slb);
        snprintf(name, sizeof(name), "grid_%dlights", counts[c]);
        BenchCsvRow("clustered", name, "cells", gs[c].cells[0]*gs[c].cells[1]*gs[c].cells[2], "count");
        BenchCsvRow("clustered", name, "entries", gs[c].entries, "count");
        BenchCsvRow("clustered", name, "fullest_cell", gs[c].fullestCell, "lights");
        BenchCsvRow("clustered", name, "build_us", buildUs[c], "us");
        printf("  grid at %d lights: %dx%dx%d cells of %.3f, %d entries (%.1f per cell), fullest %d, %d unbounded, capped %d; build %.0f us (RblSetScene with - without a clustered program)\n",
               counts[c], gs[c].cells[0], gs[c].cells[1], gs[c].cells[2], gs[c].cellSize, gs[c].entries,
               gs[c].entries/(double)((gs[c].cells[0]*gs[c].cells[1]*gs[c].cells[2] > 0)? gs[c].cells[0]*gs[c].cells[1]*gs[c].cells[2] : 1), gs[c].fullestCell, gs[c].unbounded, gs[c].cappedCells, buildUs[c]);
        snprintf(name, sizeof(name), "check_clustered_vs_deferred_%dlights", counts[c]);
        BenchCsvRow("clustered", name, "max_diff", diffDeferred[c], "1/255");
        BenchCsvRow("clustered", name, "pixels", diffDeferredPx[c], "count");
        printf("  check: clustered vs deferred at %d lights max %d/255 over %d px\n", counts[c], diffDeferred[c], diffDeferredPx[c]);
    }
    BenchCsvRow("clustered", "check_clustered_vs_slots_16lights", "max_diff", diffSlots, "1/255");
    BenchCsvRow("clustered", "check_clustered_vs_slots_16lights", "pixels", diffSlotsPx, "count");
    printf("  check: clustered vs slots at 16 lights max %d/255 over %d px\n", diffSlots, diffSlotsPx);
    if ((diffSlots < 0) || (diffSlots > 1)) { printf("bench_clustered: clustered and slots differ at 16 lights\n"); problems++; }

    for (int c = 0; c < COUNTS; c++) { RblUnloadLitShader(&s->slots[c]); MemFree(s->slotMat[c].maps); }
    RblUnloadLitShader(&s->clustered);
    RblUnloadLitShader(&s->geo);
    RblUnloadGBuffer(&s->g);
    UnloadTexture(s->albedo); UnloadTexture(s->smoke);
    UnloadMesh(s->plane);
    UnloadRenderTexture(s->target);
    RblClose();
    rtCloseContext();
    return (problems > 0)? 1 : 0;
}
