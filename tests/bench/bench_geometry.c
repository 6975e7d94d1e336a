// Benchmark suite "geometry": CPU cost of submitting camera-facing billboards, per billboard, for
//   raylib     DrawBillboardPro() per billboard, then rlDrawRenderBatchActive()
//   immediate  RblDrawBillboard() per billboard (one upload and one draw each)
//   batched    RblBeginBatch(), RblBatchAdd() per billboard, RblEndBatch() (batch loaded once)
//   batched_many  the same with one RblBatchAddMany() for the frame's array (its own batch)
//   instanced  RblDrawInstanced() once for the frame's RblInstance array (buffer loaded once)
//   v03_batched the batched path of the header's 0.3 (bench_geometry_v03.c: that header compiled in
//              its own translation unit, its own lit program and batch; the same billboards)
// at 1k / 10k / 100k billboards, without and with rotation, plus bytes uploaded per billboard,
// a memcpy bandwidth floor and each path's corner deviation from a double-precision reference
// (instanced: its vertex stage's output, captured with transform feedback).
//
// The paths are measured in interleaved rounds (one frame of each path per round, the order
// rotating), so a slow spell of this shared machine hits them alike; ratio_to_raylib is the median
// over rounds of the ratio within a round. A path's ns_per_billboard is its median frame.
//
// Timed region: from the first draw call to the end of the flush call. glFinish() runs before
// and after it, outside, so the GPU's earlier and later work is not counted. On a software GL
// (llvmpipe) the driver's vertex processing and binning run inside the draw call itself, so they
// are part of the measured submission; rasterisation is kept cheap with a 64x64 render target.
// To show that share, the time spent inside the driver's draw calls (glDraw*) and uploads
// (glBufferSubData) is measured too, by wrapping the GL entry points rlgl calls through glad's
// global pointers; excl_draw = submission minus the draw calls, about what the CPU would spend
// with a hardware GPU (whose draw call only queues work). Without those symbols (a raylib build
// that hides them) the driver rows are left out.
//
// Rows (suite "geometry"; case <path>_<N>_<rot|norot> unless noted):
//   ns_per_billboard, submit_ns_per_billboard (draw calls), flush_ns_per_billboard (flush call)
//   ratio_to_raylib, frames (rounds the medians are over; 3 for an immediate case of seconds per frame)
//   draw_ns_per_billboard (inside glDraw*), upload_ns_per_billboard (inside glBufferSubData),
//   excl_draw_ns_per_billboard (submission minus draw calls), excl_draw_ratio_to_raylib
//   batched_<N>_<rot>: over_v03 and excl_draw_over_v03 (median per-round ratio to v03_batched)
//   RblBillboard_v03 / RblBillboard / RblFade: struct_size (bytes; the fade travels beside, not inside)
//   batched_visible_<N>, batched_cull90_<N>, batched_cull90_nocull_<N>: ns_per_billboard of a fully
//   visible set and of the same set with 90 % moved outside the view (culled; and with noCull);
//   batched_cull90_<N>: over_visible, nocull_over_visible (median per-round ratios), culled (count);
//   batched_visible_<N>: culled (the part of the bench's box outside the 64x64 view)
//   <path>: bytes_per_billboard (uploaded), floor_ns_per_billboard (bytes / memcpy GB/s);
//   <path>_<N>_<rot>: ratio_to_floor, excl_draw_over_floor (the CPU outside glDraw* over the floor);
//   excl_draw_over_round_memcpy (over a memcpy of the same bytes in the same round: the same caches)
//   memcpy_64MiB: bandwidth (GB/s, median of 7 copies)
//   batched_<N>, batched_many_<N>, immediate_<N>, instanced_<N> and raylib_<N>: max_corner_error (world units) against a double-precision
//   DrawBillboardPro, over the unrotated and rotated sets; max_corner_rel_error = that error over
//   the largest reference corner distance from the world origin (compare with FLT_EPSILON 1.19e-7)
// Output: rows appended to $BENCH_CSV (see bench.h) and a summary table on stdout.
// Usage: bench_geometry [filter]   only cases whose name (e.g. batched_100000_rot) contains filter
// run (for profiling); the accuracy and bandwidth rows are always written.
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "rlgl.h"
#include "harness.h"
#include "bench.h"
#include "batch_peek.h"
#include "tf_capture.h"
#include "bench_geometry_v03.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

//----------------------------------------------------------------------------------
// Defines and Macros
//----------------------------------------------------------------------------------
#define SUITE               "geometry"
#define MAX_BILLBOARDS      100000      // Largest case; smaller cases use a prefix of the same set
#define TARGET_SIZE         64          // Render target side (small: rasterisation stays cheap)
#define ATLAS_SIZE          256         // Albedo texture side
#define ATLAS_FRAME         32          // Atlas frame side (8x8 frames)
#define SCENE_SEED          0x2545F491u // Fixed seed of the billboard set
#define IMMEDIATE_SLOW_FRAME_S 1.0      // Immediate cases estimated slower than this per frame get their own short rounds
#define MEMCPY_BYTES        (64u*1024u*1024u)
#define MEMCPY_RUNS         7

//----------------------------------------------------------------------------------
// Types and Structures Definition
//----------------------------------------------------------------------------------
typedef enum { PATH_RAYLIB = 0, PATH_IMMEDIATE, PATH_BATCHED, PATH_INSTANCED, PATH_V03, PATH_BATCHED_MANY, PATH_COUNT } BenchPath;

// DrawBillboardPro() arguments of one billboard (up is (0,1,0) and tint WHITE for all)
typedef struct RaylibBillboard {
    Rectangle source;
    Vector3 position;
    Vector2 size;
    Vector2 origin;
    float rotation;
} RaylibBillboard;

// One round: a frame of each selected path, same billboard count and rotation
typedef struct RoundCase {
    int count;              // Billboards per frame
    int rotated;            // 0: rotation = 0, 1: random rotation
    bool run[PATH_COUNT];   // Paths taking part
    int round;              // Rounds done (rotates the path order)
} RoundCase;

// Values a frame reports (ns per billboard)
#define FRAME_TOTAL         0       // First draw call .. end of the flush
#define FRAME_SUBMIT        1       // Draw calls
#define FRAME_FLUSH         2       // Flush call
#define FRAME_DRIVER_DRAW   3       // Inside glDraw* (the driver's vertex stage on a software GL)
#define FRAME_DRIVER_UPLOAD 4       // Inside glBufferSubData
#define FRAME_EXCL_DRAW     5       // Total minus FRAME_DRIVER_DRAW
#define FRAME_VALUES        6

// Values a round reports: each path's frame values, then per path the ratios to raylib
#define ROUND_FRAME(p)          ((p)*FRAME_VALUES)
#define ROUND_RATIO(p)          (PATH_COUNT*FRAME_VALUES + (p))
#define ROUND_RATIO_EXCL(p)     (PATH_COUNT*(FRAME_VALUES + 1) + (p))
#define ROUND_BATCHED_OVER_V03       (PATH_COUNT*(FRAME_VALUES + 2))
#define ROUND_BATCHED_OVER_V03_EXCL  (PATH_COUNT*(FRAME_VALUES + 2) + 1)
#define ROUND_COPY_NS_PER_BYTE  (PATH_COUNT*(FRAME_VALUES + 2) + 2)   // A memcpy of the round's billboards
#define ROUND_OVER_COPY(p)      (PATH_COUNT*(FRAME_VALUES + 2) + 3 + (p))   // Excl-draw ns / the copy's ns per byte
#define ROUND_VALUES            (PATH_COUNT*(FRAME_VALUES + 3) + 3)

