// Suite `sprites`: atlas import, animation update and the instanced path with a frame per instance.
//   import_<format>_<N>frames   ms_per_1000_frames   RblLoadAtlasFromMemory of a generated text of N frames
//                                                    (TexturePacker hash, Aseprite array with a tag per 8
//                                                    frames, libGDX old form with indexed regions)
//   import_<form>_4096frames    ms_per_1000_frames   the forms issue #28 added, each beside the plain TexturePacker hash text
//                               over_texturepacker   (interleaved over 15 rounds, median of the per-round ratios): phaser3
//                                                    (4 textures[] pages with normalMap and scale), polygon (8 vertices,
//                                                    6 triangles a frame), aseprite_slices (64 slices, a key every 64
//                                                    frames, pivots and centers), libgdx_new (compact form, rotate 270/180,
//                                                    split, pad, index)
//   import_phaser3_file         file_over_memory     RblLoadAtlas of the Phaser 3 text (4 sheets and 4 normal sheets looked
//                                                    for on disk) over RblLoadAtlasFromMemory of the same text, interleaved
//   slice_billboard_10000       ns_per_call          RblAtlasSliceBillboard (clipped sub-frame) beside RblAtlasBillboard
//                               over_frame           of the same frames; ratio (best of 20 each)
//   update_<N>                  ns_per_sprite        RblUpdateSprite over N players (pingpong tags, 1/60 s)
//   instanced_<N>               cpu_ns_per_instance  plain: RblDrawInstanced of a filled array; animated: per
//                                                    instance RblUpdateSprite + RblAtlasInstance, then the same
//                                                    draw (submission CPU time, no glFinish)
//   instanced_<N>               animated_over_plain  ratio of the two
//   bulk_update_fill_10000      ns_per_instance      RblUpdateSpriteInstances (the same work, checks once)
//   raylib_billboard_pro_10000  cpu_ns_per_billboard DrawBillboardPro of the same 10000 frames (distinct sources) and the
//                                                    batch flush, submission CPU time (raylib's draws included, no glFinish)
//   instanced_10000             animated_over_raylib / plain_over_raylib: the instanced rows over that, same run;
//                               excl_draw_*: the same without the time inside glDraw* (llvmpipe's vertex stage);
//                               excl_draw_bulk_animated_over_raylib: (bulk update + plain draw) over raylib
//   fade_*                      plain and fade runs interleaved over 15 rounds; fade_over_plain: median of the per-round ratios
//   fade_batch_10000            cpu_ns_per_billboard RblBatchAdd of 10000 billboards with distinct frames: plain (no fade) and
//                                                    fade (RblAtlasBillboardFade each: union quad, clips, weight), and fade_over_plain;
//                                                    end_ns_per_billboard: RblEndBatch (sort none: upload + draw submission)
//   fade_instanced_10000        cpu_ns_per_instance  RblDrawInstanced without / with the fades array (second buffer); ratio
//   fade_fragment_<W>           ms_per_frame         llvmpipe, glFinish included: 16 overlapping 512x512-pixel cards, albedo +
//                                                    RGB normal map, one point light; plain program vs crossFade (weight 0.5); ratio
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "rlgl.h"
#include "harness.h"
#include "bench.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

// ---- generated atlas texts ----------------------------------------------------------------------
typedef struct { char *text; int size, cap; } Text;
static void put(Text *t, const char *s)
{
    int n = (int)strlen(s);
    if (t->size + n + 1 > t->cap) { t->cap = 2*(t->size + n + 1); t->text = (char *)realloc(t->text, (size_t)t->cap); }
    memcpy(t->text + t->size, s, (size_t)n + 1); t->size += n;
}

static Text makeText(int format, int frames)
{
    Text t = { NULL, 0, 0 };
    char line[512];
    if (format == RBL_ATLAS_LIBGDX)
    {
        put(&t, "\nsheet.png\nsize: 4096, 4096\nformat: RGBA8888\nfilter: Nearest,Nearest\nrepeat: none\n");
        for (int i = 0; i < frames; i++)
        {
            snprintf(line, sizeof(line), "walk_%d\n  rotate: %s\n  xy: %d, %d\n  size: 30, 40\n  orig: 32, 48\n  offset: 1, 2\n  index: %d\n",
                     i/8, (i%3 == 0)? "true" : "false", (i%64)*64, (i/64)*48, i%8);
            put(&t, line);
        }
        return t;
    }
    bool ase = (format == RBL_ATLAS_ASEPRITE);
    put(&t, ase? "{ \"frames\": [\n" : "{\"frames\": {\n");
    for (int i = 0; i < frames; i++)
    {
        if (ase) snprintf(line, sizeof(line), "%s { \"filename\": \"walk_%d %d.aseprite\", \"frame\": { \"x\": %d, \"y\": %d, \"w\": 30, \"h\": 40 }, \"rotated\": false, \"trimmed\": true,"
                          " \"spriteSourceSize\": { \"x\": 1, \"y\": 2, \"w\": 30, \"h\": 40 }, \"sourceSize\": { \"w\": 32, \"h\": 48 }, \"duration\": 100 }\n", (i > 0)? "," : "", i/8, i, (i%64)*64, (i/64)*48);
        else snprintf(line, sizeof(line), "%s\"frame_%05d.png\": {\"frame\": {\"x\":%d,\"y\":%d,\"w\":30,\"h\":40}, \"rotated\": %s, \"trimmed\": true,"
                      " \"spriteSourceSize\": {\"x\":1,\"y\":2,\"w\":30,\"h\":40}, \"sourceSize\": {\"w\":32,\"h\":48}, \"pivot\": {\"x\":0.5,\"y\":1}}\n", (i > 0)? "," : "", i, (i%64)*64, (i/64)*48, (i%3 == 0)? "true" : "false");
        put(&t, line);
    }
    put(&t, ase? "],\n\"meta\": { \"app\": \"http://www.aseprite.org/\", \"image\": \"s.png\", \"size\": { \"w\": 4096, \"h\": 4096 }, \"frameTags\": [\n" :
                 "},\n\"meta\": {\"app\": \"https://www.codeandweb.com/texturepacker\", \"image\": \"s.png\", \"size\": {\"w\":4096,\"h\":4096}}}\n");
    if (ase)
    {
        for (int g = 0; g < frames/8; g++)
        {
            snprintf(line, sizeof(line), "%s  { \"name\": \"walk_%d\", \"from\": %d, \"to\": %d, \"direction\": \"pingpong\" }\n", (g > 0)? "," : "", g, g*8, g*8 + 7);
            put(&t, line);
        }
        put(&t, " ] } }\n");
    }
    return t;
}

