// Benchmark suite "shadows": cost of the shadow pass and of shadow receivers, and the shadow-edge
// error of each PCF footprint against the analytic hard shadow (GPU, headless GL).
//   shadow pass  ns per billboard of one directional shadow pass (RblBeginShadowMap .. RblEndShadowMap,
//                the map's clear included) drawing N = 1k and 10k billboards into maps of 512, 1024 and
//                2048 texels per side, on the batched path (RblBeginBatch, RblBatchAdd per billboard,
//                RblEndBatch) and the instanced path (one RblDrawInstanced). The billboards are
//                bench_geometry's set (fixed seed, sizes 0.5..2 in a 20 x 7 x 18 box, camera-plane facing
//                the colour pass's camera) with an alpha-tested disc sprite; the light is directional and
//                the focus sphere bounds the box. The raylib baseline, timed in the same run: the same N
//                billboards drawn by DrawBillboardPro (raylib's default shader, unlit, alpha blended,
//                facing the same camera) into a RenderTexture of the map's size, seen through an
//                orthographic raylib camera equal to the light's view, so both rasterise about the same
//                texels. One round draws one frame of each path (order rotating, as bench_geometry);
//                ratio_to_raylib is the median of the per-round ratios. Each frame: glFinish, then the
//                clock runs from the first call (RblBeginShadowMap / BeginTextureMode) to the return of
//                a glFinish after the last one (RblEndShadowMap / EndTextureMode): driver, vertex and
//                fragment work included (on llvmpipe all of it runs on the CPU, in the timed region).
//                An empty frame of each kind (no billboard: the clear) is timed in every round too;
//                marginal_ns_per_billboard = (frame - empty frame of its kind)/N, per round.
//                Checked once, untimed (1k billboards, 512 map): the fraction of texels each path covers
//                (shadow maps: depth < 1 read back with glReadPixels; raylib: alpha > 0; raylib covers a
//                little less, as its transparent sprite corners write depth and hide billboards behind
//                them) and the texels where the batched and instanced maps differ by more than 1e-5.
//   receiver     ms per frame at 1280x720 of a floor filling the view (one fixed-facing RblBillboard,
//                normal +Z, white, Lambert), seen straight down by an orthographic camera, lit by one
//                directional light and the flat ambient, receiving one 512 shadow map cast by an opaque
//                square card (3 x 3, height 1.5, turned 17 degrees so its shadow's edges cross the pixel
//                and texel grids obliquely; drawn only into the shadow map), for desc.shadowFilter 1, 2,
//                3, 4 and 6 ((n + 1)^2 depth fetches per pixel), against the same receiver variant built
//                with desc.shadowMaps = 0 (the unshadowed baseline) and raylib's own DrawBillboardPro of
//                the floor (unlit). Also timed: the pcf 2 shadow variant given no map (a scene with
//                shadowMapCount 0, nothing shadowed): what compiling shadow support in costs a scene without
//                shadows. The shadow map is rendered once (untimed); each timed frame calls RblSetScene
//                (the scene with the map for the shadowed variants, without it for the unshadowed and
//                no-map ones; it uploads to every live lit program), then draws the floor: glFinish,
//                draw, glFinish. One run
//                times raylib once, then each shadowed variant right after an unshadowed frame; ratios
//                are medians of per-run ratios (bench_lighting's scheme).
//   edge error   for each filter, the rendered RGBA8 image against the analytic hard shadow computed in
//                double precision: each pixel's floor point (the orthographic camera maps pixel centres
//                to known floor points) casts a ray toward the light; it is shadowed when the ray
//                crosses the card's plane inside the square. The expected lit and shadowed values come
//                from tests/lighting_reference.h (Lambert, sRGB). Per channel |pixel - expected| in
//                1/255: mean and max over pixels within 3 texels of the analytic shadow edge, over all
//                pixels, and the max over pixels farther than 4 texels, beyond the widest footprint's
//                reach (acne or leaks). Distances are measured in the light's view plane (perpendicular
//                to the light), in shadow-map texels (texel = 2 x focus radius / (size - 1), as
//                RblBeginShadowMap lays the map out). Edge width: the shadow factor (linear light:
//                (v - dark)/(lit - dark) after sRGB decoding) is averaged in bins of 1/8 texel of signed
//                distance along each of the 4 edges (pixels within 3 texels of a corner left out);
//                width = distance from the 10% to the 90% level, averaged over the edges;
//                shift = the largest |distance| of the 50% level from the
//                analytic edge (bias and normal offset move the edge). Next to it the ideal width of a
//                footprint of n texels: a box of n texels over the texel-quantised step, the edge falling
//                uniformly within a texel (box(n) convolved with box(1)).
// Rows (suite "shadows"):
//   pass_<raylib|batched|instanced>_<N>_<size>: ns_per_billboard, marginal_ns_per_billboard;
//   batched/instanced also ratio_to_raylib, marginal_ratio_to_raylib
//   pass_<N>_<size>: runs; pass_empty_<size>, pass_raylib_empty_<size>: ms_per_pass
//   check_coverage_<path>_1000_512: covered_fraction; check_batched_vs_instanced_depth: texels_differing
//   receiver_raylib_default_shader: ms_per_frame_1280x720
//   receiver_unshadowed: ms_per_frame_1280x720, ratio_to_raylib, spread_pct, runs, max_err_lit (1/255,
//   against the analytic lit value: the shading error without shadows)
//   receiver_pcf<n>: ms_per_frame_1280x720, ratio_to_unshadowed, ratio_to_raylib, fetches_per_pixel,
//   edge_mean_err, edge_max_err, all_mean_err, all_max_err, away_max_err (1/255), edge_pixels,
//   edge_width (texels, 10% to 90%), edge_width_ideal, edge_shift (texels)
//   receiver_pcf2_no_map: ms_per_frame_1280x720, ratio_to_unshadowed, ratio_to_raylib, max_err_lit
//   receiver_setup: pixels_per_texel, texel_world (world units), lit_value, dark_value (0..255)
// Output: rows appended to $BENCH_CSV (see bench.h) and a summary table on stdout.
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "rlgl.h"
#include "harness.h"
#include "bench.h"
#include "lighting_reference.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

//----------------------------------------------------------------------------------
// Defines and Macros
//----------------------------------------------------------------------------------
#define SUITE               "shadows"
#define FRAME_W             1280
#define FRAME_H             720
#define SCENE_SEED          0x2545F491u // bench_geometry's billboard set
#define PASS_MAX            10000       // Largest pass; the 1k pass draws a prefix of the same set
#define PASS_COUNTS         2
#define MAP_SIZES           3
#define SPRITE_SIZE         64          // Disc sprite (alpha-tested by the caster)
#define PASS_FOCUS_RADIUS   16.0f       // Bounds the billboard box (half-diagonal 13.9) and their extents

#define GL_DEPTH_COMPONENT_ 0x1902
#define GL_FLOAT_           0x1406

#define RX_MAP              512         // Receiver's shadow map
#define RX_FOCUS            8.0f        // Focus radius around the origin: texel = 16/511 world units
#define RX_VIEW             8.0f        // World units the top-down camera sees top to bottom
#define RX_FLOOR            20.0f       // Floor side (beyond the 14.2 x 8 view)
#define RX_CARD             3.0f        // Card side
#define RX_CARD_HEIGHT      1.5f
#define RX_CARD_TURN        17.0f       // Degrees about +Z
#define RX_FILTERS          5
#define RX_SHADOWED         (RX_FILTERS + 1)    // the filters, then the shadow variant given no map
#define RX_VARIANTS         (RX_SHADOWED + 2)   // raylib, unshadowed, then those
#define RX_EDGE_TEXELS      3.0         // "Near the edge": within this many texels
#define RX_AWAY_TEXELS      (0.5*RBL_SHADOW_MAX_FILTER + 1.0)   // "Away": beyond the widest filter's reach
#define RX_BIN              0.125       // Edge profile bin, texels
#define RX_BIN_RANGE        8.0         // Profile over [-range, range] texels
#define RX_BINS             128         // 2 x RX_BIN_RANGE / RX_BIN

//----------------------------------------------------------------------------------
// Types and Structures Definition
//----------------------------------------------------------------------------------
typedef enum { PASS_RAYLIB = 0, PASS_BATCHED, PASS_INSTANCED, PASS_PATHS } PassPath;
static const char *passName[PASS_PATHS] = { "raylib", "batched", "instanced" };
static const int passCounts[PASS_COUNTS] = { 1000, 10000 };
static const int mapSizes[MAP_SIZES] = { 512, 1024, 2048 };

typedef struct PassScene {
    Camera3D viewer;                // the colour pass's camera: billboards face it in every path
    Camera3D lightCamera;           // raylib orthographic camera over the light's view (baseline)
    RblLight light;
    RblScene scene;                 // the light alone (RblBeginShadowMap takes the scene's light index)
    Vector3 focus;
    float radius;
    Texture2D sprite;
    Shader lit, litInstanced;       // the colour pass's materials (the shadow pass swaps the casters in)
    Material material, materialInstanced;
    RblBatch batch;
    RblInstanceBuffer instances;
    RblInstancedDesc instancedDesc;
    RblBillboard *billboards;
    RblInstance *instanceSet;
    RblShadowMap maps[MAP_SIZES];
    RenderTexture2D targets[MAP_SIZES];
    int count;                      // case being timed
    int size;                       // map size index
    int round;
    bool ok;                        // every API call of every frame accepted
} PassScene;

// Values of one pass round
#define PV_NS(p)            (p)                     // ns per billboard of path p
#define PV_RATIO(p)         (PASS_PATHS + (p))      // ratio to raylib (raylib: 1)
#define PV_MARGINAL(p)      (2*PASS_PATHS + (p))    // (frame - empty frame of its kind)/N, ns
#define PV_MRATIO(p)        (3*PASS_PATHS + (p))    // marginal ratio to raylib's marginal
#define PV_EMPTY            (4*PASS_PATHS)          // empty shadow pass, ms
#define PV_EMPTY_RAYLIB     (4*PASS_PATHS + 1)      // empty raylib frame (clear only), ms
#define PV_VALUES           (4*PASS_PATHS + 2)

typedef struct Receiver {
    RenderTexture2D target;
    Camera3D camera;                // top-down orthographic
    RblBillboard floor;
    RblLight light;
    Color ambient;
    RblScene scene, sceneNoMap;     // light and ambient, with the map (shadowed variants) and without
    Texture2D white;
    Shader shader[RX_VARIANTS];     // [0] unused (raylib)
    Material material[RX_VARIANTS];
    RblShadowMap map;
    bool ok[RX_VARIANTS];
    bool frameOk;
    double baseMin, baseMax;        // spread of the per-run unshadowed baselines
} Receiver;

enum { RX_RAYLIB = 0, RX_UNSHADOWED = 1, RX_NOMAP = RX_VARIANTS - 1 };  // filter k: RX_UNSHADOWED + 1 + k
static const int rxFilters[RX_FILTERS] = { 1, 2, 3, 4, 6 };
#define RX_NOMAP_FILTER     2           // the default footprint

// Values of one receiver run
#define RV_MS(v)            (v)                             // ms of variant v
#define RV_RATIO_BASE(k)    (RX_VARIANTS + (k))             // shadowed variant k (RX_UNSHADOWED + 1 + k) / unshadowed
#define RV_RATIO_RAYLIB(v)  (RX_VARIANTS + RX_SHADOWED + (v) - 1)  // variant v (>= 1) / raylib
#define RV_VALUES           (RX_VARIANTS + RX_SHADOWED + RX_VARIANTS - 1)

