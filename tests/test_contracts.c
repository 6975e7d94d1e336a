// Contract suite: every public function of the header against every class of bad input (NULL, zero
// and never-loaded objects, stale and double unloads, Begin/End imbalance and nesting, mismatched
// variants, huge and negative counts and sizes, NaN/Inf/overflowing floats in every float field).
// Each case runs in its own process (fork) under ASan+UBSan with its own headless context, so a crash
// or hang fails one case, not the run. A refused call must log exactly one "RBL:" warning, return
// failure, and leave the caller's outputs, GL bindings, enable state, viewport and rlgl matrices (and
// the matrix stack depth) as they were; an accepted extreme input must leave only finite values in
// what it wrote. The public functions are read from the header: one without a case fails the suite.
// Built with small limits (RBL_MAX_BATCH_BILLBOARDS etc., see the Makefile) so limits are reached fast.
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "rlgl.h"
#include "raymath.h"
#include "harness.h"
#include "batch_peek.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "gpu_common.h"
#include "skin_rig.h"

// ---- checks -------------------------------------------------------------------------------------
static int caseFailures = 0, caseChecks = 0;
static int raylibErrors = 0;
static void ck(bool ok, const char *fmt, ...)
{
    caseChecks++;
    if (ok) return;
    caseFailures++;
    va_list a;
    va_start(a, fmt);
    printf("      ");
    vprintf(fmt, a);
    printf("\n");
    va_end(a);
    fflush(stdout);
}

// Counts the header's warnings (and rlgl's matrix-stack errors) at LOG_WARNING and above
static int reasonMismatches = 0;      // refusal lines whose text RblGetFailureReason() did not return
static void contractLog(int level, const char *text, va_list args)
{
    char line[512];
    vsnprintf(line, sizeof(line), text, args);
    if (level < LOG_WARNING) return;
    if (strncmp(line, "RBL:", 4) == 0)
    {
        warnings++; memcpy(lastWarning, line, sizeof(line));
        if (strcmp(RblGetFailureReason(), line + 5) != 0) reasonMismatches++;     // the queryable reason is the line
        if (strncmp(text, "RBL: ", 5) != 0) reasonMismatches++;     // a callback filtering the unformatted text sees it too
    }
    else if (strstr(line, "Matrix stack overflow") != NULL) raylibErrors++;
}

// ---- the caller's state a refused call must not change --------------------------------------------
typedef void (*GlGetIntegerv)(unsigned int, int *);
typedef unsigned char (*GlIsEnabled)(unsigned int);
typedef void (*GlGetBooleanv)(unsigned int, unsigned char *);
typedef void (*GlActiveTexture)(unsigned int);
static GlGetIntegerv glGetI;
static GlIsEnabled glIsOn;
static GlGetBooleanv glGetB;
static GlActiveTexture glActive;

typedef struct Snap {
    int ints[9];            // draw/read framebuffer, program, vertex array, array buffer, active texture, viewport
    int textures[16];       // 2D texture bound on units 0..15
    unsigned char enabled[5];   // depth test, blend, cull face, scissor, depth write
    Matrix modelview, projection;
} Snap;

static void snapTake(Snap *s)
{
    memset(s, 0, sizeof(*s));
    static const unsigned int names[6] = { 0x8CA6, 0x8CAA, 0x8B8D, 0x85B5, 0x8894, 0x84E0 };
    for (int i = 0; i < 6; i++) glGetI(names[i], &s->ints[i]);
    int vp[4]; glGetI(0x0BA2, vp);
    s->ints[6] = vp[0]*7919 + vp[1]; s->ints[7] = vp[2]; s->ints[8] = vp[3];
    for (int u = 0; u < 16; u++) { glActive(0x84C0 + (unsigned int)u); glGetI(0x8069, &s->textures[u]); }
    glActive((unsigned int)s->ints[5]);
    static const unsigned int caps[4] = { 0x0B71, 0x0BE2, 0x0B44, 0x0C11 };
    for (int i = 0; i < 4; i++) s->enabled[i] = glIsOn(caps[i]);
    glGetB(0x0B72, &s->enabled[4]);
    s->modelview = rlGetMatrixModelview();
    s->projection = rlGetMatrixProjection();
}

static void snapCompare(const Snap *a, const Snap *b, const char *what)
{
    static const char *intNames[9] = { "draw framebuffer", "read framebuffer", "program", "vertex array", "array buffer", "active texture", "viewport origin", "viewport width", "viewport height" };
    for (int i = 0; i < 9; i++) ck(a->ints[i] == b->ints[i], "%s: %s changed (%d -> %d)", what, intNames[i], a->ints[i], b->ints[i]);
    for (int u = 0; u < 16; u++) ck(a->textures[u] == b->textures[u], "%s: texture unit %d binding changed (%d -> %d)", what, u, a->textures[u], b->textures[u]);
    static const char *capNames[5] = { "depth test", "blend", "cull face", "scissor", "depth write" };
    for (int i = 0; i < 5; i++) ck(a->enabled[i] == b->enabled[i], "%s: %s changed (%d -> %d)", what, capNames[i], a->enabled[i], b->enabled[i]);
    ck(memcmp(&a->modelview, &b->modelview, sizeof(Matrix)) == 0, "%s: rlgl modelview changed", what);
    ck(memcmp(&a->projection, &b->projection, sizeof(Matrix)) == 0, "%s: rlgl projection changed", what);
}

static Snap before;
static void refusedBegin(void) { rlDrawRenderBatchActive(); snapTake(&before); warnings = 0; lastWarning[0] = 0; }
static void refusedEnd(bool ok, const char *what)
{
    Snap after;
    snapTake(&after);
    ck(!ok, "%s: returned success", what);
    ck(warnings == 1, "%s: %d RBL log lines, expected 1 (last: %s)", what, warnings, lastWarning);
    ck((reasonMismatches == 0) && ((warnings == 0) || (strcmp(RblGetFailureReason(), lastWarning + 5) == 0)),
       "%s: RblGetFailureReason() \"%s\" is not the logged line", what, RblGetFailureReason());
    snapCompare(&before, &after, what);
}
// expr yields true on success; V(call) turns a void call into "no success"
#define EXPECT_REFUSED(expr) do { refusedBegin(); bool ok_ = (expr); refusedEnd(ok_, #expr); } while (0)
#define V(call) ((call), false)
// A query or a harmless call: no log line, the stated result
#define EXPECT_QUIET(expr, want) do { warnings = 0; bool r_ = (expr); ck(r_ == (want), "%s: returned %d", #expr, (int)r_); ck(warnings == 0, "%s: %d RBL log lines, expected none (%s)", #expr, warnings, lastWarning); } while (0)

// A GL entry point as a function pointer (ISO C has no object-to-function pointer cast)
#define GL_PROC(var, name) do { void *p_ = rtGlProc(name); memcpy(&(var), &p_, sizeof(p_)); } while (0)

static bool allFinite(const float *f, size_t n) { for (size_t i = 0; i < n; i++) if (!isfinite(f[i])) return false; return true; }

// ---- fixture ------------------------------------------------------------------------------------
static RenderTexture2D target;
static Texture2D white;
static Material material;           // a forward lit material (Lambert, one light slot)
static Shader litShader;

static Camera3D camera(void) { return frontCamera(); }

static RblBillboard billboard(void)
{
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.size = (Vector2){ 1.0f, 1.0f };
    return b;
}

static RblLight pointLight(void)
{
    RblLight l;
    memset(&l, 0, sizeof(l));
    l.position = (Vector3){ 0.0f, 1.0f, 3.0f };
    l.color = WHITE;
    l.intensity = 4.0f;
    return l;
}

static Material litMaterial(RblLitShaderDesc desc)
{
    Material m = LoadMaterialDefault();
    m.shader = RblLoadLitShader(desc);
    m.maps[MATERIAL_MAP_ALBEDO].texture = white;
    return m;
}

static RblLitShaderDesc descOf(int brdf, bool instanced, bool deferred)
{
    RblLitShaderDesc d;
    memset(&d, 0, sizeof(d));
    d.maxLights = 1;
    d.shading.brdf = brdf;
    d.instanced = instanced;
    d.deferred = deferred;
    return d;
}

// The state a user is in mid-frame: a bound render target inside BeginMode3D, one light in the scene
static void fixtureUp(void)
{
    target = LoadRenderTexture(TARGET, TARGET);
    white = solidTexture(WHITE);
    litShader = RblLoadLitShader(descOf(RBL_BRDF_LAMBERT, false, false));
    material = LoadMaterialDefault();
    material.shader = litShader;
    material.maps[MATERIAL_MAP_ALBEDO].texture = white;
    RblLight l = pointLight();
    renderSetLights(&l, 1, DARKGRAY);
    BeginTextureMode(target);
    ClearBackground(BLACK);
    BeginMode3D(camera());
    rlDrawRenderBatchActive();
}

// Float values every float input is tried with: NaN, infinities, and finite values that overflow
static const float badFloats[5] = { NAN, INFINITY, -INFINITY, 3.0e38f, -3.0e38f };

typedef struct Field { const char *name; size_t offset; } Field;
#define FIELD(T, f) { #f, offsetof(T, f) }

static const Field billboardFloats[] = {
    FIELD(RblBillboard, position.x), FIELD(RblBillboard, position.y), FIELD(RblBillboard, position.z),
    FIELD(RblBillboard, size.x), FIELD(RblBillboard, size.y), FIELD(RblBillboard, origin.x), FIELD(RblBillboard, origin.y),
    FIELD(RblBillboard, rotation), FIELD(RblBillboard, source.x), FIELD(RblBillboard, source.y),
    FIELD(RblBillboard, source.width), FIELD(RblBillboard, source.height), FIELD(RblBillboard, up.x), FIELD(RblBillboard, up.y),
    FIELD(RblBillboard, up.z), FIELD(RblBillboard, axis.x), FIELD(RblBillboard, axis.y), FIELD(RblBillboard, axis.z),
    FIELD(RblBillboard, roundness) };
// A cross-fade's floats (RblBatchAddFade, RblDrawBillboardFade)
static const Field fadeFloats[] = {
    FIELD(RblFade, source.x), FIELD(RblFade, source.y), FIELD(RblFade, source.width), FIELD(RblFade, source.height), FIELD(RblFade, weight),
    FIELD(RblFade, clip[0].x), FIELD(RblFade, clip[0].y), FIELD(RblFade, clip[0].width), FIELD(RblFade, clip[0].height),
    FIELD(RblFade, clip[1].x), FIELD(RblFade, clip[1].y), FIELD(RblFade, clip[1].width), FIELD(RblFade, clip[1].height) };
static const Field cameraFloats[] = {
    FIELD(Camera3D, position.x), FIELD(Camera3D, position.y), FIELD(Camera3D, position.z), FIELD(Camera3D, target.x),
    FIELD(Camera3D, target.y), FIELD(Camera3D, target.z), FIELD(Camera3D, up.x), FIELD(Camera3D, up.y), FIELD(Camera3D, up.z),
    FIELD(Camera3D, fovy) };
static const Field lightFloats[] = {
    FIELD(RblLight, position.x), FIELD(RblLight, position.y), FIELD(RblLight, position.z), FIELD(RblLight, intensity),
    FIELD(RblLight, range), FIELD(RblLight, direction.x), FIELD(RblLight, direction.y), FIELD(RblLight, direction.z),
    FIELD(RblLight, innerAngle), FIELD(RblLight, outerAngle), FIELD(RblLight, constant), FIELD(RblLight, linear),
    FIELD(RblLight, quadratic) };
static const Field instancedDescFloats[] = {
    FIELD(RblInstancedDesc, up.x), FIELD(RblInstancedDesc, up.y), FIELD(RblInstancedDesc, up.z), FIELD(RblInstancedDesc, axis.x),
    FIELD(RblInstancedDesc, axis.y), FIELD(RblInstancedDesc, axis.z), FIELD(RblInstancedDesc, roundness) };
static const Field sceneFloats[] = {
    FIELD(RblScene, ambientUp.x), FIELD(RblScene, ambientUp.y), FIELD(RblScene, ambientUp.z), FIELD(RblScene, fog.start),
    FIELD(RblScene, fog.end), FIELD(RblScene, fog.density), FIELD(RblScene, exposure) };
static const Field shadowDescFloats[] = {
    FIELD(RblShadowDesc, constantBias), FIELD(RblShadowDesc, slopeBias), FIELD(RblShadowDesc, normalBias), FIELD(RblShadowDesc, minCastAngle),
    FIELD(RblShadowDesc, cascadeLambda), FIELD(RblShadowDesc, cascadeBlend) };
#define COUNT_OF(a) ((int)(sizeof(a)/sizeof((a)[0])))
#define SET_FIELD(obj, field, value) memcpy((char *)&(obj) + (field).offset, &(value), sizeof(float))

// Every camera field bad: f(camera) must be refused (one line, nothing changed)
#define EVERY_BAD_CAMERA(call) do { \
    for (int fi_ = 0; fi_ < COUNT_OF(cameraFloats); fi_++) for (int vi_ = 0; vi_ < 5; vi_++) { \
        Camera3D cam = camera(); SET_FIELD(cam, cameraFloats[fi_], badFloats[vi_]); \
        EXPECT_REFUSED(call); } \
    Camera3D cam = camera(); cam.fovy = 0.0f; EXPECT_REFUSED(call); \
    cam = camera(); cam.fovy = -45.0f; EXPECT_REFUSED(call); \
    cam = camera(); cam.fovy = 180.0f; EXPECT_REFUSED(call); \
    cam = camera(); cam.projection = 7; EXPECT_REFUSED(call); \
} while (0)

// ---- cases: geometry ------------------------------------------------------------------------------
static void c_frame_bad_camera(void)
{
    for (int fi = 0; fi < COUNT_OF(cameraFloats); fi++) for (int vi = 0; vi < 5; vi++)
    {
        Camera3D cam = camera(); SET_FIELD(cam, cameraFloats[fi], badFloats[vi]);
        warnings = 0;
        RblCameraFrame f = RblGetCameraFrame(cam);
        ck(warnings == 1, "%s = %g: %d log lines", cameraFloats[fi].name, badFloats[vi], warnings);
        ck(allFinite(&f.eye.x, 12), "%s = %g: non-finite frame", cameraFloats[fi].name, badFloats[vi]);
    }
}

static void c_frame_degenerate_cameras_are_fine(void)
{
    Camera3D cams[3] = { camera(), camera(), camera() };
    cams[0].target = cams[0].position;                  // no view direction
    cams[1].up = (Vector3){ 0.0f, 0.0f, -1.0f };        // up along the view
    cams[2].up = (Vector3){ 0.0f, 0.0f, 0.0f };         // zero up
    for (int i = 0; i < 3; i++)
    {
        warnings = 0;
        RblCameraFrame f = RblGetCameraFrame(cams[i]);
        ck(warnings == 0, "degenerate camera %d logged", i);
        ck(allFinite(&f.eye.x, 12) && fabsf(Vector3Length(f.right) - 1.0f) < 1e-5f && fabsf(Vector3DotProduct(f.right, f.up)) < 1e-5f, "degenerate camera %d: frame not orthonormal", i);
    }
}

static void c_vertices_null_and_sizes(void)
{
    RblCameraFrame f = RblGetCameraFrame(camera());
    RblBillboard b = billboard();
    RblVertex out[4], sentinel[4];
    memset(out, 0x5a, sizeof(out)); memcpy(sentinel, out, sizeof(out));
    EXPECT_REFUSED(RblBillboardVertices(NULL, 4, 4, &b, out));
    EXPECT_REFUSED(RblBillboardVertices(&f, 4, 4, NULL, out));
    EXPECT_REFUSED(RblBillboardVertices(&f, 4, 4, &b, NULL));
    EXPECT_REFUSED(RblBillboardVertices(&f, 0, 4, &b, out));
    EXPECT_REFUSED(RblBillboardVertices(&f, 4, -4, &b, out));
    EXPECT_REFUSED(RblBillboardVertices(&f, 2147483647, 4, &b, out));
    b.facing = 9; EXPECT_REFUSED(RblBillboardVertices(&f, 4, 4, &b, out));
    b.facing = -1; EXPECT_REFUSED(RblBillboardVertices(&f, 4, 4, &b, out));
    ck(memcmp(out, sentinel, sizeof(out)) == 0, "refused calls wrote to out");
}

// What a batch draws of a billboard: refused alone for NULLs, a negative capacity, a bad frame or
// billboard and polygon bits no loaded atlas holds (out untouched); a plain billboard's one quad
static void c_quads_null_sizes_and_stale_polygons(void)
{
    RblCameraFrame f = RblGetCameraFrame(camera()), bad = f;
    bad.right.x = NAN;
    RblBillboard b = billboard();
    RblVertex out[4], sentinel[4];
    memset(out, 0x5a, sizeof(out)); memcpy(sentinel, out, sizeof(out));
    EXPECT_REFUSED(RblBillboardQuads(NULL, 4, 4, &b, out, 1) >= 0);
    EXPECT_REFUSED(RblBillboardQuads(&f, 4, 4, NULL, out, 1) >= 0);
    EXPECT_REFUSED(RblBillboardQuads(&f, 4, 4, &b, out, -1) >= 0);
    EXPECT_REFUSED(RblBillboardQuads(&bad, 4, 4, &b, out, 1) >= 0);
    EXPECT_REFUSED(RblBillboardQuads(&f, 0, 4, &b, out, 1) >= 0);
    RblBillboard p = b; p.facing = 9; EXPECT_REFUSED(RblBillboardQuads(&f, 4, 4, &p, out, 1) >= 0);
    p = b; p.size.x = NAN; EXPECT_REFUSED(RblBillboardQuads(&f, 4, 4, &p, out, 1) >= 0);
    p = b; p.flags = 0xFFFFF0u; EXPECT_REFUSED(RblBillboardQuads(&f, 4, 4, &p, out, 1) >= 0);    // no atlas holds that polygon
    ck(memcmp(out, sentinel, sizeof(out)) == 0, "refused calls wrote to out");
    warnings = 0;
    int n = RblBillboardQuads(&f, 4, 4, &b, NULL, 0), m = RblBillboardQuads(&f, 4, 4, &b, out, 1);
    p = b; p.flags = 0x1000000u | 0xFFFFF0u;            // from 2^24 up flags carry no polygon
    int k = RblBillboardQuads(&f, 4, 4, &p, NULL, 0);
    ck((n == 1) && (m == 1) && (k == 1) && (warnings == 0) && allFinite(out[0].position, 3), "plain billboard: %d, %d, %d quads, %d lines", n, m, k, warnings);
}

static void c_vertices_every_float_field(void)
{
    RblCameraFrame f = RblGetCameraFrame(camera());
    for (int facing = 0; facing < 4; facing++)
    for (int fi = 0; fi < COUNT_OF(billboardFloats); fi++) for (int vi = 0; vi < 5; vi++)
    {
        RblBillboard b = billboard(); b.facing = facing; b.roundness = 0.5f;
        SET_FIELD(b, billboardFloats[fi], badFloats[vi]);
        RblVertex out[4], sentinel[4];
        memset(out, 0x5a, sizeof(out)); memcpy(sentinel, out, sizeof(out));
        warnings = 0;
        bool ok = RblBillboardVertices(&f, 64, 64, &b, out);
        if (ok) ck(warnings == 0 && allFinite(out[0].position, 3) && allFinite(out[1].position, 3) &&
                   allFinite(out[2].position, 3) && allFinite(out[3].position, 3) && allFinite(out[0].texcoord, 2) && allFinite(out[2].texcoord, 2) &&
                   allFinite(out[0].normal, 3) && allFinite(out[0].tangent, 4),
                   "facing %d %s = %g accepted with non-finite output or a log line", facing, billboardFloats[fi].name, badFloats[vi]);
        else ck(warnings == 1 && memcmp(out, sentinel, sizeof(out)) == 0, "facing %d %s = %g refused with %d log lines or out written", facing, billboardFloats[fi].name, badFloats[vi], warnings);
    }
    // A finite source rectangle whose far edge overflows
    RblBillboard b = billboard(); b.source = (Rectangle){ 3.0e38f, 0.0f, 3.0e38f, 4.0f };
    RblVertex out[4];
    warnings = 0;
    bool ok = RblBillboardVertices(&f, 64, 64, &b, out);
    ck(!ok && warnings == 1, "source far edge overflowing float accepted (or %d log lines)", warnings);
}

static void c_vertices_bad_frame(void)
{
    RblCameraFrame good = RblGetCameraFrame(camera());
    for (int i = 0; i < 12; i++) for (int vi = 0; vi < 3; vi++)
    {
        RblCameraFrame f = good;
        ((float *)&f)[i] = badFloats[vi];
        RblBillboard b = billboard();
        RblVertex out[4];
        EXPECT_REFUSED(RblBillboardVertices(&f, 4, 4, &b, out));
    }
}

// ---- cases: batches -------------------------------------------------------------------------------
static void c_batch_load_counts(void)
{
    RblBatch b;
    int bad[4] = { -1, -2147483647 - 1, RBL_MAX_BATCH_BILLBOARDS + 1, 2147483647 };
    for (int i = 0; i < 4; i++)
    {
        EXPECT_REFUSED((b = RblLoadBatch(bad[i]), RblIsBatchValid(b)));
        ck(b.state == NULL && b.capacity == 0, "capacity %d: not a zero batch", bad[i]);
    }
}

static void c_batch_valid_queries(void)
{
    RblBatch zero; memset(&zero, 0, sizeof(zero));
    EXPECT_QUIET(RblIsBatchValid(zero), false);
    RblBatch b = RblLoadBatch(4), stale = b;
    EXPECT_QUIET(RblIsBatchValid(b), true);
    RblUnloadBatch(&b);
    EXPECT_QUIET(RblIsBatchValid(stale), false);
    EXPECT_QUIET(RblIsBatchValid(b), false);
}

static void c_batch_unload(void)
{
    EXPECT_REFUSED(V(RblUnloadBatch(NULL)));
    RblBatch zero; memset(&zero, 0, sizeof(zero));
    EXPECT_REFUSED(V(RblUnloadBatch(&zero)));
    RblBatch b = RblLoadBatch(4), stale = b;
    RblUnloadBatch(&b);
    ck(b.state == NULL, "unload did not zero the batch");
    EXPECT_REFUSED(V(RblUnloadBatch(&b)));      // double unload through the zeroed holder: one line
    EXPECT_REFUSED(V(RblUnloadBatch(&stale)));       // a stale copy: one line
    ck(stale.state == NULL, "stale copy not zeroed");
}

static void c_batch_begin(void)
{
    RblBatch zero; memset(&zero, 0, sizeof(zero));
    EXPECT_REFUSED(RblBeginBatch(NULL, camera()));
    EXPECT_REFUSED(RblBeginBatch(&zero, camera()));
    RblBatch b = RblLoadBatch(4), stale = b;
    EVERY_BAD_CAMERA(RblBeginBatch(&b, cam));
    RblBillboard bb = billboard();
    ck(RblBeginBatch(&b, camera()) && RblBatchAdd(&b, material, &bb), "good batch refused");
    EXPECT_REFUSED(RblBeginBatch(&b, camera()));      // pending billboards are kept
    ck(b.count == 1, "pending billboards dropped (%d)", b.count);
    RblEndBatch(&b);
    RblUnloadBatch(&b);
    EXPECT_REFUSED(RblBeginBatch(&stale, camera()));
}