// The forms of issue #28, 4096 frames each
enum { FORM_PHASER3 = 0, FORM_POLYGON, FORM_SLICES, FORM_GDX_NEW, FORM_COUNT };
static const char *const formNames[FORM_COUNT] = { "phaser3", "polygon", "aseprite_slices", "libgdx_new" };
static Text makeFormText(int form, int frames)
{
    Text t = { NULL, 0, 0 };
    char line[768];
    if (form == FORM_GDX_NEW)
    {
        put(&t, "sheet.png\nsize:4096,4096\nformat:RGBA8888\nfilter:Nearest,Nearest\nrepeat:none\npma:true\n");
        for (int i = 0; i < frames; i++)
        {
            snprintf(line, sizeof(line), "ui:walk_%d\nbounds:%d,%d,30,40\noffsets:1,2,32,48\nrotate:%s\nsplit:2,3,4,5\npad:1,1,1,1\nindex:%d\n",
                     i/8, (i%64)*64, (i/64)*48, (i%3 == 0)? "270" : ((i%3 == 1)? "180" : "false"), i%8);
            put(&t, line);
        }
        return t;
    }
    if (form == FORM_PHASER3)
    {
        put(&t, "{\"textures\": [\n");
        for (int p = 0; p < 4; p++)
        {
            snprintf(line, sizeof(line), "%s{\"image\": \"sheet-%d.png\", \"normalMap\": \"sheet-%d_n.png\", \"format\": \"RGBA8888\", \"size\": {\"w\":4096,\"h\":4096}, \"scale\": 0.5, \"frames\": [\n",
                     (p > 0)? "]},\n" : "", p, p);
            put(&t, line);
            for (int i = p*frames/4; i < (p + 1)*frames/4; i++)
            {
                snprintf(line, sizeof(line), "%s{\"filename\": \"frame_%05d.png\", \"frame\": {\"x\":%d,\"y\":%d,\"w\":30,\"h\":40}, \"rotated\": %s, \"trimmed\": true,"
                         " \"spriteSourceSize\": {\"x\":1,\"y\":2,\"w\":30,\"h\":40}, \"sourceSize\": {\"w\":32,\"h\":48}, \"pivot\": {\"x\":0.5,\"y\":1}}\n",
                         (i > p*frames/4)? "," : "", i, (i%64)*64, ((i%1024)/64)*48, (i%3 == 0)? "true" : "false");
                put(&t, line);
            }
        }
        put(&t, "]}],\n\"meta\": {\"app\": \"https://www.codeandweb.com/texturepacker\", \"version\": \"3.0\", \"scale\": \"1\"}}\n");
        return t;
    }
    if (form == FORM_POLYGON)
    {
        put(&t, "{\"frames\": {\n");
        for (int i = 0; i < frames; i++)
        {
            int x = (i%64)*64, y = (i/64)*48;      // upright 30x40 at (1, 2) of 32x48: an octagon inside the trim
            snprintf(line, sizeof(line), "%s\"frame_%05d.png\": {\"frame\": {\"x\":%d,\"y\":%d,\"w\":30,\"h\":40}, \"rotated\": false, \"trimmed\": true,"
                     " \"spriteSourceSize\": {\"x\":1,\"y\":2,\"w\":30,\"h\":40}, \"sourceSize\": {\"w\":32,\"h\":48}, \"pivot\": {\"x\":0.5,\"y\":1},"
                     " \"vertices\": [[9,2],[23,2],[31,12],[31,32],[23,42],[9,42],[1,32],[1,12]],"
                     " \"verticesUV\": [[%d,%d],[%d,%d],[%d,%d],[%d,%d],[%d,%d],[%d,%d],[%d,%d],[%d,%d]],"
                     " \"triangles\": [[0,1,2],[0,2,3],[0,3,4],[0,4,5],[0,5,6],[0,6,7]]}\n",
                     (i > 0)? "," : "", i, x, y, x + 8, y, x + 22, y, x + 30, y + 10, x + 30, y + 30, x + 22, y + 40, x + 8, y + 40, x, y + 30, x, y + 10);
            put(&t, line);
        }
        put(&t, "},\n\"meta\": {\"app\": \"https://www.codeandweb.com/texturepacker\", \"image\": \"s.png\", \"size\": {\"w\":4096,\"h\":4096}, \"scale\": \"1\"}}\n");
        return t;
    }
    // Aseprite with slices: the array frames and tags of makeText, plus 64 slices keyed every 64 frames
    put(&t, "{ \"frames\": [\n");
    for (int i = 0; i < frames; i++)
    {
        snprintf(line, sizeof(line), "%s { \"filename\": \"walk_%d %d.aseprite\", \"frame\": { \"x\": %d, \"y\": %d, \"w\": 30, \"h\": 40 }, \"rotated\": false, \"trimmed\": true,"
                 " \"spriteSourceSize\": { \"x\": 1, \"y\": 2, \"w\": 30, \"h\": 40 }, \"sourceSize\": { \"w\": 32, \"h\": 48 }, \"duration\": 100 }\n", (i > 0)? "," : "", i/8, i, (i%64)*64, (i/64)*48);
        put(&t, line);
    }
    put(&t, "],\n\"meta\": { \"app\": \"http://www.aseprite.org/\", \"image\": \"s.png\", \"size\": { \"w\": 4096, \"h\": 4096 }, \"frameTags\": [\n");
    for (int g = 0; g < frames/8; g++)
    {
        snprintf(line, sizeof(line), "%s  { \"name\": \"walk_%d\", \"from\": %d, \"to\": %d, \"direction\": \"pingpong\" }\n", (g > 0)? "," : "", g, g*8, g*8 + 7);
        put(&t, line);
    }
    put(&t, " ], \"slices\": [\n");
    for (int sl = 0; sl < 64; sl++)
    {
        snprintf(line, sizeof(line), "%s  { \"name\": \"part_%d\", \"color\": \"#0000ffff\", \"keys\": [", (sl > 0)? "," : "", sl);
        put(&t, line);
        for (int k = 0; k < frames/64; k++)
        {
            snprintf(line, sizeof(line), "%s{ \"frame\": %d, \"bounds\": { \"x\": %d, \"y\": %d, \"w\": 8, \"h\": 8 }, \"center\": { \"x\": 2, \"y\": 2, \"w\": 4, \"h\": 4 }, \"pivot\": { \"x\": 4, \"y\": 8 } }",
                     (k > 0)? "," : "", k*64, (sl%4)*8, (sl/4)*2);
            put(&t, line);
        }
        put(&t, "] }\n");
    }
    put(&t, " ] } }\n");
    return t;
}

typedef struct { Text text; int format; } ImportCtx;
static void runImport(void *ctx, double *out)
{
    ImportCtx *c = (ImportCtx *)ctx;
    double t0 = BenchNowNs();
    RblAtlas a = RblLoadAtlasFromMemory(c->text.text, c->text.size, c->format);
    out[0] = BenchNowNs() - t0;
    if (!RblIsAtlasValid(a)) { printf("bench_sprites: generated atlas refused\n"); exit(1); }
    RblUnloadAtlas(&a);
}

// ---- draw-call timing (as bench_geometry): llvmpipe runs vertex processing inside glDraw*, so
// excl_draw = CPU submission minus the time inside the driver's draw calls, about what the CPU
// spends with a hardware GPU. Weak references stay NULL where raylib does not export glad's pointers
typedef void (*GlDrawArraysFn)(unsigned int mode, int first, int count);
typedef void (*GlDrawElementsFn)(unsigned int mode, int count, unsigned int type, const void *indices);
typedef void (*GlDrawArraysInstancedFn)(unsigned int mode, int first, int count, int instances);
extern GlDrawArraysFn glad_glDrawArrays __attribute__((weak));
extern GlDrawElementsFn glad_glDrawElements __attribute__((weak));
extern GlDrawArraysInstancedFn glad_glDrawArraysInstanced __attribute__((weak));
static GlDrawArraysFn realDrawArrays = NULL;
static GlDrawElementsFn realDrawElements = NULL;
static GlDrawArraysInstancedFn realDrawArraysInstanced = NULL;
static double drawNs = 0.0;         // inside glDraw* since the last reset
static void timedDrawArrays(unsigned int mode, int first, int count) { double t0 = BenchNowNs(); realDrawArrays(mode, first, count); drawNs += BenchNowNs() - t0; }
static void timedDrawElements(unsigned int mode, int count, unsigned int type, const void *indices) { double t0 = BenchNowNs(); realDrawElements(mode, count, type, indices); drawNs += BenchNowNs() - t0; }
static void timedDrawArraysInstanced(unsigned int mode, int first, int count, int instances) { double t0 = BenchNowNs(); realDrawArraysInstanced(mode, first, count, instances); drawNs += BenchNowNs() - t0; }
static bool wrapDraws(void)
{
    if ((&glad_glDrawArrays == NULL) || (&glad_glDrawElements == NULL) || (&glad_glDrawArraysInstanced == NULL)) return false;
    if ((glad_glDrawArrays == NULL) || (glad_glDrawElements == NULL) || (glad_glDrawArraysInstanced == NULL)) return false;
    realDrawArrays = glad_glDrawArrays; glad_glDrawArrays = timedDrawArrays;
    realDrawElements = glad_glDrawElements; glad_glDrawElements = timedDrawElements;
    realDrawArraysInstanced = glad_glDrawArraysInstanced; glad_glDrawArraysInstanced = timedDrawArraysInstanced;
    return true;
}

