// Benchmark rows of suite "sprites" for translucency and cut-outs (the atlas/animation rows are
// bench_sprites'):
//   sort_batch_<N>        ns_per_billboard of a sorted batch (RBL_SORT_BACK_TO_FRONT) and of the same
//                         batch unsorted, and their ratio, in interleaved rounds of the same run
//                         (medians of the per-round ratios); hybrid likewise (two passes)
//   sort_instanced_<N>    the same for RblInstancedDesc.sort
//   coverage_level_<L>    share of texels passing alpha 0.5 per mip level, plain and with
//                         alphaCoverage = 0.5, for a 512x512 foliage cut-out (level 0 is the target)
// Timing: RblBeginBatch .. RblEndBatch (CPU build, sort, upload, draw calls) of N random translucent
// billboards into a 64x64 target, glFinish before and after, outside the timed region.
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "rlgl.h"
#include "harness.h"
#include "bench.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define SUITE "sprites"
#define ROUNDS 7

static RblBillboard *bb;
static RblInstance *inst;

static double timeBatch(RblBatch *batch, Material m, Camera3D cam, int n, int sort, RenderTexture2D rt)
{
    batch->sort = sort;
    rtFinish();
    BeginTextureMode(rt);
    BeginMode3D(cam);
    double t0 = BenchNowNs();
    RblBeginBatch(batch, cam);
    for (int i = 0; i < n; i++) RblBatchAdd(batch, m, &bb[i]);
    RblEndBatch(batch);
    rtFinish();
    double t = BenchNowNs() - t0;
    EndMode3D();
    EndTextureMode();
    return t/n;
}

static double timeInstanced(RblInstanceBuffer *buf, Material m, Camera3D cam, int n, int sort, RenderTexture2D rt)
{
    RblInstancedDesc d;
    memset(&d, 0, sizeof(d));
    d.sort = sort;
    rtFinish();
    BeginTextureMode(rt);
    BeginMode3D(cam);
    double t0 = BenchNowNs();
    RblDrawInstanced(buf, cam, m, d, inst, n);
    rtFinish();
    double t = BenchNowNs() - t0;
    EndMode3D();
    EndTextureMode();
    return t/n;
}

static double coverage(const unsigned char *rgba, int n) { int c = 0; for (int i = 0; i < n; i++) c += (rgba[i*4 + 3] >= 128); return (double)c/n; }