// Analytic shadow of the card, in double precision
typedef struct Analytic {
    D3 light;                       // unit direction the light travels
    D3 e1, e2;                      // orthonormal basis of the plane perpendicular to it (light view)
    D3 centre, u, w;                // card centre and in-plane unit axes
    double half;                    // half side
    double corner[4][2];            // card corners in the light view (a parallelogram's, in order)
    double texel;                   // world size of a shadow-map texel
    double pixel;                   // world size of a pixel (square pixels)
} Analytic;

typedef struct EdgeStats {
    double edgeMean, edgeMax, allMean, allMax, awayMax;
    int edgePixels;
    double width, shift;            // texels; < 0 when a profile never crossed its levels
} EdgeStats;

//----------------------------------------------------------------------------------
// Shadow pass
//----------------------------------------------------------------------------------
// bench_geometry's billboards (its seed and ranges; atlas frames replaced by the whole disc sprite)
static bool BuildPassScene(PassScene *p)
{
    p->viewer.position = (Vector3){ 0.0f, 3.0f, 12.0f };
    p->viewer.target = (Vector3){ 0.0f, 1.0f, 0.0f };
    p->viewer.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    p->viewer.fovy = 60.0f;
    p->viewer.projection = CAMERA_PERSPECTIVE;
    p->billboards = (RblBillboard *)calloc(PASS_MAX, sizeof(RblBillboard));
    p->instanceSet = (RblInstance *)calloc(PASS_MAX, sizeof(RblInstance));
    if ((p->billboards == NULL) || (p->instanceSet == NULL)) return false;
    unsigned int seed = SCENE_SEED;
    for (int i = 0; i < PASS_MAX; i++)
    {
        RblBillboard *b = &p->billboards[i];
        b->position.x = rtRandomRange(&seed, -10.0f, 10.0f);
        b->position.y = rtRandomRange(&seed, -2.0f, 5.0f);
        b->position.z = rtRandomRange(&seed, -15.0f, 3.0f);
        b->size.x = rtRandomRange(&seed, 0.5f, 2.0f);
        b->size.y = rtRandomRange(&seed, 0.5f, 2.0f);
        b->origin = (Vector2){ b->size.x*0.5f, b->size.y*0.5f };
        (void)rtRandom(&seed);                      // bench_geometry's atlas frame
        (void)rtRandomRange(&seed, 0.0f, 360.0f);   // and rotation (unrotated set)
        b->tint = WHITE;
        b->facing = RBL_FACING_CAMERA_PLANE;
        b->up = (Vector3){ 0.0f, 1.0f, 0.0f };      // as DrawBillboardPro's up
        RblInstance *in = &p->instanceSet[i];
        in->position = b->position;
        in->size = b->size;
        in->origin = b->origin;
        in->tint = WHITE;
    }
    p->instancedDesc.facing = RBL_FACING_CAMERA_PLANE;
    p->instancedDesc.up = (Vector3){ 0.0f, 1.0f, 0.0f };

    memset(&p->light, 0, sizeof(p->light));
    p->light.type = RBL_LIGHT_DIRECTIONAL;
    p->light.direction = (Vector3){ -0.4f, -1.0f, -0.3f };
    p->light.color = WHITE;
    p->light.intensity = 1.0f;
    p->focus = (Vector3){ 0.0f, 1.5f, -6.0f };
    p->radius = PASS_FOCUS_RADIUS;
    p->scene.lights = &p->light;
    p->scene.lightCount = 1;
    // The light's view as RblBeginShadowMap builds it: eye 2r before the focus centre, orthographic
    // over 2r (raylib's orthographic fovy = view height); the header snaps the window to whole texels
    float l = sqrtf(p->light.direction.x*p->light.direction.x + p->light.direction.y*p->light.direction.y + p->light.direction.z*p->light.direction.z);
    Vector3 d = { p->light.direction.x/l, p->light.direction.y/l, p->light.direction.z/l };
    p->lightCamera.position = (Vector3){ p->focus.x - d.x*2.0f*p->radius, p->focus.y - d.y*2.0f*p->radius, p->focus.z - d.z*2.0f*p->radius };
    p->lightCamera.target = p->focus;
    p->lightCamera.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    p->lightCamera.fovy = 2.0f*p->radius;
    p->lightCamera.projection = CAMERA_ORTHOGRAPHIC;
    return true;
}

// One frame of a path (count 0: an empty pass); ns per billboard, or ms when count is 0
static double PassFrame(PassScene *p, PassPath path, int count, int s)
{
    const Vector3 up = { 0.0f, 1.0f, 0.0f };
    const Rectangle source = { 0.0f, 0.0f, (float)p->sprite.width, (float)p->sprite.height };
    rtFinish();
    double t0 = BenchNowNs();
    if (path == PASS_RAYLIB)
    {
        BeginTextureMode(p->targets[s]);
        ClearBackground(BLANK);
        BeginMode3D(p->lightCamera);
        for (int i = 0; i < count; i++)
        {
            const RblBillboard *b = &p->billboards[i];
            DrawBillboardPro(p->viewer, p->sprite, source, b->position, up, b->size, b->origin, 0.0f, WHITE);
        }
        EndMode3D();
        EndTextureMode();
    }
    else if (RblBeginShadowMap(&p->maps[s], &p->scene, 0, p->focus, p->radius))
    {
        if ((path == PASS_BATCHED) && (count > 0))
        {
            RblBeginBatch(&p->batch, p->viewer);
            for (int i = 0; i < count; i++) RblBatchAdd(&p->batch, p->material, &p->billboards[i]);
            RblEndBatch(&p->batch);
            if (p->batch.skipped != 0) p->ok = false;
        }
        else if ((path == PASS_INSTANCED) && (count > 0))
        {
            if (RblDrawInstanced(&p->instances, p->viewer, p->materialInstanced, p->instancedDesc, p->instanceSet, count) != count) p->ok = false;
        }
        RblEndShadowMap(&p->maps[s]);
    }
    else p->ok = false;
    rtFinish();
    double ns = BenchNowNs() - t0;
    return (count > 0)? ns/count : ns*1e-6;
}

// One frame of each path, the order rotating per round, and an empty frame of each kind
static void PassRound(void *ctx, double *out)
{
    PassScene *p = (PassScene *)ctx;
    for (int i = 0; i < PASS_PATHS; i++)
    {
        PassPath path = (PassPath)((p->round + i)%PASS_PATHS);
        out[PV_NS(path)] = PassFrame(p, path, p->count, p->size);
    }
    out[PV_EMPTY] = PassFrame(p, PASS_BATCHED, 0, p->size);
    out[PV_EMPTY_RAYLIB] = PassFrame(p, PASS_RAYLIB, 0, p->size);
    for (int i = 0; i < PASS_PATHS; i++)
    {
        double empty = (i == PASS_RAYLIB)? out[PV_EMPTY_RAYLIB] : out[PV_EMPTY];
        out[PV_MARGINAL(i)] = out[PV_NS(i)] - empty*1e6/p->count;
    }
    for (int i = 0; i < PASS_PATHS; i++)
    {
        out[PV_RATIO(i)] = (out[PV_NS(PASS_RAYLIB)] > 0.0)? out[PV_NS(i)]/out[PV_NS(PASS_RAYLIB)] : 0.0;
        out[PV_MRATIO(i)] = (out[PV_MARGINAL(PASS_RAYLIB)] > 0.0)? out[PV_MARGINAL(i)]/out[PV_MARGINAL(PASS_RAYLIB)] : 0.0;
    }
    p->round++;
}

// Check (untimed): texels a pass covers. Shadow maps: depth < 1 read back from the map's framebuffer;
// raylib's target: alpha > 0. Returns the covered fraction (-1 when unreadable); depth kept in *depth
static double PassCoverage(PassScene *p, PassPath path, int count, int s, float **depth)
{
    int n = mapSizes[s];
    PassFrame(p, path, count, s);
    if (path == PASS_RAYLIB)
    {
        Image img = rtReadTarget(p->targets[s]);
        const unsigned char *px = (const unsigned char *)img.data;
        long covered = 0;
        for (int i = 0; i < n*n; i++) covered += (px[i*4 + 3] > 0);
        UnloadImage(img);
        return (double)covered/((double)n*n);
    }
    void (*readPixels)(int, int, int, int, unsigned int, unsigned int, void *) = NULL;
    void *proc = rtGlProc("glReadPixels");
    float *d = (float *)malloc((size_t)n*n*sizeof(float));
    if ((proc == NULL) || (d == NULL)) { free(d); return -1.0; }
    memcpy(&readPixels, &proc, sizeof(proc));
    rlEnableFramebuffer(p->maps[s].state->id);
    readPixels(0, 0, n, n, GL_DEPTH_COMPONENT_, GL_FLOAT_, d);
    rlDisableFramebuffer();
    long covered = 0;
    for (int i = 0; i < n*n; i++) covered += (d[i] < 1.0f);
    *depth = d;
    return (double)covered/((double)n*n);
}

//----------------------------------------------------------------------------------
// Receiver
//----------------------------------------------------------------------------------
static Camera3D TopDown(void)
{
    Camera3D c;
    memset(&c, 0, sizeof(c));
    c.position = (Vector3){ 0.0f, 0.0f, 10.0f };
    c.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    c.fovy = RX_VIEW;
    c.projection = CAMERA_ORTHOGRAPHIC;
    return c;
}

// The card as a fixed-facing billboard (normal +Z, up turned by RX_CARD_TURN about +Z)
static RblBillboard Card(void)
{
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    double a = RX_CARD_TURN*PI/180.0;
    b.position = (Vector3){ 0.0f, 0.0f, RX_CARD_HEIGHT };
    b.size = (Vector2){ RX_CARD, RX_CARD };
    b.origin = (Vector2){ RX_CARD*0.5f, RX_CARD*0.5f };
    b.facing = RBL_FACING_FIXED;
    b.axis = (Vector3){ 0.0f, 0.0f, 1.0f };
    b.up = (Vector3){ (float)-sin(a), (float)cos(a), 0.0f };
    return b;
}

static void DrawReceiver(Receiver *r, int v)
{
    r->frameOk = true;
    if (v != RX_RAYLIB) r->frameOk = RblSetScene(((v == RX_UNSHADOWED) || (v == RX_NOMAP))? &r->sceneNoMap : &r->scene);
    BeginTextureMode(r->target);
    ClearBackground(BLANK);                 // alpha 0: coverage check
    BeginMode3D(r->camera);
    if (v == RX_RAYLIB)
    {
        Rectangle source = { 0.0f, 0.0f, (float)r->white.width, (float)r->white.height };
        DrawBillboardPro(r->camera, r->white, source, r->floor.position, r->floor.up, r->floor.size, r->floor.origin, 0.0f, WHITE);
    }
    else RblDrawBillboard(r->camera, r->material[v], r->floor);
    EndMode3D();
    EndTextureMode();
}

// glFinish, draw, glFinish; milliseconds
static double TimeReceiver(Receiver *r, int v)
{
    rtFinish();
    double t0 = BenchNowNs();
    DrawReceiver(r, v);
    rtFinish();
    return (BenchNowNs() - t0)*1e-6;
}