static void c_batch_add(void)
{
    RblBatch zero; memset(&zero, 0, sizeof(zero));
    RblBillboard bb = billboard();
    EXPECT_REFUSED(RblBatchAdd(NULL, material, &bb));
    EXPECT_REFUSED(RblBatchAdd(&zero, material, &bb));
    RblBatch b = RblLoadBatch(4);
    EXPECT_REFUSED(RblBatchAdd(&b, material, &bb));            // not begun
    RblBeginBatch(&b, camera());
    EXPECT_REFUSED(RblBatchAdd(&b, material, NULL));
    // Every float field bad: refused (one line for the batch's first skip) or finite vertices
    for (int fi = 0; fi < COUNT_OF(billboardFloats); fi++) for (int vi = 0; vi < 5; vi++)
    {
        RblBillboard x = billboard();
        SET_FIELD(x, billboardFloats[fi], badFloats[vi]);
        int before = b.state->count;        // the slot it takes if drawn (a culled one takes none)
        bool ok = RblBatchAdd(&b, material, &x);
        RblVertex v[4];
        if (ok && (b.state->count > before)) rtBatchVertices(b.state, before, v);
        // what the GPU reads: the vertices, or the record (its floats) and what the vertex stage makes of it
        if (ok && (b.state->count > before)) ck(allFinite(v[0].position, 3) && allFinite(v[2].position, 3) && allFinite(v[2].texcoord, 2) &&
                                                (!b.state->records || (allFinite(&((const rbl__BatchRecord *)(const void *)b.state->vertices + before)->position.x, 12) &&
                                                                       allFinite(&((const rbl__BatchRecord *)(const void *)b.state->vertices + before)->up.x, 7))),
                                                "%s = %g accepted with non-finite vertices", billboardFloats[fi].name, badFloats[vi]);
        if (b.count >= RBL_MAX_BATCH_BILLBOARDS - 1) { RblEndBatch(&b); RblBeginBatch(&b, camera()); }
    }
    RblEndBatch(&b);
    // A zero material, a material whose program was unloaded, a texture with a negative size
    RblBeginBatch(&b, camera());
    Material z; memset(&z, 0, sizeof(z));
    EXPECT_REFUSED(RblBatchAdd(&b, z, &bb));
    Material dead = litMaterial(descOf(RBL_BRDF_GGX, false, false));
    Shader s = dead.shader;
    RblUnloadLitShader(&s);
    dead.shader = s;
    RblEndBatch(&b); RblBeginBatch(&b, camera());        // the first skip of a batch is logged, later ones counted
    EXPECT_REFUSED(RblBatchAdd(&b, dead, &bb));
    Material neg = material; MaterialMap maps[12]; memcpy(maps, material.maps, sizeof(maps)); neg.maps = maps;
    maps[MATERIAL_MAP_ALBEDO].texture.width = -4;
    RblEndBatch(&b); RblBeginBatch(&b, camera());
    EXPECT_REFUSED(RblBatchAdd(&b, neg, &bb));
    ck(b.skipped == 1 && b.count == 0, "skips not counted (%d) or bad billboards kept (%d)", b.skipped, b.count);
    RblEndBatch(&b);
    RblUnloadBatch(&b);
}

// RblBatchAddMany: what RblBatchAdd refuses, refused for the whole call or for each billboard it
// holds (one line a batch), and an array with every bad float field leaves only finite slots
static void c_batch_add_many(void)
{
    RblBatch zero; memset(&zero, 0, sizeof(zero));
    RblBillboard bb = billboard();
    EXPECT_REFUSED(RblBatchAddMany(NULL, material, &bb, 1) > 0);
    EXPECT_REFUSED(RblBatchAddMany(&zero, material, &bb, 1) > 0);
    RblBatch b = RblLoadBatch(4);
    EXPECT_REFUSED(RblBatchAddMany(&b, material, &bb, 1) > 0);        // not begun
    RblBeginBatch(&b, camera());
    EXPECT_REFUSED(RblBatchAddMany(&b, material, NULL, 3) > 0);
    EXPECT_REFUSED(RblBatchAddMany(&b, material, &bb, -1) > 0);
    ck(RblBatchAddMany(&b, material, NULL, 0) == 0 && b.count == 0, "an empty call added %d", b.count);
    // Every float field bad, each beside good billboards (so fours form around it): refused or
    // finite; batches of 10 bad fields (60 billboards: the contracts build's batch limit is 64)
    RblEndBatch(&b);
    enum { EACH = 6, PER_BATCH = 10 };
    RblBillboard set[PER_BATCH*EACH];
    int cases = 0, batches = 0;
    for (int first = 0; first < COUNT_OF(billboardFloats)*5; first += PER_BATCH)
    {
        int n = 0;
        for (int c = first; (c < first + PER_BATCH) && (c < COUNT_OF(billboardFloats)*5); c++)
        {
            for (int k = 0; k < EACH; k++) set[n + k] = billboard();
            SET_FIELD(set[n + c%EACH], billboardFloats[c/5], badFloats[c%5]);
            n += EACH; cases++;
        }
        RblBeginBatch(&b, camera());
        warnings = 0;
        int added = RblBatchAddMany(&b, material, set, n);
        ck((added == b.count) && (b.count + b.skipped == n) && (warnings == ((b.skipped > 0)? 1 : 0)),
           "fields %d..: %d of %d added, %d skipped, %d lines (one a batch)", first, added, n, b.skipped, warnings);
        bool finite = true;
        for (int i = 0; i < b.state->count; i++)
        {
            RblVertex v[4];
            rtBatchVertices(b.state, i, v);
            finite = finite && allFinite(v[0].position, 3) && allFinite(v[2].position, 3) && allFinite(v[2].texcoord, 2) &&
                     (!b.state->records || (allFinite(&((const rbl__BatchRecord *)(const void *)b.state->vertices + i)->position.x, 12) &&
                                            allFinite(&((const rbl__BatchRecord *)(const void *)b.state->vertices + i)->up.x, 7)));
        }
        ck(finite, "fields %d..: a bad float reached a slot", first);
        RblEndBatch(&b);
        batches++;
    }
    ck(cases == COUNT_OF(billboardFloats)*5, "%d bad fields tried in %d batches", cases, batches);
    // A zero material: every billboard skipped, one line
    RblBeginBatch(&b, camera());
    Material z; memset(&z, 0, sizeof(z));
    EXPECT_REFUSED(RblBatchAddMany(&b, z, set, 5) > 0);
    ck(b.skipped == 5 && b.count == 0, "zero material: %d skipped, %d kept", b.skipped, b.count);
    RblEndBatch(&b);
    RblUnloadBatch(&b);
}

static void c_batch_limit(void)
{
    RblBatch b = RblLoadBatch(RBL_MAX_BATCH_BILLBOARDS);
    RblBillboard bb = billboard();
    RblBeginBatch(&b, camera());
    for (int i = 0; i < RBL_MAX_BATCH_BILLBOARDS; i++) RblBatchAdd(&b, material, &bb);
    ck(b.count == RBL_MAX_BATCH_BILLBOARDS, "batch holds %d", b.count);
    EXPECT_REFUSED(RblBatchAdd(&b, material, &bb));
    RblEndBatch(&b);
    RblUnloadBatch(&b);
    // Growth stops at the limit
    b = RblLoadBatch(1);
    RblBeginBatch(&b, camera());
    warnings = 0;
    for (int i = 0; i < RBL_MAX_BATCH_BILLBOARDS + 5; i++) RblBatchAdd(&b, material, &bb);
    ck(b.count == RBL_MAX_BATCH_BILLBOARDS && b.capacity == RBL_MAX_BATCH_BILLBOARDS && warnings == 1, "growth past the limit: count %d capacity %d, %d lines", b.count, b.capacity, warnings);
    RblEndBatch(&b);
    RblUnloadBatch(&b);
}

static void c_batch_end(void)
{
    RblBatch zero; memset(&zero, 0, sizeof(zero));
    EXPECT_REFUSED(V(RblEndBatch(NULL)));
    EXPECT_REFUSED(V(RblEndBatch(&zero)));
    RblBatch b = RblLoadBatch(4), stale = b;
    EXPECT_REFUSED(V(RblEndBatch(&b)));             // never begun
    RblBeginBatch(&b, camera()); RblEndBatch(&b);
    EXPECT_REFUSED(V(RblEndBatch(&b)));             // ended twice
    RblUnloadBatch(&b);
    EXPECT_REFUSED(V(RblEndBatch(&stale)));
}

static void c_draw_billboard(void)
{
    RblBillboard bb = billboard();
    EVERY_BAD_CAMERA(V(RblDrawBillboard(cam, material, bb)));
    Material z; memset(&z, 0, sizeof(z));
    EXPECT_REFUSED(V(RblDrawBillboard(camera(), z, bb)));
    Material inst = litMaterial(descOf(RBL_BRDF_LAMBERT, true, false));
    EXPECT_REFUSED(V(RblDrawBillboard(camera(), inst, bb)));      // an instanced variant through the batch
    Material def = litMaterial(descOf(RBL_BRDF_LAMBERT, false, true));
    EXPECT_REFUSED(V(RblDrawBillboard(camera(), def, bb)));       // a deferred variant outside a G-buffer pass
    bb.facing = 17;
    EXPECT_REFUSED(V(RblDrawBillboard(camera(), material, bb)));
}

static void c_close_twice(void)
{
    RblBillboard bb = billboard();
    RblDrawBillboard(camera(), material, bb);
    EXPECT_QUIET(V(RblClose()), false);
    EXPECT_QUIET(V(RblClose()), false);
}

// The reason a caller can read: "" before any refusal, then each refusal's line (every
// EXPECT_REFUSED also checks it), kept through calls that succeed
static void c_failure_reason(void)
{
    ck(strcmp(RblGetFailureReason(), "") == 0, "before any refusal: \"%s\"", RblGetFailureReason());
    EXPECT_REFUSED(V(RblUnloadBatch(NULL)));
    ck(strstr(RblGetFailureReason(), "RblUnloadBatch") == RblGetFailureReason(), "after RblUnloadBatch(NULL): \"%s\"", RblGetFailureReason());
    char kept[512];
    snprintf(kept, sizeof(kept), "%s", RblGetFailureReason());
    RblBatch b = RblLoadBatch(4);
    EXPECT_QUIET(RblIsBatchValid(b), true);
    ck(strcmp(RblGetFailureReason(), kept) == 0, "a successful call changed the reason to \"%s\"", RblGetFailureReason());
    EXPECT_REFUSED(V(RblEndBatch(&b)));                            // never begun
    ck(strstr(RblGetFailureReason(), "RblEndBatch") == RblGetFailureReason(), "after RblEndBatch unbegun: \"%s\"", RblGetFailureReason());
    RblUnloadBatch(&b);
}

// ---- cases: instanced -----------------------------------------------------------------------------
static RblInstance instance(void)
{
    RblInstance in;
    memset(&in, 0, sizeof(in));
    in.size = (Vector2){ 1.0f, 1.0f };
    return in;
}

static void c_instances_load(void)
{
    int bad[4] = { -1, -2147483647 - 1, RBL_MAX_INSTANCES + 1, 2147483647 };
    RblInstanceBuffer b;
    for (int i = 0; i < 4; i++) EXPECT_REFUSED((b = RblLoadInstanceBuffer(bad[i]), RblIsInstanceBufferValid(b)));
    RblInstanceBuffer zero; memset(&zero, 0, sizeof(zero));
    EXPECT_QUIET(RblIsInstanceBufferValid(zero), false);
    b = RblLoadInstanceBuffer(4);
    RblInstanceBuffer stale = b;
    EXPECT_QUIET(RblIsInstanceBufferValid(b), true);
    EXPECT_REFUSED(V(RblUnloadInstanceBuffer(NULL)));
    RblUnloadInstanceBuffer(&b);
    EXPECT_QUIET(RblIsInstanceBufferValid(stale), false);
    EXPECT_REFUSED(V(RblUnloadInstanceBuffer(&b)));
    EXPECT_REFUSED(V(RblUnloadInstanceBuffer(&stale)));
}

static void c_instances_bare(void)
{
    RblInstanceBuffer b = RblLoadInstanceBuffer(4);
    RblInstance in[2] = { instance(), instance() };
    RblInstancedDesc d; memset(&d, 0, sizeof(d));
    Material z; memset(&z, 0, sizeof(z));
    Material def = LoadMaterialDefault();
    EXPECT_REFUSED(RblDrawInstanced(&b, camera(), z, d, in, 2) > 0);
    EXPECT_REFUSED(RblDrawInstanced(&b, camera(), def, d, in, 2) > 0);     // raylib's default shader
    RblBillboard bb = billboard();
    EXPECT_REFUSED(V(RblDrawBillboard(camera(), z, bb)));
    RblUnloadInstanceBuffer(&b);
    UnloadMaterial(def);
}

static void c_instances_draw(void)
{
    Material inst = litMaterial(descOf(RBL_BRDF_LAMBERT, true, false));
    RblInstancedDesc d; memset(&d, 0, sizeof(d));
    RblInstance in[4] = { instance(), instance(), instance(), instance() };
    RblInstanceBuffer zero; memset(&zero, 0, sizeof(zero));
    EXPECT_REFUSED(RblDrawInstanced(NULL, camera(), inst, d, in, 4) > 0);
    EXPECT_REFUSED(RblDrawInstanced(&zero, camera(), inst, d, in, 4) > 0);      // also before any buffer exists
    RblInstanceBuffer b = RblLoadInstanceBuffer(4), stale;
    EXPECT_REFUSED(RblDrawInstanced(&b, camera(), inst, d, in, -1) > 0);
    EXPECT_REFUSED(RblDrawInstanced(&b, camera(), inst, d, NULL, 4) > 0);
    EXPECT_REFUSED(RblDrawInstanced(&b, camera(), inst, d, in, RBL_MAX_INSTANCES + 1) > 0);
    EXPECT_REFUSED(RblDrawInstanced(&b, camera(), inst, d, in, 2147483647) > 0);
    EVERY_BAD_CAMERA(RblDrawInstanced(&b, cam, inst, d, in, 4) > 0);
    for (int fi = 0; fi < COUNT_OF(instancedDescFloats); fi++) for (int vi = 0; vi < 3; vi++)
    {
        RblInstancedDesc x = d; SET_FIELD(x, instancedDescFloats[fi], badFloats[vi]);
        EXPECT_REFUSED(RblDrawInstanced(&b, camera(), inst, x, in, 4) > 0);
    }
    d.facing = 4; EXPECT_REFUSED(RblDrawInstanced(&b, camera(), inst, d, in, 4) > 0);
    d.facing = -1; EXPECT_REFUSED(RblDrawInstanced(&b, camera(), inst, d, in, 4) > 0);
    d.facing = 0;
    Material z; memset(&z, 0, sizeof(z));
    EXPECT_REFUSED(RblDrawInstanced(&b, camera(), z, d, in, 4) > 0);
    EXPECT_REFUSED(RblDrawInstanced(&b, camera(), material, d, in, 4) > 0);    // a vertex-buffer variant
    // Instances with bad floats are skipped with one line; what is drawn is the clean rest
    for (int f = 0; f < 12; f++) for (int vi = 0; vi < 5; vi++)
    {
        RblInstance x[2] = { instance(), instance() };
        ((float *)&x[1])[f] = badFloats[vi];
        warnings = 0;
        int n = RblDrawInstanced(&b, camera(), inst, d, x, 2);
        ck((n == 1 && warnings == 1) || (n == 2 && warnings == 0 && fabsf(badFloats[vi]) < 1e38f && f == 3), "instance float %d = %g: drawn %d, %d lines", f, badFloats[vi], n, warnings);
    }
    stale = b;
    RblUnloadInstanceBuffer(&b);
    EXPECT_REFUSED(RblDrawInstanced(&stale, camera(), inst, d, in, 4) > 0);
}


// ---- cases: materials -----------------------------------------------------------------------------
static Image greyImage(int w, int h) { return GenImageColor(w, h, GRAY); }

static void c_pack_material(void)
{
    RblMaterialSource src; memset(&src, 0, sizeof(src));
    RblPackedMaterial packed, sentinel;
    memset(&packed, 0x5a, sizeof(packed)); memcpy(&sentinel, &packed, sizeof(packed));
    EXPECT_REFUSED(RblPackMaterial(NULL, &packed));
    EXPECT_REFUSED(RblPackMaterial(&src, NULL));
    EXPECT_REFUSED(RblPackMaterial(&src, &packed));                     // no albedo
    src.albedo = greyImage(8, 8);
    Image bad = src.albedo;
    bad.width = -8; src.albedo = bad; EXPECT_REFUSED(RblPackMaterial(&src, &packed));
    bad.width = 8; bad.format = 9999; src.albedo = bad; EXPECT_REFUSED(RblPackMaterial(&src, &packed));
    bad.format = PIXELFORMAT_UNCOMPRESSED_GRAYSCALE; bad.height = 2147483647; src.albedo = bad; EXPECT_REFUSED(RblPackMaterial(&src, &packed));
    bad.height = 8; bad.format = PIXELFORMAT_UNCOMPRESSED_R8G8B8A8; src.albedo = bad;
    src.normal = greyImage(4, 4); EXPECT_REFUSED(RblPackMaterial(&src, &packed));   // size mismatch
    UnloadImage(src.normal); memset(&src.normal, 0, sizeof(Image));
    src.normalEncoding = 7; EXPECT_REFUSED(RblPackMaterial(&src, &packed));
    src.normalEncoding = -1; EXPECT_REFUSED(RblPackMaterial(&src, &packed));
    src.normalEncoding = 0;
    Rectangle frames[1] = { { 0.0f, 0.0f, NAN, 4.0f } };
    src.frames = frames; src.frameCount = 1; EXPECT_REFUSED(RblPackMaterial(&src, &packed));
    src.frameCount = -1; EXPECT_REFUSED(RblPackMaterial(&src, &packed));
    src.frames = NULL; src.frameCount = 3; EXPECT_REFUSED(RblPackMaterial(&src, &packed));
    frames[0] = (Rectangle){ 3.0e38f, 0.0f, 3.0e38f, 4.0f }; src.frames = frames; src.frameCount = 1;
    EXPECT_REFUSED(RblPackMaterial(&src, &packed));
    ck(memcmp(&packed, &sentinel, sizeof(packed)) == 0, "a refused pack wrote to packed");
    UnloadImage(src.albedo);
}

static void c_unload_packed(void)
{
    EXPECT_REFUSED(V(RblUnloadPackedMaterial(NULL)));
    RblMaterialSource src; memset(&src, 0, sizeof(src));
    src.albedo = greyImage(8, 8);
    RblPackedMaterial p;
    ck(RblPackMaterial(&src, &p), "pack failed");
    RblUnloadPackedMaterial(&p);
    ck(p.albedo.data == NULL, "unload did not zero");
    EXPECT_REFUSED(V(RblUnloadPackedMaterial(&p)));
    UnloadImage(src.albedo);
}

static void c_encode_decode_normal(void)
{
    unsigned char out[3] = { 7, 7, 7 };
    EXPECT_REFUSED(V(RblEncodeNormal((Vector3){ 0, 0, 1 }, RBL_NORMAL_HEMIOCT, NULL)));
    for (int e = -1; e < 6; e += 5) EXPECT_REFUSED(V(RblEncodeNormal((Vector3){ 0, 0, 1 }, e, out)));
    for (int c = 0; c < 3; c++) for (int vi = 0; vi < 5; vi++)
    {
        Vector3 n = { 0.0f, 0.0f, 1.0f };
        ((float *)&n)[c] = badFloats[vi];
        if (vi >= 3)
        {
            // A finite long vector is a direction: encoded (its unit vector), never NaN
            unsigned char code[3];
            warnings = 0; RblEncodeNormal(n, RBL_NORMAL_HEMIOCT, code);
            Vector3 d = RblDecodeNormal(code, RBL_NORMAL_HEMIOCT);
            ck(warnings <= 1 && isfinite(d.x) && isfinite(d.y) && isfinite(d.z), "long normal component %d: %d lines, decoded non-finite", c, warnings);
            continue;
        }
        EXPECT_REFUSED(V(RblEncodeNormal(n, RBL_NORMAL_HEMIOCT, out)));
    }
    EXPECT_REFUSED(V(RblEncodeNormal((Vector3){ 0, 0, 0 }, RBL_NORMAL_HEMIOCT, out)));
    ck(out[0] == 7 && out[1] == 7 && out[2] == 7, "refused encodes wrote out");
    Vector3 d;
    EXPECT_REFUSED((d = RblDecodeNormal(NULL, RBL_NORMAL_HEMIOCT), false));
    ck(d.z == 1.0f, "NULL decode is not +Z");
    EXPECT_REFUSED((d = RblDecodeNormal(out, 9), false));
    EXPECT_REFUSED((d = RblDecodeNormal(out, -3), false));
    unsigned char zero[3] = { 128, 128, 0 };
    for (int e = 1; e < 4; e++) { warnings = 0; d = RblDecodeNormal(zero, e); ck(isfinite(d.x) && isfinite(d.y) && isfinite(d.z) && warnings == 0, "decode %d of a zero texel", e); }
}

static void c_measure_normals(void)
{
    Vector3 n[2] = { { 0, 0, 1 }, { NAN, 0, 1 } };
    RblNormalErrorStats s;
    EXPECT_REFUSED((s = RblMeasureNormalEncoding(RBL_NORMAL_HEMIOCT, NULL, 4), s.count > 0));
    EXPECT_REFUSED((s = RblMeasureNormalEncoding(RBL_NORMAL_HEMIOCT, n, -1), s.count > 0));
    EXPECT_REFUSED((s = RblMeasureNormalEncoding(11, n, 1), s.count > 0));
    warnings = 0;
    s = RblMeasureNormalEncoding(RBL_NORMAL_HEMIOCT, n, 2);
    ck(isfinite(s.mean) && isfinite(s.max) && isfinite(s.p99) && s.count == 1 && warnings == 1, "a NaN normal: count %d, %d lines, mean %g", s.count, warnings, s.mean);
}

static void c_gen_maps(void)
{
    Image ok = greyImage(8, 8), img;
    Image bad[5] = { ok, ok, ok, ok, ok };
    bad[0].data = NULL; bad[1].width = -8; bad[2].format = 12345; bad[3].height = 2147483647; bad[4].width = 0;
    for (int i = 0; i < 5; i++)
    {
        EXPECT_REFUSED((img = RblGenNormalMapFromHeight(bad[i], 1.0f, false), img.data != NULL));
        EXPECT_REFUSED((img = RblGenHeightFromLuminance(bad[i]), img.data != NULL));
        EXPECT_REFUSED((img = RblGenOcclusionFromHeight(bad[i], 2, 1.0f), img.data != NULL));
    }
    for (int vi = 0; vi < 3; vi++)
    {
        EXPECT_REFUSED((img = RblGenNormalMapFromHeight(ok, badFloats[vi], true), img.data != NULL));
        EXPECT_REFUSED((img = RblGenOcclusionFromHeight(ok, 2, badFloats[vi]), img.data != NULL));
    }
    // Huge finite strength: a valid (steep) map, no NaN
    img = RblGenNormalMapFromHeight(ok, 3.0e38f, false);
    ck(img.data != NULL, "huge strength refused");
    UnloadImage(img);
    int radii[3] = { -1, RBL_MAX_OCCLUSION_RADIUS + 1, 2147483647 };
    for (int i = 0; i < 3; i++) EXPECT_REFUSED((img = RblGenOcclusionFromHeight(ok, radii[i], 1.0f), img.data != NULL));
    EXPECT_REFUSED((img = RblGenOcclusionFromHeight(ok, 2, -1.0f), img.data != NULL));
    UnloadImage(ok);
}

static void c_load_packed_textures(void)
{
    RblMaterialSource src; memset(&src, 0, sizeof(src));
    src.albedo = greyImage(8, 8);
    RblPackedMaterial p;
    RblPackMaterial(&src, &p);
    Material m = LoadMaterialDefault(), sentinel = m;
    Material nomaps = m; nomaps.maps = NULL;
    EXPECT_REFUSED(RblLoadPackedTextures(NULL, &m));
    EXPECT_REFUSED(RblLoadPackedTextures(&p, NULL));
    EXPECT_REFUSED(RblLoadPackedTextures(&p, &nomaps));
    RblPackedMaterial bad = p; bad.albedo.width = -3;
    EXPECT_REFUSED(RblLoadPackedTextures(&bad, &m));
    bad = p; bad.albedo.format = 4242;
    EXPECT_REFUSED(RblLoadPackedTextures(&bad, &m));
    bad = p; bad.layout.normalEncoding = 12;
    EXPECT_REFUSED(RblLoadPackedTextures(&bad, &m));
    ck(memcmp(&m, &sentinel, sizeof(m)) == 0 && m.maps[MATERIAL_MAP_ALBEDO].texture.id == sentinel.maps[MATERIAL_MAP_ALBEDO].texture.id, "refused loads changed the material");
    RblUnloadPackedMaterial(&p);
    UnloadImage(src.albedo);
}

