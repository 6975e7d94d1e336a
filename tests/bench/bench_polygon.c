// Suite `polygon`: polygon-packed frames (TexturePacker vertices/verticesUV/triangles) drawn as their
// polygons against the same frames drawn as their trimmed quads (the RBL_FRAME_POLYGON bits cleared),
// same run, interleaved over ROUNDS rounds (ratios: median of the per-round ratios).
//   <path>_<N>   fragments_over_quad   fragments the rasteriser produced (GL_SAMPLES_PASSED, depth test
//                                      off, an opaque sheet: no discard, so every fragment counted is one
//                                      the fragment stage shaded), polygon draw over quad draw
//                expected_over_quad    the polygon area over the quad area (the cut-away the goal removes)
//                ms_per_frame_quad / ms_per_frame_polygon / polygon_over_quad
//                                      frame time, glFinish included (llvmpipe: fragment-bound), lit by one
//                                      point light with an RGB normal map
//   Paths: batch (RblBatchAdd + RblEndBatch) and instanced (RblDrawInstanced), N cards of 96 x 96 pixels
//   on a 1024 x 768 target, each frame a 16-gon round sprite in a 64 x 64 block (area 0.765 of it).
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "rlgl.h"
#include "harness.h"
#include "bench.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 1024
#define H 768
#define CARDS 256
#define ROUNDS 9
#define SIDES 16

typedef void (*GenQueries)(int, unsigned int *);
typedef void (*QueryOp)(unsigned int, unsigned int);
typedef void (*EndQuery)(unsigned int);
typedef void (*GetQueryU)(unsigned int, unsigned int, unsigned int *);
typedef void (*Finish)(void);
static GenQueries genQueries; static QueryOp beginQuery; static EndQuery endQuery; static GetQueryU getQuery; static Finish finish;

static void *fn(const char *name) { return rtGlProc(name); }

static RblAtlas atlas;
static Material mat[2];
static RblBatch batch;
static RblInstanceBuffer ibuf;
static RblBillboard cards[2][CARDS];
static RblInstance inst[2][CARDS];
static RenderTexture2D target;
static Camera3D cam;

// 8 frames, each a 16-gon inscribed in its 64 x 64 block, fanned from its first vertex
static char *polygonSheetText(double *area)
{
    size_t cap = 1 << 16, n = 0;
    char *t = (char *)malloc(cap);
    n += (size_t)snprintf(t + n, cap - n, "{\"frames\": {");
    double a = 0.0;
    for (int f = 0; f < 8; f++)
    {
        int bx = (f % 4)*64, by = (f / 4)*64;
        n += (size_t)snprintf(t + n, cap - n, "%s\"f%d\": {\"frame\": {\"x\":%d,\"y\":%d,\"w\":64,\"h\":64}, \"vertices\": [", f? "," : "", f, bx, by);
        for (int k = 0; k < SIDES; k++) n += (size_t)snprintf(t + n, cap - n, "%s[%.4f,%.4f]", k? "," : "", 32.0 + 32.0*cos(2*PI*k/SIDES), 32.0 + 32.0*sin(2*PI*k/SIDES));
        n += (size_t)snprintf(t + n, cap - n, "], \"verticesUV\": [");
        for (int k = 0; k < SIDES; k++) n += (size_t)snprintf(t + n, cap - n, "%s[%.4f,%.4f]", k? "," : "", bx + 32.0 + 32.0*cos(2*PI*k/SIDES), by + 32.0 + 32.0*sin(2*PI*k/SIDES));
        n += (size_t)snprintf(t + n, cap - n, "], \"triangles\": [");
        for (int k = 1; k + 1 < SIDES; k++) n += (size_t)snprintf(t + n, cap - n, "%s[0,%d,%d]", (k > 1)? "," : "", k, k + 1);
        n += (size_t)snprintf(t + n, cap - n, "]}");
    }
    snprintf(t + n, cap - n, "}, \"meta\": {\"size\": {\"w\":256,\"h\":128}}}");
    a = 0.5*SIDES*32.0*32.0*sin(2*PI/SIDES)/(64.0*64.0);
    *area = a;
    return t;
}