// raylib once, then each shadowed variant right after an unshadowed frame (the run's baseline: their median)
static void ReceiverRun(void *ctx, double *out)
{
    Receiver *r = (Receiver *)ctx;
    double base[RX_SHADOWED];
    int nb = 0;
    for (int k = 0; k < RV_VALUES; k++) out[k] = 0.0;
    out[RV_MS(RX_RAYLIB)] = TimeReceiver(r, RX_RAYLIB);
    for (int k = 0; k < RX_SHADOWED; k++)
    {
        int v = RX_UNSHADOWED + 1 + k;
        if (!r->ok[v]) continue;
        base[nb++] = TimeReceiver(r, RX_UNSHADOWED);
        out[RV_MS(v)] = TimeReceiver(r, v);
    }
    double runBase = (nb > 0)? BenchMedian(base, nb) : TimeReceiver(r, RX_UNSHADOWED);
    out[RV_MS(RX_UNSHADOWED)] = runBase;
    for (int k = 0; k < RX_SHADOWED; k++) out[RV_RATIO_BASE(k)] = (runBase > 0.0)? out[RV_MS(RX_UNSHADOWED + 1 + k)]/runBase : 0.0;
    for (int v = 1; v < RX_VARIANTS; v++) out[RV_RATIO_RAYLIB(v)] = (out[RV_MS(RX_RAYLIB)] > 0.0)? out[RV_MS(v)]/out[RV_MS(RX_RAYLIB)] : 0.0;
    if ((r->baseMin == 0.0) || (runBase < r->baseMin)) r->baseMin = runBase;
    if (runBase > r->baseMax) r->baseMax = runBase;
}

//----------------------------------------------------------------------------------
// Analytic shadow and edge error
//----------------------------------------------------------------------------------
static Analytic BuildAnalytic(RblLight light, RblBillboard card, double focusRadius, int mapSize)
{
    Analytic a;
    memset(&a, 0, sizeof(a));
    a.light = dNorm(d3f(light.direction));
    a.e1 = dNorm(dCross(a.light, d3(0, 0, 1)));      // the light is not vertical here
    a.e2 = dCross(a.light, a.e1);
    a.centre = d3f(card.position);
    a.w = dNorm(d3f(card.up));
    a.u = dCross(a.w, d3(0, 0, 1));                   // a square: either in-plane perpendicular will do
    a.half = 0.5*card.size.x;
    const double su[4] = { -1, 1, 1, -1 }, sw[4] = { -1, -1, 1, 1 };
    for (int k = 0; k < 4; k++)
    {
        D3 c = dAdd(a.centre, dAdd(dScale(a.u, su[k]*a.half), dScale(a.w, sw[k]*a.half)));
        a.corner[k][0] = dDot(c, a.e1);
        a.corner[k][1] = dDot(c, a.e2);
    }
    a.texel = 2.0*focusRadius/(mapSize - 1.0);        // RblBeginShadowMap's orthographic layout
    a.pixel = RX_VIEW/(double)FRAME_H;
    return a;
}

// Floor point (z = 0) seen through the centre of pixel (x, y) (top row first) of the top-down camera
static D3 FloorAt(int x, int y)
{
    double top = RX_VIEW*0.5, right = top*FRAME_W/(double)FRAME_H;
    return d3(((x + 0.5)/FRAME_W*2.0 - 1.0)*right, (1.0 - (y + 0.5)/FRAME_H*2.0)*top, 0.0);
}

// Ray from the floor point toward the light: shadowed when it crosses the card's plane inside the square
static bool Shadowed(const Analytic *a, D3 p)
{
    double t = (a->centre.z - p.z)/(-a->light.z);
    D3 q = dSub(dSub(p, dScale(a->light, t)), a->centre);
    return (fabs(dDot(q, a->u)) < a->half) && (fabs(dDot(q, a->w)) < a->half);
}

// Distance in texels, in the light's view, from p to the shadow's outline; the nearest edge and how
// far (texels) the nearest point lies from that edge's ends
static double EdgeDistance(const Analytic *a, D3 p, int *edge, double *fromCorner)
{
    double px = dDot(p, a->e1), py = dDot(p, a->e2), best = 1e300;
    for (int k = 0; k < 4; k++)
    {
        const double *c0 = a->corner[k], *c1 = a->corner[(k + 1)%4];
        double ex = c1[0] - c0[0], ey = c1[1] - c0[1], len2 = ex*ex + ey*ey;
        double t = ((px - c0[0])*ex + (py - c0[1])*ey)/len2;
        t = fmin(fmax(t, 0.0), 1.0);
        double dx = px - (c0[0] + t*ex), dy = py - (c0[1] + t*ey), d = sqrt(dx*dx + dy*dy);
        if (d < best) { best = d; *edge = k; *fromCorner = fmin(t, 1.0 - t)*sqrt(len2)/a->texel; }
    }
    return best/a->texel;
}

// First distance where the profile reaches level (linear between non-empty bins, scanning from the
// shadowed side); -1e9 when it never does
static double Crossing(const double *sum, const int *n, double level)
{
    double prevD = 0.0, prevV = 0.0;
    bool have = false;
    for (int b = 0; b < RX_BINS; b++)
    {
        if (n[b] == 0) continue;
        double d = -RX_BIN_RANGE + (b + 0.5)*RX_BIN, v = sum[b]/n[b];
        if (v >= level) return (!have || (v == prevV))? d : prevD + (d - prevD)*(level - prevV)/(v - prevV);
        prevD = d; prevV = v; have = true;
    }
    return -1e9;
}

static EdgeStats MeasureEdge(const Analytic *a, Image img, int litByte, int darkByte)
{
    EdgeStats st;
    memset(&st, 0, sizeof(st));
    static double sum[4][RX_BINS];
    static int cnt[4][RX_BINS];
    memset(sum, 0, sizeof(sum));
    memset(cnt, 0, sizeof(cnt));
    double litLin = srgbDecode(litByte/255.0), darkLin = srgbDecode(darkByte/255.0);
    double edgeSum = 0.0, allSum = 0.0;
    long edgeValues = 0, allValues = 0;
    const unsigned char *px = (const unsigned char *)img.data;
    for (int y = 0; y < FRAME_H; y++)
        for (int x = 0; x < FRAME_W; x++)
        {
            D3 p = FloorAt(x, y);
            bool dark = Shadowed(a, p);
            int edge = 0;
            double fromCorner = 0.0, d = EdgeDistance(a, p, &edge, &fromCorner);
            double signedD = dark? -d : d;
            const unsigned char *c = px + ((size_t)y*FRAME_W + x)*4;
            int expected = dark? darkByte : litByte;
            bool near = (d <= RX_EDGE_TEXELS);
            double lin = 0.0;
            for (int ch = 0; ch < 3; ch++)
            {
                double e = (c[3] == 255)? fabs((double)c[ch] - expected) : 255.0;   // unwritten: wrong outright
                allSum += e; allValues++;
                if (e > st.allMax) st.allMax = e;
                if (near) { edgeSum += e; edgeValues++; if (e > st.edgeMax) st.edgeMax = e; }
                if ((d > RX_AWAY_TEXELS) && (e > st.awayMax)) st.awayMax = e;
                lin += srgbDecode(c[ch]/255.0)/3.0;
            }
            if (near) st.edgePixels++;
            if ((fromCorner >= RX_EDGE_TEXELS) && (fabs(signedD) < RX_BIN_RANGE))
            {
                int b = (int)floor((signedD + RX_BIN_RANGE)/RX_BIN);
                if ((b >= 0) && (b < RX_BINS)) { sum[edge][b] += (lin - darkLin)/(litLin - darkLin); cnt[edge][b]++; }
            }
        }
    st.edgeMean = (edgeValues > 0)? edgeSum/edgeValues : 0.0;
    st.allMean = (allValues > 0)? allSum/allValues : 0.0;
    double width = 0.0;
    st.shift = 0.0;
    bool ok = true;
    for (int k = 0; k < 4; k++)
    {
        double d10 = Crossing(sum[k], cnt[k], 0.1), d50 = Crossing(sum[k], cnt[k], 0.5), d90 = Crossing(sum[k], cnt[k], 0.9);
        if ((d10 < -1e8) || (d50 < -1e8) || (d90 < -1e8)) { ok = false; continue; }
        width += (d90 - d10)/4.0;
        if (fabs(d50) > st.shift) st.shift = fabs(d50);
    }
    st.width = ok? width : -1.0;
    if (!ok) st.shift = -1.0;
    return st;
}

// 10%..90% width (texels) of the profile a footprint of n texels gives when the edge falls anywhere in a
// texel: the box of n convolved with a box of 1 (the step at the texel boundary, uniformly placed)
static double IdealWidth(int n)
{
    double x10 = (0.5/n >= 0.1)? sqrt(0.2*n) : 0.5 + 0.1*n;     // quadratic foot below x = 1, then linear
    return n + 1.0 - 2.0*x10;
}

//----------------------------------------------------------------------------------
// Main
//----------------------------------------------------------------------------------
//----------------------------------------------------------------------------------
// Sprite self-shadowing (issue #26, item 1): caster identities against depth-only maps
//----------------------------------------------------------------------------------
// pass     ns per billboard of the pass above (1k and 10k billboards, map 1024, camera-facing casters)
//          into a map with the casters target and identities (the default) and into a depth-only
//          map (RblShadowDesc.selfShadow, the 0.4 format), timed alternately per round; ratio =
//          median of per-round ratios
// receiver ms per frame of the pcf 2 receiver above reading the casters target (identity compare in
//          each fetch) and a depth-only map of the same card, alternately; ratio as above
// sweep    the errors: a 1 x 2 sprite on a floor, its normal map bending the normal up to 60
//          degrees, a directional light at azimuth 0..345 (15-degree steps) x elevation 5..85
//          (20-degree steps), AXIS and CAMERA_PLANE sprites, pivot at the feet; each case rendered
//          with and without the sprite in the pass (the floor casts in both): cases where any
//          sprite pixel darkens by more than 2/255, the worst darkening and the darkened share of the
//          sprite's pixels, per caster mode (light-, camera-facing) and map (identities, depth only)
#define SELF_MAP            1024
#define SELF_VIEW           48
#define SELF_MODES          4           // identities light-facing, identities camera-facing, depth light-facing, depth camera-facing
typedef struct SelfBench {
    double passNs[2][PASS_COUNTS][2], passRatio[2][PASS_COUNTS];    // [path batched/instanced][count][identities, depth]
    double rxMs[2], rxRatio;                                        // [identities, depth]
    int cases[SELF_MODES], darkened[SELF_MODES], worst[SELF_MODES];
    double worstShare[SELF_MODES];
    RblShadowMap idMap, depthMap;
    RblShadowMap rxDepthMap;
    PassScene *p;
    Receiver *r;
    RblScene rxDepthScene;
    int count;
} SelfBench;
static const char *selfModeName[SELF_MODES] = { "identities_light_facing", "identities_camera_facing", "depth_light_facing", "depth_camera_facing" };

static double SelfPassFrame(SelfBench *sb, bool batched, bool identities)
{
    PassScene *p = sb->p;
    RblShadowMap *map = identities? &sb->idMap : &sb->depthMap;
    rtFinish();
    double t0 = BenchNowNs();
    if (RblBeginShadowMap(map, &p->scene, 0, p->focus, p->radius))
    {
        if (batched)
        {
            RblBeginBatch(&p->batch, p->viewer);
            for (int i = 0; i < sb->count; i++) RblBatchAdd(&p->batch, p->material, &p->billboards[i]);
            RblEndBatch(&p->batch);
        }
        else RblDrawInstanced(&p->instances, p->viewer, p->materialInstanced, p->instancedDesc, p->instanceSet, sb->count);
        RblEndShadowMap(map);
    }
    rtFinish();
    return (BenchNowNs() - t0)/sb->count;
}

