// Suite `sprites`: atlas import, animation update and the instanced path with a frame per instance.
//   import_<format>_<N>frames   ms_per_1000_frames   RblLoadAtlasFromMemory of a generated text of N frames
//                                                    (TexturePacker hash, Aseprite array with a tag per 8
//                                                    frames, libGDX old form with indexed regions)
//   update_<N>                  ns_per_sprite        RblUpdateSprite over N players (pingpong tags, 1/60 s)
//   instanced_<N>               cpu_ns_per_instance  plain: RblDrawInstanced of a filled array; animated: per
//                                                    instance RblUpdateSprite + RblAtlasInstance, then the same
//                                                    draw (submission CPU time, no glFinish)
//   instanced_<N>               animated_over_plain  ratio of the two
//   bulk_update_fill_10000      ns_per_instance      RblUpdateSpriteInstances (the same work, checks once)
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
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

typedef struct { Text text; int format; } ImportCtx;
static void runImport(void *ctx, double *out)
{
    ImportCtx *c = (ImportCtx *)ctx;
    double t0 = BenchNowNs();
    RblAtlas a = RblLoadAtlasFromMemory(c->text.text, c->text.size, c->format);
    out[0] = BenchNowNs() - t0;
    if (!RblIsAtlasValid(&a)) { printf("bench_sprites: generated atlas refused\n"); exit(1); }
    RblUnloadAtlas(&a);
}

// ---- animation ----------------------------------------------------------------------------------
typedef struct { RblAtlas *atlas; RblSpritePlayer *players; RblInstance *instances; int n; RblInstanceBuffer *buffer; Camera3D camera; Material material; bool animated, draw; } AnimCtx;
static void runAnim(void *ctx, double *out)
{
    AnimCtx *c = (AnimCtx *)ctx;
    double t0 = BenchNowNs();
    if (c->animated)
        for (int i = 0; i < c->n; i++)
        {
            RblUpdateSprite(&c->players[i], c->atlas, 1.0f/60.0f);
            if (c->draw) RblAtlasInstance(c->atlas, c->players[i].frame, 0.02f, &c->instances[i]);
        }
    if (c->draw) RblDrawInstanced(c->buffer, c->camera, c->material, (RblInstancedDesc){ 0 }, c->instances, c->n);
    out[0] = (BenchNowNs() - t0)/c->n;
    if (c->draw) rtFinish();      // untimed: the next run starts with the GPU idle
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
        double med[2];
        for (int animated = 0; animated < 2; animated++)
        {
            AnimCtx c;
            memset(&c, 0, sizeof(c));
            c.atlas = &anim; c.players = players; c.instances = instances; c.n = n; c.buffer = &buf; c.camera = cam; c.material = m;
            c.animated = (animated == 1); c.draw = true;
            BenchMedianOfRuns(runAnim, &c, 1, timing, &med[animated]);
            char name[32]; snprintf(name, sizeof(name), "instanced_%d_%s", n, animated? "animated" : "plain");
            printf("  %-34s %8.1f ns per instance (CPU)\n", name, med[animated]);
            BenchCsvRow("sprites", name, "cpu_ns_per_instance", med[animated], "ns");
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