// One frame: path 0 batch, 1 instanced; k 0 quads, 1 polygons; lit material m (0 batch, 1 instanced)
static void drawFrame(int path, int k)
{
    BeginTextureMode(target); ClearBackground(BLACK); BeginMode3D(cam);
    rlDisableDepthTest();
    if (path == 0)
    {
        RblBeginBatch(&batch, cam);
        for (int i = 0; i < CARDS; i++) RblBatchAdd(&batch, mat[0], &cards[k][i]);
        RblEndBatch(&batch);
    }
    else RblDrawInstanced(&ibuf, cam, mat[1], (RblInstancedDesc){ 0 }, inst[k], CARDS);
    rlEnableDepthTest();
    EndMode3D(); EndTextureMode();
}

static unsigned int fragments(int path, int k)
{
    unsigned int q = 0, samples = 0;
    genQueries(1, &q);
    BeginTextureMode(target); EndTextureMode();
    rlDrawRenderBatchActive();
    beginQuery(0x8914 /* GL_SAMPLES_PASSED */, q);
    drawFrame(path, k);
    endQuery(0x8914);
    getQuery(q, 0x8866 /* GL_QUERY_RESULT */, &samples);
    return samples;
}

static double frameMs(int path, int k)
{
    drawFrame(path, k); finish();
    double best = 1e30;
    for (int r = 0; r < 3; r++)
    {
        double t0 = BenchNowNs();
        drawFrame(path, k); finish();
        double ms = (BenchNowNs() - t0)/1e6;
        if (ms < best) best = ms;
    }
    return best;
}