static void SelfPassRound(void *ctx, double *out)
{
    SelfBench *sb = (SelfBench *)ctx;
    for (int path = 0; path < 2; path++)
    {
        static int flip = 0;
        flip ^= 1;
        double a = SelfPassFrame(sb, path == 0, flip), b = SelfPassFrame(sb, path == 0, !flip);
        out[path*3 + 0] = flip? a : b;                  // identities
        out[path*3 + 1] = flip? b : a;                  // depth only
        out[path*3 + 2] = out[path*3 + 0]/out[path*3 + 1];
    }
}

static void SelfReceiverRound(void *ctx, double *out)
{
    SelfBench *sb = (SelfBench *)ctx;
    Receiver *r = sb->r;
    const int v = RX_UNSHADOWED + 2;                     // pcf 2
    for (int k = 0; k < 2; k++)
    {
        bool depth = (k == 1);
        RblSetScene(depth? &sb->rxDepthScene : &r->scene);
        rtFinish();
        double t0 = BenchNowNs();
        BeginTextureMode(r->target);
        ClearBackground(BLANK);
        BeginMode3D(r->camera);
        RblDrawBillboard(r->camera, r->material[v], r->floor);
        EndMode3D();
        EndTextureMode();
        rtFinish();
        out[k] = (BenchNowNs() - t0)*1e-6;
    }
    out[2] = out[0]/out[1];
}

// A tangent-space normal map bending up to 60 degrees across and 30 along (tests/test_self_shadow.c's)
static Texture2D SelfNormalTexture(void)
{
    Image img = GenImageColor(32, 64, (Color){ 128, 128, 255, 255 });
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 32; x++)
        {
            double u = (x + 0.5)/32.0, v = (y + 0.5)/64.0;
            double nx = 1.7*sin(2.0*PI*1.5*u), ny = 0.6*sin(2.0*PI*3.0*v), nz = 1.0, l = sqrt(nx*nx + ny*ny + nz*nz);
            ImageDrawPixel(&img, x, y, (Color){ (unsigned char)lround((nx/l*0.5 + 0.5)*255.0), (unsigned char)lround((ny/l*0.5 + 0.5)*255.0),
                                                (unsigned char)lround((nz/l*0.5 + 0.5)*255.0), 255 });
        }
    Texture2D t = LoadTextureFromImage(img);
    UnloadImage(img);
    return t;
}

static bool SelfBenchRun(SelfBench *sb, PassScene *p, Receiver *r)
{
    sb->p = p; sb->r = r;
    RblShadowDesc sd;
    memset(&sd, 0, sizeof(sd));
    sd.size = SELF_MAP; sd.faceCamera = true;
    sb->idMap = RblLoadShadowMap(sd);
    sd.selfShadow = true;
    sb->depthMap = RblLoadShadowMap(sd);
    sd.size = RX_MAP; sd.faceCamera = false;
    sb->rxDepthMap = RblLoadShadowMap(sd);
    if (!RblIsShadowMapValid(sb->idMap) || !RblIsShadowMapValid(sb->depthMap) || !RblIsShadowMapValid(sb->rxDepthMap)) return false;
    // Pass cost
    const BenchTiming timing = { 1, 5, 15, 2.5e9 };
    for (int c = 0; c < PASS_COUNTS; c++)
    {
        double med[6];
        sb->count = passCounts[c];
        BenchMedianOfRuns(SelfPassRound, sb, 6, timing, med);
        for (int path = 0; path < 2; path++)
        {
            sb->passNs[path][c][0] = med[path*3]; sb->passNs[path][c][1] = med[path*3 + 1]; sb->passRatio[path][c] = med[path*3 + 2];
        }
    }
    // Receiver cost: the same card into a depth-only map
    if (!RblBeginShadowMap(&sb->rxDepthMap, &r->sceneNoMap, 0, (Vector3){ 0.0f, 0.0f, 0.0f }, RX_FOCUS)) return false;
    RblDrawBillboard(r->camera, r->material[RX_UNSHADOWED], Card());
    RblEndShadowMap(&sb->rxDepthMap);
    sb->rxDepthScene = r->sceneNoMap;
    sb->rxDepthScene.shadowMaps = &sb->rxDepthMap;
    sb->rxDepthScene.shadowMapCount = 1;
    double rmed[3];
    const BenchTiming rtiming = { 1, 5, 11, 4.0e9 };
    BenchMedianOfRuns(SelfReceiverRound, sb, 3, rtiming, rmed);
    sb->rxMs[0] = rmed[0]; sb->rxMs[1] = rmed[1]; sb->rxRatio = rmed[2];

    // The sweep (errors)
    RblLight light;
    memset(&light, 0, sizeof(light));
    light.type = RBL_LIGHT_DIRECTIONAL; light.color = WHITE; light.intensity = 1.0f; light.direction = (Vector3){ 0.0f, -1.0f, 0.0f };
    RblLitShaderDesc ld;
    memset(&ld, 0, sizeof(ld));
    ld.maxLights = 1; ld.shading.lightFeatures = RblGetLightFeatures(&light, 1); ld.shading.shadowMaps = 1; ld.material.normalEncoding = RBL_NORMAL_RGB;
    Shader lit = RblLoadLitShader(ld);
    Image wi = GenImageColor(4, 4, WHITE), fi = GenImageColor(4, 4, (Color){ 128, 128, 255, 255 });
    Texture2D white = LoadTextureFromImage(wi), normal = SelfNormalTexture(), flat = LoadTextureFromImage(fi);
    UnloadImage(wi); UnloadImage(fi);
    Material sprite = LoadMaterialDefault(), floorMat = LoadMaterialDefault();
    sprite.shader = floorMat.shader = lit;
    sprite.maps[MATERIAL_MAP_ALBEDO].texture = floorMat.maps[MATERIAL_MAP_ALBEDO].texture = white;
    sprite.maps[MATERIAL_MAP_NORMAL].texture = normal;
    floorMat.maps[MATERIAL_MAP_NORMAL].texture = flat;
    RblShadowMap maps[SELF_MODES];
    for (int m = 0; m < SELF_MODES; m++)
    {
        memset(&sd, 0, sizeof(sd));
        sd.size = 256; sd.selfShadow = (m >= 2); sd.faceCamera = (m & 1);
        maps[m] = RblLoadShadowMap(sd);
    }
    RenderTexture2D view = LoadRenderTexture(SELF_VIEW, SELF_VIEW);
    Camera3D viewer;
    memset(&viewer, 0, sizeof(viewer));
    viewer.position = (Vector3){ 0.0f, 1.5f, 6.0f }; viewer.target = (Vector3){ 0.0f, 1.0f, 0.0f }; viewer.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    viewer.fovy = 28.0f; viewer.projection = CAMERA_PERSPECTIVE;
    RblBillboard fl, b;
    memset(&fl, 0, sizeof(fl));
    fl.size = (Vector2){ 40.0f, 40.0f }; fl.origin = (Vector2){ 20.0f, 20.0f }; fl.facing = RBL_FACING_FIXED;
    fl.axis = (Vector3){ 0.0f, 1.0f, 0.0f }; fl.up = (Vector3){ 0.0f, 0.0f, -1.0f };
    memset(&b, 0, sizeof(b));
    b.size = (Vector2){ 1.0f, 2.0f }; b.origin = (Vector2){ 0.5f, 0.0f };
    bool ok = RblIsLitShaderValid(lit);
    for (int m = 0; m < SELF_MODES; m++) ok = ok && RblIsShadowMapValid(maps[m]);
    for (int el = 5; ok && (el <= 85); el += 20)
        for (int az = 0; az < 360; az += 15)
            for (int f = 0; f < 2; f++)
                for (int m = 0; m < SELF_MODES; m++)
                {
                    double a = az*PI/180.0, e = el*PI/180.0;
                    light.direction = (Vector3){ (float)(-cos(e)*sin(a)), (float)-sin(e), (float)(-cos(e)*cos(a)) };
                    b.facing = f? RBL_FACING_CAMERA_PLANE : RBL_FACING_AXIS;
                    Image img[2];
                    for (int with = 0; with < 2; with++)
                    {
                        RblScene scene;
                        memset(&scene, 0, sizeof(scene));
                        scene.lights = &light; scene.lightCount = 1; scene.ambient = (Color){ 40, 40, 40, 255 };
                        if (RblBeginShadowMap(&maps[m], &scene, 0, (Vector3){ 0.0f, 1.0f, 0.0f }, 4.4f))
                        {
                            RblDrawBillboard(viewer, floorMat, fl);
                            if (with) RblDrawBillboard(viewer, sprite, b);
                            RblEndShadowMap(&maps[m]);
                            scene.shadowMaps = &maps[m]; scene.shadowMapCount = 1;
                        }
                        RblSetScene(&scene);
                        BeginTextureMode(view);
                        ClearBackground(BLANK);
                        BeginMode3D(viewer);
                        RblDrawBillboard(viewer, sprite, b);
                        EndMode3D();
                        EndTextureMode();
                        img[with] = rtReadTarget(view);
                    }
                    int covered = 0, dark = 0, worst = 0;
                    const unsigned char *pw = (const unsigned char *)img[1].data, *po = (const unsigned char *)img[0].data;
                    for (int i = 0; i < SELF_VIEW*SELF_VIEW; i++)
                    {
                        if ((pw[i*4 + 3] < 255) || (po[i*4 + 3] < 255)) continue;
                        covered++;
                        int d = 0;
                        for (int ch = 0; ch < 3; ch++) if ((int)po[i*4 + ch] - pw[i*4 + ch] > d) d = (int)po[i*4 + ch] - pw[i*4 + ch];
                        dark += (d > 2);
                        if (d > worst) worst = d;
                    }
                    sb->cases[m]++;
                    sb->darkened[m] += (dark > 0);
                    if (worst > sb->worst[m]) sb->worst[m] = worst;
                    if ((covered > 0) && ((double)dark/covered > sb->worstShare[m])) sb->worstShare[m] = (double)dark/covered;
                    UnloadImage(img[0]); UnloadImage(img[1]);
                }
    RblScene none;
    memset(&none, 0, sizeof(none));
    RblSetScene(&none);
    UnloadRenderTexture(view);
    for (int m = 0; m < SELF_MODES; m++) RblUnloadShadowMap(&maps[m]);
    MemFree(sprite.maps); MemFree(floorMat.maps);
    UnloadTexture(white); UnloadTexture(normal); UnloadTexture(flat);
    RblUnloadLitShader(&lit);
    RblUnloadShadowMap(&sb->idMap); RblUnloadShadowMap(&sb->depthMap);
    return ok;
}

static void SelfBenchRows(SelfBench *sb)
{
    char name[64];
    for (int path = 0; path < 2; path++)
        for (int c = 0; c < PASS_COUNTS; c++)
        {
            snprintf(name, sizeof(name), "identities_pass_%s_%d_%d", path? "instanced" : "batched", passCounts[c], SELF_MAP);
            BenchCsvRow(SUITE, name, "ns_per_billboard", sb->passNs[path][c][0], "ns");
            BenchCsvRow(SUITE, name, "depth_only_ns_per_billboard", sb->passNs[path][c][1], "ns");
            BenchCsvRow(SUITE, name, "ratio_to_depth_only", sb->passRatio[path][c], "x");
        }
    BenchCsvRow(SUITE, "identities_receiver_pcf2", "ms_per_frame_1280x720", sb->rxMs[0], "ms");
    BenchCsvRow(SUITE, "identities_receiver_pcf2", "depth_only_ms_per_frame_1280x720", sb->rxMs[1], "ms");
    BenchCsvRow(SUITE, "identities_receiver_pcf2", "ratio_to_depth_only", sb->rxRatio, "x");
    for (int m = 0; m < SELF_MODES; m++)
    {
        snprintf(name, sizeof(name), "self_shadow_sweep_%s", selfModeName[m]);
        BenchCsvRow(SUITE, name, "cases", sb->cases[m], "cases");
        BenchCsvRow(SUITE, name, "cases_self_darkened", sb->darkened[m], "cases");
        BenchCsvRow(SUITE, name, "worst_darkening", sb->worst[m], "1/255");
        BenchCsvRow(SUITE, name, "worst_share_darkened", sb->worstShare[m], "fraction");
    }
}

