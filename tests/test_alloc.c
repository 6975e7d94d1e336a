// Allocation-failure injection: the header's allocator (RBL_MALLOC / RBL_CALLOC / RBL_REALLOC /
// RBL_FREE) is replaced by wrappers that fail at the Nth call, and every allocating path is swept
// over N (0, 1, 2, ... until a run needs no more than N calls). Each failing run must: not crash
// (ASan+UBSan), leave no allocation of the header's behind once its objects are unloaded, return an
// invalid object or failure, and log exactly one "RBL:" warning; a path that degrades instead (a
// batch that cannot grow) must keep its object valid and usable. Images handed to the caller are
// raylib's MemAlloc (freed by UnloadImage) and are outside the injected family.
#include <stddef.h>
#include <stdlib.h>

static long allocCalls = 0, allocFailAt = -1, allocLive = 0;
static void *failingMalloc(size_t n) { if (allocCalls++ == allocFailAt) return NULL; void *p = malloc(n); if (p != NULL) allocLive++; return p; }
static void *failingCalloc(size_t c, size_t n) { if (allocCalls++ == allocFailAt) return NULL; void *p = calloc(c, n); if (p != NULL) allocLive++; return p; }
static void *failingRealloc(void *q, size_t n) { if (allocCalls++ == allocFailAt) return NULL; void *p = realloc(q, n); if ((p != NULL) && (q == NULL)) allocLive++; return p; }
static void countedFree(void *p) { if (p != NULL) { allocLive--; free(p); } }
#define RBL_MALLOC(sz) failingMalloc(sz)
#define RBL_CALLOC(n, sz) failingCalloc(n, sz)
#define RBL_REALLOC(p, sz) failingRealloc(p, sz)
#define RBL_FREE(p) countedFree(p)

#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "rlgl.h"
#include "harness.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "gpu_common.h"

static int failuresSwept = 0;       // failing runs checked, over every path

// Fail the Nth allocation from now (N < 0: none)
static void failAfter(long n) { allocCalls = 0; allocFailAt = n; warnings = 0; lastWarning[0] = 0; }
// True while the last run hit the injected failure
static bool injected(void) { return (allocFailAt >= 0) && (allocCalls > allocFailAt); }

// GL objects alive (names 1..1023 of every kind the header creates): a failed load must leave none
typedef unsigned char (*GlIsFn)(unsigned int);
static int glObjects(void)
{
    static const char *names[5] = { "glIsBuffer", "glIsTexture", "glIsFramebuffer", "glIsVertexArray", "glIsProgram" };
    int n = 0;
    for (int k = 0; k < 5; k++)
    {
        GlIsFn is; void *p = rtGlProc(names[k]); memcpy(&is, &p, sizeof(p));
        for (unsigned int id = 1; id < 1024; id++) n += is(id)? 1 : 0;
    }
    return n;
}

// Sweep body: run() returns true on success; cleanup() unloads what a successful run made.
// Every failing run: failure, one log line, and the header's allocations back to where they were.
typedef bool (*RunFn)(void);
typedef void (*CleanFn)(void);
static void sweep(const char *what, RunFn run, CleanFn cleanup)
{
    int swept = 0;
    // One clean run first: state the header keeps until RblClose (the live-object list, the scene's
    // arrays, the handle table) is made once, so that what follows measures leaks, not that state
    failAfter(-1);
    RT_CHECK(run(), "%s: failed with no injected failure (%s)", what, lastWarning);
    cleanup();
    for (long n = 0; n < 10000; n++)
    {
        long liveBefore = allocLive;
        int glBefore = glObjects();
        failAfter(n);
        bool ok = run();
        bool hit = injected();
        allocFailAt = -1;
        if (!hit)
        {
            RT_CHECK(ok, "%s: failed with no injected failure (%s)", what, lastWarning);
            int made = glObjects() - glBefore;
            if (made > 0) printf("    %-34s a success holds %d GL objects\n", what, made);
            cleanup();
            RT_CHECK(allocLive == liveBefore, "%s: %ld allocations left after unloading a success", what, allocLive - liveBefore);
            printf("    %-34s %3d failing runs swept (the path allocates %ld times)\n", what, swept, allocCalls);
            return;
        }
        swept++; failuresSwept++;
        RT_CHECK(!ok, "%s: allocation %ld failed but the call reported success", what, n);
        RT_CHECK(warnings == 1, "%s: allocation %ld failed with %d log lines (last: %s)", what, n, warnings, lastWarning);
        if (ok) cleanup();
        RT_CHECK(allocLive == liveBefore, "%s: allocation %ld failed and %ld allocations leaked", what, n, allocLive - liveBefore);
        RT_CHECK(glObjects() == glBefore, "%s: allocation %ld failed and %d GL objects were left", what, n, glObjects() - glBefore);
    }
    RT_CHECK(false, "%s: never succeeded", what);
}