// Medians of one case
typedef struct CaseResult {
    bool measured;
    double nsPerBillboard;  // Submission: first draw call to end of the flush
    double submitNs;        // Draw calls only (raylib: includes its automatic flushes every 8192 quads)
    double flushNs;         // Flush call only
    double drawNs;          // Inside the driver's draw calls
    double uploadNs;        // Inside the driver's buffer uploads
    double exclDrawNs;      // nsPerBillboard minus drawNs
    double ratio;           // Median of the per-round ratio to raylib (0 = raylib not run)
    double ratioExclDraw;   // The same for exclDrawNs
    double overV03;         // batched: median per-round ratio to v03_batched (0 = not run)
    double overV03Excl;     // The same excluding the draw calls
    double overCopyBytes;   // Median per-round exclDrawNs over the same round's memcpy ns per byte (divided by the path's bytes: x floor)
    int frames;
} CaseResult;

//----------------------------------------------------------------------------------
// Global Variables Definition
//----------------------------------------------------------------------------------
static const char *pathNames[PATH_COUNT] = { "raylib", "immediate", "batched", "instanced", "v03_batched", "batched_many" };
static bool v03Available = false;           // the 0.3 baseline is built in and loaded
static const int counts[] = { 1000, 10000, 100000 };
#define COUNT_CASES ((int)(sizeof(counts)/sizeof(counts[0])))

static Camera3D camera;
static RenderTexture2D target;
static Texture2D atlas;
static Shader lit, litInstanced;
static Material material, materialInstanced;     // same atlas; vertex-buffer and instanced lit shaders
static RblBatch batch;
static RblBatch batchMany;           // the same billboards through RblBatchAddMany (its own batch: each maps its own buffer)
static RblInstanceBuffer instanceBuffer;
static RblInstancedDesc instancedDesc;
static RaylibBillboard *raylibSet[2];       // [rotated]
static RblBillboard *rblSet[2];             // [rotated], the same billboards as RblBillboard
static RblBillboard *copySet;               // Where each round's memcpy of the billboards goes
static RblInstance *instanceSet[2];         // [rotated], the same billboards as RblInstance

static CaseResult results[PATH_COUNT][COUNT_CASES][2];

//----------------------------------------------------------------------------------
// Driver call timing: rlgl calls GL through glad's global function pointers (GL 3.3 build);
// weak references stay NULL where a raylib build does not export them
//----------------------------------------------------------------------------------
typedef void (*GlDrawArraysFn)(unsigned int mode, int first, int count);
typedef void (*GlDrawElementsFn)(unsigned int mode, int count, unsigned int type, const void *indices);
typedef void (*GlDrawArraysInstancedFn)(unsigned int mode, int first, int count, int instances);
typedef void (*GlDrawElementsInstancedFn)(unsigned int mode, int count, unsigned int type, const void *indices, int instances);
typedef void (*GlBufferSubDataFn)(unsigned int target, ptrdiff_t offset, ptrdiff_t size, const void *data);

extern GlDrawArraysFn glad_glDrawArrays __attribute__((weak));
extern GlDrawElementsFn glad_glDrawElements __attribute__((weak));
extern GlDrawArraysInstancedFn glad_glDrawArraysInstanced __attribute__((weak));
extern GlDrawElementsInstancedFn glad_glDrawElementsInstanced __attribute__((weak));
extern GlBufferSubDataFn glad_glBufferSubData __attribute__((weak));

static GlDrawArraysFn realDrawArrays = NULL;
static GlDrawElementsFn realDrawElements = NULL;
static GlDrawArraysInstancedFn realDrawArraysInstanced = NULL;
static GlDrawElementsInstancedFn realDrawElementsInstanced = NULL;
static GlBufferSubDataFn realBufferSubData = NULL;
static bool driverTimed = false;            // Every entry point above is wrapped
static double driverDrawNs = 0.0;           // Accumulated inside glDraw* since the last reset
static double driverUploadNs = 0.0;         // Accumulated inside glBufferSubData

static void TimedDrawArrays(unsigned int mode, int first, int count)
{
    double t0 = BenchNowNs();
    realDrawArrays(mode, first, count);
    driverDrawNs += BenchNowNs() - t0;
}

static void TimedDrawElements(unsigned int mode, int count, unsigned int type, const void *indices)
{
    double t0 = BenchNowNs();
    realDrawElements(mode, count, type, indices);
    driverDrawNs += BenchNowNs() - t0;
}

static void TimedDrawArraysInstanced(unsigned int mode, int first, int count, int instances)
{
    double t0 = BenchNowNs();
    realDrawArraysInstanced(mode, first, count, instances);
    driverDrawNs += BenchNowNs() - t0;
}

static void TimedDrawElementsInstanced(unsigned int mode, int count, unsigned int type, const void *indices, int instances)
{
    double t0 = BenchNowNs();
    realDrawElementsInstanced(mode, count, type, indices, instances);
    driverDrawNs += BenchNowNs() - t0;
}

static void TimedBufferSubData(unsigned int target, ptrdiff_t offset, ptrdiff_t size, const void *data)
{
    double t0 = BenchNowNs();
    realBufferSubData(target, offset, size, data);
    driverUploadNs += BenchNowNs() - t0;
}

// Wraps the entry points once GL is loaded; false (nothing wrapped) if any is unavailable
static bool WrapDriverCalls(void)
{
    if ((&glad_glDrawArrays == NULL) || (&glad_glDrawElements == NULL) || (&glad_glDrawArraysInstanced == NULL) ||
        (&glad_glDrawElementsInstanced == NULL) || (&glad_glBufferSubData == NULL)) return false;
    if ((glad_glDrawArrays == NULL) || (glad_glDrawElements == NULL) || (glad_glDrawArraysInstanced == NULL) ||
        (glad_glDrawElementsInstanced == NULL) || (glad_glBufferSubData == NULL)) return false;
    realDrawArrays = glad_glDrawArrays; glad_glDrawArrays = TimedDrawArrays;
    realDrawElements = glad_glDrawElements; glad_glDrawElements = TimedDrawElements;
    realDrawArraysInstanced = glad_glDrawArraysInstanced; glad_glDrawArraysInstanced = TimedDrawArraysInstanced;
    realDrawElementsInstanced = glad_glDrawElementsInstanced; glad_glDrawElementsInstanced = TimedDrawElementsInstanced;
    realBufferSubData = glad_glBufferSubData; glad_glBufferSubData = TimedBufferSubData;
    return true;
}