// ---- animation ----------------------------------------------------------------------------------
typedef struct { RblAtlas *atlas; RblSpritePlayer *players; RblInstance *instances; int n; RblInstanceBuffer *buffer; Camera3D camera; Material material; bool animated, draw; } AnimCtx;
static void runAnim(void *ctx, double *out)
{
    AnimCtx *c = (AnimCtx *)ctx;
    drawNs = 0.0;
    double t0 = BenchNowNs();
    if (c->animated)
        for (int i = 0; i < c->n; i++)
        {
            RblUpdateSprite(&c->players[i], c->atlas, 1.0f/60.0f);
            if (c->draw) RblAtlasInstance(c->atlas, c->players[i].frame, 0.02f, &c->instances[i]);
        }
    if (c->draw) RblDrawInstanced(c->buffer, c->camera, c->material, (RblInstancedDesc){ 0 }, c->instances, c->n);
    out[0] = (BenchNowNs() - t0)/c->n;
    out[1] = out[0] - drawNs/c->n;
    if (c->draw) rtFinish();      // untimed: the next run starts with the GPU idle
}

// ---- cross-fade costs ---------------------------------------------------------------------------
typedef struct { RblBatch *batch; Camera3D camera; Material material; const RblBillboard *cards; const RblFade *fades; int n; } FadeBatchCtx;
static void runFadeBatch(void *ctx, double *out)
{
    FadeBatchCtx *c = (FadeBatchCtx *)ctx;
    drawNs = 0.0;
    double t0 = BenchNowNs();
    RblBeginBatch(c->batch, c->camera);
    if (c->fades == NULL) for (int i = 0; i < c->n; i++) RblBatchAdd(c->batch, c->material, &c->cards[i]);
    else for (int i = 0; i < c->n; i++) RblBatchAddFade(c->batch, c->material, &c->cards[i], &c->fades[i]);
    double t1 = BenchNowNs();
    RblEndBatch(c->batch);
    out[0] = (t1 - t0)/c->n;
    out[1] = (BenchNowNs() - t1 - drawNs)/c->n;      // end excluding draw calls: sort, upload, state
    rtFinish();
}

typedef struct { RblInstanceBuffer *buffer; Camera3D camera; Material material; const RblInstance *instances; const RblFade *fades; int n; bool finish; } FadeInstCtx;
static void runFadeInstanced(void *ctx, double *out)
{
    FadeInstCtx *c = (FadeInstCtx *)ctx;
    RblInstancedDesc d; memset(&d, 0, sizeof(d));
    d.fades = c->fades;
    drawNs = 0.0;
    double t0 = BenchNowNs();
    RblDrawInstanced(c->buffer, c->camera, c->material, d, c->instances, c->n);
    if (c->finish) rtFinish();
    out[0] = (BenchNowNs() - t0)/c->n;
    out[1] = out[0] - drawNs/c->n;
    if (!c->finish) rtFinish();
}

typedef struct { Texture2D texture; const Rectangle *sources; const Vector3 *positions; int n; Camera3D camera; } RaylibCtx;
static void runRaylib(void *ctx, double *out)
{
    RaylibCtx *c = (RaylibCtx *)ctx;
    drawNs = 0.0;
    double t0 = BenchNowNs();
    for (int i = 0; i < c->n; i++)
        DrawBillboardPro(c->camera, c->texture, c->sources[i], c->positions[i], (Vector3){ 0, 1, 0 }, (Vector2){ 0.64f, 0.96f }, (Vector2){ 0.32f, 0.48f }, 0.0f, WHITE);
    rlDrawRenderBatchActive();
    out[0] = (BenchNowNs() - t0)/c->n;
    out[1] = out[0] - drawNs/c->n;
    rtFinish();
}

typedef struct { RenderTexture2D target; Camera3D camera; Material material; const RblBillboard *cards; const RblFade *fades; int n; } FadeFragCtx;
static void runFadeFragment(void *ctx, double *out)
{
    FadeFragCtx *c = (FadeFragCtx *)ctx;
    rtFinish();
    double t0 = BenchNowNs();
    BeginTextureMode(c->target); ClearBackground(BLACK); BeginMode3D(c->camera);
    for (int i = 0; i < c->n; i++)
    {
        if (c->fades == NULL) RblDrawBillboard(c->camera, c->material, c->cards[i]);
        else RblDrawBillboardFade(c->camera, c->material, c->cards[i], c->fades[i]);
    }
    EndMode3D(); EndTextureMode();
    rtFinish();
    out[0] = (BenchNowNs() - t0)/1e6;
}

// Plain and fade runs interleaved in rounds (the order alternating), so a slow spell of this shared
// machine hits both alike: medians of each value and of the per-round ratio of value 0
#define FADE_ROUNDS 15
static void interleaved(BenchRunFn fn, void *plainCtx, void *fadeCtx, int values, double plain[2], double fade[2], double *ratio)
{
    double p[2][FADE_ROUNDS], f[2][FADE_ROUNDS], r[FADE_ROUNDS], out[2];
    fn(plainCtx, out); fn(fadeCtx, out);        // warm-up
    for (int k = 0; k < FADE_ROUNDS; k++)
    {
        for (int j = 0; j < 2; j++)
        {
            bool fadeRun = ((k + j) & 1) != 0;
            fn(fadeRun? fadeCtx : plainCtx, out);
            for (int v = 0; v < values; v++) { if (fadeRun) f[v][k] = out[v]; else p[v][k] = out[v]; }
        }
        r[k] = f[0][k]/p[0][k];
    }
    for (int v = 0; v < values; v++) { plain[v] = BenchMedian(p[v], FADE_ROUNDS); fade[v] = BenchMedian(f[v], FADE_ROUNDS); }
    *ratio = BenchMedian(r, FADE_ROUNDS);
}