// ---- paths --------------------------------------------------------------------------------------
static RblBatch batch;
static bool runLoadBatch(void) { batch = RblLoadBatch(8); return RblIsBatchValid(batch); }
static void cleanBatch(void) { RblUnloadBatch(&batch); }

static RblInstanceBuffer instances;
static bool runLoadInstances(void) { instances = RblLoadInstanceBuffer(8); return RblIsInstanceBufferValid(instances); }
static void cleanInstances(void) { RblUnloadInstanceBuffer(&instances); }

static RblShadowMap shadowMap;
static bool runLoadShadow(void) { RblShadowDesc d; memset(&d, 0, sizeof(d)); d.size = 64; shadowMap = RblLoadShadowMap(d); return RblIsShadowMapValid(shadowMap); }
static void cleanShadow(void) { RblUnloadShadowMap(&shadowMap); }

static RblGBuffer gbuffer;
static bool runLoadGBuffer(void) { RblGBufferDesc d; memset(&d, 0, sizeof(d)); d.width = 32; d.height = 32; d.shading.brdf = RBL_BRDF_GGX; gbuffer = RblLoadGBuffer(d); return RblIsGBufferValid(gbuffer); }
static void cleanGBuffer(void) { RblUnloadGBuffer(&gbuffer); }

static Shader lit;
static int litVariant = 0;
static bool runLoadLit(void)
{
    RblLitShaderDesc d; memset(&d, 0, sizeof(d));
    d.maxLights = 1 + litVariant;       // a variant not yet in the registry: compiled on this run
    d.shading.brdf = RBL_BRDF_BLINN_PHONG;
    lit = RblLoadLitShader(d);
    return RblIsLitShaderValid(lit);
}
static void cleanLit(void) { RblUnloadLitShader(&lit); }

static RblLight sceneLights[40];
static bool runSetScene(void)
{
    RblScene s; memset(&s, 0, sizeof(s));
    s.lights = sceneLights; s.lightCount = 40;
    return RblSetScene(&s);
}

static RblPackedMaterial packed;
static RblMaterialSource packSource;
static bool runPack(void) { return RblPackMaterial(&packSource, &packed); }
static void cleanPack(void) { RblUnloadPackedMaterial(&packed); }

static Image heightImage, genOut;
static bool runGenNormal(void) { genOut = RblGenNormalMapFromHeight(heightImage, 2.0f, true); return genOut.data != NULL; }
static bool runGenHeight(void) { genOut = RblGenHeightFromLuminance(packSource.albedo); return genOut.data != NULL; }
static bool runGenOcclusion(void) { genOut = RblGenOcclusionFromHeight(heightImage, 3, 1.0f); return genOut.data != NULL; }
static void cleanGen(void) { UnloadImage(genOut); memset(&genOut, 0, sizeof(genOut)); }

// Resident sprites: the buffer's load (tables, CPU copy, chunk bounds, GL buffer and frame table),
// and a draw's first use of an instanced program, which compiles its resident-sprite variant
static const char spriteAtlasText[] = "{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}, \"duration\": 100},"
    "{\"filename\": \"b\", \"frame\": {\"x\":4,\"y\":0,\"w\":4,\"h\":4}}], \"meta\": {\"app\": \"aseprite\", \"frameTags\": [{\"name\": \"t\", \"from\": 0, \"to\": 1, \"direction\": \"pingpong\"}]}}";