// ---- cases: lit programs and the scene ------------------------------------------------------------
static void c_load_lit_shader(void)
{
    Shader s;
    const size_t ints[] = { offsetof(RblLitShaderDesc, maxLights), offsetof(RblLitShaderDesc, shading.lightFeatures), offsetof(RblLitShaderDesc, material.normalEncoding),
                            offsetof(RblLitShaderDesc, material.emissive), offsetof(RblLitShaderDesc, shading.brdf), offsetof(RblLitShaderDesc, shading.fog),
                            offsetof(RblLitShaderDesc, shading.tonemap), offsetof(RblLitShaderDesc, shading.shadowMaps), offsetof(RblLitShaderDesc, shading.shadowFilter),
                            offsetof(RblLitShaderDesc, debugOutput), offsetof(RblLitShaderDesc, material.height), offsetof(RblLitShaderDesc, material.thickness),
                            offsetof(RblLitShaderDesc, reliefSteps) };
    const int values[3] = { -1, 1000, -2147483647 - 1 };
    for (size_t i = 0; i < sizeof(ints)/sizeof(ints[0]); i++) for (int v = 0; v < 3; v++)
    {
        RblLitShaderDesc d = descOf(0, false, false);
        memcpy((char *)&d + ints[i], &values[v], sizeof(int));
        EXPECT_REFUSED((s = RblLoadLitShader(d), s.id != 0));
        if (s.id != 0) printf("      (desc field at offset %d = %d accepted)\n", (int)ints[i], values[v]);
    }
    for (int vi = 0; vi < 5; vi++)
    {
        RblLitShaderDesc d = descOf(0, false, false); d.shading.gamma = badFloats[vi];
        EXPECT_REFUSED((s = RblLoadLitShader(d), s.id != 0));
    }
    RblLitShaderDesc d = descOf(0, false, false); d.shading.gamma = -2.0f;
    EXPECT_REFUSED((s = RblLoadLitShader(d), s.id != 0));
    d = descOf(0, true, false); d.skinning = true;     // skinning is for Models, not instances
    EXPECT_REFUSED((s = RblLoadLitShader(d), s.id != 0));
    d = descOf(0, true, true);      // instanced geometry-pass variant: not a thing
    s = RblLoadLitShader(d);
    ck((s.id == 0) || RblIsLitShaderValid(s), "instanced+deferred gave an invalid non-zero shader");
    RblUnloadLitShader(&s);
}

static void c_lit_shader_queries(void)
{
    Shader zero; memset(&zero, 0, sizeof(zero));
    EXPECT_QUIET(RblIsLitShaderValid(zero), false);
    Shader def = LoadShader(NULL, NULL);     // raylib's default
    EXPECT_QUIET(RblIsLitShaderValid(def), false);
    Shader s = RblLoadLitShader(descOf(RBL_BRDF_GGX, false, false)), stale = s;
    EXPECT_QUIET(RblIsLitShaderValid(s), true);
    RblUnloadLitShader(&s);
    EXPECT_QUIET(RblIsLitShaderValid(stale), false);
}

static void c_unload_lit_shader(void)
{
    EXPECT_REFUSED(V(RblUnloadLitShader(NULL)));
    Shader zero; memset(&zero, 0, sizeof(zero));
    EXPECT_REFUSED(V(RblUnloadLitShader(&zero)));
    Shader def = LoadShader(NULL, NULL);
    EXPECT_REFUSED(V(RblUnloadLitShader(&def)));
    Shader s = RblLoadLitShader(descOf(RBL_BRDF_GGX, false, false)), stale = s;
    RblUnloadLitShader(&s);
    ck(s.id == 0 && s.locs == NULL, "unload did not zero the shader");
    EXPECT_REFUSED(V(RblUnloadLitShader(&s)));
    EXPECT_REFUSED(V(RblUnloadLitShader(&stale)));
}

// The light grid of clustered programs under extreme accepted scenes: positions near the 2^60 limit,
// tiny and huge ranges, every light at one point (capped cells: one line), the largest scene; the grid
// stays within its limits and a draw logs nothing
static void c_light_grid_extremes(void)
{
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.clustered = true;
    Material m = litMaterial(desc);
    static RblLight l[RBL_MAX_SCENE_LIGHTS];
    RblScene scene; memset(&scene, 0, sizeof(scene)); scene.lights = l;
    for (int k = 0; k < 4; k++)
    {
        for (int i = 0; i < RBL_MAX_SCENE_LIGHTS; i++)
        {
            l[i] = pointLight();
            l[i].intensity = RBL_MAX_LIGHT_INTENSITY;
            float far = 1.1e18f*((i & 1)? 1.0f : -1.0f);
            if (k == 0) { l[i].position = (Vector3){ far, -far, (float)i }; l[i].range = 1e-30f; }
            if (k == 1) { l[i].position = (Vector3){ (float)(i%7), (float)(i%5), 0.0f }; l[i].range = (i%3 == 0)? 1e18f : 0.5f; }
            if (k == 2) { l[i].position = (i < RBL_MAX_SCENE_LIGHTS/8)? (Vector3){ (float)i, 0.0f, 1.0f } : (Vector3){ 0.0f, 0.0f, 1.0f }; l[i].range = 0.5f; }
            if (k == 3) { l[i].position = (Vector3){ far*(float)(i%3 - 1), 0.0f, (float)(i%11)*1e17f }; l[i].range = 1e17f; }
        }
        scene.lightCount = RBL_MAX_SCENE_LIGHTS;
        warnings = 0;
        ck(RblSetScene(&scene), "scene %d refused: %s", k, lastWarning);
        RblLightGridStats g = RblGetLightGridStats();
        long cells = (long)g.cells[0]*g.cells[1]*g.cells[2];
        ck((cells <= RBL_LIGHT_GRID_MAX_CELLS) && (g.entries >= 0) && (g.unbounded >= 0) && (g.unbounded <= RBL_MAX_SCENE_LIGHTS) && isfinite(g.cellSize),
           "scene %d: grid %dx%dx%d, %d entries, %d unbounded, cell %g", k, g.cells[0], g.cells[1], g.cells[2], g.entries, g.unbounded, g.cellSize);
        ck(warnings == ((k == 2)? 1 : 0), "scene %d: %d log lines (%s)", k, warnings, lastWarning);
        warnings = 0;
        BeginTextureMode(target);
        BeginMode3D(camera());
        RblDrawBillboard(camera(), m, billboard());
        EndMode3D();
        EndTextureMode();
        ck(warnings == 0, "scene %d: the draw logged %s", k, lastWarning);
    }
    RblUnloadLitShader(&m.shader);
    MemFree(m.maps);
}

static void c_light_features(void)
{
    RblLight l = pointLight();
    int f;
    EXPECT_REFUSED((f = RblGetLightFeatures(NULL, 2), f != 0));
    EXPECT_REFUSED((f = RblGetLightFeatures(&l, -1), f != 0));
    l.type = 9;
    EXPECT_REFUSED((f = RblGetLightFeatures(&l, 1), f != 0));
    l.type = 0; l.falloff = 5;
    EXPECT_REFUSED((f = RblGetLightFeatures(&l, 1), f != 0));
    EXPECT_QUIET(RblGetLightFeatures(NULL, 0) == 0, true);
}

static void c_set_scene(void)
{
    RblLight good = pointLight();
    RblScene scene; memset(&scene, 0, sizeof(scene));
    scene.lights = &good; scene.lightCount = 1;
    EXPECT_REFUSED(RblSetScene(NULL));
    RblScene x = scene; x.lightCount = -1; EXPECT_REFUSED(RblSetScene(&x));
    x = scene; x.lightCount = RBL_MAX_SCENE_LIGHTS + 1; EXPECT_REFUSED(RblSetScene(&x));
    x = scene; x.lightCount = 2147483647; EXPECT_REFUSED(RblSetScene(&x));
    x = scene; x.lights = NULL; EXPECT_REFUSED(RblSetScene(&x));
    x = scene; x.shadowMapCount = -1; EXPECT_REFUSED(RblSetScene(&x));
    x = scene; x.shadowMapCount = 2; EXPECT_REFUSED(RblSetScene(&x));      // NULL maps
    RblShadowMap maps[RBL_MAX_SHADOWS + 1]; memset(maps, 0, sizeof(maps));
    x = scene; x.shadowMaps = maps; x.shadowMapCount = 1; EXPECT_REFUSED(RblSetScene(&x));   // never-loaded map
    x = scene; x.shadowMaps = maps; x.shadowMapCount = RBL_MAX_SHADOWS + 1; EXPECT_REFUSED(RblSetScene(&x));
    x = scene; x.fog.mode = 9; EXPECT_REFUSED(RblSetScene(&x));
    x = scene; x.fog.mode = RBL_FOG_LINEAR; x.fog.start = 5; x.fog.end = 5; EXPECT_REFUSED(RblSetScene(&x));
    x = scene; x.exposure = -1.0f; EXPECT_REFUSED(RblSetScene(&x));
    for (int fi = 0; fi < COUNT_OF(sceneFloats); fi++) for (int vi = 0; vi < 5; vi++)
    {
        x = scene; x.fog.mode = RBL_FOG_EXP2; x.fog.density = 0.1f; x.fog.end = 10.0f;
        SET_FIELD(x, sceneFloats[fi], badFloats[vi]);
        warnings = 0;
        bool ok = RblSetScene(&x);
        if (ok) ck(warnings == 0 && allFinite(rbl__state.scene.fog, 4) && allFinite(rbl__state.scene.up, 3) && isfinite(rbl__state.scene.exposure) && isfinite(rbl__state.scene.fogStart),
                   "scene %s = %g accepted with non-finite packed values", sceneFloats[fi].name, badFloats[vi]);
        else ck(warnings == 1, "scene %s = %g refused with %d lines", sceneFloats[fi].name, badFloats[vi], warnings);
    }
    // Every light type x every float field
    for (int type = 0; type < 3; type++) for (int fi = 0; fi < COUNT_OF(lightFloats); fi++) for (int vi = 0; vi < 5; vi++)
    {
        RblLight l = pointLight(); l.type = type; l.direction = (Vector3){ 0, -1, 0 }; l.range = 10.0f;
        l.falloff = (fi >= 10)? RBL_FALLOFF_CLASSIC : RBL_FALLOFF_WINDOWED;
        SET_FIELD(l, lightFloats[fi], badFloats[vi]);
        x = scene; x.lights = &l;
        warnings = 0;
        bool ok = RblSetScene(&x);
        if (ok) ck(warnings == 0 && allFinite(rbl__state.scene.lights, (size_t)RBL__LIGHT_FLOATS) &&
                   (rbl__state.scene.lights[0]*rbl__state.scene.lights[0] + rbl__state.scene.lights[1]*rbl__state.scene.lights[1] + rbl__state.scene.lights[2]*rbl__state.scene.lights[2] > 0.0f || type == RBL_LIGHT_POINT),
                   "light type %d %s = %g accepted with non-finite or zero packed values", type, lightFloats[fi].name, badFloats[vi]);
        else ck(warnings == 1, "light type %d %s = %g refused with %d lines", type, lightFloats[fi].name, badFloats[vi], warnings);
    }
    RblLight l = pointLight(); l.type = 5; x = scene; x.lights = &l; EXPECT_REFUSED(RblSetScene(&x));
    l = pointLight(); l.falloff = 5; EXPECT_REFUSED(RblSetScene(&x));
    l = pointLight(); l.intensity = RBL_MAX_LIGHT_INTENSITY*2.0f; EXPECT_REFUSED(RblSetScene(&x));
}

static void c_draw_model_and_mesh(void)
{
    Model model = LoadModelFromMesh(GenMeshCube(1, 1, 1));
    model.materials[0].shader = litShader;
    EXPECT_QUIET(V(RblDrawModel(model, (Vector3){ 0, 0, 0 }, 1.0f, WHITE)), false);
    for (int vi = 0; vi < 5; vi++)
    {
        EXPECT_REFUSED(V(RblDrawModel(model, (Vector3){ badFloats[vi], 0, 0 }, 1.0f, WHITE)));
        EXPECT_REFUSED(V(RblDrawModel(model, (Vector3){ 0, 0, 0 }, badFloats[vi], WHITE)));
    }
    Model m = model; m.meshes = NULL; EXPECT_REFUSED(V(RblDrawModel(m, (Vector3){ 0, 0, 0 }, 1.0f, WHITE)));
    m = model; m.materials = NULL; EXPECT_REFUSED(V(RblDrawModel(m, (Vector3){ 0, 0, 0 }, 1.0f, WHITE)));
    m = model; m.meshCount = -1; EXPECT_REFUSED(V(RblDrawModel(m, (Vector3){ 0, 0, 0 }, 1.0f, WHITE)));
    int badIndex[2] = { 5, -1 };
    int *saved = model.meshMaterial;
    for (int i = 0; i < 2; i++) { m = model; m.meshMaterial = &badIndex[i]; EXPECT_REFUSED(V(RblDrawModel(m, (Vector3){ 0, 0, 0 }, 1.0f, WHITE))); }
    Material z; memset(&z, 0, sizeof(z));
    Material zs = model.materials[0]; zs.shader.id = 0;
    m = model; m.materials = &zs; EXPECT_REFUSED(V(RblDrawModel(m, (Vector3){ 0, 0, 0 }, 1.0f, WHITE)));
    EXPECT_REFUSED(V(RblDrawMesh(model.meshes[0], z, MatrixIdentity())));
    Matrix nan = MatrixIdentity(); nan.m12 = NAN;
    EXPECT_REFUSED(V(RblDrawMesh(model.meshes[0], material, nan)));
    Mesh noVao = model.meshes[0]; noVao.vaoId = 0; noVao.vboId = NULL;
    EXPECT_REFUSED(V(RblDrawMesh(noVao, material, MatrixIdentity())));
    Material def = litMaterial(descOf(RBL_BRDF_LAMBERT, false, true));
    EXPECT_REFUSED(V(RblDrawMesh(model.meshes[0], def, MatrixIdentity())));   // deferred variant outside a pass
    model.meshMaterial = saved;
    model.materials[0].shader = (Shader){ 0 };
    UnloadModel(model);
}

// GPU-skinned Models: a skinned program refuses what it cannot skin (no bone matrices, a bone count
// outside 1..RBL_MAX_BONES, a NaN bone, a mesh without bone data, RblDrawMesh, billboards), in the
// colour pass and in a shadow pass (where the Model's data picks the skinned caster)
static void c_draw_skinned_model(void)
{
    RblLitShaderDesc desc = descOf(RBL_BRDF_LAMBERT, false, false);
    desc.skinning = true;
#if !RBL_GPU_SKINNING
    Shader none;
    EXPECT_REFUSED((none = RblLoadLitShader(desc), none.id != 0));     // raylib without GPU skinning
    return;
#endif
    Shader skinned = RblLoadLitShader(desc);
    ck(RblIsLitShaderValid(skinned), "skinned lit program failed to load");
    SkinRig rig = skinRigLoad();
    rig.model.materials[0].shader = skinned;
    UpdateModelAnimation(rig.model, rig.anim, 1.0f);
    EXPECT_QUIET(V(RblDrawModel(rig.model, (Vector3){ 0, 0, 0 }, 1.0f, WHITE)), false);
    Model m = rig.model; m.boneMatrices = NULL; EXPECT_REFUSED(V(RblDrawModel(m, (Vector3){ 0, 0, 0 }, 1.0f, WHITE)));
    m = rig.model; m.skeleton.boneCount = RBL_MAX_BONES + 1; EXPECT_REFUSED(V(RblDrawModel(m, (Vector3){ 0, 0, 0 }, 1.0f, WHITE)));
    m = rig.model; m.skeleton.boneCount = 0; EXPECT_REFUSED(V(RblDrawModel(m, (Vector3){ 0, 0, 0 }, 1.0f, WHITE)));
    Matrix bones[SKIN_BONES];
    for (int b = 0; b < SKIN_BONES; b++)
        for (int vi = 0; vi < 5; vi++)
        {
            memcpy(bones, rig.model.boneMatrices, sizeof(bones));
            bones[b].m13 = badFloats[vi];
            m = rig.model; m.boneMatrices = bones; EXPECT_REFUSED(V(RblDrawModel(m, (Vector3){ 0, 0, 0 }, 1.0f, WHITE)));
        }
    EXPECT_REFUSED(V(RblDrawMesh(rig.model.meshes[0], rig.model.materials[0], MatrixIdentity())));
    Model cube = LoadModelFromMesh(GenMeshCube(1, 1, 1));
    cube.materials[0].shader = skinned;
    EXPECT_REFUSED(V(RblDrawModel(cube, (Vector3){ 0, 0, 0 }, 1.0f, WHITE)));
    EXPECT_REFUSED(V(RblDrawBillboard(camera(), rig.model.materials[0], billboard())));
    // Inside a shadow pass: the skinned caster compiles on first use and the same refusals hold
    RblShadowDesc sd; memset(&sd, 0, sizeof(sd)); sd.size = 64;
    RblShadowMap map = RblLoadShadowMap(sd);
    RblLight sun = pointLight(); sun.type = RBL_LIGHT_DIRECTIONAL; sun.direction = (Vector3){ 0.2f, -1.0f, 0.1f };
    RblScene scene; memset(&scene, 0, sizeof(scene)); scene.lights = &sun; scene.lightCount = 1;
    if (RblBeginShadowMap(&map, &scene, 0, (Vector3){ 0, 0, 0 }, 4.0f))
    {
        EXPECT_QUIET(V(RblDrawModel(rig.model, (Vector3){ 0, 0, 0 }, 1.0f, WHITE)), false);
        m = rig.model; m.skeleton.boneCount = RBL_MAX_BONES + 1; EXPECT_REFUSED(V(RblDrawModel(m, (Vector3){ 0, 0, 0 }, 1.0f, WHITE)));
        m = rig.model; m.boneMatrices = bones; EXPECT_REFUSED(V(RblDrawModel(m, (Vector3){ 0, 0, 0 }, 1.0f, WHITE)));
        RblEndShadowMap(&map);
    }
    else ck(false, "shadow pass refused");
    ck(rbl__state.casterIds[2] != 0, "no skinned caster after a skinned Model cast");
    RblUnloadShadowMap(&map);
    ck(rbl__state.casterIds[2] == 0, "the skinned caster outlived the last shadow map");
    cube.materials[0].shader = (Shader){ 0 };
    UnloadModel(cube);
    rig.model.materials[0].shader = (Shader){ 0 };
    skinRigUnload(&rig);
    RblUnloadLitShader(&skinned);
}

// ---- cases: G-buffer ------------------------------------------------------------------------------
static RblGBufferDesc gdesc(int brdf) { RblGBufferDesc d; memset(&d, 0, sizeof(d)); d.width = 32; d.height = 32; d.shading.brdf = brdf; return d; }

static void c_gbuffer_load(void)
{
    RblGBuffer g;
    const size_t ints[] = { offsetof(RblGBufferDesc, width), offsetof(RblGBufferDesc, height), offsetof(RblGBufferDesc, shading.brdf),
                            offsetof(RblGBufferDesc, shading.lightFeatures), offsetof(RblGBufferDesc, shading.fog), offsetof(RblGBufferDesc, shading.tonemap),
                            offsetof(RblGBufferDesc, shading.shadowMaps), offsetof(RblGBufferDesc, shading.shadowFilter) };
    const int values[4] = { -1, 1000, 1 << 30, -2147483647 - 1 };
    for (size_t i = 0; i < sizeof(ints)/sizeof(ints[0]); i++) for (int v = 0; v < 4; v++)
    {
        RblGBufferDesc d = gdesc(0);
        if ((ints[i] <= offsetof(RblGBufferDesc, height)) && (v == 1)) continue;     // 1000 pixels is a valid size
        memcpy((char *)&d + ints[i], &values[v], sizeof(int));
        EXPECT_REFUSED((g = RblLoadGBuffer(d), RblIsGBufferValid(g)));
        ck(g.state == NULL, "desc field at offset %d = %d: load left a state", (int)ints[i], values[v]);
    }
    for (int vi = 0; vi < 5; vi++) { RblGBufferDesc d = gdesc(0); d.shading.gamma = badFloats[vi]; EXPECT_REFUSED((g = RblLoadGBuffer(d), RblIsGBufferValid(g))); }
}

static void c_gbuffer_lifecycle(void)
{
    RblGBuffer zero; memset(&zero, 0, sizeof(zero));
    EXPECT_QUIET(RblIsGBufferValid(zero), false);
    RblGBuffer g = RblLoadGBuffer(gdesc(RBL_BRDF_GGX)), stale = g;
    EXPECT_QUIET(RblIsGBufferValid(g), true);
    int bpp;
    EXPECT_REFUSED((bpp = RblGBufferBytesPerPixel(NULL), bpp != 0));
    EXPECT_REFUSED((bpp = RblGBufferBytesPerPixel(&zero), bpp != 0));
    EXPECT_REFUSED(RblResizeGBuffer(NULL, 16, 16));
    EXPECT_REFUSED(RblResizeGBuffer(&zero, 16, 16));
    int sizes[5][2] = { { 0, 16 }, { 16, -1 }, { 1 << 30, 16 }, { 16, RBL_MAX_TARGET_SIZE + 1 }, { -2147483647 - 1, 4 } };
    for (int i = 0; i < 5; i++) EXPECT_REFUSED(RblResizeGBuffer(&g, sizes[i][0], sizes[i][1]));
    ck(g.width == 32 && g.height == 32 && RblIsGBufferValid(g), "refused resize changed the G-buffer");
    EXPECT_REFUSED(V(RblUnloadGBuffer(NULL)));
    RblUnloadGBuffer(&g);
    ck(g.state == NULL && g.albedo.id == 0, "unload did not zero");
    EXPECT_REFUSED(V(RblUnloadGBuffer(&g)));
    EXPECT_QUIET(RblIsGBufferValid(stale), false);
    EXPECT_REFUSED((bpp = RblGBufferBytesPerPixel(&stale), bpp != 0));
    EXPECT_REFUSED(RblResizeGBuffer(&stale, 16, 16));
    EXPECT_REFUSED(RblBeginGBuffer(&stale, camera()));
    EXPECT_REFUSED(RblDrawDeferredLights(&stale));
    EXPECT_REFUSED(V(RblResolveGBuffer(&stale)));
    EXPECT_REFUSED(V(RblSetGBufferOutput(&stale, 1, 1.0f)));
    EXPECT_REFUSED(V(RblUnloadGBuffer(&stale)));
}

static void c_gbuffer_passes(void)
{
    RblGBuffer zero; memset(&zero, 0, sizeof(zero));
    EXPECT_REFUSED(RblBeginGBuffer(NULL, camera()));
    EXPECT_REFUSED(RblBeginGBuffer(&zero, camera()));
    EXPECT_REFUSED(V(RblEndGBuffer(NULL)));
    EXPECT_REFUSED(V(RblEndGBuffer(&zero)));
    RblGBuffer g = RblLoadGBuffer(gdesc(RBL_BRDF_GGX)), h = RblLoadGBuffer(gdesc(RBL_BRDF_GGX));
    EXPECT_REFUSED(V(RblEndGBuffer(&g)));                      // never begun: projection, modelview, depth test kept
    EVERY_BAD_CAMERA(RblBeginGBuffer(&g, cam));
    ck(RblBeginGBuffer(&g, camera()), "good pass refused");
    EXPECT_REFUSED(RblBeginGBuffer(&g, camera()));             // nested, same
    EXPECT_REFUSED(RblBeginGBuffer(&h, camera()));             // nested, other
    EXPECT_REFUSED(RblDrawDeferredLights(&g));                  // lights inside the geometry pass
    EXPECT_REFUSED(V(RblResolveGBuffer(&g)));
    EXPECT_REFUSED(RblResizeGBuffer(&g, 16, 16));
    EXPECT_REFUSED(V(RblEndGBuffer(&h)));                      // ending the other one
    // Mismatched variants inside the pass: forward, other BRDF, instanced forward (a refused first
    // immediate draw creates nothing)
    RblBillboard bb = billboard();
    ck(rbl__state.immediate.state == NULL, "the immediate path exists before any immediate draw");
    EXPECT_REFUSED(V(RblDrawBillboard(camera(), material, bb)));
    ck(rbl__state.immediate.state == NULL, "a refused immediate draw created the immediate path's buffers");
    Material lam = litMaterial(descOf(RBL_BRDF_LAMBERT, false, true));
    EXPECT_REFUSED(V(RblDrawBillboard(camera(), lam, bb)));
    RblShadowMap map = RblLoadShadowMap((RblShadowDesc){ 0 });
    RblLight sun = pointLight(); sun.type = RBL_LIGHT_DIRECTIONAL; sun.direction = (Vector3){ 0, -1, 0 };
    RblScene scene; memset(&scene, 0, sizeof(scene)); scene.lights = &sun; scene.lightCount = 1;
    EXPECT_REFUSED(RblBeginShadowMap(&map, &scene, 0, (Vector3){ 0, 0, 0 }, 5.0f));   // a shadow pass inside a G-buffer pass
    RblEndGBuffer(&g);
    // Good frame, then the light and resolve calls on bad arguments
    ck(RblDrawDeferredLights(&g), "lights refused");
    EXPECT_REFUSED(RblDrawDeferredLights(NULL));
    EXPECT_REFUSED(V(RblResolveGBuffer(NULL)));
    EXPECT_REFUSED(V(RblSetGBufferOutput(NULL, 1, 1.0f)));
    EXPECT_REFUSED(V(RblSetGBufferOutput(&g, RBL_GBUFFER_OUTPUT_COUNT, 1.0f)));
    EXPECT_REFUSED(V(RblSetGBufferOutput(&g, -1, 1.0f)));
    for (int vi = 0; vi < 5; vi++) EXPECT_REFUSED(V(RblSetGBufferOutput(&g, 1, (vi < 3)? badFloats[vi] : -1.0f)));
    RblUnloadShadowMap(&map);
    RblUnloadGBuffer(&g);
    RblUnloadGBuffer(&h);
}

