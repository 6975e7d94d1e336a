// Teardown in every order a program produces: the caller's unloads (the header's and raylib's own),
// RblClose and raylib's CloseWindow in all six orders, in C with explicit calls and in C++ with RAII
// holders destroyed in reverse order of declaration. Each order runs in its own process with a real
// raylib window (make test runs it under xvfb-run). Every order must: not crash, log no "RBL:"
// warning, make no GL call from the header after CloseWindow (rlgl's GL entry points are wrapped and
// counted while a header function runs, and the header's own glIs*/glGetUniformfv pointers too), and
// leave none of the header's allocations live at the end.
// Built twice: as C99 (test_teardown) and as C++11 (test_teardown_cpp, adds the RAII orders).
#define RBL_MALLOC(sz)       tdMalloc(sz)
#define RBL_CALLOC(n, sz)    tdCalloc(n, sz)
#define RBL_REALLOC(p, sz)   tdRealloc(p, sz)
#define RBL_FREE(p)          tdFree(p)
#include <stdlib.h>
#include <stdio.h>
#include <string.h>
#include <stdarg.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

// The header's allocations, counted (a live count of 0 at the end: nothing leaked)
static long tdLive = 0;
static void *tdMalloc(size_t n) { void *p = malloc(n); if (p != NULL) tdLive++; return p; }
static void *tdCalloc(size_t n, size_t s) { void *p = calloc(n, s); if (p != NULL) tdLive++; return p; }
static void *tdRealloc(void *p, size_t n) { void *q = realloc(p, n); if ((p == NULL) && (q != NULL)) tdLive++; return q; }
static void tdFree(void *p) { if (p != NULL) tdLive--; free(p); }

#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "rlgl.h"

// ---- GL calls made by the header after the window closed ---------------------------------------
static int tdInHeader = 0;          // inside a header call (the test brackets them)
static int tdWindowClosed = 0;
static int tdLateCalls = 0;         // GL calls from the header after CloseWindow
static const char *tdLateName = "";
#define TD_NOTE(name) do { if (tdInHeader && tdWindowClosed) { tdLateCalls++; tdLateName = name; } } while (0)