//----------------------------------------------------------------------------------
// Scene
//----------------------------------------------------------------------------------
// Fixed-seed billboards in a box in front of the camera: sizes 0.5..2, pivot at the centre,
// random 32x32 atlas frames; the rotated set is the same set with a random rotation each.
static bool BuildScene(void)
{
    camera.position = (Vector3){ 0.0f, 3.0f, 12.0f };
    camera.target = (Vector3){ 0.0f, 1.0f, 0.0f };
    camera.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    camera.fovy = 60.0f;
    camera.projection = CAMERA_PERSPECTIVE;

    for (int r = 0; r < 2; r++)
    {
        raylibSet[r] = (RaylibBillboard *)calloc(MAX_BILLBOARDS, sizeof(RaylibBillboard));
        rblSet[r] = (RblBillboard *)calloc(MAX_BILLBOARDS, sizeof(RblBillboard));
        if (r == 0) copySet = (RblBillboard *)calloc(MAX_BILLBOARDS, sizeof(RblBillboard));
        instanceSet[r] = (RblInstance *)calloc(MAX_BILLBOARDS, sizeof(RblInstance));
        if ((raylibSet[r] == NULL) || (rblSet[r] == NULL) || (instanceSet[r] == NULL)) return false;
    }

    unsigned int seed = SCENE_SEED;
    const int framesPerRow = ATLAS_SIZE/ATLAS_FRAME;
    for (int i = 0; i < MAX_BILLBOARDS; i++)
    {
        RaylibBillboard a;
        a.position.x = rtRandomRange(&seed, -10.0f, 10.0f);
        a.position.y = rtRandomRange(&seed, -2.0f, 5.0f);
        a.position.z = rtRandomRange(&seed, -15.0f, 3.0f);
        a.size.x = rtRandomRange(&seed, 0.5f, 2.0f);
        a.size.y = rtRandomRange(&seed, 0.5f, 2.0f);
        a.origin = (Vector2){ a.size.x*0.5f, a.size.y*0.5f };
        int frame = (int)(rtRandom(&seed)%(unsigned int)(framesPerRow*framesPerRow));
        a.source = (Rectangle){ (float)((frame%framesPerRow)*ATLAS_FRAME), (float)((frame/framesPerRow)*ATLAS_FRAME), (float)ATLAS_FRAME, (float)ATLAS_FRAME };
        float rotation = rtRandomRange(&seed, 0.0f, 360.0f);

        for (int r = 0; r < 2; r++)
        {
            a.rotation = (r == 1)? rotation : 0.0f;
            raylibSet[r][i] = a;

            RblBillboard *b = &rblSet[r][i];
            memset(b, 0, sizeof(*b));
            b->position = a.position;
            b->size = a.size;
            b->origin = a.origin;
            b->rotation = a.rotation;
            b->source = a.source;
            b->tint = WHITE;
            b->facing = RBL_FACING_CAMERA_PLANE;
            b->up = (Vector3){ 0.0f, 1.0f, 0.0f };      // as the baseline's DrawBillboardPro up

            V03SetCard(r, i, a.position, a.size, a.origin, a.rotation, a.source);

            RblInstance *in = &instanceSet[r][i];
            memset(in, 0, sizeof(*in));
            in->position = a.position;
            in->rotation = a.rotation;
            in->size = a.size;
            in->origin = a.origin;
            in->source = a.source;
            in->tint = WHITE;
        }
    }
    memset(&instancedDesc, 0, sizeof(instancedDesc));
    instancedDesc.facing = RBL_FACING_CAMERA_PLANE;
    instancedDesc.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    return true;
}

static void FreeScene(void)
{
    for (int r = 0; r < 2; r++) { free(raylibSet[r]); free(rblSet[r]); free(instanceSet[r]); }
    free(copySet);
}

//----------------------------------------------------------------------------------
// Timed frame
//----------------------------------------------------------------------------------
// out[FRAME_*]: ns per billboard (immediate and instanced have no separate flush: SUBMIT = TOTAL)
static void RunFrame(BenchPath path, int n, int rotated, double *out)
{
    const RaylibBillboard *args = raylibSet[rotated];
    const RblBillboard *bbs = rblSet[rotated];
    const Vector3 up = { 0.0f, 1.0f, 0.0f };

    BeginTextureMode(target);
    ClearBackground(BLACK);
    BeginMode3D(camera);
    rlDrawRenderBatchActive();
    rtFinish();

    driverDrawNs = 0.0;
    driverUploadNs = 0.0;
    double t0 = BenchNowNs(), t1 = t0;
    switch (path)
    {
        case PATH_RAYLIB:
        {
            for (int i = 0; i < n; i++)
            {
                const RaylibBillboard *a = &args[i];
                DrawBillboardPro(camera, atlas, a->source, a->position, up, a->size, a->origin, a->rotation, WHITE);
            }
            t1 = BenchNowNs();
            rlDrawRenderBatchActive();
        } break;
        case PATH_IMMEDIATE:
        {
            for (int i = 0; i < n; i++) RblDrawBillboard(camera, material, bbs[i]);
            t1 = BenchNowNs();
        } break;
        case PATH_BATCHED:
        {
            RblBeginBatch(&batch, camera);
            for (int i = 0; i < n; i++) RblBatchAdd(&batch, material, &bbs[i]);
            t1 = BenchNowNs();
            RblEndBatch(&batch);
        } break;
        case PATH_BATCHED_MANY:
        {
            RblBeginBatch(&batchMany, camera);
            RblBatchAddMany(&batchMany, material, bbs, n);
            t1 = BenchNowNs();
            RblEndBatch(&batchMany);
        } break;
        case PATH_INSTANCED:
        {
            int drawn = RblDrawInstanced(&instanceBuffer, camera, materialInstanced, instancedDesc, instanceSet[rotated], n);
            t1 = BenchNowNs();
            if (drawn != n) { printf("bench_geometry: RblDrawInstanced drew %d of %d\n", drawn, n); exit(1); }
        } break;
        case PATH_V03:
        {
            int added = V03Frame(camera, rotated, n, BenchNowNs, &t1);
            if (added != n) { printf("bench_geometry: 0.3 batch took %d of %d\n", added, n); exit(1); }
        } break;
        default: break;
    }
    double t2 = BenchNowNs();
    double drawNs = driverDrawNs, uploadNs = driverUploadNs;

    rtFinish();
    EndMode3D();
    EndTextureMode();

    out[FRAME_TOTAL] = (t2 - t0)/n;
    out[FRAME_SUBMIT] = (t1 - t0)/n;
    out[FRAME_FLUSH] = (t2 - t1)/n;
    out[FRAME_DRIVER_DRAW] = drawNs/n;
    out[FRAME_DRIVER_UPLOAD] = uploadNs/n;
    out[FRAME_EXCL_DRAW] = (t2 - t0 - drawNs)/n;
}

static void *(*volatile benchCopy)(void *, const void *, size_t) = memcpy;   // not elided

// ns per byte of a memcpy of the round's n billboards (88 B each), the floor in the same caches
static double CopyFrame(int n, int rotated)
{
    rtFinish();
    double t0 = BenchNowNs();
    benchCopy(copySet, rblSet[rotated], (size_t)n*sizeof(RblBillboard));
    return (BenchNowNs() - t0)/((double)n*sizeof(RblBillboard));
}

// One frame of each selected path and the memcpy, starting with a different one each round
static void RunRound(void *ctx, double *out)
{
    RoundCase *rc = (RoundCase *)ctx;
    for (int k = 0; k < ROUND_VALUES; k++) out[k] = 0.0;
    for (int i = 0; i <= PATH_COUNT; i++)
    {
        int p = (rc->round + i)%(PATH_COUNT + 1);
        if (p == PATH_COUNT) out[ROUND_COPY_NS_PER_BYTE] = CopyFrame(rc->count, rc->rotated);
        else if (rc->run[p]) RunFrame((BenchPath)p, rc->count, rc->rotated, &out[ROUND_FRAME(p)]);
    }
    for (int p = 0; p < PATH_COUNT; p++) out[ROUND_OVER_COPY(p)] = out[ROUND_FRAME(p) + FRAME_EXCL_DRAW]/out[ROUND_COPY_NS_PER_BYTE];
    if (rc->run[PATH_RAYLIB])
    {
        const double *base = &out[ROUND_FRAME(PATH_RAYLIB)];
        for (int p = 0; p < PATH_COUNT; p++)
        {
            out[ROUND_RATIO(p)] = out[ROUND_FRAME(p) + FRAME_TOTAL]/base[FRAME_TOTAL];
            out[ROUND_RATIO_EXCL(p)] = out[ROUND_FRAME(p) + FRAME_EXCL_DRAW]/base[FRAME_EXCL_DRAW];
        }
    }
    if (rc->run[PATH_V03] && rc->run[PATH_BATCHED])
    {
        const double *v = &out[ROUND_FRAME(PATH_V03)], *b = &out[ROUND_FRAME(PATH_BATCHED)];
        out[ROUND_BATCHED_OVER_V03] = b[FRAME_TOTAL]/v[FRAME_TOTAL];
        out[ROUND_BATCHED_OVER_V03_EXCL] = b[FRAME_EXCL_DRAW]/v[FRAME_EXCL_DRAW];
    }
    rc->round++;
}