// Extreme but accepted lights leave the accumulation finite
static void c_gbuffer_extreme_lights_stay_finite(void)
{
    RblGBuffer g = RblLoadGBuffer(gdesc(RBL_BRDF_GGX));
    Material ggx = litMaterial(descOf(RBL_BRDF_GGX, false, true));
    ggx.maps[MATERIAL_MAP_ROUGHNESS].value = 0.0f;
    RblLight l[3] = { pointLight(), pointLight(), pointLight() };
    l[0].intensity = l[1].intensity = l[2].intensity = RBL_MAX_LIGHT_INTENSITY;
    l[1].position = (Vector3){ 0.0f, 0.0f, 0.001f };
    l[2].type = RBL_LIGHT_DIRECTIONAL; l[2].direction = (Vector3){ 1e30f, -1e30f, -3e38f };
    RblScene scene; memset(&scene, 0, sizeof(scene)); scene.lights = l; scene.lightCount = 3; scene.exposure = 3e38f;
    ck(RblSetScene(&scene), "extreme but valid scene refused: %s", lastWarning);
    RblBeginGBuffer(&g, camera());
    RblBillboard bb = billboard(); bb.size = (Vector2){ 4.0f, 4.0f };
    RblDrawBillboard(camera(), ggx, bb);
    RblEndGBuffer(&g);
    RblDrawDeferredLights(&g);
    // Read the RGBA16F accumulation as floats
    typedef void (*GlReadPixels)(int, int, int, int, unsigned int, unsigned int, void *);
    typedef void (*GlBindFramebuffer)(unsigned int, unsigned int);
    GlReadPixels readPixels; GL_PROC(readPixels, "glReadPixels");
    GlBindFramebuffer bindFb; GL_PROC(bindFb, "glBindFramebuffer");
    int prev = 0; glGetI(0x8CAA, &prev);
    bindFb(0x8CA8, g.state->lightId);
    static float px[32*32*4];
    readPixels(0, 0, 32, 32, 0x1908, 0x1406, px);
    bindFb(0x8CA8, (unsigned int)prev);
    int bad = 0;
    for (int i = 0; i < 32*32*4; i++) if (!isfinite(px[i])) bad++;
    ck(bad == 0, "%d non-finite accumulation values", bad);
    RblUnloadGBuffer(&g);
}

// ---- cases: scene targets (soft particles) --------------------------------------------------------
static void c_scene_target(void)
{
    RenderTexture2D t;
    int sizes[6][2] = { { 0, 16 }, { 16, 0 }, { -1, 16 }, { RBL_MAX_TARGET_SIZE + 1, 16 }, { 16, 1 << 30 }, { -2147483647 - 1, 16 } };
    for (int i = 0; i < 6; i++) EXPECT_REFUSED((t = RblLoadSceneTarget(sizes[i][0], sizes[i][1]), t.id != 0));
    // A good one: a colour texture, a depth texture, complete; raylib's UnloadRenderTexture frees it all
    warnings = 0;
    t = RblLoadSceneTarget(32, 16);
    ck((warnings == 0) && (t.id != 0) && (t.texture.id != 0) && (t.depth.id != 0) && (t.texture.width == 32) && (t.depth.height == 16),
       "RblLoadSceneTarget(32, 16): id %u, texture %u, depth %u, %d log lines", t.id, t.texture.id, t.depth.id, warnings);
    UnloadRenderTexture(t);
    // The scene's depth field: a bad size is refused with one line, the previous scene kept
    RblScene scene; memset(&scene, 0, sizeof(scene));
    scene.depth.id = 1; scene.depth.width = -4; scene.depth.height = 4;
    EXPECT_REFUSED(RblSetScene(&scene));
    scene.depth.width = RBL_MAX_TARGET_SIZE + 1;
    EXPECT_REFUSED(RblSetScene(&scene));
}

// ---- cases: shadows -------------------------------------------------------------------------------
static void c_shadow_load(void)
{
    RblShadowMap m;
    int sizes[5] = { -1, 8, RBL_MAX_TARGET_SIZE + 1, 1 << 30, -2147483647 - 1 };
    for (int i = 0; i < 5; i++) { RblShadowDesc d; memset(&d, 0, sizeof(d)); d.size = sizes[i]; EXPECT_REFUSED((m = RblLoadShadowMap(d), RblIsShadowMapValid(m))); }
    for (int fi = 0; fi < COUNT_OF(shadowDescFloats); fi++) for (int vi = 0; vi < 5; vi++)
    {
        RblShadowDesc d; memset(&d, 0, sizeof(d));
        SET_FIELD(d, shadowDescFloats[fi], badFloats[vi]);
        warnings = 0;
        m = RblLoadShadowMap(d);
        if (RblIsShadowMapValid(m)) ck(warnings == 0 && isfinite(m.desc.constantBias) && isfinite(m.desc.slopeBias) && isfinite(m.desc.normalBias) && isfinite(m.desc.minCastAngle), "shadow desc %s = %g accepted non-finite", shadowDescFloats[fi].name, badFloats[vi]);
        else ck(warnings == 1, "shadow desc %s = %g refused with %d lines", shadowDescFloats[fi].name, badFloats[vi], warnings);
        RblUnloadShadowMap(&m);
    }
    RblShadowMap zero; memset(&zero, 0, sizeof(zero));
    EXPECT_QUIET(RblIsShadowMapValid(zero), false);
    EXPECT_REFUSED(V(RblUnloadShadowMap(NULL)));
    RblShadowDesc d; memset(&d, 0, sizeof(d)); d.size = 64;
    m = RblLoadShadowMap(d);
    RblShadowMap stale = m;
    EXPECT_QUIET(RblIsShadowMapValid(m), true);
    RblUnloadShadowMap(&m);
    EXPECT_REFUSED(V(RblUnloadShadowMap(&m)));
    EXPECT_QUIET(RblIsShadowMapValid(stale), false);
    EXPECT_REFUSED(V(RblUnloadShadowMap(&stale)));
}

static void c_shadow_passes(void)
{
    RblShadowDesc d; memset(&d, 0, sizeof(d)); d.size = 64;
    RblShadowMap map = RblLoadShadowMap(d), other = RblLoadShadowMap(d), zero;
    memset(&zero, 0, sizeof(zero));
    RblLight l[2] = { pointLight(), pointLight() };
    l[0].type = RBL_LIGHT_DIRECTIONAL; l[0].direction = (Vector3){ 0.2f, -1.0f, 0.1f };
    RblScene scene; memset(&scene, 0, sizeof(scene)); scene.lights = l; scene.lightCount = 2;
    Vector3 o = { 0, 0, 0 };
    EXPECT_REFUSED(RblBeginShadowMap(NULL, &scene, 0, o, 5.0f));
    EXPECT_REFUSED(RblBeginShadowMap(&zero, &scene, 0, o, 5.0f));
    EXPECT_REFUSED(RblBeginShadowMap(&map, NULL, 0, o, 5.0f));
    EXPECT_REFUSED(RblBeginShadowMap(&map, &scene, 2, o, 5.0f));
    EXPECT_REFUSED(RblBeginShadowMap(&map, &scene, -1, o, 5.0f));
    EXPECT_REFUSED(RblBeginShadowMap(&map, &scene, 1, o, 5.0f));          // a point light casts no shadow
    for (int c = 0; c < 4; c++) for (int vi = 0; vi < 5; vi++)
    {
        Vector3 fc = o; float r = 5.0f;
        if (c < 3) ((float *)&fc)[c] = badFloats[vi]; else r = badFloats[vi];
        EXPECT_REFUSED(RblBeginShadowMap(&map, &scene, 0, fc, r));
    }
    EXPECT_REFUSED(RblBeginShadowMap(&map, &scene, 0, o, -1.0f));
    EXPECT_REFUSED(V(RblEndShadowMap(NULL)));
    EXPECT_REFUSED(V(RblEndShadowMap(&zero)));
    EXPECT_REFUSED(V(RblEndShadowMap(&map)));                              // never begun
    ck(RblBeginShadowMap(&map, &scene, 0, o, 5.0f), "good pass refused: %s", lastWarning);
    EXPECT_REFUSED(RblBeginShadowMap(&map, &scene, 0, o, 5.0f));          // nested, same
    EXPECT_REFUSED(RblBeginShadowMap(&other, &scene, 0, o, 5.0f));        // nested, other
    RblGBuffer g = RblLoadGBuffer(gdesc(0));
    EXPECT_REFUSED(RblBeginGBuffer(&g, camera()));                         // a G-buffer pass inside a shadow pass
    EXPECT_REFUSED(RblDrawDeferredLights(&g));
    EXPECT_REFUSED(V(RblEndShadowMap(&other)));
    RblEndShadowMap(&map);
    RblShadowMap stale = map;
    RblUnloadShadowMap(&map);
    EXPECT_REFUSED(RblBeginShadowMap(&stale, &scene, 0, o, 5.0f));
    EXPECT_REFUSED(V(RblEndShadowMap(&stale)));
    RblUnloadGBuffer(&g);
    RblUnloadShadowMap(&other);
}

// Omni and cascaded maps: desc combinations, pass indices, light types, the fit's inputs
static void c_shadow_omni_cascades(void)
{
    RblShadowMap m;
    int cascades[3] = { -1, 5, 1 << 30 };
    for (int i = 0; i < 3; i++) { RblShadowDesc d; memset(&d, 0, sizeof(d)); d.size = 64; d.cascades = cascades[i]; EXPECT_REFUSED((m = RblLoadShadowMap(d), RblIsShadowMapValid(m))); }
    {
        RblShadowDesc d; memset(&d, 0, sizeof(d)); d.size = 64; d.omni = true; d.cascades = 2;
        EXPECT_REFUSED((m = RblLoadShadowMap(d), RblIsShadowMapValid(m)));                 // both at once
        d.cascades = 0; d.size = RBL_MAX_TARGET_SIZE/3 + 1;
        EXPECT_REFUSED((m = RblLoadShadowMap(d), RblIsShadowMapValid(m)));                 // three faces across exceed the target size
        d.omni = false; d.cascades = 4; d.size = RBL_MAX_TARGET_SIZE/4 + 1;
        EXPECT_REFUSED((m = RblLoadShadowMap(d), RblIsShadowMapValid(m)));
        d.size = 64; d.cascadeLambda = 1.5f;
        EXPECT_REFUSED((m = RblLoadShadowMap(d), RblIsShadowMapValid(m)));
        d.cascadeLambda = 0.0f; d.cascadeBlend = 0.75f;
        EXPECT_REFUSED((m = RblLoadShadowMap(d), RblIsShadowMapValid(m)));
    }
    RblShadowDesc od; memset(&od, 0, sizeof(od)); od.size = 32; od.omni = true;
    RblShadowDesc cd; memset(&cd, 0, sizeof(cd)); cd.size = 32; cd.cascades = 3;
    RblShadowDesc sd; memset(&sd, 0, sizeof(sd)); sd.size = 32;
    RblShadowMap omni = RblLoadShadowMap(od), casc = RblLoadShadowMap(cd), single = RblLoadShadowMap(sd), zero;
    memset(&zero, 0, sizeof(zero));
    EXPECT_QUIET(RblShadowMapPasses(omni) == 6, true);
    EXPECT_QUIET(RblShadowMapPasses(casc) == 3, true);
    EXPECT_QUIET(RblShadowMapPasses(single) == 1, true);
    EXPECT_QUIET(RblShadowMapPasses(zero) == 0, true);
    RblLight l[3] = { pointLight(), pointLight(), pointLight() };
    l[0].type = RBL_LIGHT_DIRECTIONAL; l[0].direction = (Vector3){ 0.2f, -1.0f, 0.1f };
    l[2].type = RBL_LIGHT_SPOT; l[2].direction = (Vector3){ 0.0f, -1.0f, 0.0f }; l[2].outerAngle = 30.0f;
    RblScene scene; memset(&scene, 0, sizeof(scene)); scene.lights = l; scene.lightCount = 3;
    Vector3 o = { 0, 0, 0 };
    EXPECT_REFUSED(RblBeginShadowMapPass(&omni, &scene, 1, -1, o, 5.0f));
    EXPECT_REFUSED(RblBeginShadowMapPass(&omni, &scene, 1, 6, o, 5.0f));
    EXPECT_REFUSED(RblBeginShadowMapPass(&single, &scene, 0, 1, o, 5.0f));
    EXPECT_REFUSED(RblBeginShadowMapPass(&omni, &scene, 0, 0, o, 5.0f));          // omni map, directional light
    EXPECT_REFUSED(RblBeginShadowMapPass(&omni, &scene, 2, 0, o, 5.0f));          // omni map, spot light
    EXPECT_REFUSED(RblBeginShadowMapPass(&casc, &scene, 1, 0, o, 5.0f));          // cascades, point light
    EXPECT_REFUSED(RblBeginShadowMapPass(&casc, &scene, 0, 0, o, 5.0f));          // not fitted
    RblLight unbounded = pointLight(); unbounded.range = 0.0f;
    RblScene s2 = scene; s2.lights = &unbounded; s2.lightCount = 1;
    EXPECT_REFUSED(RblBeginShadowMapPass(&omni, &s2, 0, 0, o, 0.0f));            // no range, no focus
    EXPECT_REFUSED(RblFitShadowCascades(NULL, camera(), 1.0f, 0.1f, 10.0f));
    EXPECT_REFUSED(RblFitShadowCascades(&zero, camera(), 1.0f, 0.1f, 10.0f));
    EXPECT_REFUSED(RblFitShadowCascades(&single, camera(), 1.0f, 0.1f, 10.0f));
    EXPECT_REFUSED(V(RblDrawShadowCascades(single)));
    EXPECT_REFUSED(V(RblDrawShadowCascades(zero)));
    EXPECT_REFUSED(V(RblDrawShadowCascades(casc)));                              // not fitted
    EXPECT_QUIET(RblShadowCascadeColor(2).b == 241, true);
    EXPECT_QUIET(RblShadowCascadeColor(-1).r == GRAY.r && RblShadowCascadeColor(4).r == GRAY.r, true);
    EXPECT_REFUSED(RblFitShadowCascades(&omni, camera(), 1.0f, 0.1f, 10.0f));
    EVERY_BAD_CAMERA(RblFitShadowCascades(&casc, cam, 1.0f, 0.1f, 10.0f));
    for (int vi = 0; vi < 5; vi++)
    {
        EXPECT_REFUSED(RblFitShadowCascades(&casc, camera(), badFloats[vi], 0.1f, 10.0f));
        EXPECT_REFUSED(RblFitShadowCascades(&casc, camera(), 1.0f, badFloats[vi], 10.0f));
        if (vi != 3) EXPECT_REFUSED(RblFitShadowCascades(&casc, camera(), 1.0f, 0.1f, badFloats[vi]));
    }
    EXPECT_REFUSED(RblFitShadowCascades(&casc, camera(), 1.0f, 0.0f, 10.0f));      // near 0: no logarithmic split
    EXPECT_REFUSED(RblFitShadowCascades(&casc, camera(), 1.0f, 10.0f, 10.0f));
    EXPECT_REFUSED(RblFitShadowCascades(&casc, camera(), 1.0f, 0.1f, 3.0e38f));
    EXPECT_QUIET(RblFitShadowCascades(&casc, camera(), 1.0f, 0.1f, 10.0f), true);
    for (int c = 0; c < 3; c++)
    {
        ck(RblBeginShadowMapPass(&casc, &scene, 0, c, o, 0.0f), "cascade %d refused: %s", c, lastWarning);
        if (c == 1) EXPECT_REFUSED(RblFitShadowCascades(&casc, camera(), 1.0f, 0.1f, 10.0f));    // during its pass
        RblEndShadowMap(&casc);
    }
    for (int f = 0; f < 6; f++) { ck(RblBeginShadowMapPass(&omni, &scene, 1, f, o, 5.0f), "face %d refused: %s", f, lastWarning); RblEndShadowMap(&omni); }
    RblShadowMap stale = omni, staleCasc = casc;
    RblUnloadShadowMap(&omni);
    EXPECT_QUIET(RblShadowMapPasses(stale) == 0, true);
    EXPECT_REFUSED(RblBeginShadowMapPass(&stale, &scene, 1, 0, o, 5.0f));
    RblUnloadShadowMap(&casc);
    EXPECT_REFUSED(V(RblDrawShadowCascades(staleCasc)));
    RblUnloadShadowMap(&single);
}

static void c_shadow_blend(void)
{
    RblShadowDesc d; memset(&d, 0, sizeof(d)); d.size = 64;
    RblShadowMap plain = RblLoadShadowMap(d);
    d.transmittance = true;
    RblShadowMap map = RblLoadShadowMap(d);
    RblLight l = pointLight();
    l.type = RBL_LIGHT_DIRECTIONAL; l.direction = (Vector3){ 0.2f, -1.0f, 0.1f };
    RblScene scene; memset(&scene, 0, sizeof(scene)); scene.lights = &l; scene.lightCount = 1;
    Vector3 o = { 0, 0, 0 };
    EXPECT_REFUSED(RblBeginShadowBlend(true));                             // outside a pass
    EXPECT_REFUSED(V(RblEndShadowBlend()));
    ck(RblBeginShadowMap(&plain, &scene, 0, o, 5.0f), "good pass refused: %s", lastWarning);
    EXPECT_REFUSED(RblBeginShadowBlend(false));                            // no transmittance target
    RblEndShadowMap(&plain);
    ck(RblBeginShadowMap(&map, &scene, 0, o, 5.0f), "good pass refused: %s", lastWarning);
    EXPECT_REFUSED(V(RblEndShadowBlend()));                                // never begun
    ck(RblBeginShadowBlend(true), "good blend refused: %s", lastWarning);
    EXPECT_REFUSED(RblBeginShadowBlend(true));                             // nested
    RblEndShadowMap(&map);                                                 // ends the blend too
    EXPECT_REFUSED(V(RblEndShadowBlend()));
    RblShadowMap tiled;
    d.omni = true;                                                         // transmittance: single maps only
    EXPECT_REFUSED((tiled = RblLoadShadowMap(d), RblIsShadowMapValid(tiled)));
    d.omni = false; d.cascades = 2;
    EXPECT_REFUSED((tiled = RblLoadShadowMap(d), RblIsShadowMapValid(tiled)));
    RblUnloadShadowMap(&map);
    RblUnloadShadowMap(&plain);
}

static void c_shadow_focus(void)
{
    Vector3 c = { 7, 7, 7 }; float r = 7.0f;
    EXPECT_REFUSED(RblShadowFocusFromCamera(camera(), 1.0f, 0.1f, 10.0f, NULL, &r));
    EXPECT_REFUSED(RblShadowFocusFromCamera(camera(), 1.0f, 0.1f, 10.0f, &c, NULL));
    EVERY_BAD_CAMERA(RblShadowFocusFromCamera(cam, 1.0f, 0.1f, 10.0f, &c, &r));
    for (int vi = 0; vi < 5; vi++)
    {
        EXPECT_REFUSED(RblShadowFocusFromCamera(camera(), badFloats[vi], 0.1f, 10.0f, &c, &r));
        EXPECT_REFUSED(RblShadowFocusFromCamera(camera(), 1.0f, badFloats[vi], 10.0f, &c, &r));
        if (vi != 3) EXPECT_REFUSED(RblShadowFocusFromCamera(camera(), 1.0f, 0.1f, badFloats[vi], &c, &r));
    }
    EXPECT_REFUSED(RblShadowFocusFromCamera(camera(), 1.0f, 10.0f, 10.0f, &c, &r));
    EXPECT_REFUSED(RblShadowFocusFromCamera(camera(), 0.0f, 0.1f, 10.0f, &c, &r));
    EXPECT_REFUSED(RblShadowFocusFromCamera(camera(), 1.0f, 0.1f, 3.0e38f, &c, &r));
    ck(c.x == 7.0f && c.y == 7.0f && c.z == 7.0f && r == 7.0f, "refused calls wrote the outputs");
}

// ---- atlases and sprites (CPU) ----------------------------------------------------------------------
static const char atlasText[] = "{\"frames\": {\"a\": {\"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":8}, \"duration\": 100}, "
    "\"b\": {\"frame\": {\"x\":4,\"y\":0,\"w\":8,\"h\":4}, \"rotated\": true}}, "
    "\"meta\": {\"app\": \"aseprite\", \"size\": {\"w\":16,\"h\":16}, \"frameTags\": [{\"name\": \"t\", \"from\": 0, \"to\": 1, \"direction\": \"pingpong\"}]}}";
static RblAtlas goodAtlas(void) { return RblLoadAtlasFromMemory(atlasText, (int)strlen(atlasText), RBL_ATLAS_AUTO); }
static bool loadedFromMemory(const char *text, int size, int format) { RblAtlas a = RblLoadAtlasFromMemory(text, size, format); bool ok = RblIsAtlasValid(a); if (ok) RblUnloadAtlas(&a); return ok; }
static bool loadedFile(const char *name) { RblAtlas a = RblLoadAtlas(name); bool ok = RblIsAtlasValid(a); if (ok) RblUnloadAtlas(&a); return ok; }

static void c_atlas_load(void)
{
    int n = (int)strlen(atlasText);
    EXPECT_REFUSED(loadedFromMemory(NULL, n, 0));
    EXPECT_REFUSED(loadedFromMemory(atlasText, 0, 0));
    EXPECT_REFUSED(loadedFromMemory(atlasText, -5, 0));
    EXPECT_REFUSED(loadedFromMemory(atlasText, INT_MAX, 0));
    EXPECT_REFUSED(loadedFromMemory(atlasText, n, -1));
    EXPECT_REFUSED(loadedFromMemory(atlasText, n, 4));
    EXPECT_REFUSED(loadedFromMemory(atlasText, n, RBL_ATLAS_LIBGDX));     // JSON read as libGDX text
    EXPECT_REFUSED(loadedFromMemory(atlasText, n - 1, 0));                // truncated
    EXPECT_REFUSED(loadedFile(NULL));
    EXPECT_REFUSED(loadedFile(""));
    EXPECT_REFUSED(loadedFile("no/such/atlas.json"));
    ck(loadedFromMemory(atlasText, n, RBL_ATLAS_TEXTUREPACKER) && loadedFromMemory(atlasText, n, RBL_ATLAS_ASEPRITE), "good text refused: %s", lastWarning);
    // the entry cap (built here at RBL_MAX_ATLAS_ENTRIES 4096): JSON values, and rows of the frame
    // table (libGDX regions), each refused with the cap named in the line
    static char big[200000];
    int len = snprintf(big, sizeof(big), "{\"frames\": [");
    for (int i = 0; i < 600; i++) len += snprintf(big + len, sizeof(big) - (size_t)len, "%s{\"filename\": \"f\", \"frame\": {\"x\":0,\"y\":0,\"w\":1,\"h\":1}}", (i > 0)? "," : "");
    len += snprintf(big + len, sizeof(big) - (size_t)len, "]}");
    EXPECT_REFUSED(loadedFromMemory(big, len, 0));
    ck(strstr(lastWarning, "4096 JSON values (RBL_MAX_ATLAS_ENTRIES)") != NULL, "JSON cap not named: %s", lastWarning);
    len = snprintf(big, sizeof(big), "p.png\n");
    for (int i = 0; i < 4097; i++) len += snprintf(big + len, sizeof(big) - (size_t)len, "r\nxy:0,0\nsize:1,1\n");
    EXPECT_REFUSED(loadedFromMemory(big, len, 0));
    ck(strstr(lastWarning, "4096 frames (RBL_MAX_ATLAS_ENTRIES)") != NULL, "frame cap not named: %s", lastWarning);
}