int main(void)
{
    const char *backend = rtInitContext(W, H);
    if (backend == NULL) { printf("bench_polygon: no context\n"); return 1; }
    void *p;
    p = fn("glGenQueries"); memcpy(&genQueries, &p, sizeof(p));
    p = fn("glBeginQuery"); memcpy(&beginQuery, &p, sizeof(p));
    p = fn("glEndQuery"); memcpy(&endQuery, &p, sizeof(p));
    p = fn("glGetQueryObjectuiv"); memcpy(&getQuery, &p, sizeof(p));
    p = fn("glFinish"); memcpy(&finish, &p, sizeof(p));
    if (!genQueries || !beginQuery || !endQuery || !getQuery || !finish) { printf("bench_polygon: no occlusion queries\n"); return 1; }
    double area;
    char *text = polygonSheetText(&area);
    atlas = RblLoadAtlasFromMemory(text, (int)strlen(text), RBL_ATLAS_AUTO);
    free(text);
    if (!RblIsAtlasValid(atlas)) { printf("bench_polygon: atlas refused\n"); return 1; }
    Image noise = GenImageWhiteNoise(256, 128, 0.5f), normal = GenImageColor(256, 128, (Color){ 160, 140, 230, 255 });
    ImageFormat(&noise, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);       // opaque: no texel is discarded
    Texture2D albedo = LoadTextureFromImage(noise), ntex = LoadTextureFromImage(normal);
    for (int p = 0; p < 2; p++)
    {
        RblLitShaderDesc d; memset(&d, 0, sizeof(d));
        d.maxLights = 1; d.material.normalEncoding = RBL_NORMAL_RGB; d.instanced = (p == 1);
        mat[p] = LoadMaterialDefault();
        mat[p].shader = RblLoadLitShader(d);
        mat[p].maps[MATERIAL_MAP_ALBEDO].texture = albedo;
        mat[p].maps[MATERIAL_MAP_NORMAL].texture = ntex;
    }
    RblLight l; memset(&l, 0, sizeof(l));
    l.position = (Vector3){ 0, 0, 300 }; l.color = WHITE; l.intensity = 10; l.range = 2000;
    RblScene scene; memset(&scene, 0, sizeof(scene));
    scene.lights = &l; scene.lightCount = 1; scene.ambient = DARKGRAY;
    RblSetScene(&scene);
    memset(&cam, 0, sizeof(cam));
    cam.position = (Vector3){ 0, 0, 10 }; cam.up = (Vector3){ 0, 1, 0 }; cam.fovy = (float)H; cam.projection = CAMERA_ORTHOGRAPHIC;
    unsigned int seed = 99u;
    for (int i = 0; i < CARDS; i++)
    {
        RblBillboard b; memset(&b, 0, sizeof(b));
        RblAtlasBillboard(&atlas, i % 8, 1.5f, &b);         // 96 x 96 pixels
        b.position = (Vector3){ (float)((int)(rtRandom(&seed) % (W - 96)) - W/2 + 48), (float)((int)(rtRandom(&seed) % (H - 96)) - H/2), 0.0f };
        b.rotation = (float)(rtRandom(&seed) % 360);
        cards[1][i] = b;
        cards[0][i] = b;
        cards[0][i].flags &= ~(unsigned int)RBL_FRAME_POLYGON;
        for (int k = 0; k < 2; k++)
        {
            RblInstance *in = &inst[k][i];
            memset(in, 0, sizeof(*in));
            in->position = cards[k][i].position; in->rotation = cards[k][i].rotation; in->size = cards[k][i].size; in->origin = cards[k][i].origin;
            in->source = cards[k][i].source; in->flags = cards[k][i].flags;
        }
    }
    target = LoadRenderTexture(W, H);
    batch = RblLoadBatch(CARDS*4);
    ibuf = RblLoadInstanceBuffer(CARDS);
    printf("  context: %s; %d cards of 96x96 px, a %d-gon in each 64x64 block (area %.3f of it)\n", backend, CARDS, SIDES, area);
    static const char *names[2] = { "batch", "instanced" };
    for (int path = 0; path < 2; path++)
    {
        double frag[2] = { (double)fragments(path, 0), (double)fragments(path, 1) };
        double ratios[ROUNDS], ms[2][ROUNDS];
        for (int r = 0; r < ROUNDS; r++)
        {
            // alternate which goes first
            int first = r & 1;
            ms[first][r] = frameMs(path, first);
            ms[!first][r] = frameMs(path, !first);
            ratios[r] = ms[1][r]/ms[0][r];
        }
        double mq = BenchMedian(ms[0], ROUNDS), mp = BenchMedian(ms[1], ROUNDS), ratio = BenchMedian(ratios, ROUNDS);
        char name[64];
        snprintf(name, sizeof(name), "%s_%d", names[path], CARDS);
        printf("  %-16s fragments %9.0f quad %9.0f polygon: %.3f of the quad's (polygon area %.3f); %.2f ms quad, %.2f ms polygon: %.3f x (median of %d interleaved rounds)\n",
               name, frag[0], frag[1], frag[1]/frag[0], area, mq, mp, ratio, ROUNDS);
        BenchCsvRow("polygon", name, "fragments_quad", frag[0], "fragments");
        BenchCsvRow("polygon", name, "fragments_polygon", frag[1], "fragments");
        BenchCsvRow("polygon", name, "fragments_over_quad", frag[1]/frag[0], "x");
        BenchCsvRow("polygon", name, "expected_over_quad", area, "x");
        BenchCsvRow("polygon", name, "ms_per_frame_quad", mq, "ms");
        BenchCsvRow("polygon", name, "ms_per_frame_polygon", mp, "ms");
        BenchCsvRow("polygon", name, "polygon_over_quad", ratio, "x");
    }
    RblUnloadBatch(&batch);
    RblUnloadInstanceBuffer(&ibuf);
    UnloadRenderTexture(target);
    for (int p = 0; p < 2; p++) { RblUnloadLitShader(&mat[p].shader); MemFree(mat[p].maps); }
    UnloadTexture(albedo); UnloadTexture(ntex); UnloadImage(noise); UnloadImage(normal);
    RblUnloadAtlas(&atlas);
    RblClose();
    rtCloseContext();
    return 0;
}