// Culling rounds: one batched frame of each set (the visible one, 90 % outside culled, 90 % outside
// with noCull), the order rotating; values: ns per billboard of each, then the two ratios
#define CULL_VALUES 5
typedef struct CullCase { int count; const RblBillboard *sets[3]; int round; int culled, culledVisible; } CullCase;

static double CullFrame(const RblBillboard *set, int n, bool noCull, int *culled)
{
    BeginTextureMode(target);
    ClearBackground(BLACK);
    BeginMode3D(camera);
    rlDrawRenderBatchActive();
    rtFinish();
    double t0 = BenchNowNs();
    batch.noCull = noCull;
    RblBeginBatch(&batch, camera);
    for (int i = 0; i < n; i++) RblBatchAdd(&batch, material, &set[i]);
    *culled = batch.culled;
    RblEndBatch(&batch);
    double t = BenchNowNs() - t0;
    batch.noCull = true;
    rtFinish();
    EndMode3D();
    EndTextureMode();
    return t/n;
}

static void RunCullRound(void *ctx, double *out)
{
    CullCase *cc = (CullCase *)ctx;
    for (int i = 0; i < 3; i++)
    {
        int k = (cc->round + i)%3, culled = 0;
        out[k] = CullFrame(cc->sets[k], cc->count, k == 2, &culled);
        if (k == 1) cc->culled = culled;
        if (k == 0) cc->culledVisible = culled;
    }
    out[3] = out[1]/out[0];
    out[4] = out[2]/out[0];
    cc->round++;
}

//----------------------------------------------------------------------------------
// Double-precision reference of DrawBillboardPro (positive sizes)
//----------------------------------------------------------------------------------
typedef struct D3 { double x, y, z; } D3;

static D3 D3Make(double x, double y, double z) { D3 v; v.x = x; v.y = y; v.z = z; return v; }
static D3 D3From(Vector3 v) { return D3Make(v.x, v.y, v.z); }
static D3 D3Add(D3 a, D3 b) { return D3Make(a.x + b.x, a.y + b.y, a.z + b.z); }
static D3 D3Sub(D3 a, D3 b) { return D3Make(a.x - b.x, a.y - b.y, a.z - b.z); }
static D3 D3Scale(D3 a, double s) { return D3Make(a.x*s, a.y*s, a.z*s); }
static double D3Dot(D3 a, D3 b) { return a.x*b.x + a.y*b.y + a.z*b.z; }
static double D3Length(D3 a) { return sqrt(D3Dot(a, a)); }
static D3 D3Cross(D3 a, D3 b) { return D3Make(a.y*b.z - a.z*b.y, a.z*b.x - a.x*b.z, a.x*b.y - a.y*b.x); }
static D3 D3Normalize(D3 a)
{
    double len = D3Length(a);
    return (len > 0.0)? D3Scale(a, 1.0/len) : a;
}

// Corners bottom-left, bottom-right, top-right, top-left (DrawBillboardPro's points[0..3]):
// right = row 0 of the lookAt view matrix scaled by size.x, up scaled by size.y, pivot origin
// measured from the bottom-left, rotation counter-clockwise about cross(right, up).
static void ReferenceCorners(Camera3D cam, Vector3 upIn, const RaylibBillboard *a, D3 corners[4])
{
    D3 back = D3Normalize(D3Sub(D3From(cam.position), D3From(cam.target)));
    D3 right = D3Normalize(D3Cross(D3From(cam.up), back));
    right = D3Scale(right, a->size.x);
    D3 up = D3Scale(D3From(upIn), a->size.y);
    D3 origin3D = D3Add(D3Scale(D3Normalize(right), a->origin.x), D3Scale(D3Normalize(up), a->origin.y));

    D3 points[4] = { D3Make(0.0, 0.0, 0.0), right, D3Add(up, right), up };
    D3 axis = D3Normalize(D3Cross(right, up));
    double angle = (double)a->rotation*(3.14159265358979323846/180.0);
    double c = cos(angle), s = sin(angle);
    for (int i = 0; i < 4; i++)
    {
        D3 p = D3Sub(points[i], origin3D);
        if (a->rotation != 0.0f)
        {
            // Rodrigues: p cos + (k x p) sin + k (k.p)(1 - cos)
            p = D3Add(D3Add(D3Scale(p, c), D3Scale(D3Cross(axis, p), s)), D3Scale(axis, D3Dot(axis, p)*(1.0 - c)));
        }
        corners[i] = D3Add(p, D3From(a->position));
    }
}

// Deviation of float corners (xyz every strideFloats floats, 4 per billboard) from the reference;
// *maxError in world units, *scale = largest reference corner distance from the world origin
static void CornerError(const float *positions, int strideFloats, const RaylibBillboard *args, int n, double *maxError, double *scale)
{
    const Vector3 up = { 0.0f, 1.0f, 0.0f };
    for (int i = 0; i < n; i++)
    {
        D3 ref[4];
        ReferenceCorners(camera, up, &args[i], ref);
        for (int k = 0; k < 4; k++)
        {
            const float *p = positions + (size_t)(i*4 + k)*strideFloats;
            double e = D3Length(D3Sub(D3Make(p[0], p[1], p[2]), ref[k]));
            if (e > *maxError) *maxError = e;
            double r = D3Length(ref[k]);
            if (r > *scale) *scale = r;
        }
    }
}

// raylib's own corners for the same set, read back from a private rlgl batch before it is drawn
static void RaylibCornerError(int n, int rotated, double *maxError, double *scale)
{
    const Vector3 up = { 0.0f, 1.0f, 0.0f };
    rlRenderBatch own = rlLoadRenderBatch(1, n + 1);
    BeginTextureMode(target);
    BeginMode3D(camera);
    rlSetRenderBatchActive(&own);
    for (int i = 0; i < n; i++)
    {
        const RaylibBillboard *a = &raylibSet[rotated][i];
        DrawBillboardPro(camera, atlas, a->source, a->position, up, a->size, a->origin, a->rotation, WHITE);
    }
    CornerError(own.vertexBuffer[0].vertices, 3, raylibSet[rotated], n, maxError, scale);
    rlSetRenderBatchActive(NULL);       // draws what it holds, returns to the default batch
    EndMode3D();
    EndTextureMode();
    rlUnloadRenderBatch(own);
}

// The immediate path's own corners: each RblDrawBillboard() leaves its quad in the one-quad batch
static void ImmediateCorners(int n, int rotated, float *out)
{
    BeginTextureMode(target);
    BeginMode3D(camera);
    for (int i = 0; i < n; i++)
    {
        RblDrawBillboard(camera, material, rblSet[rotated][i]);
        for (int k = 0; k < 4; k++) memcpy(&out[(size_t)(i*4 + k)*3], rbl__state.immediate.state->vertices[k].position, 3*sizeof(float));
    }
    EndMode3D();
    EndTextureMode();
}