static RblAtlas spriteAtlas;
static RblSpriteBuffer spriteBuffer, drawnBuffer;
static Shader spriteLit;
static RenderTexture2D spriteTarget;
static bool runLoadSprites(void) { spriteBuffer = RblLoadSpriteBuffer(&spriteAtlas, 300); return RblIsSpriteBufferValid(spriteBuffer); }
static void cleanSprites(void) { RblUnloadSpriteBuffer(&spriteBuffer); }
static bool runDrawSprites(void)
{
    RblLitShaderDesc d; memset(&d, 0, sizeof(d)); d.instanced = true;
    spriteLit = RblLoadLitShader(d);
    if (!RblIsLitShaderValid(spriteLit)) return false;
    Material m = LoadMaterialDefault();
    m.shader = spriteLit;
    RblInstancedDesc id; memset(&id, 0, sizeof(id));
    Camera3D cam; memset(&cam, 0, sizeof(cam));
    cam.position = (Vector3){ 0.0f, 0.0f, 5.0f }; cam.up = (Vector3){ 0.0f, 1.0f, 0.0f }; cam.fovy = 45.0f; cam.projection = CAMERA_PERSPECTIVE;
    BeginTextureMode(spriteTarget); BeginMode3D(cam);
    int n = RblDrawSpriteBuffer(&drawnBuffer, cam, m, id, 0.5f);
    EndMode3D(); EndTextureMode();
    MemFree(m.maps);
    if (n == 0) RblUnloadLitShader(&spriteLit);
    return n > 0;
}
static void cleanDrawSprites(void) { RblUnloadLitShader(&spriteLit); }

static RblAtlas atlas;
static const char *atlasFile = NULL;
static char *atlasText = NULL;
static int atlasSize = 0;
static bool runLoadAtlasMemory(void) { atlas = RblLoadAtlasFromMemory(atlasText, atlasSize, RBL_ATLAS_AUTO); return RblIsAtlasValid(atlas); }
static bool runLoadAtlasFile(void) { atlas = RblLoadAtlas(atlasFile); return RblIsAtlasValid(atlas); }
static void cleanAtlas(void) { RblUnloadAtlas(&atlas); }