// rlgl calls GL through glad's pointers (globals of libraylib.a): the ones the header's unload, pass
// and close paths reach are wrapped
typedef unsigned int GLenumT;
#define TD_WRAP1(name, T1) \
    extern void (*glad_##name)(T1); static void (*td_##name)(T1); \
    static void tdw_##name(T1 a) { TD_NOTE(#name); td_##name(a); }
#define TD_WRAP2(name, T1, T2) \
    extern void (*glad_##name)(T1, T2); static void (*td_##name)(T1, T2); \
    static void tdw_##name(T1 a, T2 b) { TD_NOTE(#name); td_##name(a, b); }
#define TD_WRAP4(name, T1, T2, T3, T4) \
    extern void (*glad_##name)(T1, T2, T3, T4); static void (*td_##name)(T1, T2, T3, T4); \
    static void tdw_##name(T1 a, T2 b, T3 c, T4 d) { TD_NOTE(#name); td_##name(a, b, c, d); }
#if defined(__cplusplus)
extern "C" {
#endif
TD_WRAP1(glDeleteProgram, unsigned int)
TD_WRAP2(glDeleteBuffers, int, const unsigned int *)
TD_WRAP2(glDeleteVertexArrays, int, const unsigned int *)
TD_WRAP2(glDeleteTextures, int, const unsigned int *)
TD_WRAP2(glDeleteFramebuffers, int, const unsigned int *)
TD_WRAP2(glDeleteRenderbuffers, int, const unsigned int *)
TD_WRAP2(glBindFramebuffer, GLenumT, unsigned int)
TD_WRAP1(glBindVertexArray, unsigned int)
TD_WRAP2(glBindBuffer, GLenumT, unsigned int)
TD_WRAP1(glUseProgram, unsigned int)
TD_WRAP2(glBindTexture, GLenumT, unsigned int)
TD_WRAP1(glActiveTexture, GLenumT)
extern int (*glad_glGetUniformLocation)(unsigned int, const char *);
static int (*td_glGetUniformLocation)(unsigned int, const char *);
static int tdw_glGetUniformLocation(unsigned int a, const char *b) { TD_NOTE("glGetUniformLocation"); return td_glGetUniformLocation(a, b); }
TD_WRAP4(glGetFramebufferAttachmentParameteriv, GLenumT, GLenumT, GLenumT, int *)
TD_WRAP4(glViewport, int, int, int, int)
#if defined(__cplusplus)
}
#endif
#define TD_HOOK(name) do { td_##name = glad_##name; glad_##name = tdw_##name; } while (0)
static void tdHookGl(void)
{
    TD_HOOK(glDeleteProgram); TD_HOOK(glDeleteBuffers); TD_HOOK(glDeleteVertexArrays); TD_HOOK(glDeleteTextures);
    TD_HOOK(glDeleteFramebuffers); TD_HOOK(glDeleteRenderbuffers); TD_HOOK(glBindFramebuffer); TD_HOOK(glBindVertexArray);
    TD_HOOK(glBindBuffer); TD_HOOK(glUseProgram); TD_HOOK(glBindTexture); TD_HOOK(glActiveTexture);
    TD_HOOK(glGetUniformLocation); TD_HOOK(glGetFramebufferAttachmentParameteriv); TD_HOOK(glViewport);
}
// The header's own GL pointers (through raylib's loader, not glad): any call after the window closed counts
static unsigned char tdIsName(unsigned int name) { (void)name; TD_NOTE("glIs* (header's own)"); return 1; }
static void tdGetUniformfv(unsigned int p, int l, float *v) { (void)p; (void)l; TD_NOTE("glGetUniformfv (header's own)"); for (int i = 0; i < 16; i++) v[i] = 0.0f; }
static void tdHookHeaderProcs(void)
{
    // Once the window is gone no call may reach them: stubs that count (and never touch GL)
    rbl__GlIsName is = tdIsName;
    rbl__GlGetUniformfv get = tdGetUniformfv;
    for (int i = 0; i < RBL__GL_QUERIES; i++) if (rbl__state.glIs[i] != NULL) memcpy(&rbl__state.glIs[i], &is, sizeof(is));
    if (rbl__state.glGetUniformfv != NULL) memcpy(&rbl__state.glGetUniformfv, &get, sizeof(get));
}
#define H(call) do { tdInHeader++; call; tdInHeader--; } while (0)

// ---- the header's warnings ----------------------------------------------------------------------
static int tdWarnings = 0;
static char tdLastWarning[512];
static void tdLog(int level, const char *text, va_list args)
{
    char line[512];
    vsnprintf(line, sizeof(line), text, args);
    if ((level >= LOG_WARNING) && (strncmp(line, "RBL:", 4) == 0)) { tdWarnings++; memcpy(tdLastWarning, line, sizeof(line)); }
}

// ---- what a small game holds ----------------------------------------------------------------------
typedef struct Held {
    Material viaUnloadMaterial;     // its lit program released by raylib's UnloadMaterial
    Shader viaRbl;                  // released by RblUnloadLitShader
    Material viaRblMaterial;        // holds viaRbl (maps freed by the caller)
    Shader instanced;
    RblBatch batch;
    RblInstanceBuffer instances;
    RblShadowMap shadow;
    RblGBuffer gbuffer;
    Model model;                    // raylib's own Model, drawn by RblDrawModel
    Texture2D white;
} Held;

static RblLitShaderDesc tdDesc(bool instanced, bool deferred)
{
    RblLitShaderDesc d;
    memset(&d, 0, sizeof(d));
    d.maxLights = 2;
    d.instanced = instanced;
    d.deferred = deferred;
    d.shading.shadowMaps = 1;
    return d;
}

static void tdWindow(void)
{
    SetTraceLogLevel(LOG_WARNING);
    SetTraceLogCallback(tdLog);
    SetConfigFlags(FLAG_WINDOW_HIDDEN);
    InitWindow(160, 120, "rbillboard_lit teardown");
    tdHookGl();
}

static void tdLoad(Held *h)
{
    memset(h, 0, sizeof(*h));
    Image img = GenImageColor(4, 4, WHITE);
    h->white = LoadTextureFromImage(img);
    UnloadImage(img);
    H(h->viaUnloadMaterial = LoadMaterialDefault());
    H(h->viaUnloadMaterial.shader = RblLoadLitShader(tdDesc(false, false)));
    H(h->viaRbl = RblLoadLitShader(tdDesc(false, false)));
    h->viaRblMaterial = LoadMaterialDefault();
    h->viaRblMaterial.shader = h->viaRbl;
    h->viaRblMaterial.maps[MATERIAL_MAP_ALBEDO].texture = h->white;
    H(h->instanced = RblLoadLitShader(tdDesc(true, false)));
    H(h->batch = RblLoadBatch(16));
    H(h->instances = RblLoadInstanceBuffer(16));
    RblShadowDesc sd; memset(&sd, 0, sizeof(sd)); sd.size = 64;
    H(h->shadow = RblLoadShadowMap(sd));
    RblGBufferDesc gd; memset(&gd, 0, sizeof(gd));
    H(h->gbuffer = RblLoadGBuffer(gd));
    h->model = LoadModelFromMesh(GenMeshCube(1, 1, 1));
    h->model.materials[0].shader = h->viaRbl;
}

// One frame using everything: a shadow pass, the scene, batched, immediate, instanced and Model
// draws, a geometry pass with its lights and resolve
static void tdFrame(Held *h)
{
    Camera3D cam;
    memset(&cam, 0, sizeof(cam));
    cam.position = CLITERAL(Vector3){ 0.0f, 1.0f, 5.0f }; cam.up = CLITERAL(Vector3){ 0.0f, 1.0f, 0.0f }; cam.fovy = 45.0f;
    RblLight sun;
    memset(&sun, 0, sizeof(sun));
    sun.type = RBL_LIGHT_DIRECTIONAL; sun.direction = CLITERAL(Vector3){ 0.3f, -1.0f, -0.2f }; sun.color = WHITE; sun.intensity = 2.0f;
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = &sun; scene.lightCount = 1; scene.ambient = DARKGRAY;
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.size = CLITERAL(Vector2){ 1.0f, 1.0f };
    RblInstance in;
    memset(&in, 0, sizeof(in));
    in.size = CLITERAL(Vector2){ 1.0f, 1.0f };
    Material im = h->viaRblMaterial;
    im.shader = h->instanced;
    RblInstancedDesc idesc;
    memset(&idesc, 0, sizeof(idesc));
    bool cast;
    H(cast = RblBeginShadowMap(&h->shadow, &scene, 0, CLITERAL(Vector3){ 0, 0, 0 }, 4.0f));
    if (cast) { H(RblDrawBillboard(cam, h->viaRblMaterial, b)); H(RblEndShadowMap(&h->shadow)); scene.shadowMaps = &h->shadow; scene.shadowMapCount = 1; }
    H(RblSetScene(&scene));
    BeginDrawing();
    ClearBackground(BLACK);
    BeginMode3D(cam);
    H(RblBeginBatch(&h->batch, cam));
    H(RblBatchAdd(&h->batch, h->viaRblMaterial, &b));
    H(RblBatchAdd(&h->batch, h->viaUnloadMaterial, &b));
    H(RblEndBatch(&h->batch));
    H(RblDrawBillboard(cam, h->viaUnloadMaterial, b));
    H(RblDrawInstanced(&h->instances, cam, im, idesc, &in, 1));
    H(RblDrawModel(h->model, CLITERAL(Vector3){ 1, 0, 0 }, 0.5f, WHITE));
    EndMode3D();
    EndDrawing();
}

// The caller's unloads, the header's and raylib's mixed as games write them
static void tdUnloadObjects(Held *h)
{
    h->viaUnloadMaterial.maps[MATERIAL_MAP_ALBEDO].texture.id = 0;
    UnloadMaterial(h->viaUnloadMaterial);                 // raylib: its lit program and maps
    H(RblUnloadLitShader(&h->viaRbl));
    H(RblUnloadLitShader(&h->instanced));
    MemFree(h->viaRblMaterial.maps);
    H(RblUnloadBatch(&h->batch));
    H(RblUnloadInstanceBuffer(&h->instances));
    H(RblUnloadShadowMap(&h->shadow));
    H(RblUnloadGBuffer(&h->gbuffer));
    Shader none;
    memset(&none, 0, sizeof(none));
    h->model.materials[0].shader = none;        // raylib's UnloadModel leaves shaders to their owner
    UnloadModel(h->model);
    UnloadTexture(h->white);
}

static void tdClose(void) { H(RblClose()); }
static void tdCloseWindow(void) { CloseWindow(); tdWindowClosed = 1; tdHookHeaderProcs(); }

// The verdict of one order (in its child): 0 = every check held
static int tdVerdict(const char *order)
{
    int failed = 0;
    if (tdWarnings != 0) { printf("    %s: %d RBL warning(s), last: %s\n", order, tdWarnings, tdLastWarning); failed = 1; }
    if (tdLateCalls != 0) { printf("    %s: %d GL call(s) from the header after CloseWindow (last %s)\n", order, tdLateCalls, tdLateName); failed = 1; }
    if (tdLive != 0) { printf("    %s: %ld of the header's allocations still live\n", order, tdLive); failed = 1; }
    return failed;
}

// C: the three steps (O = the caller's unloads, C = RblClose, W = CloseWindow) in one order
static int tdRunExplicit(const char *order)
{
    Held h;
    tdWindow();
    tdLoad(&h);
    tdFrame(&h);
    tdFrame(&h);
    for (const char *c = order; *c != 0; c++)
    {
        if (*c == 'O') tdUnloadObjects(&h);
        else if (*c == 'C') tdClose();
        else tdCloseWindow();
    }
    return tdVerdict(order);
}

#if defined(__cplusplus)
// C++: holders whose destructors run in reverse order of declaration, as raylib-cpp's do
struct TdWindow { TdWindow() { tdWindow(); } ~TdWindow() { tdCloseWindow(); } };
struct TdModule { ~TdModule() { tdClose(); } };
struct TdObjects {
    Held h;
    bool loaded = false;
    void load() { tdLoad(&h); loaded = true; tdFrame(&h); tdFrame(&h); }
    ~TdObjects() { if (loaded) tdUnloadObjects(&h); }
};
template <class T> static TdObjects *tdObjectsOf(T &) { return nullptr; }
static TdObjects *tdObjectsOf(TdObjects &t) { return &t; }
template <class A, class B, class C> static void tdScope(void)
{
    A a; B b; C c;                      // destroyed c, b, a
    TdObjects *o[3] = { tdObjectsOf(a), tdObjectsOf(b), tdObjectsOf(c) };
    for (int i = 0; i < 3; i++) if (o[i] != nullptr) o[i]->load();
}
// The window must exist before loading: declared first or not, it is constructed by then (its
// constructor runs in declaration order; objects load after every constructor)
static int tdRunRaii(int which)
{
    switch (which)
    {
        case 0: tdScope<TdWindow, TdModule, TdObjects>(); break;     // unload, close, close window
        case 1: tdScope<TdWindow, TdObjects, TdModule>(); break;     // close, unload, close window
        case 2: tdScope<TdModule, TdWindow, TdObjects>(); break;     // unload, close window, close
        case 3: tdScope<TdObjects, TdWindow, TdModule>(); break;     // close, close window, unload
        case 4: tdScope<TdModule, TdObjects, TdWindow>(); break;     // close window, unload, close
        default: tdScope<TdObjects, TdModule, TdWindow>(); break;    // close window, close, unload
    }
    static const char *names[6] = { "RAII W,M,O", "RAII W,O,M", "RAII M,W,O", "RAII O,W,M", "RAII M,O,W", "RAII O,M,W" };
    return tdVerdict(names[which]);
}
#endif

int main(void)
{
    static const char *orders[6] = { "OCW", "COW", "OWC", "CWO", "WOC", "WCO" };
    static const char *said[6] = { "unload, RblClose, CloseWindow", "RblClose, unload, CloseWindow", "unload, CloseWindow, RblClose",
                                   "RblClose, CloseWindow, unload", "CloseWindow, unload, RblClose", "CloseWindow, RblClose, unload" };
#if defined(__cplusplus)
    const int runs = 12;
    const char *suite = "teardown_cpp";
#else
    const int runs = 6;
    const char *suite = "teardown";
#endif
    int passed = 0, failed = 0;
    for (int i = 0; i < runs; i++)
    {
        fflush(stdout);
        pid_t pid = fork();
        if (pid == 0)
        {
            alarm(120);
#if defined(__cplusplus)
            _exit((i < 6)? tdRunExplicit(orders[i]) : tdRunRaii(i - 6));
#else
            _exit(tdRunExplicit(orders[i]));
#endif
        }
        int status = 0;
        waitpid(pid, &status, 0);
        bool ok = WIFEXITED(status) && (WEXITSTATUS(status) == 0);
        const char *why = WIFSIGNALED(status)? " (crashed)" : "";
        if (i < 6) printf("  %s  %s%s\n", ok? "ok  " : "FAIL", said[i], why);
        else printf("  %s  C++ holders destroyed in reverse order, case %d%s\n", ok? "ok  " : "FAIL", i - 6, why);
        if (ok) passed++; else failed++;
    }
    printf("%s: %d passed, %d failed\n", suite, passed, failed);
    return (failed == 0)? 0 : 1;
}