// The instanced path's corners as its vertex stage emits them (transform feedback); false if the
// capture is not available. Triangles (0,1,2)(0,2,3): corner 3 is the 6th vertex.
static bool InstancedCorners(int n, int rotated, float *out)
{
    TfGl gl;
    if (!tfLoad(&gl)) return false;
    GLu prog = tfProgram(&gl);
    if (prog == 0) return false;
    float *gpu = tfCapture(&gl, prog, &instanceBuffer, camera, instancedDesc, atlas.width, atlas.height, instanceSet[rotated], n);
    gl.DeleteProgram(prog);
    if (gpu == NULL) return false;
    const int vertexOf[4] = { 0, 1, 2, 5 };
    for (int i = 0; i < n; i++)
        for (int k = 0; k < 4; k++) memcpy(&out[(size_t)(i*4 + k)*3], &gpu[((size_t)i*6 + vertexOf[k])*TF_FLOATS], 3*sizeof(float));
    free(gpu);
    return true;
}

// The batch's corners: where it holds records, as the record vertex stage emits them (transform
// feedback over the records its last RblEndBatch uploaded), else its vertices
static void BatchedCorners(rbl__BatchState *st, int n, RblVertex *out)
{
    TfGl gl;
    GLu prog = (st->records && tfLoad(&gl))? tfRecordProgram(&gl) : 0;
    float *gpu = (prog != 0)? tfCaptureRecords(&gl, prog, st, n) : NULL;
    if (prog != 0) gl.DeleteProgram(prog);
    const int vertexOf[4] = { 0, 1, 2, 5 };
    for (int i = 0; i < n; i++)
    {
        if (gpu == NULL) { rtBatchVertices(st, i, out + (size_t)i*4); continue; }
        for (int k = 0; k < 4; k++) memcpy(out[(size_t)i*4 + k].position, &gpu[((size_t)i*6 + vertexOf[k])*TF_FLOATS], 3*sizeof(float));
    }
    free(gpu);
}

//----------------------------------------------------------------------------------
// memcpy bandwidth
//----------------------------------------------------------------------------------

// Median GB/s (= bytes per ns) of copying MEMCPY_BYTES, 0 on allocation failure
static double MeasureMemcpyBandwidth(void)
{
    unsigned char *src = (unsigned char *)malloc(MEMCPY_BYTES);
    unsigned char *dst = (unsigned char *)malloc(MEMCPY_BYTES);
    double gbps = 0.0;
    if ((src != NULL) && (dst != NULL))
    {
        memset(src, 0x5A, MEMCPY_BYTES);
        memset(dst, 0xA5, MEMCPY_BYTES);    // pages touched before timing
        double samples[MEMCPY_RUNS];
        benchCopy(dst, src, MEMCPY_BYTES);  // warm-up
        for (int i = 0; i < MEMCPY_RUNS; i++)
        {
            double t0 = BenchNowNs();
            benchCopy(dst, src, MEMCPY_BYTES);
            samples[i] = (double)MEMCPY_BYTES/(BenchNowNs() - t0);
        }
        gbps = BenchMedian(samples, MEMCPY_RUNS);
        if (dst[MEMCPY_BYTES/2] != 0x5A) gbps = 0.0;
    }
    free(src);
    free(dst);
    return gbps;
}

//----------------------------------------------------------------------------------
// Main
//----------------------------------------------------------------------------------
static void CaseName(char *buf, size_t size, BenchPath path, int n, int rotated)
{
    snprintf(buf, size, "%s_%d_%s", pathNames[path], n, rotated? "rot" : "norot");
}