static void fadeBench(const RblAtlas *anim, const RblSpritePlayer *players, const RblInstance *instances, int n, RblInstanceBuffer *buf, Camera3D cam, Material instMat, BenchTiming timing)
{
    // Batch: the same 10000 frames, without and with a fade each (the next frame over the same quad)
    RblLitShaderDesc desc; memset(&desc, 0, sizeof(desc));
    Material plain = instMat, fade = instMat;
    plain.shader = RblLoadLitShader(desc);
    desc.crossFade = true;
    fade.shader = RblLoadLitShader(desc);
    desc.instanced = true;
    Material fadeInst = instMat;
    fadeInst.shader = RblLoadLitShader(desc);
    RblBillboard *cards = (RblBillboard *)calloc((size_t)n, sizeof(RblBillboard));
    RblFade *fades = (RblFade *)calloc((size_t)n, sizeof(RblFade));
    for (int i = 0; i < n; i++)
    {
        cards[i].position = instances[i].position;
        RblAtlasBillboard(anim, players[i].frame, 0.02f, &cards[i]);
        int next = players[i].frame;
        fades[i].weight = RblSpriteBlend(&players[i], anim, &next);
        fades[i].source = anim->frames[next].source;         // zero clips: over this frame's quad
        fades[i].flags = anim->frames[next].flags & RBL_FRAME_ROTATED;
        if (fades[i].weight <= 0.0f) fades[i].weight = 0.5f;       // every billboard fades
    }
    RblBatch batch = RblLoadBatch(n);
    double plainNs[2], fadeNs[2], batchRatio;
    RblBillboard *faded = (RblBillboard *)malloc((size_t)n*sizeof(RblBillboard));
    RblFade *fadedFades = (RblFade *)calloc((size_t)n, sizeof(RblFade));
    memcpy(faded, cards, (size_t)n*sizeof(RblBillboard));
    // Faded cards as an application builds them: the union quad and clips of the two frames
    for (int i = 0; i < n; i++)
    {
        int next = players[i].frame;
        RblSpriteBlend(&players[i], anim, &next);
        RblAtlasBillboardFade(anim, players[i].frame, next, fades[i].weight, 0.02f, &faded[i], &fadedFades[i]);
    }
    FadeBatchCtx bcPlain = { &batch, cam, plain, cards, NULL, n }, bcFade = { &batch, cam, fade, faded, fadedFades, n };
    interleaved(runFadeBatch, &bcPlain, &bcFade, 2, plainNs, fadeNs, &batchRatio);
    (void)timing;
    printf("  %-34s %8.1f ns per billboard add, %6.1f end excluding draw calls (CPU)\n", "fade_batch_10000_plain", plainNs[0], plainNs[1]);
    printf("  %-34s %8.1f ns per billboard add, %6.1f end excluding draw calls (CPU)\n", "fade_batch_10000_fade", fadeNs[0], fadeNs[1]);
    printf("  %-34s %8.3f x add (median of %d interleaved rounds), %.3f x end\n", "fade_batch_10000 fade/plain", batchRatio, FADE_ROUNDS, fadeNs[1]/plainNs[1]);
    BenchCsvRow("sprites", "fade_batch_10000_plain", "cpu_ns_per_billboard", plainNs[0], "ns");
    BenchCsvRow("sprites", "fade_batch_10000_fade", "cpu_ns_per_billboard", fadeNs[0], "ns");
    BenchCsvRow("sprites", "fade_batch_10000", "fade_over_plain", batchRatio, "x");
    BenchCsvRow("sprites", "fade_batch_10000_plain", "end_ns_per_billboard", plainNs[1], "ns");
    BenchCsvRow("sprites", "fade_batch_10000_fade", "end_ns_per_billboard", fadeNs[1], "ns");
    // Instanced: the same draw without and with the fades array (its own buffer, uploaded per draw)
    double inst[2][2], instRatio, instExclRatio;
    {
        FadeInstCtx icPlain = { buf, cam, instMat, instances, NULL, n, false }, icFade = { buf, cam, fadeInst, instances, fades, n, false };
        interleaved(runFadeInstanced, &icPlain, &icFade, 2, inst[0], inst[1], &instRatio);
        instExclRatio = inst[1][1]/inst[0][1];
    }
    printf("  %-34s %8.1f ns per instance (CPU), %6.1f excluding draw calls\n", "fade_instanced_10000_plain", inst[0][0], inst[0][1]);
    printf("  %-34s %8.1f ns per instance (CPU), %6.1f excluding draw calls\n", "fade_instanced_10000_fade", inst[1][0], inst[1][1]);
    printf("  %-34s %8.3f x (median of %d interleaved rounds), %.3f x excluding draw calls (medians)\n", "fade_instanced_10000 fade/plain", instRatio, FADE_ROUNDS, instExclRatio);
    BenchCsvRow("sprites", "fade_instanced_10000_plain", "cpu_ns_per_instance", inst[0][0], "ns");
    BenchCsvRow("sprites", "fade_instanced_10000_fade", "cpu_ns_per_instance", inst[1][0], "ns");
    BenchCsvRow("sprites", "fade_instanced_10000", "fade_over_plain", instRatio, "x");
    BenchCsvRow("sprites", "fade_instanced_10000_plain", "excl_draw_ns_per_instance", inst[0][1], "ns");
    BenchCsvRow("sprites", "fade_instanced_10000_fade", "excl_draw_ns_per_instance", inst[1][1], "ns");
    BenchCsvRow("sprites", "fade_instanced_10000", "excl_draw_fade_over_plain", instExclRatio, "x");
    // Fragment cost on llvmpipe: 16 cards covering a 512x512 target, albedo + RGB normal map, a light
    {
        Image noise = GenImageWhiteNoise(1024, 512, 0.5f), normal = GenImageColor(1024, 512, (Color){ 160, 140, 230, 255 });
        Texture2D albedo = LoadTextureFromImage(noise), ntex = LoadTextureFromImage(normal);
        UnloadImage(noise); UnloadImage(normal);
        RblLitShaderDesc fd; memset(&fd, 0, sizeof(fd));
        fd.maxLights = 1; fd.material.normalEncoding = RBL_NORMAL_RGB;
        Material fm[2];
        for (int k = 0; k < 2; k++)
        {
            fd.crossFade = (k == 1);
            fm[k] = LoadMaterialDefault();
            fm[k].shader = RblLoadLitShader(fd);
            fm[k].maps[MATERIAL_MAP_ALBEDO].texture = albedo;
            fm[k].maps[MATERIAL_MAP_NORMAL].texture = ntex;
        }
        RblLight l; memset(&l, 0, sizeof(l));
        l.position = (Vector3){ 0, 0, 3 }; l.color = WHITE; l.intensity = 10; l.range = 20;
        RblScene scene; memset(&scene, 0, sizeof(scene));
        scene.lights = &l; scene.lightCount = 1; scene.ambient = DARKGRAY;
        RblSetScene(&scene);
        Camera3D oc; memset(&oc, 0, sizeof(oc));
        oc.position = (Vector3){ 0, 0, 10 }; oc.up = (Vector3){ 0, 1, 0 }; oc.fovy = 2.0f; oc.projection = CAMERA_ORTHOGRAPHIC;
        RblBillboard big[2][16];
        RblFade bigFades[16];
        for (int k = 0; k < 2; k++)
            for (int i = 0; i < 16; i++)
            {
                memset(&big[k][i], 0, sizeof(RblBillboard));
                big[k][i].position = (Vector3){ 0, 0, 0.01f*i }; big[k][i].size = (Vector2){ 2, 2 }; big[k][i].origin = (Vector2){ 1, 1 };
                big[k][i].source = (Rectangle){ 0, 0, 512, 512 };
                big[k][i].tint = (Color){ 255, 255, 255, 255 };
                if (k == 1) { memset(&bigFades[i], 0, sizeof(RblFade)); bigFades[i].source = (Rectangle){ 512, 0, 512, 512 }; bigFades[i].weight = 0.5f; }
            }
        RenderTexture2D target = LoadRenderTexture(512, 512);
        double ms[2], msRatio;
        {
            FadeFragCtx fcPlain = { target, oc, fm[0], big[0], NULL, 16 }, fcFade = { target, oc, fm[1], big[1], bigFades, 16 };
            double a[2], b[2];
            interleaved(runFadeFragment, &fcPlain, &fcFade, 1, a, b, &msRatio);
            ms[0] = a[0]; ms[1] = b[0];
        }
        printf("  %-34s %8.2f ms per frame (llvmpipe, glFinish)\n", "fade_fragment_512_plain", ms[0]);
        printf("  %-34s %8.2f ms per frame (llvmpipe, glFinish)\n", "fade_fragment_512_fade", ms[1]);
        printf("  %-34s %8.3f x (median of %d interleaved rounds)\n", "fade_fragment_512 fade/plain", msRatio, FADE_ROUNDS);
        BenchCsvRow("sprites", "fade_fragment_512_plain", "ms_per_frame", ms[0], "ms");
        BenchCsvRow("sprites", "fade_fragment_512_fade", "ms_per_frame", ms[1], "ms");
        BenchCsvRow("sprites", "fade_fragment_512", "fade_over_plain", msRatio, "x");
        UnloadRenderTexture(target);
        for (int k = 0; k < 2; k++) { RblUnloadLitShader(&fm[k].shader); MemFree(fm[k].maps); }
        UnloadTexture(albedo); UnloadTexture(ntex);
    }
    RblUnloadBatch(&batch);
    free(cards); free(faded); free(fadedFades); free(fades);
    RblUnloadLitShader(&plain.shader); RblUnloadLitShader(&fade.shader); RblUnloadLitShader(&fadeInst.shader);
}