// ---- tests --------------------------------------------------------------------------------------
static void test_alloc_every_loading_path_fails_cleanly_at_every_allocation(void)
{
    for (int i = 0; i < 40; i++)
    {
        memset(&sceneLights[i], 0, sizeof(RblLight));
        sceneLights[i].position = (Vector3){ (float)i, 1.0f, 0.0f };
        sceneLights[i].color = WHITE;
        sceneLights[i].intensity = 1.0f;
    }
    memset(&packSource, 0, sizeof(packSource));
    packSource.albedo = GenImageGradientLinear(32, 32, 45, RED, BLUE);
    packSource.normal = GenImageColor(32, 32, (Color){ 128, 128, 255, 255 });
    packSource.specular = GenImageColor(32, 32, GRAY);
    packSource.occlusion = GenImageColor(32, 32, WHITE);
    packSource.emissive = GenImageColor(32, 32, DARKGRAY);
    static const Rectangle frames[2] = { { 0, 0, 16, 32 }, { 16, 0, 16, 32 } };
    packSource.frames = frames; packSource.frameCount = 2;
    packSource.mipmaps = true;
    heightImage = GenImageGradientRadial(32, 32, 0.2f, WHITE, BLACK);

    sweep("RblLoadBatch", runLoadBatch, cleanBatch);
    sweep("RblLoadInstanceBuffer", runLoadInstances, cleanInstances);
    failAfter(-1);
    spriteAtlas = RblLoadAtlasFromMemory(spriteAtlasText, (int)strlen(spriteAtlasText), RBL_ATLAS_AUTO);
    RT_CHECK(RblIsAtlasValid(spriteAtlas), "sprite atlas refused (%s)", lastWarning);
    sweep("RblLoadSpriteBuffer", runLoadSprites, cleanSprites);
    drawnBuffer = RblLoadSpriteBuffer(&spriteAtlas, 4);
    RblSpriteInstance four[4];
    for (int i = 0; i < 4; i++) { four[i] = RblMakeSprite((Vector3){ 0.3f*(float)i, 0.0f, 0.0f }, 0.05f, 0.0f, 0, WHITE); RblAnimateSprite(&four[i], 0, -1, 0.0f, 1.0f); }
    RT_CHECK(RblUpdateSprites(&drawnBuffer, 0, 4, four), "sprites refused");
    spriteTarget = LoadRenderTexture(32, 32);
    sweep("RblDrawSpriteBuffer (variant compile)", runDrawSprites, cleanDrawSprites);
    UnloadRenderTexture(spriteTarget);
    RblUnloadSpriteBuffer(&drawnBuffer);
    RblUnloadAtlas(&spriteAtlas);
    sweep("RblLoadShadowMap", runLoadShadow, cleanShadow);
    sweep("RblLoadGBuffer", runLoadGBuffer, cleanGBuffer);
    for (litVariant = 0; litVariant < 1; litVariant++) sweep("RblLoadLitShader", runLoadLit, cleanLit);
    // The scene keeps its arrays until RblClose; a scene larger than their capacity grows them. A
    // failed growth keeps the previous scene (and its arrays) whole.
    for (long n = 0; n < 16; n++)
    {
        RblScene small; memset(&small, 0, sizeof(small));
        small.lights = sceneLights; small.lightCount = 1;
        RT_CHECK(RblSetScene(&small), "one-light scene refused");
        int capacity = rbl__state.scene.lightCapacity;
        long liveBefore = allocLive;
        failAfter(n);
        bool ok = runSetScene();
        bool hit = injected();
        allocFailAt = -1;
        if (!hit)
        {
            RT_CHECK(ok && (rbl__state.scene.lightCount == 40), "40-light scene refused without a failure");
            printf("    %-34s %3ld failing runs swept (growth from %d lights allocates %ld times)\n", "RblSetScene (1 -> 40 lights)", n, capacity, allocCalls);
            break;
        }
        RT_CHECK(!ok && (warnings == 1) && (rbl__state.scene.lightCount == 1) && (rbl__state.scene.lightCapacity == capacity),
                 "scene growth failure %ld: ok %d, %d lines, %d lights kept", n, ok, warnings, rbl__state.scene.lightCount);
        RT_CHECK(allocLive == liveBefore, "scene growth failure %ld: %ld allocations leaked", n, allocLive - liveBefore);
        failuresSwept++;
        if (capacity >= 40) { RT_CHECK(false, "scene capacity %d already holds 40 lights: growth not exercised", capacity); break; }
    }
    sweep("RblPackMaterial (all maps, mips)", runPack, cleanPack);
    sweep("RblGenNormalMapFromHeight", runGenNormal, cleanGen);
    sweep("RblGenHeightFromLuminance", runGenHeight, cleanGen);
    sweep("RblGenOcclusionFromHeight", runGenOcclusion, cleanGen);
    // Atlases: every fixture format from memory (JSON nodes, names, frames, tags, slices, polygons,
    // multi-texture pages, libGDX grouping) and the file loader (the multipack: two files, two
    // sheets; Phaser 3 pages: sheet and normal-sheet paths found and kept)
    static const char *fixtures[9] = { "texturepacker/hash.json", "texturepacker/array.json", "aseprite/tags.json", "libgdx/old.atlas", "libgdx/new.atlas",
        "texturepacker/phaser3.json", "texturepacker/polygon.json", "aseprite/slices.json", "libgdx/rotations.atlas" };
    for (int i = 0; i < 9; i++)
    {
        char path[128];
        snprintf(path, sizeof(path), "tests/fuzz/corpus/%s", fixtures[i]);
        unsigned char *data = LoadFileData(path, &atlasSize);
        atlasText = (char *)data;
        RT_CHECK(data != NULL, "%s missing", path);
        if (data == NULL) continue;
        char what[96];
        snprintf(what, sizeof(what), "RblLoadAtlasFromMemory (%s)", strrchr(fixtures[i], '/') + 1);
        sweep(what, runLoadAtlasMemory, cleanAtlas);
        UnloadFileData(data);
    }
    RT_CHECK(rtAtlasFixtures() != NULL, "fixtures");
    atlasFile = "build/tests/atlas/texturepacker/multi-0.json";
    sweep("RblLoadAtlas (multipack)", runLoadAtlasFile, cleanAtlas);
    atlasFile = "build/tests/atlas/texturepacker/phaser3.json";
    sweep("RblLoadAtlas (Phaser 3 pages, normal sheets)", runLoadAtlasFile, cleanAtlas);
    printf("    %d failing runs in all\n", failuresSwept);
    UnloadImage(packSource.albedo); UnloadImage(packSource.normal); UnloadImage(packSource.specular);
    UnloadImage(packSource.occlusion); UnloadImage(packSource.emissive); UnloadImage(heightImage);
}