static void c_atlas_lifecycle(void)
{
    RblAtlas zero; memset(&zero, 0, sizeof(zero));
    EXPECT_QUIET(RblIsAtlasValid(zero), false);
    RblAtlas a = goodAtlas(), stale = a;
    EXPECT_QUIET(RblIsAtlasValid(a), true);
    EXPECT_QUIET(RblAtlasFindFrame(&a, "b") == 1, true);
    EXPECT_QUIET(RblAtlasFindTag(&a, "nope") == -1, true);
    EXPECT_REFUSED(RblAtlasFindFrame(&a, NULL) >= 0);
    EXPECT_REFUSED(RblAtlasFindTag(&a, NULL) >= 0);
    EXPECT_REFUSED(RblAtlasFindFrame(NULL, "a") >= 0);
    EXPECT_REFUSED(RblAtlasFindTag(&zero, "t") >= 0);
    EXPECT_REFUSED(V(RblUnloadAtlas(NULL)));
    EXPECT_REFUSED(V(RblUnloadAtlas(&zero)));
    RblUnloadAtlas(&a);
    ck(a.state == NULL && a.frames == NULL && a.frameCount == 0, "unload did not zero");
    EXPECT_REFUSED(V(RblUnloadAtlas(&a)));
    EXPECT_REFUSED(V(RblUnloadAtlas(&stale)));
    EXPECT_QUIET(RblIsAtlasValid(stale), false);
    EXPECT_REFUSED(RblAtlasFindFrame(&stale, "a") >= 0);
    EXPECT_REFUSED(RblAtlasFindTag(&stale, "t") >= 0);
}

static void c_atlas_quads(void)
{
    RblAtlas a = goodAtlas(), zero; memset(&zero, 0, sizeof(zero));
    RblBillboard b, b0; memset(&b, 0x5A, sizeof(b)); b0 = b;
    RblInstance in, in0; memset(&in, 0x5A, sizeof(in)); in0 = in;
    EXPECT_REFUSED(RblAtlasBillboard(&a, 0, 1.0f, NULL));
    EXPECT_REFUSED(RblAtlasInstance(&a, 0, 1.0f, NULL));
    EXPECT_REFUSED(RblAtlasBillboard(NULL, 0, 1.0f, &b));
    EXPECT_REFUSED(RblAtlasInstance(&zero, 0, 1.0f, &in));
    for (int f = -1; f <= 2; f += 3) { EXPECT_REFUSED(RblAtlasBillboard(&a, f, 1.0f, &b)); EXPECT_REFUSED(RblAtlasInstance(&a, f, 1.0f, &in)); }
    float scales[4] = { 0.0f, -1.0f, 2e15f, 1e-45f };
    for (int vi = 0; vi < 9; vi++)
    {
        float s = (vi < 5)? badFloats[vi] : scales[vi - 5];
        if (vi == 8) continue;      // the smallest denormal is a valid (tiny) scale
        EXPECT_REFUSED(RblAtlasBillboard(&a, 0, s, &b));
        EXPECT_REFUSED(RblAtlasInstance(&a, 1, s, &in));
    }
    ck(memcmp(&b, &b0, sizeof(b)) == 0 && memcmp(&in, &in0, sizeof(in)) == 0, "refused calls wrote their outputs");
    ck(RblAtlasBillboard(&a, 1, 1e15f, &b) && allFinite(&b.size.x, 2) && allFinite(&b.origin.x, 2), "largest scale: non-finite or refused");
    ck(RblAtlasInstance(&a, 0, 1e-45f, &in) && allFinite(&in.size.x, 2), "tiny scale refused");
    RblAtlas stale = a;
    RblUnloadAtlas(&a);
    EXPECT_REFUSED(RblAtlasBillboard(&stale, 0, 1.0f, &b));
}

// Slice keys as sub-frames: NULL outputs and names, zero and stale atlases, keys and frames out of
// range, a key at a frame it does not cover, a key outside the frame's drawn pixels, bad scales;
// outputs untouched; accepted extremes finite
static void c_atlas_slices(void)
{
    static const char text[] = "{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":8}, \"trimmed\": true, \"spriteSourceSize\": {\"x\":2,\"y\":0,\"w\":4,\"h\":8},"
        " \"sourceSize\": {\"w\":8,\"h\":8}}, {\"filename\": \"b\", \"frame\": {\"x\":4,\"y\":0,\"w\":8,\"h\":8}}], \"meta\": {\"app\": \"aseprite\", \"size\": {\"w\":16,\"h\":16},"
        " \"scale\": \"0.5\", \"slices\": [{\"name\": \"s\", \"keys\": [{\"frame\": 1, \"bounds\": {\"x\":0,\"y\":0,\"w\":2,\"h\":2}, \"pivot\": {\"x\":1,\"y\":1}}]},"
        " {\"name\": \"edge\", \"keys\": [{\"frame\": 0, \"bounds\": {\"x\":0,\"y\":0,\"w\":2,\"h\":8}}]}]}}";
    RblAtlas a = RblLoadAtlasFromMemory(text, (int)strlen(text), RBL_ATLAS_AUTO), zero; memset(&zero, 0, sizeof(zero));
    ck(RblIsAtlasValid(a) && a.sliceCount == 2, "fixture: %s", lastWarning);
    RblBillboard b, b0; memset(&b, 0x5A, sizeof(b)); b0 = b;
    RblInstance in, in0; memset(&in, 0x5A, sizeof(in)); in0 = in;
    EXPECT_QUIET(RblAtlasFindSlice(&a, "s", 1) == 0, true);
    EXPECT_QUIET(RblAtlasFindSlice(&a, "s", 0) == -1, true);
    EXPECT_QUIET(RblAtlasFindSlice(&a, "edge", 1) == 1, true);
    EXPECT_REFUSED(RblAtlasFindSlice(&a, NULL, 0) >= 0);
    EXPECT_REFUSED(RblAtlasFindSlice(&a, "s", -1) >= 0);
    EXPECT_REFUSED(RblAtlasFindSlice(&a, "s", 2) >= 0);
    EXPECT_REFUSED(RblAtlasFindSlice(NULL, "s", 0) >= 0);
    EXPECT_REFUSED(RblAtlasFindSlice(&zero, "s", 0) >= 0);
    EXPECT_REFUSED(RblAtlasSliceBillboard(&a, 0, 1, 1.0f, NULL));
    EXPECT_REFUSED(RblAtlasSliceInstance(&a, 0, 1, 1.0f, NULL));
    EXPECT_REFUSED(RblAtlasSliceBillboard(NULL, 0, 1, 1.0f, &b));
    EXPECT_REFUSED(RblAtlasSliceInstance(&zero, 0, 1, 1.0f, &in));
    const int keys[2] = { -1, 2 }, frames[2] = { -1, 2 };
    for (int k = 0; k < 2; k++)
    {
        EXPECT_REFUSED(RblAtlasSliceBillboard(&a, keys[k], 1, 1.0f, &b));
        EXPECT_REFUSED(RblAtlasSliceInstance(&a, 0, frames[k], 1.0f, &in));
    }
    EXPECT_REFUSED(RblAtlasSliceBillboard(&a, 0, 0, 1.0f, &b));     // key 0 covers frame 1 only
    EXPECT_REFUSED(RblAtlasSliceInstance(&a, 1, 0, 1.0f, &in));     // "edge" lies left of frame 0's trim
    const float scales[3] = { 0.0f, -1.0f, 2e15f };
    for (int vi = 0; vi < 8; vi++)
    {
        float sc = (vi < 5)? badFloats[vi] : scales[vi - 5];
        EXPECT_REFUSED(RblAtlasSliceBillboard(&a, 0, 1, sc, &b));
        EXPECT_REFUSED(RblAtlasSliceInstance(&a, 1, 1, sc, &in));
    }
    ck(memcmp(&b, &b0, sizeof(b)) == 0 && memcmp(&in, &in0, sizeof(in)) == 0, "refused calls wrote their outputs");
    ck(RblAtlasSliceBillboard(&a, 0, 1, 1e15f, &b) && allFinite(&b.size.x, 2) && allFinite(&b.origin.x, 2) && allFinite(&b.source.x, 4), "largest scale: non-finite or refused");
    ck(RblAtlasSliceInstance(&a, 1, 1, 1e-45f, &in) && allFinite(&in.size.x, 2) && allFinite(&in.origin.x, 2), "tiny scale refused");
    RblAtlas stale = a;
    RblUnloadAtlas(&a);
    EXPECT_REFUSED(RblAtlasSliceBillboard(&stale, 0, 1, 1.0f, &b));
    EXPECT_REFUSED(RblAtlasFindSlice(&stale, "s", 1) >= 0);
}

// A page's textures into a Material: NULL and stale atlases, pages, materials, a suffix naming no
// file, a normal sheet of another size, a sheet not of the stated size, a sheet not found; nothing
// changes in the material on refusal; the accepted calls fill the slots and the layout
static void c_atlas_textures(void)
{
    MakeDirectory("build/tests/contracts");
    Image img = GenImageColor(16, 16, RED);
    ExportImage(img, "build/tests/contracts/sheet.png");
    ExportImage(img, "build/tests/contracts/sheet_n.png");
    ExportImage(img, "build/tests/contracts/wrong.png");
    UnloadImage(img);
    img = GenImageColor(8, 8, BLUE);
    ExportImage(img, "build/tests/contracts/sheet_small.png");
    ExportImage(img, "build/tests/contracts/wrong_n.png");
    UnloadImage(img);
    SaveFileText("build/tests/contracts/sheet.json", (char *)"{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}], \"meta\": {\"image\": \"sheet.png\", \"size\": {\"w\":16,\"h\":16}}}");
    SaveFileText("build/tests/contracts/big.json", (char *)"{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}], \"meta\": {\"image\": \"sheet.png\", \"size\": {\"w\":32,\"h\":32}}}");
    SaveFileText("build/tests/contracts/wrong.json", (char *)"{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}], \"meta\": {\"image\": \"wrong.png\"}}");
    static const char memText[] = "{\"frames\": [{\"filename\": \"a\", \"frame\": {\"x\":0,\"y\":0,\"w\":4,\"h\":4}}], \"meta\": {\"image\": \"nowhere.png\"}}";
    RblAtlas a = RblLoadAtlas("build/tests/contracts/sheet.json"), big = RblLoadAtlas("build/tests/contracts/big.json"), wrong = RblLoadAtlas("build/tests/contracts/wrong.json");
    RblAtlas mem = RblLoadAtlasFromMemory(memText, (int)strlen(memText), RBL_ATLAS_AUTO), zero; memset(&zero, 0, sizeof(zero));
    ck(RblIsAtlasValid(a) && RblIsAtlasValid(big) && RblIsAtlasValid(wrong) && RblIsAtlasValid(mem) && (a.pages[0].normalImage != NULL), "fixtures: %s", lastWarning);
    Material m = LoadMaterialDefault(), noMaps = m;
    noMaps.maps = NULL;
    Material keep = m;
    Texture2D t0 = m.maps[MATERIAL_MAP_ALBEDO].texture, t2 = m.maps[MATERIAL_MAP_NORMAL].texture;
    RblMaterialLayout layout, layout0; memset(&layout, 0x5A, sizeof(layout)); layout0 = layout;
    EXPECT_REFUSED(RblLoadAtlasTextures(NULL, 0, NULL, &m, &layout));
    EXPECT_REFUSED(RblLoadAtlasTextures(&zero, 0, NULL, &m, &layout));
    EXPECT_REFUSED(RblLoadAtlasTextures(&a, -1, NULL, &m, &layout));
    EXPECT_REFUSED(RblLoadAtlasTextures(&a, 1, NULL, &m, &layout));
    EXPECT_REFUSED(RblLoadAtlasTextures(&a, 0, NULL, NULL, &layout));
    EXPECT_REFUSED(RblLoadAtlasTextures(&a, 0, NULL, &noMaps, &layout));
    EXPECT_REFUSED(RblLoadAtlasTextures(&a, 0, "_none", &m, &layout));       // sheet_none.png does not exist
    EXPECT_REFUSED(RblLoadAtlasTextures(&a, 0, "_small", &m, &layout));      // 8x8 beside a 16x16 sheet
    EXPECT_REFUSED(RblLoadAtlasTextures(&big, 0, NULL, &m, &layout));        // stated 32x32, the file 16x16
    EXPECT_REFUSED(RblLoadAtlasTextures(&wrong, 0, NULL, &m, &layout));      // its "_n" sheet is 8x8
    EXPECT_REFUSED(RblLoadAtlasTextures(&mem, 0, NULL, &m, &layout));        // as written, nowhere
    ck(memcmp(&m, &keep, sizeof(m)) == 0 && memcmp(&m.maps[MATERIAL_MAP_ALBEDO].texture, &t0, sizeof(t0)) == 0 && memcmp(&m.maps[MATERIAL_MAP_NORMAL].texture, &t2, sizeof(t2)) == 0 &&
       memcmp(&layout, &layout0, sizeof(layout)) == 0, "refused calls changed the material or the layout");
    // accepted: the sheet and its "_n" sheet; "" loads the sheet alone (the normal slot kept)
    EXPECT_QUIET(RblLoadAtlasTextures(&a, 0, NULL, &m, &layout), true);
    ck(m.maps[MATERIAL_MAP_ALBEDO].texture.width == 16 && m.maps[MATERIAL_MAP_NORMAL].texture.width == 16 && layout.normalEncoding == RBL_NORMAL_RGB && !layout.premultipliedAlpha, "loaded slots");
    Texture2D loaded[2] = { m.maps[MATERIAL_MAP_ALBEDO].texture, m.maps[MATERIAL_MAP_NORMAL].texture };
    EXPECT_QUIET(RblLoadAtlasTextures(&a, 0, "", &m, NULL), true);
    ck(m.maps[MATERIAL_MAP_NORMAL].texture.id == loaded[1].id && m.maps[MATERIAL_MAP_ALBEDO].texture.id != loaded[0].id, "\"\": the normal slot changed");
    UnloadTexture(loaded[0]); UnloadTexture(loaded[1]); UnloadTexture(m.maps[MATERIAL_MAP_ALBEDO].texture);
    MemFree(m.maps);
    RblAtlas stale = a;
    RblUnloadAtlas(&a);
    EXPECT_REFUSED(RblLoadAtlasTextures(&stale, 0, NULL, &keep, NULL));
    RblUnloadAtlas(&big); RblUnloadAtlas(&wrong); RblUnloadAtlas(&mem);
}

// Cross-fade quads: NULL outputs, atlases, frames (either), weights, scales, stale; outputs
// untouched; a good pair of equal frames is the single frame's quad, unclipped
static void c_atlas_fade_quads(void)
{
    RblAtlas a = goodAtlas(), zero; memset(&zero, 0, sizeof(zero));
    RblBillboard b, b0; memset(&b, 0x5A, sizeof(b)); b0 = b;
    RblInstance in, in0; memset(&in, 0x5A, sizeof(in)); in0 = in;
    RblFade f, f0; memset(&f, 0x5A, sizeof(f)); f0 = f;
    RblBillboard one0; RblInstance in1; RblFade f1, f2;         // outputs of accepted calls
    EXPECT_REFUSED(RblAtlasBillboardFade(&a, 0, 1, 0.5f, 1.0f, NULL, &f));
    EXPECT_REFUSED(RblAtlasBillboardFade(&a, 0, 1, 0.5f, 1.0f, &b, NULL));
    EXPECT_REFUSED(RblAtlasInstanceFade(&a, 0, 1, 0.5f, 1.0f, NULL, &f));
    EXPECT_REFUSED(RblAtlasInstanceFade(&a, 0, 1, 0.5f, 1.0f, &in, NULL));
    EXPECT_REFUSED(RblAtlasBillboardFade(NULL, 0, 1, 0.5f, 1.0f, &b, &f));
    EXPECT_REFUSED(RblAtlasInstanceFade(&zero, 0, 1, 0.5f, 1.0f, &in, &f));
    const int frames[4] = { -1, 2, INT_MIN, INT_MAX };
    for (int k = 0; k < 4; k++)
    {
        EXPECT_REFUSED(RblAtlasBillboardFade(&a, frames[k], 1, 0.5f, 1.0f, &b, &f));
        EXPECT_REFUSED(RblAtlasBillboardFade(&a, 0, frames[k], 0.5f, 1.0f, &b, &f));
        EXPECT_REFUSED(RblAtlasInstanceFade(&a, frames[k], 0, 0.5f, 1.0f, &in, &f));
        EXPECT_REFUSED(RblAtlasInstanceFade(&a, 1, frames[k], 0.5f, 1.0f, &in, &f));
    }
    const float weights[4] = { -1e-7f, -0.5f, 1.0000001f, 2.0f };
    for (int vi = 0; vi < 9; vi++)
    {
        float w = (vi < 5)? badFloats[vi] : weights[vi - 5];
        EXPECT_REFUSED(RblAtlasBillboardFade(&a, 0, 1, w, 1.0f, &b, &f));
        EXPECT_REFUSED(RblAtlasInstanceFade(&a, 1, 0, w, 1.0f, &in, &f));
    }
    const float scales[4] = { 0.0f, -1.0f, 2e15f, -1e-45f };
    for (int vi = 0; vi < 9; vi++)
    {
        float sc = (vi < 5)? badFloats[vi] : scales[vi - 5];
        EXPECT_REFUSED(RblAtlasBillboardFade(&a, 0, 1, 0.5f, sc, &b, &f));
        EXPECT_REFUSED(RblAtlasInstanceFade(&a, 1, 0, 0.5f, sc, &in, &f));
    }
    // Frames on different sheets (one texture is sampled); a frame with an empty trim cannot reach the
    // fade: the importer refuses the atlas
    static const char twoSheets[] = "sheet.png\nsize:64,32\na\nbounds:1,2,10,6\nb\nbounds:20,0,4,4\n\nsecond.png\nsize:8,8\nc\nbounds:0,0,8,8\n";
    static const char emptyTrim[] = "sheet.png\nsize:64,32\na\nbounds:1,2,10,6\nb\nbounds:20,0,0,0\n";
    RblAtlas p = RblLoadAtlasFromMemory(twoSheets, (int)strlen(twoSheets), RBL_ATLAS_LIBGDX);
    ck(RblIsAtlasValid(p) && (p.pageCount == 2) && (p.frameCount == 3) && (p.frames[2].page == 1), "two-sheet atlas: valid %d, %d pages, %d frames",
       RblIsAtlasValid(p), p.pageCount, p.frameCount);
    if (RblIsAtlasValid(p) && (p.frameCount == 3))
    {
        EXPECT_REFUSED(RblAtlasBillboardFade(&p, 0, 2, 0.5f, 1.0f, &b, &f));
        EXPECT_REFUSED(RblAtlasInstanceFade(&p, 2, 1, 0.5f, 1.0f, &in, &f));
        ck(RblAtlasBillboardFade(&p, 0, 1, 0.5f, 1.0f, &one0, &f1) && RblAtlasInstanceFade(&p, 1, 0, 0.5f, 1.0f, &in1, &f2), "frames of one sheet refused: %s", lastWarning);
    }
    RblUnloadAtlas(&p);
    EXPECT_REFUSED(loadedFromMemory(emptyTrim, (int)strlen(emptyTrim), RBL_ATLAS_LIBGDX));
    ck(memcmp(&b, &b0, sizeof(b)) == 0 && memcmp(&in, &in0, sizeof(in)) == 0 && memcmp(&f, &f0, sizeof(f)) == 0, "refused calls wrote their outputs");
    RblBillboard one; memset(&one, 0, sizeof(one)); memset(&b, 0, sizeof(b));
    RblFade bf; memset(&bf, 0, sizeof(bf));
    ck(RblAtlasBillboard(&a, 1, 2.0f, &one) && RblAtlasBillboardFade(&a, 1, 1, 0.25f, 2.0f, &b, &bf) && memcmp(&one.source, &b.source, sizeof(Rectangle)) == 0 &&
       memcmp(&one.size, &b.size, sizeof(Vector2)) == 0 && memcmp(&one.origin, &b.origin, sizeof(Vector2)) == 0 && b.flags == one.flags && bf.weight == 0.25f &&
       bf.clip[0].x == 0.0f && bf.clip[0].width == 1.0f && bf.clip[1].y == 0.0f && bf.clip[1].height == 1.0f, "equal frames: not the single frame's quad");
    ck(RblAtlasInstanceFade(&a, 0, 1, 1.0f, 1e15f, &in, &f) && allFinite(&in.size.x, 2) && allFinite(&in.origin.x, 2) && allFinite(&f.clip[0].x, 8) && allFinite(&f.source.x, 4), "largest scale: non-finite or refused");
    RblAtlas stale = a;
    RblUnloadAtlas(&a);
    EXPECT_REFUSED(RblAtlasBillboardFade(&stale, 0, 1, 0.5f, 1.0f, &b, &f));
    EXPECT_REFUSED(RblAtlasInstanceFade(&stale, 0, 1, 0.5f, 1.0f, &in, &f));
}

static bool played(const RblAtlas *a, int tag, int loops) { RblSpritePlayer p = RblPlaySprite(a, tag, loops); return p.tag == tag; }
static void c_sprites(void)
{
    RblAtlas a = goodAtlas(), zero; memset(&zero, 0, sizeof(zero));
    EXPECT_REFUSED(played(NULL, 0, 0));
    EXPECT_REFUSED(played(&zero, 0, 0));
    EXPECT_REFUSED(played(&a, -2, 0));
    EXPECT_REFUSED(played(&a, 1, 0));
    EXPECT_REFUSED(played(&a, 0, -2));
    ck(played(&a, 0, 0) && played(&a, -1, -1), "good play refused: %s", lastWarning);
    RblSpritePlayer p = RblPlaySprite(&a, 0, 0), p0 = p;
    EXPECT_REFUSED(RblUpdateSprite(NULL, &a, 0.1f));
    EXPECT_REFUSED(RblUpdateSprite(&p, NULL, 0.1f));
    EXPECT_REFUSED(RblUpdateSprite(&p, &zero, 0.1f));
    for (int vi = 0; vi < 3; vi++) EXPECT_REFUSED(RblUpdateSprite(&p, &a, badFloats[vi]));
    EXPECT_REFUSED(RblUpdateSprite(&p, &a, -0.5f));
    ck(memcmp(&p, &p0, sizeof(p)) == 0, "refused updates changed the player");
    // a player not made by RblPlaySprite for this atlas: refused, untouched
    RblSpritePlayer bad[7];
    for (int k = 0; k < 7; k++) bad[k] = p0;
    bad[0].frame = 5; bad[1].step = 0; bad[2].time = NAN; bad[3].loops = -1; bad[4].passes = -1; bad[5].tag = 3; bad[6].time = -1.0f;
    for (int k = 0; k < 7; k++)
    {
        RblSpritePlayer before = bad[k];
        int next = 77;
        EXPECT_REFUSED(RblUpdateSprite(&bad[k], &a, 0.1f));
        EXPECT_REFUSED(RblSpriteBlend(&bad[k], &a, &next) > 0.0f || next != 77);
        ck(memcmp(&bad[k], &before, sizeof(before)) == 0 && next == 77, "corrupt player %d changed", k);
    }
    int next = 77;
    EXPECT_REFUSED(RblSpriteBlend(&p, &a, NULL) > 0.0f);
    EXPECT_REFUSED(RblSpriteBlend(NULL, &a, &next) > 0.0f || next != 77);
    EXPECT_REFUSED(RblSpriteBlend(&p, &zero, &next) > 0.0f || next != 77);
    // accepted extremes: the largest finite dt, then the player stays inside its tag with finite time
    ck(RblUpdateSprite(&p, &a, 3.0e38f) && (p.frame >= 0) && (p.frame <= 1) && allFinite(&p.time, 1), "huge dt: frame %d time %g", p.frame, p.time);
    // bulk: refusals change nothing; bad players are skipped entries (one line for the call)
    RblSpritePlayer ps[2] = { p0, p0 };
    RblInstance is[2]; memset(is, 0x5A, sizeof(is));
    RblInstance is0[2]; memcpy(is0, is, sizeof(is));
    EXPECT_REFUSED(RblUpdateSpriteInstances(ps, is, 2, NULL, 0.1f, 1.0f) > 0);
    EXPECT_REFUSED(RblUpdateSpriteInstances(ps, is, 2, &zero, 0.1f, 1.0f) > 0);
    EXPECT_REFUSED(RblUpdateSpriteInstances(NULL, is, 2, &a, 0.1f, 1.0f) > 0);
    EXPECT_REFUSED(RblUpdateSpriteInstances(ps, NULL, 2, &a, 0.1f, 1.0f) > 0);
    EXPECT_REFUSED(RblUpdateSpriteInstances(ps, is, -1, &a, 0.1f, 1.0f) > 0);
    EXPECT_REFUSED(RblUpdateSpriteInstances(ps, is, INT_MIN, &a, 0.1f, 1.0f) > 0);
    for (int vi = 0; vi < 5; vi++)
    {
        if (vi < 3) EXPECT_REFUSED(RblUpdateSpriteInstances(ps, is, 2, &a, badFloats[vi], 1.0f) > 0);
        EXPECT_REFUSED(RblUpdateSpriteInstances(ps, is, 2, &a, 0.1f, badFloats[vi]) > 0);
    }
    EXPECT_REFUSED(RblUpdateSpriteInstances(ps, is, 2, &a, -1.0f, 1.0f) > 0);
    EXPECT_REFUSED(RblUpdateSpriteInstances(ps, is, 2, &a, 0.1f, 0.0f) > 0);
    ck(memcmp(is, is0, sizeof(is)) == 0 && memcmp(&ps[0], &p0, sizeof(p0)) == 0, "refused bulk updates wrote");
    ps[1].frame = 9;
    warnings = 0;
    ck(RblUpdateSpriteInstances(ps, is, 2, &a, 3.0e38f, 1e15f) == 1 && warnings == 1 && allFinite(&is[0].size.x, 2) && allFinite(&is[0].origin.x, 2) &&
       memcmp(&is[1], &is0[1], sizeof(RblInstance)) == 0, "bulk with one bad player: %d lines", warnings);
    // N-way sectors
    Vector3 v = { 0, 0, -1 };
    for (int d = -1; d <= 361; d += 362) EXPECT_REFUSED(RblSpriteViewSector(v, 0.0f, d) >= 0);
    EXPECT_REFUSED(RblSpriteViewSector(v, 0.0f, 0) >= 0);
    for (int c = 0; c < 4; c++) for (int vi = 0; vi < 3; vi++)
    {
        Vector3 w = v; float facing = 0.0f;
        if (c < 3) ((float *)&w)[c] = badFloats[vi]; else facing = badFloats[vi];
        EXPECT_REFUSED(RblSpriteViewSector(w, facing, 8) >= 0);
    }
    EXPECT_REFUSED(RblSpriteViewSector(v, 3.0e38f, 8) >= 0);
    int s = RblSpriteViewSector((Vector3){ 3.0e38f, -3.0e38f, 3.0e38f }, 1e9f, 16);
    ck(s >= 0 && s < 16, "huge finite view: sector %d", s);
    RblUnloadAtlas(&a);
}