// ---- resident sprite buffers (RblSpriteBuffer) vs re-uploaded instances -------------------------
// Five ways to draw n sprites each frame: resident and unchanged; resident and animated on the GPU
// (the clock moves); re-uploaded (RblDrawInstanced, 56 B an instance, unchanged); animated on the
// CPU (RblUpdateSpriteInstances + RblDrawInstanced); resident and written whole each frame
// (RblUpdateSprites of all n, 32 B a sprite, then the draw); and a memcpy of those 32 B a sprite
// (the floor in the same caches). Rounds interleave the six (order rotating), medians per way.
// Values: CPU ns per sprite, the same excluding glDraw* (llvmpipe does its vertex work there), and
// microseconds per draw excluding glDraw*.
enum { RES_STATIC = 0, RES_GPU_ANIM, RES_REUPLOAD, RES_CPU_ANIM, RES_UPDATED, RES_COPY, RES_WAYS };
static const char *const resNames[RES_WAYS] = { "resident", "resident_gpu_animated", "reuploaded", "cpu_animated", "resident_updated", "memcpy_32B" };
typedef struct {
    int way, n;
    RblSpriteBuffer *still, *moving, *updated;
    const RblSpriteInstance *sprites;       // RES_UPDATED: written whole each frame (RblUpdateSprites), then drawn
    RblSpriteInstance *copy;                // RES_COPY: the same bytes memcpy'd (the floor, in the same rounds)
    RblInstanceBuffer *buffer;
    RblInstance *instances;
    RblSpritePlayer *players;
    const RblAtlas *atlas;
    Camera3D camera;
    Material material;
    float clock;
} ResCtx;

static void runResident(void *ctx, double *out)
{
    ResCtx *c = (ResCtx *)ctx;
    RblInstancedDesc d; memset(&d, 0, sizeof(d));
    drawNs = 0.0;
    double t0 = BenchNowNs();
    switch (c->way)
    {
        case RES_STATIC: RblDrawSpriteBuffer(c->still, c->camera, c->material, d, c->clock); break;
        case RES_GPU_ANIM: c->clock += 1.0f/60.0f; RblDrawSpriteBuffer(c->moving, c->camera, c->material, d, c->clock); break;
        case RES_REUPLOAD: RblDrawInstanced(c->buffer, c->camera, c->material, d, c->instances, c->n); break;
        case RES_COPY: memcpy(c->copy, c->sprites, (size_t)c->n*sizeof(RblSpriteInstance)); break;
        case RES_UPDATED:
            if (!RblUpdateSprites(c->updated, 0, c->n, c->sprites)) { printf("bench_sprites: update refused\n"); exit(1); }
            RblDrawSpriteBuffer(c->updated, c->camera, c->material, d, c->clock);
            break;
        default:
            RblUpdateSpriteInstances(c->players, c->instances, c->n, c->atlas, 1.0f/60.0f, 0.005f);
            RblDrawInstanced(c->buffer, c->camera, c->material, d, c->instances, c->n);
            break;
    }
    double t = BenchNowNs() - t0;
    out[0] = t/c->n;
    out[1] = (t - drawNs)/c->n;
    out[2] = (t - drawNs)/1000.0;
    rtFinish();       // untimed: the next run starts with the GPU idle
}