static void SelfBenchSummary(const SelfBench *sb)
{
    printf("\nshadows: sprite self-shadowing, caster identities (casters target, the default) against depth-only maps (selfShadow)\n");
    printf("  pass, ns per billboard (map %d, camera-facing casters; medians of alternating rounds):\n", SELF_MAP);
    for (int path = 0; path < 2; path++)
        for (int c = 0; c < PASS_COUNTS; c++)
            printf("    %-9s %6d: identities %7.0f, depth only %7.0f = %.2fx\n", path? "instanced" : "batched", passCounts[c],
                   sb->passNs[path][c][0], sb->passNs[path][c][1], sb->passRatio[path][c]);
    printf("  receiver pcf 2 at 1280x720: identities %.2f ms, depth only %.2f ms = %.2fx\n", sb->rxMs[0], sb->rxMs[1], sb->rxRatio);
    printf("  sweep (azimuth 0..345/15 x elevation 5..85/20, AXIS and CAMERA_PLANE, bent normals): cases where the sprite darkens itself\n");
    for (int m = 0; m < SELF_MODES; m++)
        printf("    %-26s %3d of %3d, worst %3d/255, at most %.0f%% of its pixels\n", selfModeName[m], sb->darkened[m], sb->cases[m], sb->worst[m], 100.0*sb->worstShare[m]);
}

//----------------------------------------------------------------------------------
// Omni (point-light) maps and cascades
//----------------------------------------------------------------------------------
// omni pass: one omni map (six faces of OC_FACE texels, one casters target) against six spot maps
// of the same size (outer angle 45: the six cube faces), every face/spot drawing the same N
// billboards (batched) from a point light at the billboard box's centre; alternating per round.
// lookup: ms per 1280x720 frame of the receiver floor (the receiver section's view and card) with
// pcf 2 through one variant (point and directional features), against the same variant without
// shadow maps: a directional light with one map, a point light with an omni map, a directional
// light with 4 cascades (fitted to a camera looking obliquely over the floor: depths 5..25, so
// cascades and blend bands spread over the frame); order rotating per run.
// cascades at equal memory: one 2048 map over a camera's 0.5..100 (RblShadowFocusFromCamera)
// against 2, 3, 4 cascades of 2048/sqrt(n) texels (the same texel count); the texel's world size
// where a point 5 and 50 units ahead falls; the pass time of all cascades against the one map (10k
// billboards, batched).
#define OC_FACE             512
#define OC_CASCADE_MEMORY   2048
typedef struct OmniBench {
    PassScene *p;
    Receiver *r;
    RblShadowMap omni, spots[6];
    RblLight point, spotLights[6];
    RblScene pointScene, spotScene;
    int count;
    // lookup
    Shader shader[2];                  // unshadowed, shadowed (pcf 2)
    Material material[2];
    RblShadowMap rxOmni, rxCascades;
    RblLight rxPoint, rxSun;
    RblScene rxScenes[4];              // none (sun), sun + map, point + omni, sun + cascades
    bool ok;
} OmniBench;

static double OmniPassFrame(OmniBench *ob, bool omni)
{
    PassScene *p = ob->p;
    rtFinish();
    double t0 = BenchNowNs();
    for (int f = 0; f < 6; f++)
    {
        bool begun = omni? RblBeginShadowMapPass(&ob->omni, &ob->pointScene, 0, f, p->focus, 0.0f) : RblBeginShadowMap(&ob->spots[f], &ob->spotScene, f, p->focus, 0.0f);
        if (!begun) { ob->ok = false; continue; }
        RblBeginBatch(&p->batch, p->viewer);
        for (int i = 0; i < ob->count; i++) RblBatchAdd(&p->batch, p->material, &p->billboards[i]);
        RblEndBatch(&p->batch);
        RblEndShadowMap(omni? &ob->omni : &ob->spots[f]);
    }
    rtFinish();
    return (BenchNowNs() - t0)/ob->count;
}

static void OmniPassRound(void *ctx, double *out)
{
    static int flip = 0;
    OmniBench *ob = (OmniBench *)ctx;
    flip ^= 1;
    double a = OmniPassFrame(ob, flip), b = OmniPassFrame(ob, !flip);
    out[0] = flip? a : b; out[1] = flip? b : a; out[2] = out[0]/out[1];
}

static double OmniLookupFrame(OmniBench *ob, int k)
{
    Receiver *r = ob->r;
    RblSetScene(&ob->rxScenes[k]);
    rtFinish();
    double t0 = BenchNowNs();
    BeginTextureMode(r->target);
    ClearBackground(BLANK);
    BeginMode3D(r->camera);
    RblDrawBillboard(r->camera, ob->material[(k == 0)? 0 : 1], r->floor);
    EndMode3D();
    EndTextureMode();
    rtFinish();
    return (BenchNowNs() - t0)*1e-6;
}

static void OmniLookupRound(void *ctx, double *out)
{
    static int rot = 0;
    OmniBench *ob = (OmniBench *)ctx;
    double ms[4];
    for (int i = 0; i < 4; i++) { int k = (i + rot)%4; ms[k] = OmniLookupFrame(ob, k); }
    rot++;
    for (int k = 0; k < 4; k++) { out[k] = ms[k]; out[4 + k] = ms[k]/ms[0]; }
}

// Texel world size where view depth d falls, for a cascaded map after a pass (tiles set)
static double CascadeTexelAt(const RblShadowMap *m, double d)
{
    const rbl__ShadowMapState *st = m->state;
    for (int c = 0; c < st->kind; c++) if (d < st->split[c + 1]) return 1.0/(st->tiles[c][0]*m->size);
    return -1.0;
}