// A billboard refused by the immediate path and by a batch, each with one line and nothing changed
static void expectBillboardRefused(Material m, RblBillboard b)
{
    EXPECT_REFUSED(V(RblDrawBillboard(camera(), m, b)));
    RblBatch batch = RblLoadBatch(2);
    RblBeginBatch(&batch, camera());
    EXPECT_REFUSED(RblBatchAdd(&batch, m, &b));
    RblEndBatch(&batch);
    RblUnloadBatch(&batch);
}

// The same for a cross-fade (fade NULL: the batch's entry point only, the immediate one takes a value)
static void expectFadeRefused(Material m, RblBillboard b, const RblFade *f)
{
    if (f != NULL) EXPECT_REFUSED(V(RblDrawBillboardFade(camera(), m, b, *f)));
    RblBatch batch = RblLoadBatch(2);
    RblBeginBatch(&batch, camera());
    EXPECT_REFUSED(RblBatchAddFade(&batch, m, &b, f));
    ck(batch.count == 0 && batch.skipped == 1, "refused fade: count %d, skipped %d", batch.count, batch.skipped);
    RblEndBatch(&batch);
    RblUnloadBatch(&batch);
}

// Cross-fades: a player's fade is RblAtlasBillboardFade of RblSpriteBlend's pair (the one way to set
// one up); a fade weight outside 0..1 or NaN/Inf fade floats are refused on every path (one line; an
// instanced draw skips that instance and draws the rest, its fades still paired)
static void c_fades(void)
{
    RblAtlas a = goodAtlas();
    RblSpritePlayer p = RblPlaySprite(&a, 0, 0);
    RblFade f;
    RblBillboard fb; memset(&fb, 0, sizeof(fb));
    int next = -1;
    p.time = 0.05f;
    float w = RblSpriteBlend(&p, &a, &next);
    bool faded = RblAtlasBillboardFade(&a, p.frame, next, w, 0.01f, &fb, &f);
    ck(faded && (f.weight == w) && isfinite(f.weight) && (f.weight >= 0.0f) && (f.weight <= 1.0f), "good fade: %d, weight %g (blend %g), frame %d", faded, f.weight, w, next);
    RblUnloadAtlas(&a);

    // Weights outside 0..1 on the billboard paths (NaN/Inf ride with billboardFloats)
    RblLitShaderDesc fd = descOf(RBL_BRDF_LAMBERT, false, false);
    fd.crossFade = true;
    Material m = litMaterial(fd);
    const float outside[4] = { -1e-7f, -0.5f, 1.0000001f, 2.0f };
    RblFade none; memset(&none, 0, sizeof(none));
    for (int k = 0; k < 4; k++)
    {
        RblFade bf = none;
        bf.weight = outside[k];
        expectFadeRefused(m, billboard(), &bf);
    }
    expectFadeRefused(m, billboard(), NULL);
    for (int fi = 0; fi < COUNT_OF(fadeFloats); fi++) for (int vi = 0; vi < 5; vi++)
    {
        RblFade bf = none;
        bf.weight = 0.5f;
        SET_FIELD(bf, fadeFloats[fi], badFloats[vi]);
        expectFadeRefused(m, billboard(), &bf);
    }
    // The plain entry points never read a fade: a good billboard added beside bad fades is drawn
    {
        RblBatch batch = RblLoadBatch(2);
        RblBillboard b = billboard();
        RblBeginBatch(&batch, camera());
        ck(RblBatchAdd(&batch, m, &b) && batch.count == 1 && batch.skipped == 0, "plain billboard in a crossFade batch refused");
        RblEndBatch(&batch);
        RblUnloadBatch(&batch);
    }
    // Instanced: every fade float bad, and weights outside 0..1: that instance skipped, one line
    RblLitShaderDesc id = descOf(RBL_BRDF_LAMBERT, true, false);
    id.crossFade = true;
    Material inst = litMaterial(id);
    RblInstanceBuffer buf = RblLoadInstanceBuffer(2);
    RblInstancedDesc d; memset(&d, 0, sizeof(d));
    // Finite clip rectangles the shaders cannot divide by: negative, zero (with others set), tiny, huge
    const Rectangle badClips[6] = { { 0, 0, -1, 1 }, { 0.5f, 0, 0, 1 }, { 0, 0, 1, 1e-7f }, { 0, 0, 2e6f, 1 }, { 2e6f, 0, 1, 1 }, { 0, -2e6f, 1, 1 } };
    for (int k = 0; k < 12; k++)
    {
        RblFade bf = none;
        bf.weight = 0.5f;
        bf.clip[k & 1] = badClips[k/2];
        expectFadeRefused(m, billboard(), &bf);
    }
    for (int fi = 0; fi < 13*5 + 4 + 12; fi++)  // source x, y, width, height, weight, (flags skipped) 8 clip floats x every bad float; weights outside 0..1; bad clips
    {
        RblInstance x[2] = { instance(), instance() };
        RblFade fades[2]; memset(fades, 0, sizeof(fades));
        fades[0].weight = fades[1].weight = 0.5f;
        if (fi < 65) ((float *)&fades[1])[(fi/5 < 5)? fi/5 : fi/5 + 1] = badFloats[fi % 5];
        else if (fi < 69) fades[1].weight = outside[fi - 65];
        else fades[1].clip[(fi - 69) & 1] = badClips[(fi - 69)/2];
        d.fades = fades;
        warnings = 0;
        int n = RblDrawInstanced(&buf, camera(), inst, d, x, 2);
        ck(n == 1 && warnings == 1 && buf.skipped == 1, "bad fade case %d: drawn %d, %d lines, skipped %d", fi, n, warnings, buf.skipped);
    }
    RblUnloadInstanceBuffer(&buf);
}

// ---- cases: held like raylib (stale copies, raylib's unloads, NULL inside raylib structs) -----------
// A tiny program of the caller's own (raylib's default vertex stage): what a raylib user loads
static Shader ownShader(void)
{
    static const char *fs330 = "#version 330\nin vec2 fragTexCoord;\nin vec4 fragColor;\nuniform sampler2D texture0;\nuniform vec4 colDiffuse;\nout vec4 finalColor;\nvoid main() { finalColor = texture(texture0, fragTexCoord)*colDiffuse*fragColor; }\n";
    return LoadShaderFromMemory(NULL, fs330);
}

// Every header draw of m, one at a time, each refused with one line and nothing changed (a stale or
// broken Material is never read past its shader: ASan fails the case if it is)
static void expectEveryDrawRefused(Material m, const char *what)
{
    RblBillboard b = billboard();
    printf("      %s\n", what);
    expectBillboardRefused(m, b);
    Mesh cube = GenMeshCube(1, 1, 1);
    EXPECT_REFUSED(V(RblDrawMesh(cube, m, MatrixIdentity())));
    Model model = LoadModelFromMesh(cube);
    Material *own = model.materials;
    model.materials = &m;
    model.materialCount = 1;
    EXPECT_REFUSED(V(RblDrawModel(model, (Vector3){ 0, 0, 0 }, 1.0f, WHITE)));
    model.materials = own;
    UnloadModel(model);
    // Inside a shadow pass every material casts through the header's casters: still refused
    RblShadowDesc sd; memset(&sd, 0, sizeof(sd)); sd.size = 64;
    RblShadowMap map = RblLoadShadowMap(sd);
    RblLight sun = pointLight(); sun.type = RBL_LIGHT_DIRECTIONAL; sun.direction = (Vector3){ 0.2f, -1.0f, 0.1f };
    RblScene scene; memset(&scene, 0, sizeof(scene)); scene.lights = &sun; scene.lightCount = 1;
    if (RblBeginShadowMap(&map, &scene, 0, (Vector3){ 0, 0, 0 }, 4.0f))
    {
        EXPECT_REFUSED(V(RblDrawBillboard(camera(), m, b)));
        RblEndShadowMap(&map);
    }
    RblUnloadShadowMap(&map);
}

static void expectInstancedRefused(Material m)
{
    RblInstanceBuffer buf = RblLoadInstanceBuffer(2);
    RblInstance x = instance();
    RblInstancedDesc d; memset(&d, 0, sizeof(d));
    EXPECT_REFUSED(RblDrawInstanced(&buf, camera(), m, d, &x, 1) > 0);
    RblUnloadInstanceBuffer(&buf);
}

// ---- resident sprite buffers ------------------------------------------------------------------------
static RblSpriteInstance sprite(void) { return RblMakeSprite((Vector3){ 0.0f, 0.0f, 0.0f }, 0.05f, 10.0f, 1, WHITE); }

static void c_sprite_buffer_load(void)
{
    RblAtlas a = goodAtlas(), zero; memset(&zero, 0, sizeof(zero));
    int bad[4] = { -1, -2147483647 - 1, RBL_MAX_INSTANCES + 1, 2147483647 };
    RblSpriteBuffer b;
    for (int i = 0; i < 4; i++) EXPECT_REFUSED((b = RblLoadSpriteBuffer(&a, bad[i]), RblIsSpriteBufferValid(b)));
    EXPECT_REFUSED((b = RblLoadSpriteBuffer(NULL, 4), RblIsSpriteBufferValid(b)));
    EXPECT_REFUSED((b = RblLoadSpriteBuffer(&zero, 4), RblIsSpriteBufferValid(b)));
    RblSpriteBuffer none; memset(&none, 0, sizeof(none));
    EXPECT_QUIET(RblIsSpriteBufferValid(none), false);
    b = RblLoadSpriteBuffer(&a, 4);
    RblSpriteBuffer stale = b;
    EXPECT_QUIET(RblIsSpriteBufferValid(b), true);
    EXPECT_REFUSED(V(RblUnloadSpriteBuffer(NULL)));
    EXPECT_REFUSED(V(RblUnloadSpriteBuffer(&none)));
    RblUnloadSpriteBuffer(&b);
    EXPECT_QUIET(RblIsSpriteBufferValid(stale), false);
    EXPECT_REFUSED(V(RblUnloadSpriteBuffer(&b)));
    EXPECT_REFUSED(V(RblUnloadSpriteBuffer(&stale)));
    // the buffer outlives its atlas: the table is its own
    b = RblLoadSpriteBuffer(&a, 4);
    RblUnloadAtlas(&a);
    RblSpriteInstance s[2] = { sprite(), sprite() };
    EXPECT_QUIET(RblUpdateSprites(&b, 0, 2, s), true);
    RblUnloadSpriteBuffer(&b);
}

// The GPU store of a sprite buffer (read back where the context maps; else zeros), its pivot copy
// and bounds: what a refused update must leave as they were
typedef struct SpriteKept { RblSpriteInstance gpu[8]; float pivots[8*4], bounds[7]; int count; } SpriteKept;
static SpriteKept spriteKept(const RblSpriteBuffer *b)
{
    SpriteKept k;
    memset(&k, 0, sizeof(k));
    if (rbl__canMap())
    {
        const void *p = rbl__mapBuffer(b->state->vboId, sizeof(k.gpu), true);
        if (p != NULL) memcpy(k.gpu, p, sizeof(k.gpu));
        rbl__unmapBuffer(b->state->vboId);
    }
    memcpy(k.pivots, b->state->pivots, sizeof(k.pivots));
    memcpy(k.bounds, b->state->bounds, sizeof(k.bounds));
    k.count = b->state->count;
    return k;
}

// A refused update writes nothing: the buffer's GPU store, pivot copy, bounds and count stay as
// they were, whether the range is a part (checked first) or the whole buffer (checked as written)
static void c_sprite_buffer_update(void)
{
    RblAtlas a = goodAtlas();
    RblSpriteBuffer b = RblLoadSpriteBuffer(&a, 8), zero, stale;
    memset(&zero, 0, sizeof(zero));
    RblSpriteInstance s[8];
    for (int i = 0; i < 8; i++) s[i] = sprite();
    EXPECT_QUIET(RblUpdateSprites(&b, 0, 3, s), true);
    const SpriteKept kept = spriteKept(&b);
    EXPECT_REFUSED(RblUpdateSprites(NULL, 0, 1, s));
    EXPECT_REFUSED(RblUpdateSprites(&zero, 0, 1, s));
    const int ranges[][2] = { { -1, 1 }, { 0, -1 }, { 0, 9 }, { 8, 1 }, { 7, 2 }, { 1, 2147483647 }, { 2147483647, 1 }, { -2147483647 - 1, 2 } };
    for (int r = 0; r < COUNT_OF(ranges); r++) EXPECT_REFUSED(RblUpdateSprites(&b, ranges[r][0], ranges[r][1], s));
    EXPECT_REFUSED(RblUpdateSprites(&b, 0, 2, NULL));
    EXPECT_QUIET(RblUpdateSprites(&b, 0, 0, NULL), true);           // an empty range is no update
    // every float field NaN/Inf/huge, negative scale, half-float speeds Inf, NaN, negative; unknown
    // mode bits; a frame or tag the atlas lacks: refused, even as the last of a good range
    const size_t floats[5] = { offsetof(RblSpriteInstance, position.x), offsetof(RblSpriteInstance, position.y), offsetof(RblSpriteInstance, position.z),
                               offsetof(RblSpriteInstance, scale), offsetof(RblSpriteInstance, start) };
    for (int f = 0; f < 5; f++) for (int vi = 0; vi < 5; vi++)
    {
        RblSpriteInstance x[3] = { sprite(), sprite(), sprite() };
        memcpy((char *)&x[2] + floats[f], &badFloats[vi], sizeof(float));
        EXPECT_REFUSED(RblUpdateSprites(&b, 0, 3, x));
        RblSpriteInstance all[8];
        for (int i = 0; i < 8; i++) all[i] = sprite();
        memcpy((char *)&all[7 - vi] + floats[f], &badFloats[vi], sizeof(float));
        EXPECT_REFUSED(RblUpdateSprites(&b, 0, 8, all));
    }
    RblSpriteInstance x = sprite();
    x.scale = -0.05f; EXPECT_REFUSED(RblUpdateSprites(&b, 1, 1, &x));
    x = sprite(); x.speed = 0x7C00; EXPECT_REFUSED(RblUpdateSprites(&b, 1, 1, &x));
    x = sprite(); x.speed = 0x7E00; EXPECT_REFUSED(RblUpdateSprites(&b, 1, 1, &x));
    x = sprite(); x.speed = 0xBC00; EXPECT_REFUSED(RblUpdateSprites(&b, 1, 1, &x));
    x = sprite(); x.mode = 0x10; EXPECT_REFUSED(RblUpdateSprites(&b, 1, 1, &x));
    x = sprite(); x.frame = 2; EXPECT_REFUSED(RblUpdateSprites(&b, 1, 1, &x));           // the atlas has frames 0, 1
    x = sprite(); RblAnimateSprite(&x, 0, 0, 0.0f, 1.0f); x.frame = 1; EXPECT_REFUSED(RblUpdateSprites(&b, 1, 1, &x));  // and tag 0
    const SpriteKept now = spriteKept(&b);
    ck(memcmp(&kept, &now, sizeof(kept)) == 0 && b.count == 3 && b.state->count == 3, "a refused update changed the buffer");
    // at the capacity: accepted; scale 0 (hidden), every tag and the every-frame tag
    x = sprite(); x.scale = 0.0f; s[7] = x;
    RblAnimateSprite(&s[6], -1, -1, 0.0f, 65504.0f);
    RblAnimateSprite(&s[5], 0, 254, -5.0f, 0.0f);
    EXPECT_QUIET(RblUpdateSprites(&b, 0, 8, s), true);
    stale = b;
    RblUnloadSpriteBuffer(&b);
    EXPECT_REFUSED(RblUpdateSprites(&stale, 0, 1, s));
    RblUnloadAtlas(&a);
}

static void c_sprite_buffer_draw(void)
{
    RblAtlas a = goodAtlas();
    Material inst = litMaterial(descOf(RBL_BRDF_LAMBERT, true, false));
    RblInstancedDesc d; memset(&d, 0, sizeof(d));
    RblSpriteBuffer b = RblLoadSpriteBuffer(&a, 4), zero, stale;
    memset(&zero, 0, sizeof(zero));
    RblSpriteInstance s[4] = { sprite(), sprite(), sprite(), sprite() };
    RblUpdateSprites(&b, 0, 4, s);
    EXPECT_REFUSED(RblDrawSpriteBuffer(NULL, camera(), inst, d, 0.0f) > 0);
    EXPECT_REFUSED(RblDrawSpriteBuffer(&zero, camera(), inst, d, 0.0f) > 0);
    EVERY_BAD_CAMERA(RblDrawSpriteBuffer(&b, cam, inst, d, 0.0f) > 0);
    for (int vi = 0; vi < 5; vi++) if (fabsf(badFloats[vi]) > 1e38f || !isfinite(badFloats[vi])) EXPECT_REFUSED(RblDrawSpriteBuffer(&b, camera(), inst, d, badFloats[vi]) > 0);
    for (int fi = 0; fi < COUNT_OF(instancedDescFloats); fi++) for (int vi = 0; vi < 3; vi++)
    {
        RblInstancedDesc x = d; SET_FIELD(x, instancedDescFloats[fi], badFloats[vi]);
        EXPECT_REFUSED(RblDrawSpriteBuffer(&b, camera(), inst, x, 0.0f) > 0);
    }
    RblInstancedDesc x = d;
    x.facing = 4; EXPECT_REFUSED(RblDrawSpriteBuffer(&b, camera(), inst, x, 0.0f) > 0);
    x.facing = -1; EXPECT_REFUSED(RblDrawSpriteBuffer(&b, camera(), inst, x, 0.0f) > 0);
    x = d; x.sort = RBL_SORT_BACK_TO_FRONT; EXPECT_REFUSED(RblDrawSpriteBuffer(&b, camera(), inst, x, 0.0f) > 0);
    RblFade fades[4]; memset(fades, 0, sizeof(fades));
    x = d; x.fades = fades; EXPECT_REFUSED(RblDrawSpriteBuffer(&b, camera(), inst, x, 0.0f) > 0);
    Material z; memset(&z, 0, sizeof(z));
    EXPECT_REFUSED(RblDrawSpriteBuffer(&b, camera(), z, d, 0.0f) > 0);
    EXPECT_REFUSED(RblDrawSpriteBuffer(&b, camera(), material, d, 0.0f) > 0);    // a vertex-buffer variant
    warnings = 0;
    int n = RblDrawSpriteBuffer(&b, camera(), inst, d, 1.0e30f);                    // any finite clock below 2^120
    ck(n == 4 && warnings == 0, "good draw: %d drawn, %d lines (%s)", n, warnings, lastWarning);
    stale = b;
    RblUnloadSpriteBuffer(&b);
    EXPECT_REFUSED(RblDrawSpriteBuffer(&stale, camera(), inst, d, 0.0f) > 0);
    RblUnloadAtlas(&a);
}