int main(int argc, char **argv)
{
    const char *filter = (argc > 1)? argv[1] : NULL;
    double benchStart = BenchNowNs();
    const char *backend = rtInitContext(TARGET_SIZE, TARGET_SIZE);
    if (backend == NULL) { printf("bench_geometry: no GL context\n"); return 1; }

    driverTimed = WrapDriverCalls();
    target = LoadRenderTexture(TARGET_SIZE, TARGET_SIZE);
    Image checked = GenImageChecked(ATLAS_SIZE, ATLAS_SIZE, ATLAS_FRAME/2, ATLAS_FRAME/2, ORANGE, DARKBLUE);
    atlas = LoadTextureFromImage(checked);
    UnloadImage(checked);

    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = 1;                         // one light slot (0.3's default; 1.0's is 4)
    lit = RblLoadLitShader(desc);
    RblLight light = { 0 };
    light.position = (Vector3){ 0.0f, 6.0f, 8.0f };
    light.color = WHITE;
    light.intensity = 60.0f;
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = &light;
    scene.lightCount = 1;
    scene.ambient = (Color){ 40, 40, 40, 255 };
    if (!RblIsLitShaderValid(lit) || !RblSetScene(&scene))
    {
        printf("bench_geometry: lit shader failed\n");
        return 1;
    }
    desc.instanced = true;
    litInstanced = RblLoadLitShader(desc);      // loaded after RblSetScene: gets the current scene at load
    if (!RblIsLitShaderValid(litInstanced) || !RblSetScene(&scene))
    {
        printf("bench_geometry: instanced lit shader failed\n");
        return 1;
    }
    material = LoadMaterialDefault();
    material.shader = lit;
    material.maps[MATERIAL_MAP_ALBEDO].texture = atlas;
    materialInstanced = LoadMaterialDefault();
    materialInstanced.shader = litInstanced;
    materialInstanced.maps[MATERIAL_MAP_ALBEDO].texture = atlas;

    v03Available = V03Init(atlas, MAX_BILLBOARDS, light.position, light.intensity, scene.ambient);
    if (!v03Available) printf("bench_geometry: the 0.3 baseline is not built in (no git history) or failed to load: its rows are left out\n");
    batch = RblLoadBatch(MAX_BILLBOARDS);     // enough for the largest case: never grows
    batchMany = RblLoadBatch(MAX_BILLBOARDS);
    batch.noCull = true;                        // the same work as raylib and 0.3 (the culling rows turn it on)
    batchMany.noCull = true;
    instanceBuffer = RblLoadInstanceBuffer(MAX_BILLBOARDS);
    if ((target.id == 0) || (atlas.id == 0) || !RblIsBatchValid(batch) || !RblIsInstanceBufferValid(instanceBuffer) || !BuildScene())
    {
        printf("bench_geometry: setup failed\n");
        return 1;
    }

    // The immediate path's one-quad batch exists from the first draw: it keeps what it is given, as
    // raylib does (the same work; the culling rows below show what culling saves)
    RblDrawBillboard(camera, material, rblSet[0][0]);
    if (rbl__state.immediate.state != NULL) rbl__state.immediate.noCull = true;
    if (sizeof(((RoundCase *)NULL)->run) == 0 || ROUND_VALUES > BENCH_MAX_VALUES) { printf("bench_geometry: %d round values, BENCH_MAX_VALUES %d\n", ROUND_VALUES, BENCH_MAX_VALUES); return 1; }
    printf("bench_geometry: GL context %s, render target %dx%d, atlas %dx%d, billboards in a box in front of the camera%s\n",
           backend, TARGET_SIZE, TARGET_SIZE, ATLAS_SIZE, ATLAS_SIZE, driverTimed? "" : "; driver calls not timed (glad symbols not found)");
    fflush(stdout);

    // Per (N, rotation): warm-up 1 round, median of 5..15 rounds, no new round after ~3 s. A slow
    // immediate case (seconds per frame) runs afterwards in 3 rounds of its own beside raylib.
    const BenchTiming timing = { 1, 5, 15, 3.0e9 }, slowTiming = { 0, 3, 3, 0.0 };
    char name[64];
    double batchedError[COUNT_CASES] = { 0 }, batchedScale[COUNT_CASES] = { 0 }, manyError[COUNT_CASES] = { 0 }, manyScale[COUNT_CASES] = { 0 };

    for (int c = 0; c < COUNT_CASES; c++)
    {
        for (int rotated = 0; rotated < 2; rotated++)
        {
            RoundCase rc;
            memset(&rc, 0, sizeof(rc));
            rc.count = counts[c];
            rc.rotated = rotated;
            bool selected[PATH_COUNT], slowImmediate = false;
            for (int p = 0; p < PATH_COUNT; p++)
            {
                CaseName(name, sizeof(name), (BenchPath)p, counts[c], rotated);
                selected[p] = ((filter == NULL) || (strstr(name, filter) != NULL)) && ((p != PATH_V03) || v03Available);
                // The immediate path costs one upload and one draw per billboard: where the previous
                // (smaller) case predicts seconds per frame it gets fewer rounds of its own
                if (selected[p] && (p == PATH_IMMEDIATE) && (c > 0) && results[p][c - 1][rotated].measured)
                {
                    double estimate = results[p][c - 1][rotated].nsPerBillboard*counts[c]*1e-9;
                    if (estimate > IMMEDIATE_SLOW_FRAME_S)
                    {
                        slowImmediate = true;
                        printf("  %-26s estimated %.2f s per frame: %d rounds of its own after the others\n", name, estimate, slowTiming.minRuns);
                    }
                }
            }

            for (int pass = 0; pass < 2; pass++)
            {
                // pass 0: every selected path (the slow immediate case left out); pass 1: that case beside raylib
                bool fill[PATH_COUNT];
                bool any = false;
                for (int p = 0; p < PATH_COUNT; p++)
                {
                    bool slow = slowImmediate && (p == PATH_IMMEDIATE);
                    fill[p] = selected[p] && ((pass == 0)? !slow : slow);
                    rc.run[p] = fill[p] || ((pass == 1) && slowImmediate && (p == PATH_RAYLIB));
                    any = any || fill[p];
                }
                if (!any) continue;

                double medians[ROUND_VALUES];
                int rounds = BenchMedianOfRuns(RunRound, &rc, ROUND_VALUES, (pass == 0)? timing : slowTiming, medians);

                for (int p = 0; p < PATH_COUNT; p++)
                {
                    if (!fill[p]) continue;
                    CaseResult *res = &results[p][c][rotated];
                    CaseName(name, sizeof(name), (BenchPath)p, counts[c], rotated);
                    res->measured = true;
                    res->frames = rounds;
                    const double *frame = &medians[ROUND_FRAME(p)];
                    res->nsPerBillboard = frame[FRAME_TOTAL];
                    res->submitNs = frame[FRAME_SUBMIT];
                    res->flushNs = frame[FRAME_FLUSH];
                    res->drawNs = frame[FRAME_DRIVER_DRAW];
                    res->uploadNs = frame[FRAME_DRIVER_UPLOAD];
                    res->exclDrawNs = frame[FRAME_EXCL_DRAW];
                    res->ratio = rc.run[PATH_RAYLIB]? medians[ROUND_RATIO(p)] : 0.0;
                    res->ratioExclDraw = rc.run[PATH_RAYLIB]? medians[ROUND_RATIO_EXCL(p)] : 0.0;
                    bool againstV03 = (p == PATH_BATCHED) && rc.run[PATH_V03];
                    res->overV03 = againstV03? medians[ROUND_BATCHED_OVER_V03] : 0.0;
                    res->overV03Excl = againstV03? medians[ROUND_BATCHED_OVER_V03_EXCL] : 0.0;
                    res->overCopyBytes = medians[ROUND_OVER_COPY(p)];
                    if (againstV03)
                    {
                        BenchCsvRow(SUITE, name, "over_v03", res->overV03, "x");
                        BenchCsvRow(SUITE, name, "excl_draw_over_v03", res->overV03Excl, "x");
                    }

                    BenchCsvRow(SUITE, name, "ns_per_billboard", res->nsPerBillboard, "ns");
                    if ((p == PATH_RAYLIB) || (p == PATH_BATCHED) || (p == PATH_V03))
                    {
                        BenchCsvRow(SUITE, name, "submit_ns_per_billboard", res->submitNs, "ns");
                        BenchCsvRow(SUITE, name, "flush_ns_per_billboard", res->flushNs, "ns");
                    }
                    if (rc.run[PATH_RAYLIB]) BenchCsvRow(SUITE, name, "ratio_to_raylib", res->ratio, "x");
                    if (driverTimed)
                    {
                        BenchCsvRow(SUITE, name, "draw_ns_per_billboard", res->drawNs, "ns");
                        BenchCsvRow(SUITE, name, "upload_ns_per_billboard", res->uploadNs, "ns");
                        BenchCsvRow(SUITE, name, "excl_draw_ns_per_billboard", res->exclDrawNs, "ns");
                        if (rc.run[PATH_RAYLIB]) BenchCsvRow(SUITE, name, "excl_draw_ratio_to_raylib", res->ratioExclDraw, "x");
                    }
                    BenchCsvRow(SUITE, name, "frames", res->frames, "count");
                    printf("  %-26s %10.1f ns/billboard", name, res->nsPerBillboard);
                    if (rc.run[PATH_RAYLIB]) printf(" %8.3fx raylib (excl draw %6.1f ns, %.3fx)", res->ratio, res->exclDrawNs, res->ratioExclDraw);
                    if (res->overV03 > 0.0) printf(" %.3fx 0.3 (excl draw %.3fx)", res->overV03, res->overV03Excl);
                    printf("  (median of %d frames)\n", res->frames);
                }
            }
            fflush(stdout);

            if (selected[PATH_BATCHED])
            {
                // The batch still holds the last batched frame: its vertices, or its records (their
                // corners as the record vertex stage emits them)
                if ((batch.count != counts[c]) || (batch.skipped != 0))
                {
                    printf("bench_geometry: batch holds %d billboards (%d skipped), expected %d\n", batch.count, batch.skipped, counts[c]);
                    return 1;
                }
                RblVertex *corners = (RblVertex *)malloc((size_t)counts[c]*4*sizeof(RblVertex));
                if (corners == NULL) return 1;
                BatchedCorners(batch.state, counts[c], corners);
                CornerError(corners[0].position, (int)(sizeof(RblVertex)/sizeof(float)), raylibSet[rotated], counts[c], &batchedError[c], &batchedScale[c]);
                free(corners);
            }
            if (selected[PATH_BATCHED_MANY])
            {
                if ((batchMany.count != counts[c]) || (batchMany.skipped != 0))
                {
                    printf("bench_geometry: RblBatchAddMany's batch holds %d billboards (%d skipped), expected %d\n", batchMany.count, batchMany.skipped, counts[c]);
                    return 1;
                }
                RblVertex *corners = (RblVertex *)malloc((size_t)counts[c]*4*sizeof(RblVertex));
                if (corners == NULL) return 1;
                BatchedCorners(batchMany.state, counts[c], corners);
                CornerError(corners[0].position, (int)(sizeof(RblVertex)/sizeof(float)), raylibSet[rotated], counts[c], &manyError[c], &manyScale[c]);
                free(corners);
            }
        }
    }

    // Culling: the same set fully visible, and with 90 % moved outside the view (culled, then kept
    // with noCull), interleaved per round
    if ((filter == NULL) || (strstr("batched_cull", filter) != NULL))
    {
        RblBillboard *cull90 = (RblBillboard *)malloc((size_t)MAX_BILLBOARDS*sizeof(RblBillboard));
        if (cull90 == NULL) { printf("bench_geometry: out of memory\n"); return 1; }
        memcpy(cull90, rblSet[0], (size_t)MAX_BILLBOARDS*sizeof(RblBillboard));
        for (int i = 0; i < MAX_BILLBOARDS; i++) if (i%10 != 0) cull90[i].position.x += (i%2)? 500.0f : -500.0f;
        for (int c = 0; c < COUNT_CASES; c++)
        {
            CullCase cc;
            memset(&cc, 0, sizeof(cc));
            cc.count = counts[c];
            cc.sets[0] = rblSet[0]; cc.sets[1] = cull90; cc.sets[2] = cull90;
            double medians[CULL_VALUES];
            int rounds = BenchMedianOfRuns(RunCullRound, &cc, CULL_VALUES, timing, medians);
            static const char *const cullNames[3] = { "batched_visible", "batched_cull90", "batched_cull90_nocull" };
            for (int k = 0; k < 3; k++)
            {
                snprintf(name, sizeof(name), "%s_%d", cullNames[k], counts[c]);
                BenchCsvRow(SUITE, name, "ns_per_billboard", medians[k], "ns");
                BenchCsvRow(SUITE, name, "frames", rounds, "count");
            }
            snprintf(name, sizeof(name), "batched_cull90_%d", counts[c]);
            BenchCsvRow(SUITE, name, "over_visible", medians[3], "x");
            BenchCsvRow(SUITE, name, "nocull_over_visible", medians[4], "x");
            BenchCsvRow(SUITE, name, "culled", cc.culled, "count");
            snprintf(name, sizeof(name), "batched_visible_%d", counts[c]);
            BenchCsvRow(SUITE, name, "culled", cc.culledVisible, "count");
            printf("  batched %6d: visible %7.1f ns/billboard (%d of the box outside the view, culled), 90 %% outside %7.1f (%.3fx; %d culled), 90 %% outside with noCull %7.1f (%.3fx)  (median of %d rounds)\n",
                   counts[c], medians[0], cc.culledVisible, medians[1], medians[3], cc.culled, medians[2], medians[4], rounds);
        }
        free(cull90);
        fflush(stdout);
    }

    // Corner accuracy of every path and of raylib itself against the double-precision
    // DrawBillboardPro reference, over the rotated and unrotated sets: batched from the last timed
    // frame, immediate and instanced captured here (untimed) for the largest set, smaller sets
    // being its prefixes
    float *captured[2][2] = { { NULL, NULL }, { NULL, NULL } };     // [immediate, instanced][rotated]
    bool instancedCaptured = true;
    for (int rotated = 0; rotated < 2; rotated++)
    {
        captured[0][rotated] = (float *)malloc((size_t)MAX_BILLBOARDS*4*3*sizeof(float));
        captured[1][rotated] = (float *)malloc((size_t)MAX_BILLBOARDS*4*3*sizeof(float));
        if ((captured[0][rotated] == NULL) || (captured[1][rotated] == NULL)) { printf("bench_geometry: out of memory\n"); return 1; }
        ImmediateCorners(MAX_BILLBOARDS, rotated, captured[0][rotated]);
        instancedCaptured = instancedCaptured && InstancedCorners(MAX_BILLBOARDS, rotated, captured[1][rotated]);
    }
    if (!instancedCaptured) printf("  instanced corners: transform feedback unavailable, no accuracy row\n");
    for (int c = 0; c < COUNT_CASES; c++)
    {
        double raylibError = 0.0, raylibScale = 0.0;
        double pathError[2] = { 0.0, 0.0 }, pathScale[2] = { 0.0, 0.0 };
        for (int rotated = 0; rotated < 2; rotated++)
        {
            RaylibCornerError(counts[c], rotated, &raylibError, &raylibScale);
            CornerError(captured[0][rotated], 3, raylibSet[rotated], counts[c], &pathError[0], &pathScale[0]);
            if (instancedCaptured) CornerError(captured[1][rotated], 3, raylibSet[rotated], counts[c], &pathError[1], &pathScale[1]);
        }
        const char *rowPath[4] = { "batched", "immediate", "instanced", "batched_many" };
        const double rowError[4] = { batchedError[c], pathError[0], pathError[1], manyError[c] }, rowScale[4] = { batchedScale[c], pathScale[0], pathScale[1], manyScale[c] };
        for (int k = 0; k < 4; k++)
        {
            if (rowScale[k] <= 0.0) continue;     // not run (filter) or not captured
            snprintf(name, sizeof(name), "%s_%d", rowPath[k], counts[c]);
            BenchCsvRow(SUITE, name, "max_corner_error", rowError[k], "world_units");
            BenchCsvRow(SUITE, name, "max_corner_rel_error", rowError[k]/rowScale[k], "rel");
        }
        snprintf(name, sizeof(name), "raylib_%d", counts[c]);
        BenchCsvRow(SUITE, name, "max_corner_error", raylibError, "world_units");
        BenchCsvRow(SUITE, name, "max_corner_rel_error", raylibError/raylibScale, "rel");
        if (c == COUNT_CASES - 1)
        {
            printf("  max corner error vs double reference (%d billboards, rot+norot; world units, relative to the largest corner distance):\n"
                   "    raylib %.3g (%.3g rel)", counts[c], raylibError, raylibError/raylibScale);
            for (int k = 0; k < 4; k++)
                if (rowScale[k] > 0.0) printf(", %s %.3g (%.3g rel)", rowPath[k], rowError[k], rowError[k]/rowScale[k]);
            printf("; FLT_EPSILON 1.19e-07\n");
        }
    }
    for (int k = 0; k < 2; k++) for (int rotated = 0; rotated < 2; rotated++) free(captured[k][rotated]);

    // Upload volume and the memory-bandwidth floor. rlgl's batch uploads, per vertex, positions
    // (3 floats), texcoords (2 floats), normals (3 floats) and colours (4 bytes) in four
    // glBufferSubData calls (indices are static); immediate uploads 4 RblVertex (52 bytes each),
    // batched one record (the RblBillboard, 88 bytes; 4 RblVertex where the context has no GLSL 3), instanced one
    // RblInstance (56 bytes).
    const bool records = (batch.state != NULL) && batch.state->records, manyRecords = (batchMany.state != NULL) && batchMany.state->records;
    const double bytesPerBillboard[PATH_COUNT] = {
        4.0*(3*sizeof(float) + 2*sizeof(float) + 3*sizeof(float) + 4*sizeof(unsigned char)),
        4.0*sizeof(RblVertex),
        records? (double)sizeof(rbl__BatchRecord) : 4.0*sizeof(RblVertex),
        (double)sizeof(RblInstance),
        4.0*(double)V03VertexSize(),
        manyRecords? (double)sizeof(rbl__BatchRecord) : 4.0*sizeof(RblVertex)
    };
    double gbps = MeasureMemcpyBandwidth();
    // Struct sizes: 0.3's billboard, this one's, and the cross-fade that now travels beside it
    if (v03Available) BenchCsvRow(SUITE, "RblBillboard_v03", "struct_size", (double)V03BillboardSize(), "bytes");
    BenchCsvRow(SUITE, "RblBillboard", "struct_size", (double)sizeof(RblBillboard), "bytes");
    BenchCsvRow(SUITE, "RblFade", "struct_size", (double)sizeof(RblFade), "bytes");
    printf("  struct sizes: RblBillboard %d bytes (0.3: %d), RblFade %d bytes beside it (RblBatchAddFade); RblVertex %d bytes (0.3: %d)\n",
           (int)sizeof(RblBillboard), (int)V03BillboardSize(), (int)sizeof(RblFade), (int)sizeof(RblVertex), (int)V03VertexSize());
    BenchCsvRow(SUITE, "memcpy_64MiB", "bandwidth", gbps, "GB/s");
    for (int p = 0; p < PATH_COUNT; p++)
    {
        if (bytesPerBillboard[p] <= 0.0) continue;      // the 0.3 baseline not built in
        double floorNs = (gbps > 0.0)? bytesPerBillboard[p]/gbps : 0.0;
        BenchCsvRow(SUITE, pathNames[p], "bytes_per_billboard", bytesPerBillboard[p], "bytes");
        BenchCsvRow(SUITE, pathNames[p], "floor_ns_per_billboard", floorNs, "ns");
        for (int c = 0; c < COUNT_CASES; c++)
        {
            for (int rotated = 0; rotated < 2; rotated++)
            {
                const CaseResult *res = &results[p][c][rotated];
                if (!res->measured || (floorNs <= 0.0)) continue;
                CaseName(name, sizeof(name), (BenchPath)p, counts[c], rotated);
                BenchCsvRow(SUITE, name, "ratio_to_floor", res->nsPerBillboard/floorNs, "x");
                if (driverTimed) BenchCsvRow(SUITE, name, "excl_draw_over_floor", res->exclDrawNs/floorNs, "x");
                if (driverTimed) BenchCsvRow(SUITE, name, "excl_draw_over_round_memcpy", res->overCopyBytes/bytesPerBillboard[p], "x");
            }
        }
    }

    // Summary
    printf("\ngeometry summary (ns per billboard, medians; x raylib = median per-round ratio; x floor = over\n"
           "bytes uploaded / memcpy %.2f GB/s; x copy = excl-draw over a memcpy of the same bytes in the same round,\n"
           "median per-round ratio; draw = inside glDraw*, excl-draw = total minus draw)\n", gbps);
    printf("  %-12s %7s %-6s %10s %9s %8s %9s %10s %9s %9s %8s %9s\n", "path", "N", "rot", "total", "x raylib", "x floor",
           "draw", "excl-draw", "x raylib", "x floor", "x copy", "bytes/bb");
    double worst[PATH_COUNT] = { 0 }, worstExcl[PATH_COUNT] = { 0 };
    for (int c = 0; c < COUNT_CASES; c++)
    {
        for (int rotated = 0; rotated < 2; rotated++)
        {
            for (int p = 0; p < PATH_COUNT; p++)
            {
                const CaseResult *res = &results[p][c][rotated];
                const char *rot = rotated? "rot" : "norot";
                if (!res->measured) continue;     // filtered out
                double floorRatio = (gbps > 0.0)? res->nsPerBillboard/(bytesPerBillboard[p]/gbps) : 0.0;
                if (res->ratio > worst[p]) worst[p] = res->ratio;
                if (res->ratioExclDraw > worstExcl[p]) worstExcl[p] = res->ratioExclDraw;
                char ratioText[16] = "n/a", exclText[16] = "n/a", drawText[16] = "n/a", exclNsText[16] = "n/a", exclFloorText[16] = "n/a", copyText[16] = "n/a";
                if (res->ratio > 0.0) snprintf(ratioText, sizeof(ratioText), "%.3fx", res->ratio);
                if (driverTimed)
                {
                    snprintf(drawText, sizeof(drawText), "%.1f", res->drawNs);
                    snprintf(exclNsText, sizeof(exclNsText), "%.1f", res->exclDrawNs);
                    if (res->ratioExclDraw > 0.0) snprintf(exclText, sizeof(exclText), "%.3fx", res->ratioExclDraw);
                    if (gbps > 0.0) snprintf(exclFloorText, sizeof(exclFloorText), "%.2fx", res->exclDrawNs/(bytesPerBillboard[p]/gbps));
                    if (bytesPerBillboard[p] > 0.0) snprintf(copyText, sizeof(copyText), "%.2fx", res->overCopyBytes/bytesPerBillboard[p]);
                }
                printf("  %-12s %7d %-6s %10.1f %9s %7.1fx %9s %10s %9s %9s %8s %9.0f\n", pathNames[p], counts[c], rot,
                       res->nsPerBillboard, ratioText, floorRatio, drawText, exclNsText, exclText, exclFloorText, copyText, bytesPerBillboard[p]);
            }
        }
    }
    const double targets[PATH_COUNT] = { 0.0, 0.0, 0.25, 0.05, 0.0, 0.25 };
    for (int p = PATH_BATCHED; p < PATH_COUNT; p++)
    {
        if ((worst[p] <= 0.0) || (targets[p] <= 0.0)) continue;
        // The target is CPU cost. Without the driver timing, totals are all there is to judge it by.
        if (worstExcl[p] > 0.0)
            printf("  target %-9s <= %.2fx raylib CPU (excluding driver draw calls): worst %.3fx -> %s; totals including the\n"
                   "    driver's draw calls (a software GL runs the GPU's vertex stage there): worst %.3fx\n",
                   pathNames[p], targets[p], worstExcl[p], (worstExcl[p] <= targets[p])? "met" : "NOT met", worst[p]);
        else
            printf("  target %-9s <= %.2fx raylib CPU: worst total %.3fx -> %s (no driver timing: draw calls included)\n",
                   pathNames[p], targets[p], worst[p], (worst[p] <= targets[p])? "met" : "NOT met");
    }
    // Issue #27's goal for the batch at 100k: CPU per billboard (excluding the driver's draw calls)
    // at most 0.08x DrawBillboardPro's, and below 0.3's in the same rounds
    for (int rotated = 0; rotated < 2; rotated++)
    {
        const CaseResult *res = &results[PATH_BATCHED][COUNT_CASES - 1][rotated];
        if (!res->measured || (res->ratioExclDraw <= 0.0)) continue;
        printf("  goal batched 100000 %-5s CPU <= 0.08x raylib: %.3fx -> %s", rotated? "rot" : "norot", res->ratioExclDraw, (res->ratioExclDraw <= 0.08)? "met" : "NOT met");
        if (res->overV03Excl > 0.0) printf("; below 0.3: %.3fx -> %s", res->overV03Excl, (res->overV03Excl < 1.0)? "met" : "NOT met");
        printf("\n");
    }
    printf("bench_geometry: done in %.1f s, rows in %s\n", (BenchNowNs() - benchStart)*1e-9, BenchCsvPath());

    RblUnloadBatch(&batch);
    RblUnloadBatch(&batchMany);
    RblUnloadInstanceBuffer(&instanceBuffer);
    RblUnloadLitShader(&lit);
    RblUnloadLitShader(&litInstanced);
    MemFree(material.maps);
    MemFree(materialInstanced.maps);
    if (v03Available) V03Close();
    RblClose();                                 // after the Unload calls
    UnloadTexture(atlas);
    UnloadRenderTexture(target);
    FreeScene();
    rtCloseContext();
    return 0;
}