static int OmniCascadeBench(PassScene *p, Receiver *r, const char **why)
{
    static OmniBench obs;
    OmniBench *ob = &obs;
    memset(ob, 0, sizeof(*ob));
    ob->p = p; ob->r = r; ob->ok = true;
    *why = NULL;
    // ---- omni pass vs six spot passes
    RblShadowDesc sd;
    memset(&sd, 0, sizeof(sd));
    sd.size = OC_FACE; sd.faceCamera = true;
    RblShadowDesc od = sd;
    od.omni = true;
    ob->omni = RblLoadShadowMap(od);
    memset(&ob->point, 0, sizeof(ob->point));
    ob->point.type = RBL_LIGHT_POINT; ob->point.position = p->focus; ob->point.color = WHITE; ob->point.intensity = 1.0f; ob->point.range = PASS_FOCUS_RADIUS;
    ob->pointScene.lights = &ob->point; ob->pointScene.lightCount = 1;
    const Vector3 axes[6] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
    for (int f = 0; f < 6; f++)
    {
        ob->spots[f] = RblLoadShadowMap(sd);
        ob->spotLights[f] = ob->point;
        ob->spotLights[f].type = RBL_LIGHT_SPOT; ob->spotLights[f].direction = axes[f];
        ob->spotLights[f].innerAngle = 40.0f; ob->spotLights[f].outerAngle = 45.0f;
        if (!RblIsShadowMapValid(ob->spots[f])) ob->ok = false;
    }
    ob->spotScene.lights = ob->spotLights; ob->spotScene.lightCount = 6;
    if (!RblIsShadowMapValid(ob->omni) || !ob->ok) { *why = "omni or spot maps failed to load"; return 0; }
    double passMed[PASS_COUNTS][3];
    int passRuns[PASS_COUNTS];
    const BenchTiming timing = { 1, 5, 11, 2.5e9 };
    for (int c = 0; c < PASS_COUNTS; c++)
    {
        ob->count = passCounts[c];
        passRuns[c] = BenchMedianOfRuns(OmniPassRound, ob, 3, timing, passMed[c]);
    }
    if (!ob->ok) { *why = "an omni or spot pass was refused"; return 0; }

    // ---- lookup cost per fragment
    ob->rxSun = r->light;
    memset(&ob->rxPoint, 0, sizeof(ob->rxPoint));
    ob->rxPoint.type = RBL_LIGHT_POINT; ob->rxPoint.position = (Vector3){ 0.5f, -0.3f, 4.0f }; ob->rxPoint.color = WHITE; ob->rxPoint.intensity = 12.0f; ob->rxPoint.range = 30.0f;
    RblLight both[2] = { ob->rxSun, ob->rxPoint };
    RblLitShaderDesc ld;
    memset(&ld, 0, sizeof(ld));
    ld.maxLights = 1; ld.shading.lightFeatures = RblGetLightFeatures(both, 2); ld.shading.brdf = RBL_BRDF_LAMBERT;
    for (int v = 0; v < 2; v++)
    {
        ld.shading.shadowMaps = v; ld.shading.shadowFilter = v? 2 : 0;
        ob->shader[v] = RblLoadLitShader(ld);
        ob->material[v] = LoadMaterialDefault();
        ob->material[v].shader = ob->shader[v];
        ob->material[v].maps[MATERIAL_MAP_ALBEDO].texture = r->white;
        if (!RblIsLitShaderValid(ob->shader[v])) ob->ok = false;
    }
    RblShadowDesc rod;
    memset(&rod, 0, sizeof(rod));
    rod.size = RX_MAP; rod.omni = true;
    ob->rxOmni = RblLoadShadowMap(rod);
    RblShadowDesc rcd;
    memset(&rcd, 0, sizeof(rcd));
    rcd.size = RX_MAP; rcd.cascades = 4;
    ob->rxCascades = RblLoadShadowMap(rcd);
    RblBillboard card = Card();
    RblScene pointOnly; memset(&pointOnly, 0, sizeof(pointOnly)); pointOnly.lights = &ob->rxPoint; pointOnly.lightCount = 1; pointOnly.ambient = r->ambient;
    RblScene sunOnly; memset(&sunOnly, 0, sizeof(sunOnly)); sunOnly.lights = &ob->rxSun; sunOnly.lightCount = 1; sunOnly.ambient = r->ambient;
    for (int f = 0; f < RblShadowMapPasses(ob->rxOmni); f++)
        if (RblBeginShadowMapPass(&ob->rxOmni, &pointOnly, 0, f, (Vector3){ 0 }, 0.0f)) { RblDrawBillboard(r->camera, ob->material[0], card); RblEndShadowMap(&ob->rxOmni); }
        else ob->ok = false;
    Camera3D oblique;
    memset(&oblique, 0, sizeof(oblique));
    oblique.position = (Vector3){ 0.0f, -12.0f, 6.0f }; oblique.target = (Vector3){ 0.0f, 2.0f, 0.0f }; oblique.up = (Vector3){ 0.0f, 0.0f, 1.0f };
    oblique.fovy = 60.0f; oblique.projection = CAMERA_PERSPECTIVE;
    if (!RblFitShadowCascades(&ob->rxCascades, oblique, 16.0f/9.0f, 0.5f, 40.0f)) ob->ok = false;
    for (int c = 0; c < RblShadowMapPasses(ob->rxCascades); c++)
        if (RblBeginShadowMapPass(&ob->rxCascades, &sunOnly, 0, c, (Vector3){ 0 }, 0.0f)) { RblDrawBillboard(r->camera, ob->material[0], card); RblEndShadowMap(&ob->rxCascades); }
        else ob->ok = false;
    ob->rxScenes[0] = sunOnly;
    ob->rxScenes[1] = r->scene;                      // the receiver section's sun and map
    ob->rxScenes[2] = pointOnly; ob->rxScenes[2].shadowMaps = &ob->rxOmni; ob->rxScenes[2].shadowMapCount = 1;
    ob->rxScenes[3] = sunOnly; ob->rxScenes[3].shadowMaps = &ob->rxCascades; ob->rxScenes[3].shadowMapCount = 1;
    double lookMed[8] = { 0 };
    int lookRuns = 0;
    if (ob->ok)
    {
        const BenchTiming lt = { 2, 7, 21, 3e9 };
        lookRuns = BenchMedianOfRuns(OmniLookupRound, ob, 8, lt, lookMed);
    }
    else *why = "lookup variants or maps failed";

    // ---- cascades at equal memory
    double texel5[5] = { 0 }, texel50[5] = { 0 }, passMs[5] = { 0 }, passRatio[5] = { 0 };
    int sizes[5] = { 0 };
    Camera3D cam;
    memset(&cam, 0, sizeof(cam));
    cam.position = (Vector3){ 0.0f, 2.0f, 10.0f }; cam.target = (Vector3){ 0.0f, 1.0f, -10.0f }; cam.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    cam.fovy = 60.0f; cam.projection = CAMERA_PERSPECTIVE;
    RblShadowMap eq[5];
    memset(eq, 0, sizeof(eq));
    Vector3 focus; float radius = 0.0f;
    RblShadowFocusFromCamera(cam, 16.0f/9.0f, 0.5f, 100.0f, &focus, &radius);
    for (int n = 1; n <= 4; n++)
    {
        RblShadowDesc cd;
        memset(&cd, 0, sizeof(cd));
        cd.size = sizes[n] = (int)floor(OC_CASCADE_MEMORY/sqrt((double)n));
        cd.cascades = (n > 1)? n : 0; cd.faceCamera = true;
        eq[n] = RblLoadShadowMap(cd);
        if (!RblIsShadowMapValid(eq[n])) { ob->ok = false; continue; }
        if (n > 1) RblFitShadowCascades(&eq[n], cam, 16.0f/9.0f, 0.5f, 100.0f);
        // Pass time: every cascade (or the one map) drawing the 10k billboards, three runs, median
        double runs[3];
        for (int k = 0; k < 3; k++)
        {
            rtFinish();
            double t0 = BenchNowNs();
            for (int c = 0; c < RblShadowMapPasses(eq[n]); c++)
            {
                if (!RblBeginShadowMapPass(&eq[n], &p->scene, 0, c, focus, radius)) { ob->ok = false; continue; }
                RblBeginBatch(&p->batch, p->viewer);
                for (int i = 0; i < PASS_MAX; i++) RblBatchAdd(&p->batch, p->material, &p->billboards[i]);
                RblEndBatch(&p->batch);
                RblEndShadowMap(&eq[n]);
            }
            rtFinish();
            runs[k] = (BenchNowNs() - t0)*1e-6;
        }
        passMs[n] = BenchMedian(runs, 3);
        if (n == 1) { texel5[n] = texel50[n] = eq[n].state->texelWorld; }
        else { texel5[n] = CascadeTexelAt(&eq[n], 5.0); texel50[n] = CascadeTexelAt(&eq[n], 50.0); }
        passRatio[n] = passMs[n]/passMs[1];
    }

    // ---- rows and summary
    char name[96];
    for (int c = 0; c < PASS_COUNTS; c++)
    {
        snprintf(name, sizeof(name), "omni_pass_%d_%d", passCounts[c], OC_FACE);
        BenchCsvRow(SUITE, name, "ns_per_billboard_six_faces", passMed[c][0], "ns");
        BenchCsvRow(SUITE, name, "ratio_to_six_spot_passes", passMed[c][2], "x");
        BenchCsvRow(SUITE, name, "runs", passRuns[c], "runs");
        snprintf(name, sizeof(name), "six_spot_passes_%d_%d", passCounts[c], OC_FACE);
        BenchCsvRow(SUITE, name, "ns_per_billboard_six_maps", passMed[c][1], "ns");
    }
    const char *lookName[4] = { "lookup_unshadowed", "lookup_directional_map", "lookup_omni", "lookup_cascades4" };
    if (lookRuns > 0)
        for (int k = 0; k < 4; k++)
        {
            BenchCsvRow(SUITE, lookName[k], "ms_per_frame_1280x720", lookMed[k], "ms");
            BenchCsvRow(SUITE, lookName[k], "ratio_to_unshadowed", lookMed[4 + k], "x");
        }
    for (int n = 1; n <= 4; n++)
    {
        snprintf(name, sizeof(name), "cascades_%d_equal_memory", n);
        BenchCsvRow(SUITE, name, "tile_texels_per_side", sizes[n], "texels");
        BenchCsvRow(SUITE, name, "texel_at_5", texel5[n], "world");
        BenchCsvRow(SUITE, name, "texel_at_50", texel50[n], "world");
        BenchCsvRow(SUITE, name, "texel_at_5_vs_one_map", texel5[n]/texel5[1], "x");
        BenchCsvRow(SUITE, name, "pass_ms_10000", passMs[n], "ms");
        BenchCsvRow(SUITE, name, "pass_ratio_to_one_map", passRatio[n], "x");
    }
    printf("\nshadows: omni maps and cascades\n");
    printf("  omni pass (6 faces of %d into one target) vs six spot maps (45-degree cones, %d each), batched, ns per billboard per frame:\n", OC_FACE, OC_FACE);
    for (int c = 0; c < PASS_COUNTS; c++)
        printf("    N %5d: omni %8.0f, six spots %8.0f, ratio %.2fx (%d runs)\n", passCounts[c], passMed[c][0], passMed[c][1], passMed[c][2], passRuns[c]);
    if (lookRuns > 0)
    {
        printf("  lookup (pcf 2, 1280x720 floor, %d runs): ms per frame and ratio to the same variant without maps\n", lookRuns);
        for (int k = 0; k < 4; k++) printf("    %-24s %8.2f  %5.2fx\n", lookName[k], lookMed[k], lookMed[4 + k]);
    }
    printf("  equal memory (%d^2 texels), camera fovy 60, 16:9, 0.5..100: texel world size at 5 and 50 units, pass time (10k billboards)\n", OC_CASCADE_MEMORY);
    for (int n = 1; n <= 4; n++)
        printf("    %d %-8s tile %4d: texel at 5 %.4f (%.2fx one map), at 50 %.4f; pass %.1f ms (%.2fx)\n", n, (n == 1)? "map" : "cascades", sizes[n],
               texel5[n], texel5[n]/texel5[1], texel50[n], passMs[n], passRatio[n]);
    // ---- release
    RblScene none;
    memset(&none, 0, sizeof(none));
    RblSetScene(&none);
    for (int n = 1; n <= 4; n++) RblUnloadShadowMap(&eq[n]);
    RblUnloadShadowMap(&ob->rxOmni); RblUnloadShadowMap(&ob->rxCascades);
    for (int v = 0; v < 2; v++) { if (RblIsLitShaderValid(ob->shader[v])) RblUnloadLitShader(&ob->shader[v]); MemFree(ob->material[v].maps); }
    RblUnloadShadowMap(&ob->omni);
    for (int f = 0; f < 6; f++) RblUnloadShadowMap(&ob->spots[f]);
    if (!ob->ok && (*why == NULL)) *why = "a cascade map failed";
    return ob->ok? 1 : 0;
}