// Growth inside a frame: a batch or instance buffer that cannot grow keeps what it holds, skips the
// rest with one line, draws, and unloads without a leak
static void test_alloc_growth_failures_keep_objects_valid(void)
{
    Texture2D white = solidTexture(WHITE);
    Material m = LoadMaterialDefault();
    m.shader = RblLoadLitShader((RblLitShaderDesc){ 0 });
    m.maps[MATERIAL_MAP_ALBEDO].texture = white;
    RblLitShaderDesc idesc; memset(&idesc, 0, sizeof(idesc)); idesc.instanced = true;
    Material mi = m;
    mi.shader = RblLoadLitShader(idesc);
    RenderTexture2D rt = LoadRenderTexture(TARGET, TARGET);
    BeginTextureMode(rt);
    BeginMode3D(frontCamera());
    RblBillboard bb; memset(&bb, 0, sizeof(bb)); bb.size = (Vector2){ 1, 1 };
    RblBatch warm = RblLoadBatch(1);        // the live-object list exists from here on (freed by RblClose)
    RblBeginBatch(&warm, frontCamera());    // and the lit program's batch-record variant (held by the program)
    RblBatchAdd(&warm, m, &bb);
    RblEndBatch(&warm);
    RblUnloadBatch(&warm);
    for (long n = 0; n < 64; n++)
    {
        long liveBefore = allocLive;
        RblBatch b = RblLoadBatch(1);
        RblBeginBatch(&b, frontCamera());
        failAfter(n);
        int added = 0;
        for (int i = 0; i < 40; i++) added += RblBatchAdd(&b, m, &bb);
        RblEndBatch(&b);        // the GPU side grows here: its index allocation is swept too
        bool hit = injected();
        allocFailAt = -1;
        RT_CHECK(RblIsBatchValid(b) && (b.count == added), "batch growth failure %ld: invalid batch or count %d vs %d added", n, b.count, added);
        if (hit) RT_CHECK(warnings == 1, "batch growth failure %ld: %d lines, %d added (last: %s)", n, warnings, added, lastWarning);
        RblUnloadBatch(&b);
        RT_CHECK(allocLive == liveBefore, "batch growth failure %ld: %ld allocations leaked", n, allocLive - liveBefore);
        if (!hit) { printf("    batch growth: %ld failing runs swept\n", n); break; }
    }
    // A lit program's batch-record variant is compiled at its first batch draw: where that fails, the
    // batch draws from vertices (every billboard drawn, no line), and a later draw makes the variant
    for (long n = 0; rtGlsl3() && (n < 64); n++)
    {
        long liveBefore = allocLive;
        Material fresh = m;
        fresh.shader = RblLoadLitShader((RblLitShaderDesc){ .maxLights = 2 });
        RblBatch b = RblLoadBatch(8);
        RblBeginBatch(&b, frontCamera());
        for (int i = 0; i < 8; i++) RblBatchAdd(&b, fresh, &bb);
        failAfter(n);
        RblEndBatch(&b);
        bool hit = injected();
        allocFailAt = -1;
        rbl__Program *p = rbl__findLit(fresh.shader.id);
        RT_CHECK(RblIsBatchValid(b) && (b.count == 8) && (warnings == 0), "variant failure %ld: batch invalid, count %d or %d lines (%s)", n, b.count, warnings, lastWarning);
        if (hit) RT_CHECK((p != NULL) && (p->recordVariant == NULL) && !b.state->records, "variant failure %ld: %s", n, (p == NULL)? "program gone" : "the batch kept records without a variant");
        else RT_CHECK((p != NULL) && (p->recordVariant != NULL), "variant failure %ld: no variant made without a failure", n);
        RblUnloadBatch(&b);
        RblUnloadLitShader(&fresh.shader);
        RT_CHECK(allocLive == liveBefore, "variant failure %ld: %ld allocations leaked", n, allocLive - liveBefore);
        if (!hit) { printf("    batch-record variant: %ld failing runs swept\n", n); break; }
    }
    RblInstance in[40];
    memset(in, 0, sizeof(in));
    for (int i = 0; i < 40; i++) in[i].size = (Vector2){ 1, 1 };
    RblInstancedDesc d; memset(&d, 0, sizeof(d));
    for (long n = 0; n < 64; n++)
    {
        long liveBefore = allocLive;
        RblInstanceBuffer b = RblLoadInstanceBuffer(1);
        failAfter(n);
        int drawn = RblDrawInstanced(&b, frontCamera(), mi, d, in, 40);
        bool hit = injected();
        allocFailAt = -1;
        RT_CHECK(RblIsInstanceBufferValid(b), "instance growth failure %ld: buffer invalid", n);
        if (hit) RT_CHECK((drawn == 0) && (warnings == 1), "instance growth failure %ld: drawn %d, %d lines", n, drawn, warnings);
        else RT_CHECK(drawn == 40, "instance draw without failure drew %d", drawn);
        RT_CHECK(RblDrawInstanced(&b, frontCamera(), mi, d, in, 1) == 1, "instance buffer %ld unusable after a failed growth", n);
        RblUnloadInstanceBuffer(&b);
        RT_CHECK(allocLive == liveBefore, "instance growth failure %ld: %ld allocations leaked", n, allocLive - liveBefore);
        if (!hit) { printf("    instance growth: %ld failing runs swept\n", n); break; }
    }
    EndMode3D();
    EndTextureMode();
    UnloadRenderTexture(rt);
    RblUnloadLitShader(&mi.shader);
    UnloadMaterial(m);
    UnloadTexture(white);
}