// Constructors: bad values give one line and a hidden sprite / an untouched one
static void c_sprite_values(void)
{
    RblSpriteInstance s;
    const float bad[3] = { NAN, INFINITY, -INFINITY };
    for (int vi = 0; vi < 3; vi++)
    {
        EXPECT_REFUSED((s = RblMakeSprite((Vector3){ bad[vi], 0.0f, 0.0f }, 1.0f, 0.0f, 0, WHITE), s.scale != 0.0f));
        EXPECT_REFUSED((s = RblMakeSprite((Vector3){ 0.0f, 0.0f, 0.0f }, bad[vi], 0.0f, 0, WHITE), s.scale != 0.0f));
        EXPECT_REFUSED((s = RblMakeSprite((Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f, bad[vi], 0, WHITE), s.scale != 0.0f));
    }
    EXPECT_REFUSED((s = RblMakeSprite((Vector3){ 3.0e38f, 0.0f, 0.0f }, 1.0f, 0.0f, 0, WHITE), s.scale != 0.0f));
    EXPECT_REFUSED((s = RblMakeSprite((Vector3){ 0.0f, 0.0f, 0.0f }, -1.0f, 0.0f, 0, WHITE), s.scale != 0.0f));
    EXPECT_REFUSED((s = RblMakeSprite((Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f, 0.0f, -1, WHITE), s.scale != 0.0f));
    EXPECT_REFUSED((s = RblMakeSprite((Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f, 0.0f, 65536, WHITE), s.scale != 0.0f));
    s = RblMakeSprite((Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f, -90.0f, 65535, WHITE);
    ck(s.rotation == 49152 && s.frame == 65535, "rotation -90 degrees packs as %u (want 49152)", s.rotation);
    s = RblMakeSprite((Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f, 1.0e30f, 0, WHITE);     // any finite angle, reduced
    ck(s.scale == 1.0f, "a huge finite rotation was refused");
    RblSpriteInstance kept = sprite(), t = kept;
    EXPECT_REFUSED(RblAnimateSprite(NULL, 0, 0, 0.0f, 1.0f));
    EXPECT_REFUSED(RblAnimateSprite(&t, -2, 0, 0.0f, 1.0f));
    EXPECT_REFUSED(RblAnimateSprite(&t, 65535, 0, 0.0f, 1.0f));
    EXPECT_REFUSED(RblAnimateSprite(&t, 0, -2, 0.0f, 1.0f));
    EXPECT_REFUSED(RblAnimateSprite(&t, 0, 255, 0.0f, 1.0f));
    for (int vi = 0; vi < 5; vi++) EXPECT_REFUSED(RblAnimateSprite(&t, 0, 0, badFloats[vi], 1.0f));
    for (int vi = 0; vi < 5; vi++) EXPECT_REFUSED(RblAnimateSprite(&t, 0, 0, 0.0f, badFloats[vi]));
    EXPECT_REFUSED(RblAnimateSprite(&t, 0, 0, 0.0f, -1.0f));
    EXPECT_REFUSED(RblAnimateSprite(&t, 0, 0, 0.0f, 65520.0f));                 // rounds past the largest half
    ck(memcmp(&t, &kept, sizeof(t)) == 0, "a refused RblAnimateSprite changed the sprite");
    EXPECT_QUIET(RblAnimateSprite(&t, 65534, 254, -1.0e30f, 65504.0f), true);
    ck(t.speed == 0x7BFF && (t.mode >> 8) == 254 && (t.mode & RBL_SPRITE_ANIMATED), "limits packed as speed %04x mode %04x", t.speed, t.mode);
    EXPECT_QUIET(RblAnimateSprite(&t, 0, 0, 0.0f, 5.9604645e-08f), true);           // the least subnormal half
    ck(t.speed == 1, "least subnormal speed packed as %04x", t.speed);
}

// Capacities at the limit and one past; an update of the whole capacity; a draw of it
static void c_sprite_buffer_counts(void)
{
    RblAtlas a = goodAtlas();
    RblSpriteBuffer b;
    EXPECT_REFUSED((b = RblLoadSpriteBuffer(&a, RBL_MAX_INSTANCES + 1), RblIsSpriteBufferValid(b)));
    b = RblLoadSpriteBuffer(&a, RBL_MAX_INSTANCES);
    ck(RblIsSpriteBufferValid(b), "a buffer of RBL_MAX_INSTANCES did not load");
    static RblSpriteInstance s[RBL_MAX_INSTANCES];
    for (int i = 0; i < RBL_MAX_INSTANCES; i++) s[i] = sprite();
    EXPECT_QUIET(RblUpdateSprites(&b, 0, RBL_MAX_INSTANCES, s), true);
    EXPECT_REFUSED(RblUpdateSprites(&b, 1, RBL_MAX_INSTANCES, s));
    Material inst = litMaterial(descOf(RBL_BRDF_LAMBERT, true, false));
    RblInstancedDesc d; memset(&d, 0, sizeof(d));
    warnings = 0;
    int n = RblDrawSpriteBuffer(&b, camera(), inst, d, 0.0f);
    ck(n == RBL_MAX_INSTANCES && warnings == 0, "draw at the limit: %d drawn, %d lines", n, warnings);
    RblUnloadSpriteBuffer(&b);
    RblUnloadAtlas(&a);
}

// A lit Shader copy after each way its program can die (the header's unload, raylib's UnloadShader,
// raylib's UnloadMaterial), then with nothing loaded since, another lit program loaded (GL hands out
// the deleted id again) and a raylib shader of the caller's loaded: every draw refuses the copy
static void c_stale_shader_copies(void)
{
    static const char *ways[3] = { "RblUnloadLitShader", "UnloadShader", "UnloadMaterial" };
    static const char *after[3] = { "nothing loaded since", "another lit program loaded", "a raylib shader loaded" };
    for (int w = 0; w < 3; w++) for (int a = 0; a < 3; a++) for (int instanced = 0; instanced < 2; instanced++)
    {
        Material m = litMaterial(descOf(RBL_BRDF_GGX, instanced == 1, false));
        Material copy = m;                          // raylib users copy Materials (a Model holds copies)
        Shader handle = m.shader;
        if (w == 0) RblUnloadLitShader(&handle);
        else if (w == 1) UnloadShader(handle);
        else { m.maps[MATERIAL_MAP_ALBEDO].texture.id = 0; UnloadMaterial(m); }   // the white texture is the fixture's
        Shader next = { 0 };
        if (a == 1) next = RblLoadLitShader(descOf(RBL_BRDF_GGX, instanced == 1, false));
        if (a == 2) next = ownShader();
        char what[160];
        snprintf(what, sizeof(what), "%s after %s, %s (%s)", instanced? "instanced" : "forward", ways[w], after[a], (next.id == copy.shader.id)? "same id" : "new id");
        EXPECT_QUIET(RblIsLitShaderValid(copy.shader), false);
        if (w == 2) { MaterialMap live[12]; memset(live, 0, sizeof(live)); copy.maps = live; }     // UnloadMaterial freed the copy's maps: point at live ones (the shader alone must refuse)
        if (instanced) expectInstancedRefused(copy); else expectEveryDrawRefused(copy, what);
        Shader s = copy.shader;
        if (w == 0) EXPECT_REFUSED(V(RblUnloadLitShader(&s)));       // double unload of the header's
        if (a == 1) RblUnloadLitShader(&next);
        if (a == 2) UnloadShader(next);
        if (w != 2) MemFree(m.maps);
    }
}

// GL drivers hand a deleted program's name to the next program (Mesa does not: its names only grow),
// so the reuse is staged: the registry and the stale copy are given the name the newer program got,
// as a reusing driver would have left them, before the header next looks
typedef unsigned int (*GlCreateProgram)(void);
typedef void (*GlDeleteProgram)(unsigned int);
static void c_stale_shader_copies_reused_id(void)
{
    GlCreateProgram createProgram; GL_PROC(createProgram, "glCreateProgram");
    GlDeleteProgram deleteProgram; GL_PROC(deleteProgram, "glDeleteProgram");
    for (int w = 0; w < 2; w++)
    {
        // A raylib shader of the caller's takes the name of a lit program raylib deleted unnoticed
        Material m = litMaterial(descOf(RBL_BRDF_GGX, false, false));
        Material copy = m;
        rbl__Program *entry = rbl__findLit(m.shader.id);
        if (w == 0) UnloadShader(m.shader); else { m.maps[MATERIAL_MAP_ALBEDO].texture.id = 0; UnloadMaterial(m); }
        Shader own = ownShader();
        ck(entry != NULL, "no registry entry for a loaded lit program");
        if (entry == NULL) continue;
        entry->shader.id = own.id;          // as if GL had handed the deleted name to the caller's program
        copy.shader.id = own.id;
        MaterialMap live[12]; memset(live, 0, sizeof(live)); live[MATERIAL_MAP_ALBEDO].texture = white;
        if (w == 1) copy.maps = live;
        expectEveryDrawRefused(copy, (w == 0)? "after UnloadShader, the name reused by a raylib shader" : "after UnloadMaterial, the name reused by a raylib shader");
        // ... while the caller's own Material with that program draws as raylib would
        Material mine = material; mine.shader = own;
        EXPECT_QUIET(V(RblDrawBillboard(camera(), mine, billboard())), false);
        UnloadShader(own);
        if (w == 0) MemFree(m.maps);
    }
    // A lit load takes the name of a lit program raylib deleted unnoticed: GL's next program name is
    // found (Mesa: the highest + 1; the loader compiles two shaders first), the dead entry renamed to it
    Material m = litMaterial(descOf(RBL_BRDF_GGX, false, false));
    Material copy = m;
    rbl__Program *entry = rbl__findLit(m.shader.id);
    UnloadShader(m.shader);
    unsigned int probe = createProgram();
    deleteProgram(probe);
    unsigned int next = probe + 3;
    if (entry != NULL) entry->shader.id = next;
    copy.shader.id = next;
    Shader fresh = RblLoadLitShader(descOf(RBL_BRDF_GGX, false, false));
    if (fresh.id != next) printf("      (lit reuse not staged: the new program got %u, not %u)\n", fresh.id, next);
    else
    {
        ck(RblIsLitShaderValid(fresh) && !RblIsLitShaderValid(copy.shader), "the reused name: new handle valid %d, stale copy valid %d", RblIsLitShaderValid(fresh), RblIsLitShaderValid(copy.shader));
        expectEveryDrawRefused(copy, "after UnloadShader, the name reused by a lit load");
        Material now = material; now.shader = fresh;
        EXPECT_QUIET(V(RblDrawBillboard(camera(), now, billboard())), false);
    }
    ck(fresh.id == next, "GL's next program name was not where Mesa puts it (%u, predicted %u): the lit reuse was not staged", fresh.id, next);
    RblUnloadLitShader(&fresh);
    MemFree(m.maps);
}

// Stale copies of the header's objects whose state address was taken by a newer object: the id,
// not the pointer, decides (a forged copy with the newer state and the older id is refused)
static void c_stale_objects_reused_address(void)
{
    RblBatch a = RblLoadBatch(4), staleA = a;
    RblUnloadBatch(&a);
    RblBatch b = RblLoadBatch(4), forged = b;
    forged.id = staleA.id;
    EXPECT_QUIET(RblIsBatchValid(forged), false);
    EXPECT_REFUSED(RblBeginBatch(&forged, camera()));
    EXPECT_REFUSED(V(RblUnloadBatch(&forged)));
    ck(RblIsBatchValid(b), "the newer batch was touched by its forged copy");
    RblUnloadBatch(&b);

    RblInstanceBuffer ia = RblLoadInstanceBuffer(4), staleI = ia;
    RblUnloadInstanceBuffer(&ia);
    RblInstanceBuffer ib = RblLoadInstanceBuffer(4), forgedI = ib;
    forgedI.id = staleI.id;
    EXPECT_QUIET(RblIsInstanceBufferValid(forgedI), false);
    EXPECT_REFUSED(V(RblUnloadInstanceBuffer(&forgedI)));
    ck(RblIsInstanceBufferValid(ib), "the newer instance buffer was touched by its forged copy");
    RblUnloadInstanceBuffer(&ib);

    RblGBuffer ga = RblLoadGBuffer(gdesc(RBL_BRDF_GGX)), staleG = ga;
    RblUnloadGBuffer(&ga);
    RblGBuffer gb = RblLoadGBuffer(gdesc(RBL_BRDF_GGX)), forgedG = gb;
    forgedG.id = staleG.id;
    EXPECT_QUIET(RblIsGBufferValid(forgedG), false);
    EXPECT_REFUSED(RblBeginGBuffer(&forgedG, camera()));
    EXPECT_REFUSED(V(RblUnloadGBuffer(&forgedG)));
    ck(RblIsGBufferValid(gb), "the newer G-buffer was touched by its forged copy");
    RblUnloadGBuffer(&gb);

    RblAtlas aa = goodAtlas(), staleA2 = aa;
    RblUnloadAtlas(&aa);
    RblAtlas ab = goodAtlas(), forgedA = ab;
    forgedA.id = staleA2.id;
    EXPECT_QUIET(RblIsAtlasValid(forgedA), false);
    EXPECT_REFUSED(RblAtlasFindFrame(&forgedA, "a") >= 0);
    EXPECT_REFUSED(V(RblUnloadAtlas(&forgedA)));
    ck(RblIsAtlasValid(ab), "the newer atlas was touched by its forged copy");
    RblUnloadAtlas(&ab);

    RblShadowDesc sd; memset(&sd, 0, sizeof(sd)); sd.size = 64;
    RblShadowMap ma = RblLoadShadowMap(sd), staleM = ma;
    RblUnloadShadowMap(&ma);
    RblShadowMap mb = RblLoadShadowMap(sd), forgedM = mb;
    forgedM.id = staleM.id;
    EXPECT_QUIET(RblIsShadowMapValid(forgedM), false);
    EXPECT_REFUSED(V(RblUnloadShadowMap(&forgedM)));
    ck(RblIsShadowMapValid(mb), "the newer shadow map was touched by its forged copy");
    RblUnloadShadowMap(&mb);
}

// NULL and dead pointers and GL names inside raylib structs: maps, locs, a Model's arrays, textures
// and meshes unloaded by raylib
static void c_null_and_dead_inside_raylib_structs(void)
{
    Material noMaps = material; noMaps.maps = NULL;
    expectEveryDrawRefused(noMaps, "maps NULL");
    Material lit = litMaterial(descOf(RBL_BRDF_LAMBERT, true, false));
    Material noMapsI = lit; noMapsI.maps = NULL;
    expectInstancedRefused(noMapsI);
    Shader own = ownShader();
    Material noLocs = material; noLocs.shader = own; noLocs.shader.locs = NULL;
    expectEveryDrawRefused(noLocs, "the caller's shader with locs NULL");
    Material deadProgram = material; deadProgram.shader = own;
    UnloadShader(own);
    expectEveryDrawRefused(deadProgram, "the caller's shader unloaded");
    // A texture unloaded by raylib, still in the maps (albedo, and a normal map)
    Texture2D t = solidTexture(WHITE), n = solidTexture(BLUE);
    MaterialMap maps[12]; memcpy(maps, material.maps, sizeof(maps));
    Material deadTex = material; deadTex.maps = maps;
    maps[MATERIAL_MAP_ALBEDO].texture = t;
    UnloadTexture(t);
    expectEveryDrawRefused(deadTex, "albedo texture unloaded");
    maps[MATERIAL_MAP_ALBEDO].texture = white;
    maps[MATERIAL_MAP_NORMAL].texture = n;
    UnloadTexture(n);
    expectEveryDrawRefused(deadTex, "normal texture unloaded");
    // A Mesh copy whose GPU data raylib unloaded, and one never uploaded
    Mesh cube = GenMeshCube(1, 1, 1), stale = cube;
    UnloadMesh(cube);
    EXPECT_REFUSED(V(RblDrawMesh(stale, material, MatrixIdentity())));
    Mesh zeroVao = GenMeshCube(1, 1, 1), noVao = zeroVao;
    noVao.vaoId = 0;
    EXPECT_REFUSED(V(RblDrawMesh(noVao, material, MatrixIdentity())));
    UnloadMesh(zeroVao);
    // A Model with NULL arrays
    Model model = LoadModelFromMesh(GenMeshCube(1, 1, 1));
    model.materials[0].shader = litShader;
    Model m = model; m.meshMaterial = NULL; EXPECT_REFUSED(V(RblDrawModel(m, (Vector3){ 0, 0, 0 }, 1.0f, WHITE)));
    m = model; m.materials[0].maps = NULL;
    EXPECT_REFUSED(V(RblDrawModel(m, (Vector3){ 0, 0, 0 }, 1.0f, WHITE)));
    m.materials[0].maps = model.materials[0].maps;
    model.materials[0].shader = (Shader){ 0 };
    UnloadModel(model);
    MemFree(lit.maps);
    RblUnloadLitShader(&lit.shader);
}

// Every count at its limit (accepted) and one past it (refused before any element is read)
static void c_counts_at_and_past_limits(void)
{
    static RblLight lights[RBL_MAX_SCENE_LIGHTS + 1];
    for (int i = 0; i <= RBL_MAX_SCENE_LIGHTS; i++) lights[i] = pointLight();
    EXPECT_QUIET(RblGetLightFeatures(lights, RBL_MAX_SCENE_LIGHTS) == RBL_LIGHT_FEATURE_POINT, true);
    EXPECT_REFUSED(RblGetLightFeatures(lights, RBL_MAX_SCENE_LIGHTS + 1) != 0);
    RblScene scene; memset(&scene, 0, sizeof(scene)); scene.lights = lights;
    scene.lightCount = RBL_MAX_SCENE_LIGHTS;
    EXPECT_QUIET(RblSetScene(&scene), true);
    scene.lightCount = RBL_MAX_SCENE_LIGHTS + 1;
    EXPECT_REFUSED(RblSetScene(&scene));
    RblAtlas a = goodAtlas();
    static RblSpritePlayer players[RBL_MAX_INSTANCES + 1];
    static RblInstance inst[RBL_MAX_INSTANCES + 1];
    for (int i = 0; i <= RBL_MAX_INSTANCES; i++) { players[i] = RblPlaySprite(&a, -1, 0); inst[i] = instance(); }
    EXPECT_QUIET(RblUpdateSpriteInstances(players, inst, RBL_MAX_INSTANCES, &a, 0.01f, 0.01f) == RBL_MAX_INSTANCES, true);
    EXPECT_REFUSED(RblUpdateSpriteInstances(players, inst, RBL_MAX_INSTANCES + 1, &a, 0.01f, 0.01f) != 0);
    Material im = litMaterial(descOf(RBL_BRDF_LAMBERT, true, false));
    RblInstanceBuffer buf = RblLoadInstanceBuffer(0);
    RblInstancedDesc d; memset(&d, 0, sizeof(d));
    for (int i = 0; i <= RBL_MAX_INSTANCES; i++) inst[i] = instance();
    warnings = 0;
    int drawn = RblDrawInstanced(&buf, camera(), im, d, inst, RBL_MAX_INSTANCES);
    ck(drawn == RBL_MAX_INSTANCES && warnings <= 1, "instances at the limit: %d drawn, %d lines", drawn, warnings);   // a growth line is INFO
    EXPECT_REFUSED(RblDrawInstanced(&buf, camera(), im, d, inst, RBL_MAX_INSTANCES + 1) > 0);
    RblUnloadInstanceBuffer(&buf);
    RblUnloadAtlas(&a);
}

// Material values (maps[].value, colours, params[]) as NaN, +-Inf and values whose products overflow:
// every draw accepted, and a float target holds only finite colours
static void c_material_values_every_float(void)
{
    RenderTexture2D ft = LoadRenderTexture(16, 16);
    unsigned int fbo = rlLoadFramebuffer();
    unsigned int tex = rlLoadTexture(NULL, 16, 16, PIXELFORMAT_UNCOMPRESSED_R32G32B32A32, 1);
    rlFramebufferAttach(fbo, tex, RL_ATTACHMENT_COLOR_CHANNEL0, RL_ATTACHMENT_TEXTURE2D, 0);
    static const int slots[6] = { MATERIAL_MAP_NORMAL, MATERIAL_MAP_ROUGHNESS, MATERIAL_MAP_METALNESS, MATERIAL_MAP_EMISSION, MATERIAL_MAP_OCCLUSION, MATERIAL_MAP_ALBEDO };
    for (int brdf = 0; brdf < 3; brdf++)
    {
        Material m = litMaterial(descOf(brdf, false, false));
        m.maps[MATERIAL_MAP_EMISSION].color = WHITE;
        m.maps[MATERIAL_MAP_SPECULAR].color = WHITE;
        for (int k = 0; k < 6 + 4; k++) for (int vi = 0; vi < 5; vi++)
        {
            Material v = m;
            MaterialMap maps[12]; memcpy(maps, m.maps, sizeof(maps)); v.maps = maps;
            if (k < 6) maps[slots[k]].value = badFloats[vi]; else v.params[k - 6] = badFloats[vi];
            rlEnableFramebuffer(fbo);
            rlViewport(0, 0, 16, 16);
            rlClearColor(0, 0, 0, 0); rlClearScreenBuffers();
            warnings = 0;
            RblBillboard b = billboard(); b.size = (Vector2){ 4, 4 };
            RblDrawBillboard(camera(), v, b);
            rlDrawRenderBatchActive();
            float *px = rtReadFloatPixels(tex, 16, 16);
            bool finite = (px != NULL);
            for (int i = 0; finite && (i < 16*16*4); i++) finite = isfinite(px[i]);
            free(px);
            ck(finite && warnings == 0, "brdf %d %s %d = %g: %s, %d lines", brdf, (k < 6)? "maps value" : "params", (k < 6)? slots[k] : k - 6, badFloats[vi], finite? "finite" : "non-finite pixels", warnings);
        }
        RblUnloadLitShader(&m.shader);
        MemFree(m.maps);
    }
    rlUnloadFramebuffer(fbo);
    rlUnloadTexture(tex);
    BeginTextureMode(target);       // back to the fixture's target (the snapshots compare it)
    UnloadRenderTexture(ft);
}

// Directions of any finite length (FIXED up and normal, AXIS axis) give a unit frame; a CAMERA_PLANE
// up long enough to overflow the quad is refused
static void c_vertices_long_directions(void)
{
    RblCameraFrame f = RblGetCameraFrame(camera());
    const float longs[4] = { 1e20f, -3e38f, 1e13f, 3.0e38f };
    for (int i = 0; i < 4; i++) for (int which = 0; which < 3; which++)
    {
        RblBillboard b = billboard(), unit = billboard();
        b.facing = unit.facing = (which < 2)? RBL_FACING_FIXED : RBL_FACING_AXIS;
        b.axis = unit.axis = (Vector3){ 0.0f, 0.0f, 1.0f };
        b.up = unit.up = (Vector3){ 0.0f, 1.0f, 0.0f };
        if (which == 0) { b.up = (Vector3){ 0.0f, longs[i], 0.0f }; unit.up = (Vector3){ 0.0f, (longs[i] > 0)? 1.0f : -1.0f, 0.0f }; }
        else { b.axis = (Vector3){ 0.0f, 0.0f, longs[i] }; unit.axis = (Vector3){ 0.0f, 0.0f, (longs[i] > 0)? 1.0f : -1.0f }; }
        if (which == 2) { b.axis = (Vector3){ 0.0f, longs[i], 0.0f }; unit.axis = (Vector3){ 0.0f, (longs[i] > 0)? 1.0f : -1.0f, 0.0f }; }
        RblVertex out[4], want[4];
        warnings = 0;
        bool ok = RblBillboardVertices(&f, 4, 4, &b, out), okUnit = RblBillboardVertices(&f, 4, 4, &unit, want);
        ck(ok && okUnit && warnings == 0 && memcmp(out, want, sizeof(out)) == 0, "%s %s = %g: %s (the unit vector's frame expected)",
           (which < 2)? "FIXED" : "AXIS", (which == 0)? "up" : "axis", longs[i], ok? "a different frame" : "refused");
    }
    RblBillboard b = billboard();
    b.up = (Vector3){ 0.0f, 1.5e9f, 0.0f };
    RblVertex out[4];
    EXPECT_REFUSED(RblBillboardVertices(&f, 4, 4, &b, out));
}

// Begin/End of each pass against every other pass, both nesting orders: a batch ends only in the
// pass it began in; shadow and G-buffer passes refuse each other and their own unloads; a shadow pass
// or geometry pass inside raylib's BeginTextureMode returns to that target
static void c_passes_against_passes(void)
{
    RblShadowDesc sd; memset(&sd, 0, sizeof(sd)); sd.size = 64;
    RblShadowMap map = RblLoadShadowMap(sd);
    RblGBuffer g = RblLoadGBuffer(gdesc(RBL_BRDF_LAMBERT));
    RblLight sun = pointLight(); sun.type = RBL_LIGHT_DIRECTIONAL; sun.direction = (Vector3){ 0.2f, -1.0f, 0.1f };
    RblScene scene; memset(&scene, 0, sizeof(scene)); scene.lights = &sun; scene.lightCount = 1;
    RblBillboard b = billboard();
    Material def = litMaterial(descOf(RBL_BRDF_LAMBERT, false, true));
    // Batch begun in the colour pass, ended inside a shadow pass / a geometry pass (and back outside)
    RblBatch batch = RblLoadBatch(4);
    RblBeginBatch(&batch, camera());
    RblBatchAdd(&batch, material, &b);
    ck(RblBeginShadowMap(&map, &scene, 0, (Vector3){ 0, 0, 0 }, 4.0f), "shadow pass refused");
    EXPECT_REFUSED(RblBatchAdd(&batch, material, &b));
    EXPECT_REFUSED(V(RblEndBatch(&batch)));
    EXPECT_REFUSED(V(RblUnloadShadowMap(&map)));                 // its own pass is in progress
    RblEndShadowMap(&map);
    ck(RblBeginGBuffer(&g, camera()), "geometry pass refused");
    EXPECT_REFUSED(V(RblEndBatch(&batch)));
    EXPECT_REFUSED(V(RblUnloadGBuffer(&g)));                     // its own pass is in progress
    EXPECT_REFUSED(V(RblResolveGBuffer(&g)));
    RblEndGBuffer(&g);
    EXPECT_QUIET(V(RblEndBatch(&batch)), false);                  // back in the colour pass: ends
    // Batch begun inside a shadow pass, ended after it
    ck(RblBeginShadowMap(&map, &scene, 0, (Vector3){ 0, 0, 0 }, 4.0f), "shadow pass refused");
    RblBeginBatch(&batch, camera());
    RblBatchAdd(&batch, material, &b);
    EXPECT_REFUSED(V(RblResolveGBuffer(&g)));                    // resolve inside a shadow pass
    RblEndShadowMap(&map);
    EXPECT_REFUSED(V(RblEndBatch(&batch)));
    ck(RblBeginShadowMap(&map, &scene, 0, (Vector3){ 0, 0, 0 }, 4.0f), "shadow pass refused");
    EXPECT_QUIET(V(RblEndBatch(&batch)), false);                  // in its pass again: ends
    RblEndShadowMap(&map);
    // Batch begun inside a geometry pass, ended after it
    ck(RblBeginGBuffer(&g, camera()), "geometry pass refused");
    RblBeginBatch(&batch, camera());
    RblBatchAdd(&batch, def, &b);
    RblEndGBuffer(&g);
    EXPECT_REFUSED(V(RblEndBatch(&batch)));
    ck(RblBeginGBuffer(&g, camera()), "geometry pass refused");
    EXPECT_QUIET(V(RblEndBatch(&batch)), false);
    RblEndGBuffer(&g);
    // Passes inside raylib's BeginTextureMode return to that target
    RenderTexture2D rt = LoadRenderTexture(24, 24);
    EndMode3D(); EndTextureMode();
    BeginTextureMode(rt);
    int fb = 0; glGetI(0x8CA6, &fb);
    ck(RblBeginShadowMap(&map, &scene, 0, (Vector3){ 0, 0, 0 }, 4.0f), "shadow pass refused");
    RblEndShadowMap(&map);
    int after = 0; glGetI(0x8CA6, &after);
    ck(after == fb, "shadow pass inside BeginTextureMode left framebuffer %d (was %d)", after, fb);
    RblGBuffer follow; { RblGBufferDesc d = gdesc(RBL_BRDF_LAMBERT); d.width = d.height = 0; follow = RblLoadGBuffer(d); }
    ck(RblBeginGBuffer(&follow, camera()), "geometry pass refused");
    RblEndGBuffer(&follow);
    glGetI(0x8CA6, &after);
    ck(after == fb, "geometry pass inside BeginTextureMode left framebuffer %d (was %d)", after, fb);
    ck(follow.width == 24 && follow.height == 24, "a size-0 G-buffer inside BeginTextureMode(24x24) is %dx%d", follow.width, follow.height);
    EndTextureMode();
    BeginTextureMode(target); BeginMode3D(camera());
    RblUnloadGBuffer(&follow);
    UnloadRenderTexture(rt);
    RblUnloadBatch(&batch);
    RblUnloadGBuffer(&g);
    RblUnloadShadowMap(&map);
    RblUnloadLitShader(&def.shader);
    MemFree(def.maps);
}

// The scene's own references dying after RblSetScene: a shadow map unloaded (its light draws
// unshadowed, said once), the depth texture unloaded (soft particles unsoftened, said once), a
// deferred light pass before any geometry pass (refused)
static void c_scene_references_die(void)
{
    RblShadowDesc sd; memset(&sd, 0, sizeof(sd)); sd.size = 64;
    RblShadowMap map = RblLoadShadowMap(sd);
    RblLight sun = pointLight(); sun.type = RBL_LIGHT_DIRECTIONAL; sun.direction = (Vector3){ 0.2f, -1.0f, 0.1f };
    RblScene scene; memset(&scene, 0, sizeof(scene)); scene.lights = &sun; scene.lightCount = 1;
    ck(RblBeginShadowMap(&map, &scene, 0, (Vector3){ 0, 0, 0 }, 4.0f), "shadow pass refused");
    RblEndShadowMap(&map);
    scene.shadowMaps = &map; scene.shadowMapCount = 1;
    RblGBufferDesc gd = gdesc(RBL_BRDF_LAMBERT); gd.shading.shadowMaps = 1;
    RblGBuffer g = RblLoadGBuffer(gd);
    EXPECT_REFUSED(RblDrawDeferredLights(&g));                   // no geometry pass yet
    ck(RblSetScene(&scene), "scene refused: %s", lastWarning);
    RblLitShaderDesc rd = descOf(RBL_BRDF_LAMBERT, false, false); rd.shading.shadowMaps = 1;
    Material receiver = litMaterial(rd);
    RblUnloadShadowMap(&map);
    RblBillboard b = billboard();
    warnings = 0;
    RblDrawBillboard(camera(), receiver, b);
    RblDrawBillboard(camera(), receiver, b);
    ck(warnings == 1 && strstr(lastWarning, "unloaded after RblSetScene") != NULL, "draws after the scene's map was unloaded: %d lines (%s)", warnings, lastWarning);
    // The depth texture: refused by RblSetScene when already gone, noted once when it goes later
    RenderTexture2D st = RblLoadSceneTarget(16, 16);
    RblScene soft; memset(&soft, 0, sizeof(soft)); soft.lights = &sun; soft.lightCount = 1; soft.depth = st.depth;
    ck(RblSetScene(&soft), "scene with a depth texture refused: %s", lastWarning);
    RblLitShaderDesc pd = descOf(RBL_BRDF_LAMBERT, false, false); pd.softParticles = true;
    Material smoke = litMaterial(pd);
    UnloadRenderTexture(st);
    warnings = 0;
    RblDrawBillboard(camera(), smoke, b);
    RblDrawBillboard(camera(), smoke, b);
    ck(warnings == 1 && strstr(lastWarning, "depth texture") != NULL, "draws after the scene's depth was unloaded: %d lines (%s)", warnings, lastWarning);
    EXPECT_REFUSED(RblSetScene(&soft));
    RblUnloadGBuffer(&g);
    RblUnloadLitShader(&receiver.shader); MemFree(receiver.maps);
    RblUnloadLitShader(&smoke.shader); MemFree(smoke.maps);
}

// The header's scene target of a plain frame: nested, unbalanced, inside other passes
static void c_scene_depth(void)
{
    EXPECT_REFUSED(V(RblEndSceneDepth()));                       // never begun
    ck(RblBeginSceneDepth(), "good scene-depth pass refused: %s", lastWarning);
    EXPECT_REFUSED(RblBeginSceneDepth());                        // nested
    RblEndSceneDepth();
    EXPECT_REFUSED(V(RblEndSceneDepth()));                       // twice
    RblShadowDesc sd; memset(&sd, 0, sizeof(sd)); sd.size = 64;
    RblShadowMap map = RblLoadShadowMap(sd);
    RblLight sun = pointLight(); sun.type = RBL_LIGHT_DIRECTIONAL; sun.direction = (Vector3){ 0.2f, -1.0f, 0.1f };
    RblScene scene; memset(&scene, 0, sizeof(scene)); scene.lights = &sun; scene.lightCount = 1;
    ck(RblBeginShadowMap(&map, &scene, 0, (Vector3){ 0, 0, 0 }, 4.0f), "shadow pass refused");
    EXPECT_REFUSED(RblBeginSceneDepth());
    RblEndShadowMap(&map);
    RblGBuffer g = RblLoadGBuffer(gdesc(RBL_BRDF_LAMBERT));
    ck(RblBeginGBuffer(&g, camera()), "geometry pass refused");
    EXPECT_REFUSED(RblBeginSceneDepth());
    RblEndGBuffer(&g);
    RblUnloadGBuffer(&g);
    RblUnloadShadowMap(&map);
}

// ---- the case table -----------------------------------------------------------------------------
typedef struct Case { const char *functions; const char *name; void (*run)(void); const char *classes; } Case;

// The classes of input the suite must cover (each case names the ones it tries)
static const struct { const char *tag; const char *what; } classTable[] = {
    { "null", "NULL pointers, zero and never-loaded objects" },
    { "stale-header", "stale copies after the header's unload, double unloads" },
    { "stale-raylib", "stale copies after raylib's unload (UnloadShader, UnloadMaterial, UnloadTexture, UnloadMesh, UnloadRenderTexture)" },
    { "stale-reused", "stale copies whose GL id or state address a newer load took" },
    { "null-inside", "NULL and dangling pointers inside raylib structs (maps, locs, meshes, materials, boneMatrices)" },
    { "counts", "every count at its limit and one past" },
    { "floats", "NaN, +-Inf and overflowing squares/products in every float field (Material values included)" },
    { "nesting", "Begin/End against every other pass, both orders (batch, G-buffer, shadow map, BeginTextureMode)" },
    { "variants", "mismatched program variants" },
    { "scene-refs", "the scene's references dying after RblSetScene" },
    { "lifetime", "module lifetime (RblClose twice; teardown orders: test_teardown)" },
};
#define BARE "(no lit program loaded yet) "
static const Case cases[] = {
    { "RblGetCameraFrame", "NaN/Inf/huge in every camera field", c_frame_bad_camera, "floats" },
    { "RblGetCameraFrame", "degenerate cameras: no log, orthonormal", c_frame_degenerate_cameras_are_fine, "floats" },
    { "RblBillboardVertices", "NULL pointers, sizes, facing", c_vertices_null_and_sizes, "null counts" },
    { "RblBillboardQuads", "NULL pointers, capacity, bad frame and billboard, stale polygon bits; out untouched", c_quads_null_sizes_and_stale_polygons, "null stale-header counts floats" },
    { "RblBillboardVertices", "every float field x every facing", c_vertices_every_float_field, "floats" },
    { "RblBillboardVertices", "NaN/Inf camera frame", c_vertices_bad_frame, "floats" },
    { "RblLoadBatch", "negative and huge capacities", c_batch_load_counts, "counts" },
    { "RblIsBatchValid", "zero, loaded, stale", c_batch_valid_queries, "null stale-header" },
    { "RblUnloadBatch", "NULL, zero, double, stale", c_batch_unload, "null stale-header" },
    { "RblBeginBatch", "NULL, zero, stale, pending, bad camera", c_batch_begin, "null stale-header nesting floats" },
    { "RblBatchAdd", "NULL, not begun, bad floats, bad materials", c_batch_add, "null floats variants" },
    { "RblBatchAddMany", "NULL, not begun, NULL array, negative count, bad floats among good ones, a zero material", c_batch_add_many, "null floats variants" },
    { "RblBatchAdd RblLoadBatch", "the billboard limit", c_batch_limit, "counts" },
    { "RblEndBatch", "NULL, zero, unbegun, twice, stale", c_batch_end, "null nesting stale-header" },
    { "RblDrawBillboard", "bad camera, materials, variants", c_draw_billboard, "floats variants" },
    { "RblClose", "twice", c_close_twice, "lifetime" },
    { "RblGetFailureReason", "none yet, after refusals, kept through successes", c_failure_reason, "lifetime" },
    { "RblLoadInstanceBuffer RblIsInstanceBufferValid RblUnloadInstanceBuffer", "counts, zero, stale, double", c_instances_load, "counts null stale-header" },
    { "RblLoadSceneTarget RblSetScene", "sizes; the scene's depth field", c_scene_target, "counts" },
    { "RblLoadSpriteBuffer RblIsSpriteBufferValid RblUnloadSpriteBuffer", "atlas NULL/zero, counts, zero, stale, double; the atlas unloaded first", c_sprite_buffer_load, "counts null stale-header" },
    { "RblUpdateSprites", "NULL, zero, stale; ranges past the end and overflowing; NaN/Inf/huge floats, half-float speeds, mode bits, frames and tags outside the atlas", c_sprite_buffer_update, "null stale-header counts floats" },
    { "RblDrawSpriteBuffer", "NULL, zero, stale; camera, clock, desc (sort, fades), materials", c_sprite_buffer_draw, "null stale-header floats variants" },
    { "RblMakeSprite RblAnimateSprite", "NaN/Inf/huge fields, frame/tag/loops outside their ranges, speeds past the largest half", c_sprite_values, "floats counts null" },
    { "RblLoadSpriteBuffer RblUpdateSprites RblDrawSpriteBuffer", "capacity at RBL_MAX_INSTANCES and one past; a full update and draw", c_sprite_buffer_counts, "counts" },
    { "RblDrawInstanced", "NULL, stale, counts, camera, desc, materials, bad instances", c_instances_draw, "null stale-header counts floats variants" },
    { "RblDrawInstanced RblDrawBillboard", BARE "zero and raylib-default materials", c_instances_bare, "null variants" },
    { "RblPackMaterial", "NULL, sizes, formats, encodings, frames", c_pack_material, "null counts" },
    { "RblUnloadPackedMaterial", "NULL, double", c_unload_packed, "null stale-header" },
    { "RblEncodeNormal RblDecodeNormal", "NULL, encodings, NaN/Inf/huge, zero", c_encode_decode_normal, "null floats" },
    { "RblMeasureNormalEncoding", "NULL, counts, encoding, NaN normal", c_measure_normals, "null counts floats" },
    { "RblGenNormalMapFromHeight RblGenHeightFromLuminance RblGenOcclusionFromHeight", "images, strengths, radii", c_gen_maps, "counts floats" },
    { "RblLoadPackedTextures", "NULL, bad images, no maps", c_load_packed_textures, "null" },
    { "RblLoadLitShader", "every desc field out of range", c_load_lit_shader, "counts floats" },
    { "RblIsLitShaderValid", "zero, raylib default, stale", c_lit_shader_queries, "null stale-header" },
    { "RblUnloadLitShader", "NULL, zero, default, double, stale", c_unload_lit_shader, "null stale-header stale-raylib" },
    { "RblGetLightFeatures", "NULL, counts, types", c_light_features, "null counts" },
    { "RblSetScene", "counts, maps, fog, every float of scene and lights", c_set_scene, "counts floats" },
    { "RblSetScene RblGetLightGridStats", "clustered scenes: far positions, tiny/huge ranges, one point (capped), the largest", c_light_grid_extremes, "counts floats" },
    { "RblDrawModel RblDrawMesh", "bad models, transforms, materials, variants", c_draw_model_and_mesh, "null-inside floats variants" },
    { "RblDrawModel RblDrawMesh RblDrawBillboard", "skinned programs: bones NULL, counts, NaN bones, meshes without bone data, shadow pass", c_draw_skinned_model, "null-inside counts floats variants" },
    { "RblLoadGBuffer", "every desc field out of range", c_gbuffer_load, "counts" },
    { "RblIsGBufferValid RblGBufferBytesPerPixel RblResizeGBuffer RblUnloadGBuffer", "NULL, zero, sizes, stale, double", c_gbuffer_lifecycle, "null stale-header counts" },
    { "RblBeginGBuffer RblEndGBuffer RblDrawDeferredLights RblSetGBufferOutput RblResolveGBuffer", "imbalance, nesting, mismatched variants, bad arguments", c_gbuffer_passes, "nesting variants" },
    { "RblDrawDeferredLights", "extreme accepted lights keep the accumulation finite", c_gbuffer_extreme_lights_stay_finite, "floats" },
    { "RblLoadShadowMap RblIsShadowMapValid RblUnloadShadowMap", "sizes, desc floats, zero, stale, double", c_shadow_load, "counts floats stale-header" },
    { "RblBeginShadowMap RblEndShadowMap", "NULL, indices, focus, imbalance, nesting, stale", c_shadow_passes, "null nesting stale-header floats" },
    { "RblShadowFocusFromCamera", "NULL outputs, camera, aspect, range", c_shadow_focus, "null floats" },
    { "RblShadowMapPasses RblBeginShadowMapPass RblFitShadowCascades RblDrawShadowCascades RblShadowCascadeColor", "omni/cascade descs, pass indices, light types, unfitted, fit inputs, stale", c_shadow_omni_cascades, "null counts floats nesting stale-header" },
    { "RblBeginShadowBlend RblEndShadowBlend", "outside a pass, no target, nesting, imbalance", c_shadow_blend, "nesting" },
    { "RblLoadAtlas RblLoadAtlasFromMemory", "NULL, sizes, formats, truncated, missing file", c_atlas_load, "null counts" },
    { "RblIsAtlasValid RblUnloadAtlas RblAtlasFindFrame RblAtlasFindTag", "NULL, zero, double, stale, NULL names", c_atlas_lifecycle, "null stale-header" },
    { "RblAtlasBillboard RblAtlasInstance", "NULL, frames, scales, stale; outputs untouched", c_atlas_quads, "null stale-header" },
    { "RblAtlasFindSlice RblAtlasSliceBillboard RblAtlasSliceInstance", "NULL, stale, keys, frames, uncovered frames, outside the trim, scales; outputs untouched", c_atlas_slices, "null stale-header counts floats" },
    { "RblLoadAtlasTextures", "NULL, stale, pages, materials (maps NULL), missing or mis-sized sheets; material untouched", c_atlas_textures, "null null-inside stale-header counts" },
    { "RblAtlasBillboardFade RblAtlasInstanceFade", "NULL, frames, weights, scales, stale, different sheets, empty trims; outputs untouched; equal frames unclipped", c_atlas_fade_quads, "null stale-header" },
    { "RblPlaySprite RblUpdateSprite RblUpdateSpriteInstances RblSpriteBlend RblSpriteViewSector", "NULL, stale, bad dt/scale/counts, corrupt players, directions, NaN/Inf", c_sprites, "null stale-header counts floats" },
    { "RblDrawBillboardFade RblBatchAddFade RblDrawInstanced", "cross-fade: weights outside 0..1, NaN/Inf fades on every path", c_fades, "null floats stale-header" },
    { "RblDrawBillboard RblBatchAdd RblEndBatch RblDrawInstanced RblDrawMesh RblDrawModel RblIsLitShaderValid RblUnloadLitShader", "lit Shader copies after RblUnloadLitShader, UnloadShader, UnloadMaterial; then nothing, a lit load, a raylib load", c_stale_shader_copies, "stale-header stale-raylib stale-reused" },
    { "RblDrawBillboard RblBatchAdd RblEndBatch RblDrawMesh RblDrawModel RblIsLitShaderValid RblLoadLitShader", "lit Shader copies whose GL name a raylib shader or a lit load took (reuse staged)", c_stale_shader_copies_reused_id, "stale-reused stale-raylib" },
    { "RblIsBatchValid RblBeginBatch RblUnloadBatch RblIsInstanceBufferValid RblUnloadInstanceBuffer RblIsGBufferValid RblBeginGBuffer RblUnloadGBuffer RblIsShadowMapValid RblUnloadShadowMap RblIsAtlasValid RblAtlasFindFrame RblUnloadAtlas", "stale copies whose state address a newer object took", c_stale_objects_reused_address, "stale-reused" },
    { "RblDrawBillboard RblBatchAdd RblDrawInstanced RblDrawMesh RblDrawModel", "NULL maps/locs/arrays; shaders, textures and meshes raylib unloaded", c_null_and_dead_inside_raylib_structs, "null-inside stale-raylib" },
    { "RblGetLightFeatures RblSetScene RblUpdateSpriteInstances RblDrawInstanced", "every count at its limit and one past", c_counts_at_and_past_limits, "counts" },
    { "RblDrawBillboard", "Material values (maps[].value, params[]) NaN/Inf/overflowing: finite float output", c_material_values_every_float, "floats" },
    { "RblBillboardVertices", "FIXED/AXIS directions of any finite length; CAMERA_PLANE up overflowing", c_vertices_long_directions, "floats" },
    { "RblBeginBatch RblBatchAdd RblEndBatch RblBeginShadowMap RblEndShadowMap RblBeginGBuffer RblEndGBuffer RblResolveGBuffer RblUnloadShadowMap RblUnloadGBuffer", "every pass against every other, both orders; inside BeginTextureMode", c_passes_against_passes, "nesting" },
    { "RblSetScene RblDrawDeferredLights RblDrawBillboard", "shadow map and depth texture unloaded after RblSetScene; lights before a geometry pass", c_scene_references_die, "scene-refs stale-raylib" },
    { "RblBeginSceneDepth RblEndSceneDepth", "nested, unbalanced, inside shadow and geometry passes", c_scene_depth, "nesting null" },
};

// One case in a child process: its own context and fixture, then the matrix stack depth check
static int runCase(const Case *c)
{
    alarm(60);      // a hang fails the case
    if (rtInitContext(256, 256) == NULL) return 3;
    GL_PROC(glGetI, "glGetIntegerv");
    GL_PROC(glIsOn, "glIsEnabled");
    GL_PROC(glGetB, "glGetBooleanv");
    GL_PROC(glActive, "glActiveTexture");
    SetTraceLogLevel(LOG_WARNING);
    SetTraceLogCallback(contractLog);
    if (strncmp(c->name, BARE, strlen(BARE)) == 0) { BeginMode3D(camera()); rlDrawRenderBatchActive(); }
    else fixtureUp();
    c->run();
    rlDrawRenderBatchActive();
    // rlgl's matrix stack holds 32: a pass left open shows as an overflow before 32 pushes
    raylibErrors = 0;
    for (int i = 0; i < 31; i++) rlPushMatrix();
    ck(raylibErrors == 0, "rlgl matrix stack left deeper than it was (overflow after pushes)");
    printf("      %d checks\n", caseChecks);
    fflush(stdout);
    return (caseFailures == 0)? 0 : 1;
}

// Public function names of the header (lines "RBLAPI <type> <name>(")
static int headerFunctions(const char *path, char names[][64], int max)
{
    FILE *f = fopen(path, "r");
    if (f == NULL) return -1;
    char line[1024];
    int n = 0;
    while (fgets(line, sizeof(line), f) != NULL)
    {
        if (strncmp(line, "RBLAPI ", 7) != 0) continue;
        char *paren = strchr(line, '(');
        if (paren == NULL) continue;
        char *end = paren;
        while ((end > line) && (end[-1] == ' ')) end--;
        char *start = end;
        while ((start > line) && (start[-1] != ' ') && (start[-1] != '*')) start--;
        if ((n < max) && (end - start < 63)) { memcpy(names[n], start, (size_t)(end - start)); names[n][end - start] = 0; n++; }
    }
    fclose(f);
    return n;
}

static bool caseCovers(const Case *c, const char *fn)
{
    const char *p = c->functions;
    size_t len = strlen(fn);
    while ((p = strstr(p, fn)) != NULL)
    {
        if (((p == c->functions) || (p[-1] == ' ')) && ((p[len] == 0) || (p[len] == ' '))) return true;
        p += len;
    }
    return false;
}

int main(int argc, char **argv)
{
    const char *header = (argc > 1)? argv[1] : "rbillboard_lit.h";
    const char *filter = (argc > 2)? argv[2] : NULL;
    static char names[128][64];
    int fnCount = headerFunctions(header, names, 128);
    if (fnCount <= 0) { printf("contracts: cannot read public functions from %s\ncontracts: 0 passed, 1 failed\n", header); return 1; }
    const int caseCount = (int)(sizeof(cases)/sizeof(cases[0]));
    int passed = 0, failed = 0;
    int fnCases[128] = { 0 }, fnPassed[128] = { 0 };
    static bool caseOk[256];
    for (int i = 0; i < caseCount; i++)
    {
        if ((filter != NULL) && (strstr(cases[i].functions, filter) == NULL) && (strstr(cases[i].name, filter) == NULL)) continue;
        fflush(stdout);
        pid_t pid = fork();
        if (pid == 0) _exit(runCase(&cases[i]));
        int status = 0;
        waitpid(pid, &status, 0);
        bool ok = WIFEXITED(status) && (WEXITSTATUS(status) == 0);
        const char *why = ok? "" : WIFSIGNALED(status)? ((WTERMSIG(status) == SIGALRM)? " (hang: killed after 60 s)" : " (crashed)") :
                          (WEXITSTATUS(status) == 3)? " (no context)" : (WEXITSTATUS(status) == 66)? " (sanitizer report)" : (WEXITSTATUS(status) == 1)? "" : " (abort)";
        printf("  %s  %s: %s%s\n", ok? "ok  " : "FAIL", cases[i].functions, cases[i].name, why);
        if (ok) passed++; else failed++;
        caseOk[i] = ok;
        for (int f = 0; f < fnCount; f++) if (caseCovers(&cases[i], names[f])) { fnCases[f]++; if (ok) fnPassed[f]++; }
    }
    printf("\n  %-28s %5s %6s\n", "function", "cases", "passed");
    for (int f = 0; f < fnCount; f++)
    {
        printf("  %-28s %5d %6d\n", names[f], fnCases[f], fnPassed[f]);
        if ((filter == NULL) && (fnCases[f] == 0)) { printf("  FAIL  %s has no contract case\n", names[f]); failed++; }
    }
    printf("\n  %-14s %5s %6s  %s\n", "class", "cases", "passed", "what");
    for (int k = 0; k < (int)(sizeof(classTable)/sizeof(classTable[0])); k++)
    {
        int n = 0, okCount = 0;
        for (int i = 0; i < caseCount; i++)
        {
            if ((filter != NULL) && (strstr(cases[i].functions, filter) == NULL) && (strstr(cases[i].name, filter) == NULL)) continue;
            Case tagged = cases[i];
            tagged.functions = cases[i].classes;
            if (caseCovers(&tagged, classTable[k].tag)) { n++; if (caseOk[i]) okCount++; }
        }
        printf("  %-14s %5d %6d  %s\n", classTable[k].tag, n, okCount, classTable[k].what);
        if ((filter == NULL) && (n == 0)) { printf("  FAIL  class %s has no contract case\n", classTable[k].tag); failed++; }
    }
    printf("contracts: %d passed, %d failed\n", passed, failed);
    return (failed == 0)? 0 : 1;
}