int main(void)
{
    double benchStart = BenchNowNs();
    SetTraceLogLevel(LOG_WARNING);
    const char *backend = rtInitContext(FRAME_W, FRAME_H);
    if (backend == NULL) { printf("bench_shadows: no headless GL context, skipped\n"); return 0; }
    int problems = 0;

    // ---- shadow pass ---------------------------------------------------------------------------------
    static PassScene ps;
    PassScene *p = &ps;
    memset(p, 0, sizeof(*p));
    if (!BuildPassScene(p)) { printf("bench_shadows: out of memory\n"); rtCloseContext(); return 1; }
    Image spriteImg = GenImageColor(SPRITE_SIZE, SPRITE_SIZE, BLANK);
    ImageDrawCircle(&spriteImg, SPRITE_SIZE/2, SPRITE_SIZE/2, SPRITE_SIZE/2 - 2, WHITE);
    p->sprite = LoadTextureFromImage(spriteImg);
    UnloadImage(spriteImg);
    RblLitShaderDesc pd;
    memset(&pd, 0, sizeof(pd));
    pd.maxLights = 1;
    pd.shading.lightFeatures = RblGetLightFeatures(&p->light, 1);
    pd.shading.shadowMaps = 1;
    p->lit = RblLoadLitShader(pd);
    pd.instanced = true;
    p->litInstanced = RblLoadLitShader(pd);
    p->material = LoadMaterialDefault();
    p->material.shader = p->lit;
    p->material.maps[MATERIAL_MAP_ALBEDO].texture = p->sprite;
    p->materialInstanced = LoadMaterialDefault();
    p->materialInstanced.shader = p->litInstanced;
    p->materialInstanced.maps[MATERIAL_MAP_ALBEDO].texture = p->sprite;
    p->batch = RblLoadBatch(PASS_MAX);
    p->instances = RblLoadInstanceBuffer(PASS_MAX);
    bool passOk = RblIsLitShaderValid(p->lit) && RblIsLitShaderValid(p->litInstanced) && RblIsBatchValid(p->batch) && RblIsInstanceBufferValid(p->instances);
    for (int s = 0; s < MAP_SIZES; s++)
    {
        RblShadowDesc sd;
        memset(&sd, 0, sizeof(sd));
        sd.size = mapSizes[s];
        sd.faceCamera = true;           // as the baseline's billboards: both rasterise about the same texels
        p->maps[s] = RblLoadShadowMap(sd);
        p->targets[s] = LoadRenderTexture(mapSizes[s], mapSizes[s]);
        passOk = passOk && RblIsShadowMapValid(p->maps[s]) && (p->targets[s].id != 0);
    }
    double passNs[PASS_PATHS][PASS_COUNTS][MAP_SIZES], passRatio[PASS_PATHS][PASS_COUNTS][MAP_SIZES];
    double passMarginal[PASS_PATHS][PASS_COUNTS][MAP_SIZES], passMRatio[PASS_PATHS][PASS_COUNTS][MAP_SIZES];
    double emptyMs[MAP_SIZES], emptyRaylibMs[MAP_SIZES], coverage[PASS_PATHS] = { -1.0, -1.0, -1.0 };
    int passRuns[PASS_COUNTS][MAP_SIZES];
    long depthDiff = -1;
    memset(passNs, 0, sizeof(passNs));
    memset(passRatio, 0, sizeof(passRatio));
    memset(passMarginal, 0, sizeof(passMarginal));
    memset(passMRatio, 0, sizeof(passMRatio));
    memset(emptyMs, 0, sizeof(emptyMs));
    memset(emptyRaylibMs, 0, sizeof(emptyRaylibMs));
    memset(passRuns, 0, sizeof(passRuns));
    if (!passOk) { printf("bench_shadows: shadow maps, casters or buffers failed to load: shadow pass rows skipped\n"); problems++; }
    else
    {
        // Every path once, untimed (shader compiles, buffer growth), and checked to be accepted
        p->ok = true;
        for (int path = 0; path < PASS_PATHS; path++) PassFrame(p, (PassPath)path, PASS_MAX, 0);
        if (!p->ok) { printf("bench_shadows: a shadow pass was refused or skipped billboards\n"); problems++; }
        // Coverage at 1k on the smallest map: the paths rasterise about the same texels; batched and
        // instanced write the same depths (texels differing by more than 1e-5 counted)
        float *depth[PASS_PATHS] = { NULL, NULL, NULL };
        for (int path = 0; path < PASS_PATHS; path++) coverage[path] = PassCoverage(p, (PassPath)path, passCounts[0], 0, &depth[path]);
        if ((depth[PASS_BATCHED] != NULL) && (depth[PASS_INSTANCED] != NULL))
        {
            depthDiff = 0;
            for (int i = 0; i < mapSizes[0]*mapSizes[0]; i++) depthDiff += (fabsf(depth[PASS_BATCHED][i] - depth[PASS_INSTANCED][i]) > 1e-5f);
        }
        for (int path = 0; path < PASS_PATHS; path++) free(depth[path]);
        if ((coverage[PASS_BATCHED] <= 0.0) || (coverage[PASS_INSTANCED] <= 0.0)) { printf("bench_shadows: a shadow pass wrote no depth\n"); problems++; }
        // llvmpipe, 2 cores: a 10k round at 2048 takes ~0.25 s (fill dominates)
        const BenchTiming timing = { 0, 5, 15, 2.5e9 };
        for (int c = 0; c < PASS_COUNTS; c++)
            for (int s = 0; s < MAP_SIZES; s++)
            {
                double med[PV_VALUES];
                p->count = passCounts[c]; p->size = s; p->round = 0;
                passRuns[c][s] = BenchMedianOfRuns(PassRound, p, PV_VALUES, timing, med);
                for (int k = 0; k < PASS_PATHS; k++)
                {
                    passNs[k][c][s] = med[PV_NS(k)]; passRatio[k][c][s] = med[PV_RATIO(k)];
                    passMarginal[k][c][s] = med[PV_MARGINAL(k)]; passMRatio[k][c][s] = med[PV_MRATIO(k)];
                }
                if (c == PASS_COUNTS - 1) { emptyMs[s] = med[PV_EMPTY]; emptyRaylibMs[s] = med[PV_EMPTY_RAYLIB]; }
            }
        if (!p->ok) { printf("bench_shadows: a timed shadow pass was refused or skipped billboards\n"); problems++; }
    }

    // ---- receiver ------------------------------------------------------------------------------------
    static Receiver rx;
    Receiver *r = &rx;
    memset(r, 0, sizeof(*r));
    r->target = LoadRenderTexture(FRAME_W, FRAME_H);
    r->camera = TopDown();
    r->floor.size = (Vector2){ RX_FLOOR, RX_FLOOR };
    r->floor.origin = (Vector2){ RX_FLOOR*0.5f, RX_FLOOR*0.5f };
    r->floor.facing = RBL_FACING_FIXED;
    r->floor.axis = (Vector3){ 0.0f, 0.0f, 1.0f };
    r->floor.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    r->light.type = RBL_LIGHT_DIRECTIONAL;
    r->light.direction = (Vector3){ 0.5f, 0.3f, -1.0f };
    r->light.color = WHITE;
    r->light.intensity = 1.0f;
    r->ambient = (Color){ 40, 40, 40, 255 };
    r->sceneNoMap.lights = &r->light;
    r->sceneNoMap.lightCount = 1;
    r->sceneNoMap.ambient = r->ambient;
    Image whiteImg = GenImageColor(4, 4, WHITE);
    r->white = LoadTextureFromImage(whiteImg);
    UnloadImage(whiteImg);
    RblLitShaderDesc rd;
    memset(&rd, 0, sizeof(rd));
    rd.maxLights = 1;
    rd.shading.lightFeatures = RblGetLightFeatures(&r->light, 1);
    rd.shading.brdf = RBL_BRDF_LAMBERT;
    r->ok[RX_RAYLIB] = true;
    for (int v = 1; v < RX_VARIANTS; v++)
    {
        RblLitShaderDesc d = rd;
        d.shading.shadowMaps = (v == RX_UNSHADOWED)? 0 : 1;
        d.shading.shadowFilter = (v == RX_UNSHADOWED)? 0 : ((v == RX_NOMAP)? RX_NOMAP_FILTER : rxFilters[v - RX_UNSHADOWED - 1]);
        r->shader[v] = RblLoadLitShader(d);
        r->material[v] = LoadMaterialDefault();
        r->material[v].shader = r->shader[v];
        r->material[v].maps[MATERIAL_MAP_ALBEDO].texture = r->white;
        r->ok[v] = RblIsLitShaderValid(r->shader[v]);
        if (!r->ok[v]) { printf("bench_shadows: receiver variant %d failed to load\n", v); problems++; }
    }
    RblShadowDesc rsd;
    memset(&rsd, 0, sizeof(rsd));
    rsd.size = RX_MAP;
    r->map = RblLoadShadowMap(rsd);
    RblBillboard card = Card();
    bool mapOk = RblIsShadowMapValid(r->map) && RblBeginShadowMap(&r->map, &r->sceneNoMap, 0, (Vector3){ 0.0f, 0.0f, 0.0f }, RX_FOCUS);
    if (mapOk)
    {
        RblDrawBillboard(r->camera, r->material[RX_UNSHADOWED], card);    // FIXED: the camera does not matter
        RblEndShadowMap(&r->map);
    }
    else { printf("bench_shadows: receiver shadow map failed: shadowed rows skipped\n"); problems++; }
    r->scene = r->sceneNoMap;           // the rendered map, received by the shadowed variants
    r->scene.shadowMaps = &r->map;
    r->scene.shadowMapCount = 1;
    for (int k = 0; k < RX_FILTERS; k++) r->ok[RX_UNSHADOWED + 1 + k] = r->ok[RX_UNSHADOWED + 1 + k] && mapOk;

    // Analytic values and the edge error (untimed; also warms every variant up)
    Analytic an = BuildAnalytic(r->light, card, RX_FOCUS, RX_MAP);
    if (mapOk && (fabs(an.texel - r->map.state->texelWorld) > 1e-6*an.texel))
    {
        printf("bench_shadows: texel %.7g (2r/(size - 1)) differs from the map's texelWorld %.7g\n", an.texel, (double)r->map.state->texelWorld);
        problems++;
    }
    RefEnvironment env;
    memset(&env, 0, sizeof(env));
    env.ambient = r->ambient;
    env.up = d3(0, 0, 1);
    RefSurface surface;
    memset(&surface, 0, sizeof(surface));
    surface.position = d3(0, 0, 0);
    surface.normal = d3(0, 0, 1);
    surface.albedo = refLinear(WHITE);
    surface.specularMap = -1.0;
    surface.occlusion = 1.0;
    D3 eye = d3f(r->camera.position);
    RefParams rp;                       // the receivers' program and material: Lambert, every value default
    memset(&rp, 0, sizeof(rp));
    rp.brdf = rd.shading.brdf;
    RefRgb litRef = refFinish(&rp, refShade(&rp, &r->light, 1, &env, &surface, eye), surface.position, eye);
    RefRgb darkRef = refFinish(&rp, refShade(&rp, &r->light, 0, &env, &surface, eye), surface.position, eye);
    int litByte = (int)floor(litRef.r*255.0 + 0.5), darkByte = (int)floor(darkRef.r*255.0 + 0.5);
    EdgeStats edge[RX_FILTERS];
    memset(edge, 0, sizeof(edge));
    int litErr = -1, noMapErr = -1;
    for (int v = 0; v < RX_VARIANTS; v++)
    {
        if (!r->ok[v]) continue;
        DrawReceiver(r, v);
        if (!r->frameOk) { printf("bench_shadows: receiver variant %d: scene (lights, shadow map) rejected\n", v); problems++; r->ok[v] = false; continue; }
        Image img = rtReadTarget(r->target);
        const unsigned char *px = (const unsigned char *)img.data;
        int missing = 0, worst = 0;
        for (int i = 0; i < FRAME_W*FRAME_H; i++)
        {
            missing += (px[i*4 + 3] == 0);
            if ((v == RX_UNSHADOWED) || (v == RX_NOMAP)) for (int ch = 0; ch < 3; ch++) { int e = abs((int)px[i*4 + ch] - litByte); if (e > worst) worst = e; }
        }
        if (missing > 0) { printf("bench_shadows: receiver variant %d leaves %d pixels unwritten\n", v, missing); problems++; }
        if (v == RX_UNSHADOWED) litErr = worst;
        if (v == RX_NOMAP) noMapErr = worst;
        if ((v > RX_UNSHADOWED) && (v < RX_NOMAP)) edge[v - RX_UNSHADOWED - 1] = MeasureEdge(&an, img, litByte, darkByte);
        UnloadImage(img);
    }

    // Frame cost
    const BenchTiming rtiming = { 1, 5, 11, 7.0e9 };
    double rmed[RV_VALUES];
    memset(rmed, 0, sizeof(rmed));
    int rruns = r->ok[RX_UNSHADOWED]? BenchMedianOfRuns(ReceiverRun, r, RV_VALUES, rtiming, rmed) : 0;
    double rbase = rmed[RV_MS(RX_UNSHADOWED)];
    double rspread = (rbase > 0.0)? 100.0*(r->baseMax - r->baseMin)/rbase : 0.0;

    // ---- sprite self-shadowing: identities against depth-only maps ---------------------------------------
    SelfBench sb;
    memset(&sb, 0, sizeof(sb));
    bool selfOk = passOk && r->ok[RX_UNSHADOWED + 2] && mapOk;
    if (selfOk) selfOk = SelfBenchRun(&sb, p, r);
    if (!selfOk) { printf("bench_shadows: self-shadowing rows skipped\n"); problems++; }

    // ---- rows ----------------------------------------------------------------------------------------
    char name[64];
    if (passOk)
    {
        for (int c = 0; c < PASS_COUNTS; c++)
            for (int s = 0; s < MAP_SIZES; s++)
            {
                for (int k = 0; k < PASS_PATHS; k++)
                {
                    snprintf(name, sizeof(name), "pass_%s_%d_%d", passName[k], passCounts[c], mapSizes[s]);
                    BenchCsvRow(SUITE, name, "ns_per_billboard", passNs[k][c][s], "ns");
                    BenchCsvRow(SUITE, name, "marginal_ns_per_billboard", passMarginal[k][c][s], "ns");
                    if (k != PASS_RAYLIB) BenchCsvRow(SUITE, name, "ratio_to_raylib", passRatio[k][c][s], "x");
                    if (k != PASS_RAYLIB) BenchCsvRow(SUITE, name, "marginal_ratio_to_raylib", passMRatio[k][c][s], "x");
                }
                snprintf(name, sizeof(name), "pass_%d_%d", passCounts[c], mapSizes[s]);
                BenchCsvRow(SUITE, name, "runs", passRuns[c][s], "runs");
            }
        for (int s = 0; s < MAP_SIZES; s++)
        {
            snprintf(name, sizeof(name), "pass_empty_%d", mapSizes[s]);
            BenchCsvRow(SUITE, name, "ms_per_pass", emptyMs[s], "ms");
            snprintf(name, sizeof(name), "pass_raylib_empty_%d", mapSizes[s]);
            BenchCsvRow(SUITE, name, "ms_per_pass", emptyRaylibMs[s], "ms");
        }
        for (int k = 0; k < PASS_PATHS; k++)
        {
            snprintf(name, sizeof(name), "check_coverage_%s_%d_%d", passName[k], passCounts[0], mapSizes[0]);
            if (coverage[k] >= 0.0) BenchCsvRow(SUITE, name, "covered_fraction", coverage[k], "fraction");
        }
        if (depthDiff >= 0) BenchCsvRow(SUITE, "check_batched_vs_instanced_depth", "texels_differing", (double)depthDiff, "texels");
    }
    BenchCsvRow(SUITE, "receiver_setup", "pixels_per_texel", an.texel/an.pixel, "px");
    BenchCsvRow(SUITE, "receiver_setup", "texel_world", an.texel, "units");
    BenchCsvRow(SUITE, "receiver_setup", "lit_value", litByte, "1/255");
    BenchCsvRow(SUITE, "receiver_setup", "dark_value", darkByte, "1/255");
    if (rruns > 0)
    {
        BenchCsvRow(SUITE, "receiver_raylib_default_shader", "ms_per_frame_1280x720", rmed[RV_MS(RX_RAYLIB)], "ms");
        BenchCsvRow(SUITE, "receiver_unshadowed", "ms_per_frame_1280x720", rbase, "ms");
        BenchCsvRow(SUITE, "receiver_unshadowed", "ratio_to_raylib", rmed[RV_RATIO_RAYLIB(RX_UNSHADOWED)], "x");
        BenchCsvRow(SUITE, "receiver_unshadowed", "spread_pct", rspread, "%");
        BenchCsvRow(SUITE, "receiver_unshadowed", "runs", rruns, "runs");
    }
    if (litErr >= 0) BenchCsvRow(SUITE, "receiver_unshadowed", "max_err_lit", litErr, "1/255");
    for (int k = 0; k < RX_FILTERS; k++)
    {
        int v = RX_UNSHADOWED + 1 + k;
        if (!r->ok[v]) continue;
        snprintf(name, sizeof(name), "receiver_pcf%d", rxFilters[k]);
        if (rruns > 0)
        {
            BenchCsvRow(SUITE, name, "ms_per_frame_1280x720", rmed[RV_MS(v)], "ms");
            BenchCsvRow(SUITE, name, "ratio_to_unshadowed", rmed[RV_RATIO_BASE(k)], "x");
            BenchCsvRow(SUITE, name, "ratio_to_raylib", rmed[RV_RATIO_RAYLIB(v)], "x");
        }
        BenchCsvRow(SUITE, name, "fetches_per_pixel", (rxFilters[k] + 1)*(rxFilters[k] + 1), "fetches");
        BenchCsvRow(SUITE, name, "edge_mean_err", edge[k].edgeMean, "1/255");
        BenchCsvRow(SUITE, name, "edge_max_err", edge[k].edgeMax, "1/255");
        BenchCsvRow(SUITE, name, "all_mean_err", edge[k].allMean, "1/255");
        BenchCsvRow(SUITE, name, "all_max_err", edge[k].allMax, "1/255");
        BenchCsvRow(SUITE, name, "away_max_err", edge[k].awayMax, "1/255");
        BenchCsvRow(SUITE, name, "edge_pixels", edge[k].edgePixels, "pixels");
        BenchCsvRow(SUITE, name, "edge_width", edge[k].width, "texels");
        BenchCsvRow(SUITE, name, "edge_width_ideal", IdealWidth(rxFilters[k]), "texels");
        BenchCsvRow(SUITE, name, "edge_shift", edge[k].shift, "texels");
    }

    snprintf(name, sizeof(name), "receiver_pcf%d_no_map", RX_NOMAP_FILTER);
    if (r->ok[RX_NOMAP] && (rruns > 0))
    {
        BenchCsvRow(SUITE, name, "ms_per_frame_1280x720", rmed[RV_MS(RX_NOMAP)], "ms");
        BenchCsvRow(SUITE, name, "ratio_to_unshadowed", rmed[RV_RATIO_BASE(RX_SHADOWED - 1)], "x");
        BenchCsvRow(SUITE, name, "ratio_to_raylib", rmed[RV_RATIO_RAYLIB(RX_NOMAP)], "x");
    }
    if (noMapErr >= 0) BenchCsvRow(SUITE, name, "max_err_lit", noMapErr, "1/255");

    if (selfOk) SelfBenchRows(&sb);

    // ---- omni and cascades ---------------------------------------------------------------------------
    const char *ocWhy = NULL;
    if (passOk && !OmniCascadeBench(p, r, &ocWhy)) { printf("bench_shadows: omni/cascade rows: %s\n", (ocWhy != NULL)? ocWhy : "failed"); problems++; }

    // ---- release -------------------------------------------------------------------------------------
    for (int s = 0; s < MAP_SIZES; s++) { RblUnloadShadowMap(&p->maps[s]); UnloadRenderTexture(p->targets[s]); }
    RblUnloadBatch(&p->batch);
    RblUnloadInstanceBuffer(&p->instances);
    if (RblIsLitShaderValid(p->lit)) RblUnloadLitShader(&p->lit);
    if (RblIsLitShaderValid(p->litInstanced)) RblUnloadLitShader(&p->litInstanced);
    MemFree(p->material.maps);
    MemFree(p->materialInstanced.maps);
    UnloadTexture(p->sprite);
    free(p->billboards);
    free(p->instanceSet);
    RblScene none;                      // the scene no longer lists the map unloaded below
    memset(&none, 0, sizeof(none));
    RblSetScene(&none);
    RblUnloadShadowMap(&r->map);
    for (int v = 1; v < RX_VARIANTS; v++)
    {
        if (RblIsLitShaderValid(r->shader[v])) RblUnloadLitShader(&r->shader[v]);
        MemFree(r->material[v].maps);
    }
    UnloadTexture(r->white);
    UnloadRenderTexture(r->target);
    RblClose();
    rtCloseContext();

    // ---- summary -------------------------------------------------------------------------------------
    if (passOk)
    {
        printf("shadows: shadow pass, ns per billboard (Begin..End of the pass + glFinish; medians), directional light,\n");
        printf("  bench_geometry's billboards facing the viewer, alpha-tested %dx%d disc sprite, focus radius %.0f; %s context\n",
               SPRITE_SIZE, SPRITE_SIZE, (double)PASS_FOCUS_RADIUS, backend);
        printf("  baseline: DrawBillboardPro (raylib default shader, unlit) into a RenderTexture of the map's size, same view\n");
        printf("  marginal = (frame - an empty frame of the same kind, i.e. the clear)/N; ratios are medians of per-round ratios\n");
        printf("  %5s %6s | %-15s | %-23s | %-23s | %4s\n", "", "", "raylib", "batched", "instanced", "");
        printf("  %5s %6s | %7s %7s | %7s %7s %7s | %7s %7s %7s | %4s\n", "map", "N", "total", "margin", "total", "xraylib", "margin",
               "total", "xraylib", "margin", "runs");
        for (int c = 0; c < PASS_COUNTS; c++)
            for (int s = 0; s < MAP_SIZES; s++)
                printf("  %5d %6d | %7.0f %7.0f | %7.0f %6.2fx %7.0f | %7.0f %6.2fx %7.0f | %4d\n", mapSizes[s], passCounts[c],
                       passNs[PASS_RAYLIB][c][s], passMarginal[PASS_RAYLIB][c][s],
                       passNs[PASS_BATCHED][c][s], passRatio[PASS_BATCHED][c][s], passMarginal[PASS_BATCHED][c][s],
                       passNs[PASS_INSTANCED][c][s], passRatio[PASS_INSTANCED][c][s], passMarginal[PASS_INSTANCED][c][s], passRuns[c][s]);
        printf("  empty frame, ms (map size 512/1024/2048): shadow pass");
        for (int s = 0; s < MAP_SIZES; s++) printf(" %.2f", emptyMs[s]);
        printf(", raylib clear");
        for (int s = 0; s < MAP_SIZES; s++) printf(" %.2f", emptyRaylibMs[s]);
        printf("\n  check (%d billboards, %d map): covered fraction raylib %.3f, batched %.3f, instanced %.3f; batched vs instanced depth: %ld texels differ\n",
               passCounts[0], mapSizes[0], coverage[PASS_RAYLIB], coverage[PASS_BATCHED], coverage[PASS_INSTANCED], depthDiff);
    }
    printf("\nshadows: receiver, ms per frame at %dx%d: a white Lambert floor seen straight down (orthographic), one directional\n", FRAME_W, FRAME_H);
    printf("  light, one %d shadow map of a %.0fx%.0f card at height %.1f (texel %.4f world units = %.2f pixels); medians of %d runs\n",
           RX_MAP, (double)RX_CARD, (double)RX_CARD, (double)RX_CARD_HEIGHT, an.texel, an.texel/an.pixel, rruns);
    printf("  expected floor: lit %d, shadowed %d (double-precision reference); errors per channel in 1/255 against the hard shadow;\n", litByte, darkByte);
    printf("  edge = within %.0f texels of the analytic shadow edge, away = beyond %.0f texels; width = 10%%..90%% of the shadow factor, in texels\n",
           RX_EDGE_TEXELS, RX_AWAY_TEXELS);
    printf("  %-16s %9s %8s %8s %7s | %-15s %-15s %8s | %6s %6s %6s\n", "variant", "ms", "xunshad", "xraylib", "fetches",
           "edge mean/max", "all mean/max", "away max", "width", "ideal", "shift");
    printf("  %-16s %9.2f %8s %7.2fx %7s |\n", "raylib unlit", rmed[RV_MS(RX_RAYLIB)], "", 1.0, "");
    printf("  %-16s %9.2f %7.2fx %7.2fx %7d | lit value max err %d/255 (per-run baselines spread %.0f%%)\n", "unshadowed", rbase, 1.0,
           rmed[RV_RATIO_RAYLIB(RX_UNSHADOWED)], 0, litErr, rspread);
    for (int k = 0; k < RX_FILTERS; k++)
    {
        int v = RX_UNSHADOWED + 1 + k;
        char label[32];
        snprintf(label, sizeof(label), "pcf %d", rxFilters[k]);
        if (!r->ok[v]) { printf("  %-16s -\n", label); continue; }
        printf("  %-16s %9.2f %7.2fx %7.2fx %7d | %6.2f %6.0f   %6.2f %6.0f   %8.0f | %6.2f %6.2f %6.2f\n", label, rmed[RV_MS(v)], rmed[RV_RATIO_BASE(k)],
               rmed[RV_RATIO_RAYLIB(v)], (rxFilters[k] + 1)*(rxFilters[k] + 1), edge[k].edgeMean, edge[k].edgeMax, edge[k].allMean, edge[k].allMax,
               edge[k].awayMax, edge[k].width, IdealWidth(rxFilters[k]), edge[k].shift);
    }
    if (r->ok[RX_NOMAP])
    {
        char label[32];
        snprintf(label, sizeof(label), "pcf %d, no map", RX_NOMAP_FILTER);
        printf("  %-16s %9.2f %7.2fx %7.2fx %7d | shadow variant, scene without maps: lit value max err %d/255\n", label, rmed[RV_MS(RX_NOMAP)],
               rmed[RV_RATIO_BASE(RX_SHADOWED - 1)], rmed[RV_RATIO_RAYLIB(RX_NOMAP)], 0, noMapErr);
    }
    printf("  ideal width (box of n texels over the texel step, edge positions uniform):");
    for (int k = 0; k < RX_FILTERS; k++) printf(" pcf %d %.2f%s", rxFilters[k], IdealWidth(rxFilters[k]), (k < RX_FILTERS - 1)? "," : "\n");
    printf("  (%d pixels within %.0f texels of the edge)\n", r->ok[RX_UNSHADOWED + 1]? edge[0].edgePixels : 0, RX_EDGE_TEXELS);
    if (selfOk) SelfBenchSummary(&sb);
    printf("bench_shadows: done in %.1f s, rows in %s%s\n", (BenchNowNs() - benchStart)*1e-9, BenchCsvPath(), problems? " (with problems, see above)" : "");
    return 0;
}