int main(void)
{
    if (rtInitContext(64, 64) == NULL) { printf("bench_blend: no context\n"); return 1; }
    const int sizes[2] = { 10000, 100000 };
    bb = (RblBillboard *)calloc(100000, sizeof(RblBillboard));
    inst = (RblInstance *)calloc(100000, sizeof(RblInstance));
    unsigned int seed = 99u;
    for (int i = 0; i < 100000; i++)
    {
        Vector3 p = { rtRandomRange(&seed, -20.0f, 20.0f), rtRandomRange(&seed, -20.0f, 20.0f), rtRandomRange(&seed, -40.0f, 0.0f) };
        bb[i].position = p; bb[i].size = (Vector2){ 0.05f, 0.05f }; bb[i].origin = (Vector2){ 0.025f, 0.025f };
        inst[i].position = p; inst[i].size = bb[i].size; inst[i].origin = bb[i].origin;
    }
    Camera3D cam;
    memset(&cam, 0, sizeof(cam));
    cam.position = (Vector3){ 0.0f, 0.0f, 10.0f }; cam.up = (Vector3){ 0.0f, 1.0f, 0.0f }; cam.fovy = 60.0f; cam.projection = CAMERA_PERSPECTIVE;
    Image img = GenImageColor(4, 4, (Color){ 255, 255, 255, 128 });
    Texture2D tex = LoadTextureFromImage(img);
    UnloadImage(img);
    RblLitShaderDesc d;
    memset(&d, 0, sizeof(d));
    Material m = LoadMaterialDefault(), mi = LoadMaterialDefault();
    m.shader = RblLoadLitShader(d);
    d.instanced = true;
    mi.shader = RblLoadLitShader(d);
    m.maps[MATERIAL_MAP_ALBEDO].texture = tex; mi.maps[MATERIAL_MAP_ALBEDO].texture = tex;
    m.params[RBL_PARAM_ALPHA_CUTOFF] = 0.01f; mi.params[RBL_PARAM_ALPHA_CUTOFF] = 0.01f;
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.ambient = WHITE;
    RblSetScene(&scene);
    RenderTexture2D rt = LoadRenderTexture(64, 64);
    RblBatch batch = RblLoadBatch(100000);
    RblInstanceBuffer buf = RblLoadInstanceBuffer(100000);
    printf("  %-22s %12s %12s %12s %8s %8s\n", "case", "unsorted ns", "sorted ns", "hybrid ns", "sorted x", "hybrid x");
    for (int s = 0; s < 2; s++)
    {
        int n = sizes[s];
        double un[ROUNDS], so[ROUNDS], hy[ROUNDS], r1[ROUNDS], r2[ROUNDS];
        timeBatch(&batch, m, cam, n, RBL_SORT_BACK_TO_FRONT, rt);        // warm-up (scratch allocated once)
        for (int r = 0; r < ROUNDS; r++)
        {
            un[r] = timeBatch(&batch, m, cam, n, RBL_SORT_NONE, rt);
            so[r] = timeBatch(&batch, m, cam, n, RBL_SORT_BACK_TO_FRONT, rt);
            hy[r] = timeBatch(&batch, m, cam, n, RBL_SORT_HYBRID, rt);
            r1[r] = so[r]/un[r]; r2[r] = hy[r]/un[r];
        }
        char name[64];
        snprintf(name, sizeof(name), "sort_batch_%d", n);
        double mu = BenchMedian(un, ROUNDS), ms = BenchMedian(so, ROUNDS), mh = BenchMedian(hy, ROUNDS), q1 = BenchMedian(r1, ROUNDS), q2 = BenchMedian(r2, ROUNDS);
        printf("  %-22s %12.1f %12.1f %12.1f %8.2f %8.2f\n", name, mu, ms, mh, q1, q2);
        BenchCsvRow(SUITE, name, "unsorted_ns_per_billboard", mu, "ns");
        BenchCsvRow(SUITE, name, "sorted_ns_per_billboard", ms, "ns");
        BenchCsvRow(SUITE, name, "hybrid_ns_per_billboard", mh, "ns");
        BenchCsvRow(SUITE, name, "sorted_over_unsorted", q1, "x");
        BenchCsvRow(SUITE, name, "hybrid_over_unsorted", q2, "x");
        timeInstanced(&buf, mi, cam, n, RBL_SORT_BACK_TO_FRONT, rt);
        for (int r = 0; r < ROUNDS; r++)
        {
            un[r] = timeInstanced(&buf, mi, cam, n, RBL_SORT_NONE, rt);
            so[r] = timeInstanced(&buf, mi, cam, n, RBL_SORT_BACK_TO_FRONT, rt);
            r1[r] = so[r]/un[r];
        }
        snprintf(name, sizeof(name), "sort_instanced_%d", n);
        mu = BenchMedian(un, ROUNDS); ms = BenchMedian(so, ROUNDS); q1 = BenchMedian(r1, ROUNDS);
        printf("  %-22s %12.1f %12.1f %12s %8.2f\n", name, mu, ms, "-", q1);
        BenchCsvRow(SUITE, name, "unsorted_ns_per_instance", mu, "ns");
        BenchCsvRow(SUITE, name, "sorted_ns_per_instance", ms, "ns");
        BenchCsvRow(SUITE, name, "sorted_over_unsorted", q1, "x");
    }
    // Coverage per mip level: a 512x512 cut-out of thin blades
    const int w = 512;
    Image leaves = GenImageColor(w, w, (Color){ 50, 120, 40, 0 });
    for (int b = 0; b < 400; b++)
    {
        float x0 = rtRandomRange(&seed, 0.0f, (float)w), y0 = rtRandomRange(&seed, 0.0f, (float)w), a = rtRandomRange(&seed, 0.0f, 6.28f);
        for (int k = 0; k < 120; k++) { int x = (int)(x0 + cosf(a)*k*0.5f), y = (int)(y0 + sinf(a)*k*0.5f); if ((x >= 0) && (y >= 0) && (x < w) && (y < w)) ImageDrawPixel(&leaves, x, y, (Color){ 50, 120, 40, 255 }); }
    }
    RblMaterialSource src;
    memset(&src, 0, sizeof(src));
    src.albedo = leaves; src.mipmaps = true;
    RblPackedMaterial plain, kept;
    RblPackMaterial(&src, &plain);
    src.alphaCoverage = 0.5f;
    RblPackMaterial(&src, &kept);
    printf("  %-22s %10s %10s\n", "coverage (alpha>=0.5)", "plain", "kept");
    size_t off = 0;
    for (int l = 0, s = w; l < plain.albedo.mipmaps; l++, s = (s > 1)? s/2 : 1)
    {
        double cp = coverage((const unsigned char *)plain.albedo.data + off*4, s*s), ck = coverage((const unsigned char *)kept.albedo.data + off*4, s*s);
        char name[64];
        snprintf(name, sizeof(name), "coverage_level_%d", l);
        printf("  %-22s %10.4f %10.4f\n", name, cp, ck);
        BenchCsvRow(SUITE, name, "plain_share", cp, "share");
        BenchCsvRow(SUITE, name, "kept_share", ck, "share");
        off += (size_t)s*s;
    }
    RblUnloadPackedMaterial(&plain); RblUnloadPackedMaterial(&kept); UnloadImage(leaves);
    RblUnloadBatch(&batch); RblUnloadInstanceBuffer(&buf);
    UnloadRenderTexture(rt); UnloadTexture(tex);
    RblClose();
    rtCloseContext();
    free(bb); free(inst);
    return 0;
}