#define RES_ROUNDS 9
static void residentBench(RblAtlas *anim, Camera3D cam, Material m)
{
    static const int sizes[3] = { 1000, 10000, 100000 };
    const int most = 100000;
    RblSpriteInstance *still = (RblSpriteInstance *)calloc((size_t)most, sizeof(RblSpriteInstance));
    RblSpriteInstance *moving = (RblSpriteInstance *)calloc((size_t)most, sizeof(RblSpriteInstance));
    RblInstance *inst = (RblInstance *)calloc((size_t)most, sizeof(RblInstance));
    RblSpritePlayer *players = (RblSpritePlayer *)malloc((size_t)most*sizeof(RblSpritePlayer));
    for (int i = 0; i < most; i++)
    {
        // a 20 x 20 field in view (the camera at z 30 sees about 25 units)
        Vector3 p = { -10.0f + 20.0f*(float)(i%317)/317.0f, -10.0f + 20.0f*(float)((i/317)%311)/311.0f, -0.0001f*(float)(i%1000) };
        int tag = i%anim->tagCount;
        players[i] = RblPlaySprite(anim, tag, -1);
        RblUpdateSprite(&players[i], anim, 0.0137f*(float)(i%97));
        still[i] = RblMakeSprite(p, 0.005f, 0.0f, players[i].frame, WHITE);     // small: llvmpipe's fill stays out of the way
        moving[i] = still[i];
        RblAnimateSprite(&moving[i], tag, -1, -0.0137f*(float)(i%97), 1.0f);
        memset(&inst[i], 0, sizeof(inst[i]));
        inst[i].position = p;
        RblAtlasInstance(anim, players[i].frame, 0.005f, &inst[i]);
    }
    // memcpy bandwidth, this run: the floor of writing B bytes per sprite is B x ns per byte
    double nsPerByte = 1e30;
    {
        size_t bytes = (size_t)most*sizeof(RblInstance);
        char *a = (char *)malloc(bytes), *b = (char *)malloc(bytes);
        memset(a, 1, bytes); memset(b, 2, bytes);
        for (int r = 0; r < 20; r++)
        {
            double t0 = BenchNowNs();
            memcpy(b, a, bytes);
            double ns = (BenchNowNs() - t0)/(double)bytes;
            if (ns < nsPerByte) nsPerByte = ns;
            a[r] = b[bytes - 1 - (size_t)r];
        }
        free(a); free(b);
        printf("  %-34s %8.3f ns per byte (%.1f GB/s, best of 20 copies of %.1f MB)\n", "memcpy_bandwidth", nsPerByte, 1.0/nsPerByte, bytes/1e6);
        BenchCsvRow("sprites", "memcpy_bandwidth", "ns_per_byte", nsPerByte, "ns");
    }
    printf("  %-34s %8d B RblSpriteInstance (resident, animated on the GPU) vs %d B RblInstance (%.2fx)\n", "struct_sizes", (int)sizeof(RblSpriteInstance), (int)sizeof(RblInstance), (double)sizeof(RblSpriteInstance)/sizeof(RblInstance));
    BenchCsvRow("sprites", "struct_sizes", "sprite_instance_bytes", (double)sizeof(RblSpriteInstance), "B");
    BenchCsvRow("sprites", "struct_sizes", "instance_bytes", (double)sizeof(RblInstance), "B");
    // Its own target and 3D mode: the rows before leave other matrices behind
    RenderTexture2D rt = LoadRenderTexture(256, 256);
    BeginTextureMode(rt); ClearBackground(BLACK); BeginMode3D(cam);
    const double bytesWritten[RES_WAYS] = { 0.0, 0.0, (double)sizeof(RblInstance), (double)(sizeof(RblInstance) + 36 + sizeof(RblSpritePlayer)), (double)sizeof(RblSpriteInstance), 0.0 };
    for (int s = 0; s < 3; s++)
    {
        int n = sizes[s];
        RblSpriteBuffer sb = RblLoadSpriteBuffer(anim, n), mb = RblLoadSpriteBuffer(anim, n), ub = RblLoadSpriteBuffer(anim, n);
        RblInstanceBuffer ib = RblLoadInstanceBuffer(n);
        if (!RblUpdateSprites(&sb, 0, n, still) || !RblUpdateSprites(&mb, 0, n, moving)) { printf("bench_sprites: sprites refused\n"); exit(1); }
        RblSpritePlayer *pl = (RblSpritePlayer *)malloc((size_t)n*sizeof(RblSpritePlayer));
        RblInstance *in = (RblInstance *)malloc((size_t)n*sizeof(RblInstance));
        memcpy(pl, players, (size_t)n*sizeof(RblSpritePlayer));
        memcpy(in, inst, (size_t)n*sizeof(RblInstance));
        RblSpriteInstance *copy = (RblSpriteInstance *)malloc((size_t)n*sizeof(RblSpriteInstance));
        ResCtx c[RES_WAYS];
        for (int w = 0; w < RES_WAYS; w++)
        {
            memset(&c[w], 0, sizeof(c[w]));
            c[w].way = w; c[w].n = n; c[w].still = &sb; c[w].moving = &mb; c[w].updated = &ub; c[w].sprites = still; c[w].copy = copy; c[w].buffer = &ib;
            c[w].instances = (w == RES_CPU_ANIM)? in : inst; c[w].players = pl; c[w].atlas = anim; c[w].camera = cam; c[w].material = m;
        }
        double v[RES_WAYS][3][RES_ROUNDS], out[3];
        for (int w = 0; w < RES_WAYS; w++) runResident(&c[w], out);       // warm-up
        for (int r = 0; r < RES_ROUNDS; r++)
            for (int k = 0; k < RES_WAYS; k++)
            {
                int w = (k + r)%RES_WAYS;
                runResident(&c[w], out);
                for (int j = 0; j < 3; j++) v[w][j][r] = out[j];
            }
        double med[RES_WAYS][3];
        for (int w = 0; w < RES_WAYS; w++) for (int j = 0; j < 3; j++) med[w][j] = BenchMedian(v[w][j], RES_ROUNDS);
        for (int w = 0; w < RES_WAYS; w++)
        {
            char name[48]; snprintf(name, sizeof(name), "%s_%d", resNames[w], n);
            double floor = bytesWritten[w]*nsPerByte;
            printf("  %-34s %8.2f ns per sprite (CPU), %7.2f excl draw calls, %7.1f us per draw excl; floor %3.0f B x bw = %.2f ns%s\n", name, med[w][0], med[w][1], med[w][2],
                   bytesWritten[w], floor, (floor > 0.0)? "" : " (nothing written per frame)");
            BenchCsvRow("sprites", name, "cpu_ns_per_sprite", med[w][0], "ns");
            BenchCsvRow("sprites", name, "excl_draw_ns_per_sprite", med[w][1], "ns");
            BenchCsvRow("sprites", name, "excl_draw_us_per_draw", med[w][2], "us");
            if (floor > 0.0) BenchCsvRow("sprites", name, "excl_draw_over_floor", med[w][1]/floor, "x");
        }
        printf("  %-34s %8.3f x resident, %.3f x GPU-animated, %.3f x CPU-animated (CPU excl draw calls, medians of %d interleaved rounds)\n", "", med[RES_STATIC][1]/med[RES_REUPLOAD][1],
               med[RES_GPU_ANIM][1]/med[RES_REUPLOAD][1], med[RES_CPU_ANIM][1]/med[RES_REUPLOAD][1], RES_ROUNDS);
        char name[48]; snprintf(name, sizeof(name), "resident_%d", n);
        BenchCsvRow("sprites", name, "excl_draw_over_reuploaded", med[RES_STATIC][1]/med[RES_REUPLOAD][1], "x");
        // The whole-set update against a memcpy of its bytes in the same round (the same caches)
        {
            double ratio[RES_ROUNDS];
            for (int r = 0; r < RES_ROUNDS; r++) ratio[r] = v[RES_UPDATED][1][r]/v[RES_COPY][1][r];
            double q = BenchMedian(ratio, RES_ROUNDS);
            snprintf(name, sizeof(name), "resident_updated_%d", n);
            printf("  %-34s %8.2f x a memcpy of the same %d x 32 B in the same round (update + draw, excl draw calls; median of %d)\n", name, q, n, RES_ROUNDS);
            BenchCsvRow("sprites", name, "excl_draw_over_round_memcpy", q, "x");
        }
        // What of a resident draw is this header's own CPU (checks and chunk culling, no GL: the
        // camera turned away), and what any draw costs the driver (RblDrawInstanced of 1 instance)
        {
            Camera3D away = cam;
            away.target = (Vector3){ cam.position.x, cam.position.y, cam.position.z + 1.0f };
            RblInstancedDesc d; memset(&d, 0, sizeof(d));
            double own[RES_ROUNDS], one[RES_ROUNDS];
            for (int r = 0; r < RES_ROUNDS; r++)
            {
                EndMode3D(); BeginMode3D(away);         // culling reads the pass's matrices
                double t0 = BenchNowNs();
                for (int k = 0; k < 100; k++) RblDrawSpriteBuffer(&sb, away, m, d, 0.0f);
                own[r] = (BenchNowNs() - t0)/100.0/1000.0;
                EndMode3D(); BeginMode3D(cam);
                drawNs = 0.0;
                t0 = BenchNowNs();
                RblDrawInstanced(&ib, cam, m, d, inst, 1);
                one[r] = (BenchNowNs() - t0 - drawNs)/1000.0;
                rtFinish();
            }
            double o = BenchMedian(own, RES_ROUNDS), g = BenchMedian(one, RES_ROUNDS);
            snprintf(name, sizeof(name), "resident_%d_own_cpu", n);
            printf("  %-34s %8.2f us per draw: checks and culling of %d chunks (no GL); a 1-instance RblDrawInstanced costs %.1f us excl draw calls (driver state)\n", name, o, (n + 255)/256, g);
            BenchCsvRow("sprites", name, "us_per_draw", o, "us");
            BenchCsvRow("sprites", "instanced_1", "excl_draw_us_per_draw", g, "us");
        }
        snprintf(name, sizeof(name), "resident_gpu_animated_%d", n);
        BenchCsvRow("sprites", name, "excl_draw_over_cpu_animated", med[RES_GPU_ANIM][1]/med[RES_CPU_ANIM][1], "x");
        free(pl); free(in); free(copy);
        RblUnloadSpriteBuffer(&sb); RblUnloadSpriteBuffer(&mb); RblUnloadSpriteBuffer(&ub); RblUnloadInstanceBuffer(&ib);
    }
    // Culling: 100000 resident sprites all in view, and the same with 90 % moved far to the side
    // (in buffer order, as tiles of a level would lie); wall time with glFinish (llvmpipe's vertex
    // work included) and CPU excluding glDraw*
    {
        int n = most;
        RblSpriteBuffer seen = RblLoadSpriteBuffer(anim, n), side = RblLoadSpriteBuffer(anim, n);
        RblUpdateSprites(&seen, 0, n, still);
        for (int i = n/10; i < n; i++) still[i].position.x += 1000.0f + 0.01f*(float)i;
        RblUpdateSprites(&side, 0, n, still);
        RblInstancedDesc d; memset(&d, 0, sizeof(d));
        double wall[2][RES_ROUNDS], cpu[2][RES_ROUNDS];
        int drawn[2] = { 0, 0 };
        for (int r = 0; r < RES_ROUNDS + 1; r++)
            for (int k = 0; k < 2; k++)
            {
                int w = (k + r)%2;
                rtFinish();
                drawNs = 0.0;
                double t0 = BenchNowNs();
                drawn[w] = RblDrawSpriteBuffer(w? &side : &seen, cam, m, d, 0.0f);
                double t1 = BenchNowNs();
                rtFinish();
                if (r == 0) continue;            // warm-up
                wall[w][r - 1] = (BenchNowNs() - t0)/1e6;
                cpu[w][r - 1] = (t1 - t0 - drawNs)/1000.0;
            }
        double wv = BenchMedian(wall[0], RES_ROUNDS), wo = BenchMedian(wall[1], RES_ROUNDS), cv = BenchMedian(cpu[0], RES_ROUNDS), co = BenchMedian(cpu[1], RES_ROUNDS);
        printf("  %-34s %8.2f ms per frame (glFinish), %6.1f us CPU excl draw calls; %d drawn\n", "cull_100000_visible", wv, cv, drawn[0]);
        printf("  %-34s %8.2f ms per frame (glFinish), %6.1f us CPU excl draw calls; %d drawn\n", "cull_100000_offscreen90", wo, co, drawn[1]);
        printf("  %-34s %8.3f x wall, %.3f x CPU excl draw calls (medians of %d interleaved rounds)\n", "cull_100000 offscreen90/visible", wo/wv, co/cv, RES_ROUNDS);
        BenchCsvRow("sprites", "cull_100000_visible", "ms_per_frame", wv, "ms");
        BenchCsvRow("sprites", "cull_100000_offscreen90", "ms_per_frame", wo, "ms");
        BenchCsvRow("sprites", "cull_100000", "offscreen90_over_visible", wo/wv, "x");
        RblUnloadSpriteBuffer(&seen); RblUnloadSpriteBuffer(&side);
    }
    EndMode3D(); EndTextureMode();
    UnloadRenderTexture(rt);
    free(still); free(moving); free(inst); free(players);
}