// The optional fade streams: a batch's (allocated at its first faded billboard, sorted copy at its
// first sorted end) and an instance buffer's compacted/sorted fades. A failure skips with one line
// (batch: the billboard; instanced: the draw), the object stays valid and unloads without a leak
static void test_alloc_fade_streams_fail_cleanly_and_keep_objects_valid(void)
{
    Texture2D white = solidTexture(WHITE);
    RblLitShaderDesc desc; memset(&desc, 0, sizeof(desc)); desc.crossFade = true;
    Material m = LoadMaterialDefault();
    m.shader = RblLoadLitShader(desc);
    m.maps[MATERIAL_MAP_ALBEDO].texture = white;
    desc.instanced = true;
    Material mi = m;
    mi.shader = RblLoadLitShader(desc);
    RenderTexture2D rt = LoadRenderTexture(TARGET, TARGET);
    BeginTextureMode(rt);
    BeginMode3D(frontCamera());
    RblBillboard bb; memset(&bb, 0, sizeof(bb)); bb.size = (Vector2){ 1, 1 };
    RblBatch warm = RblLoadBatch(1);        // the live-object list exists from here on (freed by RblClose)
    RblBeginBatch(&warm, frontCamera());    // and the lit program's batch-record variant (held by the program)
    RblBatchAdd(&warm, m, &bb);
    RblEndBatch(&warm);
    RblUnloadBatch(&warm);
    for (int sorted = 0; sorted < 2; sorted++)
        for (long n = 0; n < 64; n++)
        {
            long liveBefore = allocLive;
            RblBatch b = RblLoadBatch(1);
            b.sort = sorted? RBL_SORT_BACK_TO_FRONT : RBL_SORT_NONE;
            RblBeginBatch(&b, frontCamera());
            failAfter(n);
            int added = 0;
            for (int i = 0; i < 40; i++)
            {
                RblBillboard x = bb;
                x.position.z = -0.01f*i;
                RblFade f; memset(&f, 0, sizeof(f)); f.weight = 0.5f;
                added += (i >= 3)? RblBatchAddFade(&b, m, &x, &f) : RblBatchAdd(&b, m, &x);   // the stream starts at the fourth billboard
            }
            RblEndBatch(&b);
            bool hit = injected();
            allocFailAt = -1;
            RT_CHECK(RblIsBatchValid(b) && (b.count == added), "fade batch failure %ld: invalid batch or count %d vs %d added", n, b.count, added);
            if (hit) RT_CHECK(warnings == 1, "fade batch failure %ld: %d lines, %d added (last: %s)", n, warnings, added, lastWarning);
            RblBeginBatch(&b, frontCamera());
            RblFade half; memset(&half, 0, sizeof(half)); half.weight = 0.5f;
            RT_CHECK(RblBatchAddFade(&b, m, &bb, &half), "fade batch %ld unusable after the failure", n);
            RblEndBatch(&b);
            RblUnloadBatch(&b);
            RT_CHECK(allocLive == liveBefore, "fade batch failure %ld: %ld allocations leaked", n, allocLive - liveBefore);
            if (!hit) { printf("    fade batch (%s): %ld failing runs swept\n", sorted? "sorted" : "unsorted", n); break; }
        }
    RblInstance in[40];
    RblFade fades[40];
    memset(in, 0, sizeof(in)); memset(fades, 0, sizeof(fades));
    for (int i = 0; i < 40; i++) { in[i].size = (Vector2){ 1, 1 }; in[i].position.z = -0.01f*i; fades[i].weight = 0.5f; }
    fades[7].weight = NAN;          // one bad fade: the compacted copy is made too
    RblInstancedDesc d; memset(&d, 0, sizeof(d));
    d.fades = fades;
    for (int sorted = 0; sorted < 2; sorted++)
        for (long n = 0; n < 64; n++)
        {
            long liveBefore = allocLive;
            RblInstanceBuffer b = RblLoadInstanceBuffer(1);
            d.sort = sorted? RBL_SORT_BACK_TO_FRONT : RBL_SORT_NONE;
            failAfter(n);
            int drawn = RblDrawInstanced(&b, frontCamera(), mi, d, in, 40);
            bool hit = injected();
            allocFailAt = -1;
            RT_CHECK(RblIsInstanceBufferValid(b), "fade instance failure %ld: buffer invalid", n);
            // the skipped instance logs its own line; a failed allocation refuses the draw (or, sorting, draws unsorted) with one more
            if (hit) RT_CHECK(((drawn == 0) && (warnings == 1)) || (sorted && (drawn == 39) && (warnings == 2)), "fade instance failure %ld: drawn %d, %d lines (last: %s)", n, drawn, warnings, lastWarning);
            else RT_CHECK(drawn == 39 && warnings == 1, "fade instance draw without failure drew %d, %d lines", drawn, warnings);
            RT_CHECK(RblDrawInstanced(&b, frontCamera(), mi, d, in, 1) == 1, "fade instance buffer %ld unusable after a failure", n);
            RblUnloadInstanceBuffer(&b);
            RT_CHECK(allocLive == liveBefore, "fade instance failure %ld: %ld allocations leaked", n, allocLive - liveBefore);
            if (!hit) { printf("    fade instances (%s): %ld failing runs swept\n", sorted? "sorted" : "unsorted", n); break; }
        }
    EndMode3D();
    EndTextureMode();
    UnloadRenderTexture(rt);
    RblUnloadLitShader(&mi.shader);
    UnloadMaterial(m);
    UnloadTexture(white);
}

// After every object is unloaded, RblClose returns every allocation of the header's
static void test_alloc_close_releases_everything(void)
{
    RblClose();
    RT_CHECK(allocLive == 0, "after RblClose %ld of the header's allocations are still live", allocLive);
}

int main(int argc, char **argv)
{
    static const RtTest tests[] = {
        RT_TEST(test_alloc_every_loading_path_fails_cleanly_at_every_allocation),
        RT_TEST(test_alloc_growth_failures_keep_objects_valid),
        RT_TEST(test_alloc_fade_streams_fail_cleanly_and_keep_objects_valid),
        RT_TEST(test_alloc_close_releases_everything),
    };
    const char *backend = rtInitContext(256, 256);
    if (backend == NULL) { printf("alloc: 0 passed, 1 failed\n"); return 1; }
    SetTraceLogLevel(LOG_WARNING);
    SetTraceLogCallback(countingLog);
    return rtRun("alloc", tests, (int)(sizeof(tests)/sizeof(tests[0])), argc, argv);
}