int main(void)
{
    SetTraceLogLevel(LOG_WARNING);
    BenchTiming timing = { 2, 5, 30, 2e9 };
    static const int formats[3] = { RBL_ATLAS_TEXTUREPACKER, RBL_ATLAS_ASEPRITE, RBL_ATLAS_LIBGDX };
    static const char *names[3] = { "texturepacker", "aseprite", "libgdx" };
    RblAtlas anim; memset(&anim, 0, sizeof(anim));
    for (int f = 0; f < 3; f++)
    {
        const int frames = 4096;
        ImportCtx c = { makeText(formats[f], frames), formats[f] };
        double med;
        BenchMedianOfRuns(runImport, &c, 1, timing, &med);
        char name[64]; snprintf(name, sizeof(name), "import_%s_%dframes", names[f], frames);
        printf("  %-34s %8.3f ms per 1000 frames (%.1f KiB text)\n", name, med/1e6*1000.0/frames, c.text.size/1024.0);
        BenchCsvRow("sprites", name, "ms_per_1000_frames", med/1e6*1000.0/frames, "ms");
        if (formats[f] == RBL_ATLAS_ASEPRITE) anim = RblLoadAtlasFromMemory(c.text.text, c.text.size, formats[f]);
        free(c.text.text);
    }
    // the new forms beside the plain TexturePacker hash text, interleaved (median of per-round ratios)
    {
        enum { ROUNDS = 15 };
        const int frames = 4096;
        Text plain = makeText(RBL_ATLAS_TEXTUREPACKER, frames);
        for (int form = 0; form < FORM_COUNT; form++)
        {
            Text t = makeFormText(form, frames);
            double ms[2][ROUNDS], ratio[ROUNDS];
            for (int r = 0; r < ROUNDS + 2; r++)
            {
                double v[2];
                for (int k = 0; k < 2; k++)
                {
                    const Text *x = (k == 0)? &plain : &t;
                    double t0 = BenchNowNs();
                    RblAtlas a = RblLoadAtlasFromMemory(x->text, x->size, RBL_ATLAS_AUTO);
                    v[k] = BenchNowNs() - t0;
                    if (!RblIsAtlasValid(a) || (a.frameCount != frames)) { printf("bench_sprites: generated %s atlas refused\n", (k == 0)? "plain" : formNames[form]); exit(1); }
                    RblUnloadAtlas(&a);
                }
                if (r < 2) continue;        // warm-up
                ms[0][r - 2] = v[0]/1e6*1000.0/frames; ms[1][r - 2] = v[1]/1e6*1000.0/frames; ratio[r - 2] = v[1]/v[0];
            }
            double base = BenchMedian(ms[0], ROUNDS), mine = BenchMedian(ms[1], ROUNDS), over = BenchMedian(ratio, ROUNDS);
            char name[64]; snprintf(name, sizeof(name), "import_%s_%dframes", formNames[form], frames);
            printf("  %-34s %8.3f ms per 1000 frames (%.1f KiB text), %.2fx the plain TexturePacker text (%.3f ms)\n", name, mine, t.size/1024.0, over, base);
            BenchCsvRow("sprites", name, "ms_per_1000_frames", mine, "ms");
            BenchCsvRow("sprites", name, "over_texturepacker", over, "x");
            if (form == FORM_PHASER3)
            {
                // the same text from a file: each textures[] image and normalMap looked for on disk
                MakeDirectory("build/bench/atlas");
                Image one = GenImageColor(1, 1, WHITE);
                for (int p = 0; p < 4; p++)
                {
                    char path[64];
                    snprintf(path, sizeof(path), "build/bench/atlas/sheet-%d.png", p); ExportImage(one, path);
                    snprintf(path, sizeof(path), "build/bench/atlas/sheet-%d_n.png", p); ExportImage(one, path);
                }
                UnloadImage(one);
                SaveFileData("build/bench/atlas/phaser3.json", t.text, t.size);
                double fr[ROUNDS];
                for (int r = 0; r < ROUNDS + 2; r++)
                {
                    double t0 = BenchNowNs();
                    RblAtlas a = RblLoadAtlasFromMemory(t.text, t.size, RBL_ATLAS_AUTO);
                    double mem = BenchNowNs() - t0;
                    RblUnloadAtlas(&a);
                    t0 = BenchNowNs();
                    a = RblLoadAtlas("build/bench/atlas/phaser3.json");
                    double file = BenchNowNs() - t0;
                    if (!RblIsAtlasValid(a) || (a.pages[3].normalImage == NULL)) { printf("bench_sprites: Phaser 3 file refused\n"); exit(1); }
                    RblUnloadAtlas(&a);
                    if (r >= 2) fr[r - 2] = file/mem;
                }
                double fileOver = BenchMedian(fr, ROUNDS);
                printf("  %-34s %8.2fx from memory (8 sheets looked for; includes reading the file)\n", "import_phaser3_file", fileOver);
                BenchCsvRow("sprites", "import_phaser3_file", "file_over_memory", fileOver, "x");
            }
            free(t.text);
        }
        // a slice's sub-frame beside the frame's own quad (best of 20 each)
        Text st = makeFormText(FORM_SLICES, frames);
        RblAtlas sa = RblLoadAtlasFromMemory(st.text, st.size, RBL_ATLAS_AUTO);
        free(st.text);
        static int keyOf[10000];
        for (int i = 0; i < 10000; i++) keyOf[i] = RblAtlasFindSlice(&sa, "part_5", i%frames);
        double best[2] = { 1e30, 1e30 };
        RblBillboard bb; memset(&bb, 0, sizeof(bb));
        for (int r = 0; r < 20; r++)
            for (int k = 0; k < 2; k++)
            {
                double t0 = BenchNowNs();
                if (k == 0) for (int i = 0; i < 10000; i++) RblAtlasBillboard(&sa, i%frames, 0.02f, &bb);
                else for (int i = 0; i < 10000; i++) RblAtlasSliceBillboard(&sa, keyOf[i], i%frames, 0.02f, &bb);
                double ns = (BenchNowNs() - t0)/10000.0;
                if (ns < best[k]) best[k] = ns;
            }
        printf("  %-34s %8.1f ns per call (RblAtlasBillboard %.1f ns: %.2fx)\n", "slice_billboard_10000", best[1], best[0], best[1]/best[0]);
        BenchCsvRow("sprites", "slice_billboard_10000", "ns_per_call", best[1], "ns");
        BenchCsvRow("sprites", "frame_billboard_10000", "ns_per_call", best[0], "ns");
        BenchCsvRow("sprites", "slice_billboard_10000", "over_frame", best[1]/best[0], "x");
        RblUnloadAtlas(&sa);
        free(plain.text);
    }
    // players spread over the tags and phases
    static const int counts[2] = { 10000, 100000 };
    RblSpritePlayer *players = (RblSpritePlayer *)malloc(sizeof(RblSpritePlayer)*100000);
    RblInstance *instances = (RblInstance *)calloc(100000, sizeof(RblInstance));
    for (int i = 0; i < 100000; i++)
    {
        players[i] = RblPlaySprite(&anim, i%anim.tagCount, 0);
        RblUpdateSprite(&players[i], &anim, 0.0137f*(float)(i%97));
    }
    for (int k = 0; k < 2; k++)
    {
        AnimCtx c;
        memset(&c, 0, sizeof(c));
        c.atlas = &anim; c.players = players; c.instances = instances; c.n = counts[k]; c.animated = true;
        double med;
        BenchMedianOfRuns(runAnim, &c, 1, timing, &med);
        char name[32]; snprintf(name, sizeof(name), "update_%d", counts[k]);
        printf("  %-34s %8.1f ns per sprite\n", name, med);
        BenchCsvRow("sprites", name, "ns_per_sprite", med, "ns");
    }
    // the per-instance fields of a frame (RblAtlasInstance) alone
    {
        double best = 1e30;
        for (int r = 0; r < 20; r++)
        {
            double t0 = BenchNowNs();
            for (int i = 0; i < 10000; i++) RblAtlasInstance(&anim, players[i].frame, 0.02f, &instances[i]);
            double ns = (BenchNowNs() - t0)/10000.0;
            if (ns < best) best = ns;
        }
        printf("  %-34s %8.1f ns per instance (best of 20)\n", "fill_10000", best);
        BenchCsvRow("sprites", "fill_10000", "ns_per_instance", best, "ns");
    }
    // instanced: plain vs a frame per instance
    if (rtInitContext(256, 256) == NULL || !rtGlsl3()) { printf("  (no GLSL 3 context: instanced rows skipped)\n"); }
    else
    {
        RblLitShaderDesc desc; memset(&desc, 0, sizeof(desc)); desc.instanced = true;
        Material m = LoadMaterialDefault();
        m.shader = RblLoadLitShader(desc);
        Image sheet = GenImageColor(4096, 4096, WHITE);
        m.maps[MATERIAL_MAP_ALBEDO].texture = LoadTextureFromImage(sheet);
        UnloadImage(sheet);
        RblInstanceBuffer buf = RblLoadInstanceBuffer(10000);
        Camera3D cam; memset(&cam, 0, sizeof(cam));
        cam.position = (Vector3){ 0, 0, 30 }; cam.up = (Vector3){ 0, 1, 0 }; cam.fovy = 45; cam.projection = CAMERA_PERSPECTIVE;
        const int n = 10000;
        for (int i = 0; i < n; i++)
        {
            instances[i].position = (Vector3){ (float)(i%100) - 50.0f, (float)(i/100) - 50.0f, 0.0f };
            RblAtlasInstance(&anim, players[i].frame, 0.02f, &instances[i]);
        }
        RenderTexture2D rt = LoadRenderTexture(256, 256);
        BeginTextureMode(rt); BeginMode3D(cam);
        double med[2], excl[2];
        bool wrapped = wrapDraws();
        for (int animated = 0; animated < 2; animated++)
        {
            AnimCtx c;
            memset(&c, 0, sizeof(c));
            c.atlas = &anim; c.players = players; c.instances = instances; c.n = n; c.buffer = &buf; c.camera = cam; c.material = m;
            c.animated = (animated == 1); c.draw = true;
            double both[2];
            BenchMedianOfRuns(runAnim, &c, 2, timing, both);
            med[animated] = both[0]; excl[animated] = both[1];
            char name[32]; snprintf(name, sizeof(name), "instanced_%d_%s", n, animated? "animated" : "plain");
            printf("  %-34s %8.1f ns per instance (CPU), %6.1f excluding draw calls\n", name, med[animated], excl[animated]);
            BenchCsvRow("sprites", name, "cpu_ns_per_instance", med[animated], "ns");
            if (wrapped) BenchCsvRow("sprites", name, "excl_draw_ns_per_instance", excl[animated], "ns");
        }
        // the bulk form: one call updates the players and refills the instances
        double bulkBest = 1e30;
        for (int r = 0; r < 20; r++)
        {
            double t0 = BenchNowNs();
            RblUpdateSpriteInstances(players, instances, n, &anim, 1.0f/60.0f, 0.02f);
            double ns = (BenchNowNs() - t0)/n;
            if (ns < bulkBest) bulkBest = ns;
        }
        printf("  %-34s %8.1f ns per instance (best of 20)\n", "bulk_update_fill_10000", bulkBest);
        BenchCsvRow("sprites", "bulk_update_fill_10000", "ns_per_instance", bulkBest, "ns");
        // raylib's DrawBillboardPro over the same frames (distinct sources), in the same run
        {
            Rectangle *src = (Rectangle *)malloc((size_t)n*sizeof(Rectangle));
            Vector3 *pos = (Vector3 *)malloc((size_t)n*sizeof(Vector3));
            for (int i = 0; i < n; i++) { src[i] = instances[i].source; src[i].width = fabsf(src[i].width); src[i].height = fabsf(src[i].height); pos[i] = instances[i].position; }
            RaylibCtx rc = { m.maps[MATERIAL_MAP_ALBEDO].texture, src, pos, n, cam };
            double ray[2];
            BenchMedianOfRuns(runRaylib, &rc, 2, timing, ray);
            printf("  %-34s %8.1f ns per billboard (CPU), %6.1f excluding draw calls\n", "raylib_billboard_pro_10000", ray[0], ray[1]);
            printf("  %-34s %8.3f x animated, %.3f x plain (CPU incl. llvmpipe's vertex work in glDraw*)\n", "instanced_10000 / raylib", med[1]/ray[0], med[0]/ray[0]);
            BenchCsvRow("sprites", "raylib_billboard_pro_10000", "cpu_ns_per_billboard", ray[0], "ns");
            BenchCsvRow("sprites", "instanced_10000", "animated_over_raylib", med[1]/ray[0], "x");
            BenchCsvRow("sprites", "instanced_10000", "plain_over_raylib", med[0]/ray[0], "x");
            if (wrapped)
            {
                printf("  %-34s %8.3f x animated, %.3f x plain (target <= 0.05 x, excluding draw calls)\n", "instanced_10000 / raylib excl draw", excl[1]/ray[1], excl[0]/ray[1]);
                BenchCsvRow("sprites", "raylib_billboard_pro_10000", "excl_draw_ns_per_billboard", ray[1], "ns");
                BenchCsvRow("sprites", "instanced_10000", "excl_draw_animated_over_raylib", excl[1]/ray[1], "x");
                BenchCsvRow("sprites", "instanced_10000", "excl_draw_plain_over_raylib", excl[0]/ray[1], "x");
            }
            free(src); free(pos);
        }
        if (wrapped)
        {
            // The bulk update (RblUpdateSpriteInstances) + the instanced draw of distinct frames, over raylib
            double ray[2];
            Rectangle *src = (Rectangle *)malloc((size_t)n*sizeof(Rectangle));
            Vector3 *pos = (Vector3 *)malloc((size_t)n*sizeof(Vector3));
            for (int i = 0; i < n; i++) { src[i] = instances[i].source; src[i].width = fabsf(src[i].width); src[i].height = fabsf(src[i].height); pos[i] = instances[i].position; }
            RaylibCtx rc = { m.maps[MATERIAL_MAP_ALBEDO].texture, src, pos, n, cam };
            BenchMedianOfRuns(runRaylib, &rc, 2, timing, ray);
            printf("  %-34s %8.3f x ((bulk %.1f + draw %.1f) / raylib %.1f ns, excluding draw calls)\n", "instanced_10000 bulk+draw / raylib", (bulkBest + excl[0])/ray[1], bulkBest, excl[0], ray[1]);
            BenchCsvRow("sprites", "instanced_10000", "excl_draw_bulk_animated_over_raylib", (bulkBest + excl[0])/ray[1], "x");
            free(src); free(pos);
        }
        fadeBench(&anim, players, instances, n, &buf, cam, m, timing);
        if (wrapped) residentBench(&anim, cam, m);
        else printf("  (glDraw* not wrapped: resident rows skipped)\n");
        EndMode3D(); EndTextureMode();
        printf("  %-34s %8.3f x\n", "instanced_10000 animated/plain", med[1]/med[0]);
        BenchCsvRow("sprites", "instanced_10000", "animated_over_plain", med[1]/med[0], "x");
        UnloadRenderTexture(rt);
        RblUnloadInstanceBuffer(&buf);
        UnloadTexture(m.maps[MATERIAL_MAP_ALBEDO].texture);
        RblUnloadLitShader(&m.shader);
        MemFree(m.maps);
        RblClose();
        rtCloseContext();
    }
    free(players); free(instances);
    RblUnloadAtlas(&anim);
    return 0;
}
