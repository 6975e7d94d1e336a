// Benchmark suite "api": what the 1.0 API costs in programs, GL calls and public surface (GPU, headless GL).
//   values_only_materials_16  16 Materials differing only in values (GGX roughness, metalness, albedo
//                colour) on Shaders from RblLoadLitShader of one desc: registry entries it added.
//   showcase     examples/shaders_lit_billboards.c (RBL_SHOWCASE_NO_MAIN, as tests/tools/showcase_headless.c)
//   deferred_example  examples/shaders_deferred_billboards.c (RBL_DEFERRED_NO_MAIN, as tests/tools/deferred_headless.c)
//                programs: after init and one frame (frame 0), the live entries (refs > 0) of the header's
//                program registry rbl__state.programs[], every kind (RBL__KIND_LIT: lit/G-buffer
//                geometry variants, RBL__KIND_CASTER: shadow casters, RBL__KIND_PASS: G-buffer lighting
//                passes), as distinct GL program ids. raylib's default shader is not counted. Printed
//                beside it: the entries by kind and, as a cross-check, the GL program objects alive
//                (glIsProgram over ids 1..BENCH_GL_SCAN_IDS, raylib's default shader excluded).
//                showcase only, per frame, averaged over frames 2..11 (0 and 1 warm up), each frame as
//                showcase_headless.c's RenderFrame (800x450 RenderTexture):
//                  uniform_calls_per_frame  glUniform* calls (glUniformMatrix* included)
//                  gl_calls_per_frame       every GL call
//                Counted, not estimated: rlgl calls GL through glad's function-pointer variables
//                (glad_gl*, globals of libraylib.a). After rtInitContext every non-NULL one is saved
//                and replaced by a counting wrapper of the same signature that forwards. The wrappers
//                are generated at build time from raylib's external/glad.h (all its glad_gl* pointers,
//                not only those rlgl.h names, so no entry point rlgl can reach goes uncounted); after the
//                frames every pointer is checked to still be its wrapper. The header and the examples
//                call GL only through rlgl/raylib. Printed beside it: the entry points called per frame
//                (any that rlgl.h does not reference is flagged).
//   public       rbillboard_lit.h's public section (the lines before "#if defined(RBILLBOARD_LIT_IMPLEMENTATION)"):
//                  functions  lines starting with "RBLAPI "
//                  types      lines starting with "typedef struct" or "typedef enum"
//                (file: argv[1], default rbillboard_lit.h, run from the repository root)
// Rows (suite "api", unit "count"):
//   values_only_materials_16|showcase|deferred_example: programs
//   showcase: uniform_calls_per_frame, gl_calls_per_frame
//   public: functions, types
// Build (the Makefile's rule): this file is compiled four ways and three of them linked together:
//   -DBENCH_API_GEN      a generator: bench_api_gen <glad.h> <rlgl.h> > bench_api_gl.h (the wrappers; with
//                        no readable glad.h it writes a header without them and the GL rows are skipped)
//   (nothing)            main(): the header's implementation, values_only, public rows, the GL wrappers
//   -DBENCH_API_PART=1   the showcase, with its own private copy of the header (RBLAPI static)
//   -DBENCH_API_PART=2   the deferred example, likewise (both examples define the same names)
// Output: rows appended to $BENCH_CSV (see bench.h) and a summary on stdout.

#if defined(BENCH_API_GEN)
//==================================================================================
// Generator: one counting wrapper per glad_gl* pointer of glad.h
//==================================================================================
#include <ctype.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define GEN_LINE 4096

typedef struct GenProc { char pfn[128]; char ret[64]; char params[1024]; } GenProc;

static bool GenReferenced(const char *text, const char *name)
{
    // name followed by optional spaces and '(' and not preceded by an identifier character
    size_t n = strlen(name);
    for (const char *p = strstr(text, name); p != NULL; p = strstr(p + 1, name))
    {
        if ((p > text) && (isalnum((unsigned char)p[-1]) || (p[-1] == '_'))) continue;
        const char *q = p + n;
        while ((*q == ' ') || (*q == '\t')) q++;
        if (*q == '(') return true;
    }
    return false;
}

static char *GenReadAll(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL) return NULL;
    fseek(f, 0, SEEK_END);
    long size = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *text = (char *)malloc((size_t)size + 1);
    if ((text == NULL) || (fread(text, 1, (size_t)size, f) != (size_t)size)) { fclose(f); free(text); return NULL; }
    text[size] = '\0';
    fclose(f);
    return text;
}

// "GLint location, const GLfloat * value" -> params with names a0, a1 ... and the argument list "a0, a1"
static void GenParams(const char *in, char *params, size_t paramsSize, char *args, size_t argsSize)
{
    params[0] = '\0'; args[0] = '\0';
    char buf[1024];
    snprintf(buf, sizeof(buf), "%s", in);
    char *s = buf;
    while (isspace((unsigned char)*s)) s++;
    if ((strcmp(s, "void") == 0) || (*s == '\0')) { snprintf(params, paramsSize, "void"); return; }
    int k = 0;
    for (char *piece = strtok(s, ","); piece != NULL; piece = strtok(NULL, ","), k++)
    {
        size_t len = strlen(piece);
        while ((len > 0) && isspace((unsigned char)piece[len - 1])) piece[--len] = '\0';
        size_t end = len;
        while ((end > 0) && (isalnum((unsigned char)piece[end - 1]) || (piece[end - 1] == '_'))) end--;
        piece[end] = '\0';                                  // type without its name
        size_t pl = strlen(params), al = strlen(args);
        snprintf(params + pl, paramsSize - pl, "%s%sa%d", (k > 0)? ", " : "", piece, k);
        snprintf(args + al, argsSize - al, "%sa%d", (k > 0)? ", " : "", k);
    }
}

int main(int argc, char **argv)
{
    const char *gladPath = (argc > 1)? argv[1] : "";
    char *rlgl = (argc > 2)? GenReadAll(argv[2]) : NULL;
    FILE *glad = (gladPath[0] != '\0')? fopen(gladPath, "r") : NULL;
    printf("// Generated by bench_api_gen (tests/bench/bench_api.c) from %s: do not edit\n", (glad != NULL)? gladPath : "(no glad.h)");
    if (glad == NULL)
    {
        fprintf(stderr, "bench_api_gen: no glad.h (%s): GL calls will not be counted\n", gladPath);
        printf("#define BENCH_GL_WRAPPED 0\n");
        return 0;
    }

    static GenProc procs[4096];
    int procCount = 0;
    static char names[4096][128];
    static int nameProc[4096];
    int nameCount = 0;
    char line[GEN_LINE];
    while (fgets(line, sizeof(line), glad) != NULL)
    {
        // typedef RET (GLAD_API_PTR *PFN...PROC)(PARAMS);
        const char *mark = strstr(line, " (GLAD_API_PTR *PFN");
        if ((strncmp(line, "typedef ", 8) == 0) && (mark != NULL) && (procCount < 4096))
        {
            GenProc *p = &procs[procCount];
            size_t retLen = (size_t)(mark - (line + 8));
            if (retLen >= sizeof(p->ret)) continue;
            memcpy(p->ret, line + 8, retLen); p->ret[retLen] = '\0';
            const char *pfn = mark + strlen(" (GLAD_API_PTR *");
            const char *close = strchr(pfn, ')');
            const char *open = (close != NULL)? strchr(close, '(') : NULL;
            const char *end = (open != NULL)? strrchr(open, ')') : NULL;
            if ((close == NULL) || (open == NULL) || (end == NULL)) continue;
            snprintf(p->pfn, sizeof(p->pfn), "%.*s", (int)(close - pfn), pfn);
            snprintf(p->params, sizeof(p->params), "%.*s", (int)(end - open - 1), open + 1);
            procCount++;
            continue;
        }
        // GLAD_API_CALL PFN...PROC glad_glName;
        char pfn[128], var[128];
        if ((strncmp(line, "GLAD_API_CALL PFN", 17) == 0) && (sscanf(line, "GLAD_API_CALL %127s %127[A-Za-z0-9_];", pfn, var) == 2) &&
            (strncmp(var, "glad_gl", 7) == 0) && (nameCount < 4096))
        {
            int found = -1;
            for (int i = 0; (i < procCount) && (found < 0); i++) if (strcmp(procs[i].pfn, pfn) == 0) found = i;
            if (found < 0) { fprintf(stderr, "bench_api_gen: no typedef for %s (%s)\n", var, pfn); return 1; }
            snprintf(names[nameCount], sizeof(names[0]), "%s", var + 5);     // glName
            nameProc[nameCount++] = found;
        }
    }
    fclose(glad);
    if (nameCount == 0) { fprintf(stderr, "bench_api_gen: no glad_gl* pointers in %s\n", gladPath); return 1; }

    printf("#define BENCH_GL_WRAPPED 1\n#include <stddef.h>\n#include \"%s\"\n#define BENCH_GL_COUNT %d\n", gladPath, nameCount);
    printf("static long long benchGlCalls[BENCH_GL_COUNT];\n");
    printf("static const char *const benchGlNames[BENCH_GL_COUNT] = {\n");
    for (int i = 0; i < nameCount; i++) printf("    \"%s\",\n", names[i]);
    printf("};\n// 1: a glUniform* entry point (glUniformMatrix* included)\nstatic const unsigned char benchGlUniform[BENCH_GL_COUNT] = {\n");
    for (int i = 0; i < nameCount; i++) printf("%s%d,%s", ((i%32) == 0)? "    " : "", strncmp(names[i], "glUniform", 9) == 0, ((i%32) == 31)? "\n" : "");
    printf("\n};\n// 1: referenced by rlgl.h (gl<Name>( in its text)\nstatic const unsigned char benchGlRlgl[BENCH_GL_COUNT] = {\n");
    int referenced = 0;
    for (int i = 0; i < nameCount; i++)
    {
        int r = (rlgl != NULL) && GenReferenced(rlgl, names[i]);
        referenced += r;
        printf("%s%d,%s", ((i%32) == 0)? "    " : "", r, ((i%32) == 31)? "\n" : "");
    }
    printf("\n};\n#define BENCH_GL_RLGL_REFERENCED %d\n#define BENCH_GL_RLGL_KNOWN %d\n", referenced, rlgl != NULL);
    for (int i = 0; i < nameCount; i++)
    {
        const GenProc *p = &procs[nameProc[i]];
        char params[1200], args[256];
        GenParams(p->params, params, sizeof(params), args, sizeof(args));
        bool isVoid = (strcmp(p->ret, "void") == 0);
        printf("static %s benchGlReal%d;\n", p->pfn, i);
        printf("static %s GLAD_API_PTR benchGlWrap%d(%s) { benchGlCalls[%d]++; %sbenchGlReal%d(%s); }\n",
               p->ret, i, params, i, isVoid? "" : "return ", i, args);
        if (strcmp(names[i], "glIsProgram") == 0) printf("#define BENCH_GL_REAL_IS_PROGRAM benchGlReal%d\n", i);
    }
    // Per pointer, one small function (one function of 1007 branches takes GCC -O2 half a minute):
    // op 0 saves and replaces it if non-NULL, op 1 tells if it was saved but is no longer the wrapper
    // (set again by someone else: its calls would go uncounted), op 2 tells if it is NULL
    for (int i = 0; i < nameCount; i++)
        printf("static int benchGlOp%d(int op) { if (op == 0) { if (glad_%s == NULL) return 0; benchGlReal%d = glad_%s; glad_%s = benchGlWrap%d; return 1; }"
               " return (op == 1)? ((benchGlReal%d != NULL) && (glad_%s != benchGlWrap%d)) : (glad_%s == NULL); }\n",
               i, names[i], i, names[i], names[i], i, i, names[i], i, names[i]);
    printf("static int (*const benchGlOps[BENCH_GL_COUNT])(int) = {\n");
    for (int i = 0; i < nameCount; i++) printf("%sbenchGlOp%d,%s", ((i%8) == 0)? "    " : " ", i, ((i%8) == 7)? "\n" : "");
    printf("\n};\n");
    printf("static int benchGlEach(int op) { int n = 0; for (int i = 0; i < BENCH_GL_COUNT; i++) n += benchGlOps[i](op); return n; }\n");
    printf("static int benchGlInstall(void) { return benchGlEach(0); }          // Pointers wrapped\n");
    printf("static int benchGlReplacedSince(void) { return benchGlEach(1); }    // Wrapped, then set again\n");
    printf("static int benchGlNull(void) { return benchGlEach(2); }             // NULL (not in this context)\n");
    if (rlgl != NULL)
    {
        // Entry points rlgl.h names that glad.h lacks (GLES-only or platform branches): listed for the record
        printf("// rlgl.h names gl*( not declared by glad.h:");
        for (const char *p = rlgl; (p = strstr(p, "gl")) != NULL; p++)
        {
            if ((p > rlgl) && (isalnum((unsigned char)p[-1]) || (p[-1] == '_'))) continue;
            if (!isupper((unsigned char)p[2])) continue;
            char name[128];
            int n = 0;
            while ((n < 127) && (isalnum((unsigned char)p[n]) || (p[n] == '_'))) { name[n] = p[n]; n++; }
            name[n] = '\0';
            const char *q = p + n;
            while ((*q == ' ') || (*q == '\t')) q++;
            if (*q != '(') continue;
            bool known = false;
            for (int i = 0; (i < nameCount) && !known; i++) known = (strcmp(names[i], name) == 0);
            static char listed[256][128];
            static int listedCount = 0;
            for (int i = 0; (i < listedCount) && !known; i++) known = (strcmp(listed[i], name) == 0);
            if (!known && (listedCount < 256)) { snprintf(listed[listedCount++], sizeof(listed[0]), "%s", name); printf(" %s", name); }
        }
        printf("\n");
    }
    free(rlgl);
    return 0;
}

#else
//==================================================================================
// The benchmark (three units, see the top)
//==================================================================================
#if !defined(BENCH_API_PART)
    #define RBILLBOARD_LIT_IMPLEMENTATION
    #include "rbillboard_lit.h"
#elif (BENCH_API_PART == 1) || (BENCH_API_PART == 2)
    // A private copy of the header per example: its public functions unused here are not errors
    #define RBLAPI static
    #if defined(__GNUC__)
        #pragma GCC diagnostic ignored "-Wunused-function"
    #endif
    #if (BENCH_API_PART == 1)
        #define RBL_SHOWCASE_NO_MAIN
        #include "../../examples/shaders_lit_billboards.c"
    #else
        #define RBL_DEFERRED_NO_MAIN
        #include "../../examples/shaders_deferred_billboards.c"
    #endif
#else
    #error "BENCH_API_PART: 1 (showcase) or 2 (deferred)"
#endif
#include "rlgl.h"
#include "harness.h"
#include "bench.h"

#include <stdio.h>
#include <string.h>

#define SUITE               "api"
#define FRAME_W             800                 // as showcase_headless.c and deferred_headless.c
#define FRAME_H             450
#define WARM_FRAMES         2                   // frames 0 and 1
#define COUNTED_FRAMES      10                  // frames 2..11
#define VALUES_MATERIALS    16
#define BENCH_GL_SCAN_IDS   4096                // GL program names scanned by the cross-check

// What one example holds and costs (filled by the example units)
typedef struct BenchApiResult {
    bool ran;
    int programs;                   // distinct program ids of live registry entries
    int lit, caster, pass;          // live registry entries by kind
    int glPrograms;                 // GL program objects alive (glIsProgram), raylib's default excluded; -1: unknown
    double glCalls, uniformCalls;   // per counted frame (-1: not counted)
    long long glCallsMin, glCallsMax;   // over the counted frames
} BenchApiResult;

// Main unit: the GL call counters (all glad_gl* pointers wrapped)
bool BenchGlWrapped(void);
void BenchGlReset(void);
long long BenchGlTotal(void);
long long BenchGlUniformTotal(void);
void BenchGlPrintCalled(int frames);
int BenchGlLivePrograms(void);
// Example units
bool BenchApiShowcase(BenchApiResult *out);
bool BenchApiDeferred(BenchApiResult *out);

// Live entries of this unit's program registry, by kind, and their distinct ids
static void CountRegistry(BenchApiResult *r)
{
    unsigned int ids[RBL_SHADER_CACHE_SIZE];
    r->programs = r->lit = r->caster = r->pass = 0;
    for (int i = 0; (i < rbl__state.programCount) && (i < RBL_SHADER_CACHE_SIZE); i++)
    {
        const rbl__Program *p = rbl__state.programs[i];
        if (p->key.kind == RBL__KIND_LIT) r->lit++;
        else if (p->key.kind == RBL__KIND_CASTER) r->caster++;
        else r->pass++;
        bool seen = false;
        for (int k = 0; (k < r->programs) && !seen; k++) seen = (ids[k] == p->shader.id);
        if (!seen) ids[r->programs++] = p->shader.id;
    }
}

#if (BENCH_API_PART == 1)
//----------------------------------------------------------------------------------
// Showcase
//----------------------------------------------------------------------------------
static void RenderFrame(RenderTexture2D target, int frame)      // as tests/tools/showcase_headless.c
{
    ShowcaseUpdate((float)frame/60.0f);
    ShowcaseDrawShadows();
    BeginTextureMode(target);
        ClearBackground(showcaseBackground);
        BeginMode3D(showcaseCamera);
            ShowcaseDraw();
        EndMode3D();
    EndTextureMode();
}

bool BenchApiShowcase(BenchApiResult *out)
{
    memset(out, 0, sizeof(*out));
    ShowcaseInit();
    RenderTexture2D target = LoadRenderTexture(FRAME_W, FRAME_H);
    RenderFrame(target, 0);
    CountRegistry(out);
    out->glPrograms = BenchGlLivePrograms();
    for (int f = 1; f < WARM_FRAMES; f++) RenderFrame(target, f);
    long long total = 0, uniforms = 0;
    out->glCallsMin = -1;
    for (int f = WARM_FRAMES; f < WARM_FRAMES + COUNTED_FRAMES; f++)
    {
        BenchGlReset();
        RenderFrame(target, f);
        long long n = BenchGlTotal();
        total += n;
        uniforms += BenchGlUniformTotal();
        if ((out->glCallsMin < 0) || (n < out->glCallsMin)) out->glCallsMin = n;
        if (n > out->glCallsMax) out->glCallsMax = n;
        if (f == WARM_FRAMES + COUNTED_FRAMES - 1) { printf("showcase: entry points called in frame %d:\n", f); BenchGlPrintCalled(1); }
    }
    out->glCalls = BenchGlWrapped()? (double)total/COUNTED_FRAMES : -1.0;
    out->uniformCalls = BenchGlWrapped()? (double)uniforms/COUNTED_FRAMES : -1.0;
    UnloadRenderTexture(target);
    ShowcaseUnload();
    out->ran = true;
    return true;
}

#elif (BENCH_API_PART == 2)
//----------------------------------------------------------------------------------
// Deferred example
//----------------------------------------------------------------------------------
static void Frame(RenderTexture2D target, float time)          // as tests/tools/deferred_headless.c
{
    DeferredUpdate(time);
    DeferredPasses();
    BeginTextureMode(target);
        DeferredCompose();
    EndTextureMode();
}

bool BenchApiDeferred(BenchApiResult *out)
{
    memset(out, 0, sizeof(*out));
    DeferredInit(FRAME_W, FRAME_H);
    if (!deferredValid) printf("deferred_example: G-buffer unavailable, the forward fallback renders\n");
    RenderTexture2D target = LoadRenderTexture(FRAME_W, FRAME_H);
    Frame(target, 0.0f);
    CountRegistry(out);
    out->glPrograms = BenchGlLivePrograms();
    for (int f = 1; f < WARM_FRAMES; f++) Frame(target, f/60.0f);
    long long total = 0, uniforms = 0;
    out->glCallsMin = -1;
    for (int f = WARM_FRAMES; f < WARM_FRAMES + COUNTED_FRAMES; f++)
    {
        BenchGlReset();
        Frame(target, f/60.0f);
        long long n = BenchGlTotal();
        total += n;
        uniforms += BenchGlUniformTotal();
        if ((out->glCallsMin < 0) || (n < out->glCallsMin)) out->glCallsMin = n;
        if (n > out->glCallsMax) out->glCallsMax = n;
    }
    out->glCalls = BenchGlWrapped()? (double)total/COUNTED_FRAMES : -1.0;
    out->uniformCalls = BenchGlWrapped()? (double)uniforms/COUNTED_FRAMES : -1.0;
    UnloadRenderTexture(target);
    DeferredUnload();
    out->ran = true;
    return true;
}

#else
//----------------------------------------------------------------------------------
// Main unit: GL call counters, values_only, public surface, main()
//----------------------------------------------------------------------------------
#if defined(BENCH_API_GL)
    #include "bench_api_gl.h"           // generated by the Makefile rule (bench_api_gen)
#else
    #define BENCH_GL_WRAPPED 0
#endif

#if BENCH_GL_WRAPPED
bool BenchGlWrapped(void) { return true; }
void BenchGlReset(void) { memset(benchGlCalls, 0, sizeof(benchGlCalls)); }
long long BenchGlTotal(void) { long long n = 0; for (int i = 0; i < BENCH_GL_COUNT; i++) n += benchGlCalls[i]; return n; }
long long BenchGlUniformTotal(void) { long long n = 0; for (int i = 0; i < BENCH_GL_COUNT; i++) if (benchGlUniform[i]) n += benchGlCalls[i]; return n; }
void BenchGlPrintCalled(int frames)
{
    int column = 0;
    for (int i = 0; i < BENCH_GL_COUNT; i++)
    {
        if (benchGlCalls[i] == 0) continue;
        printf("%s%s %.1f%s", (column == 0)? "  " : ", ", benchGlNames[i], (double)benchGlCalls[i]/frames,
               (BENCH_GL_RLGL_KNOWN && !benchGlRlgl[i])? " (NOT referenced by rlgl.h)" : "");
        if (++column == 6) { printf("\n"); column = 0; }
    }
    if (column != 0) printf("\n");
}
int BenchGlLivePrograms(void)
{
    int n = 0;
    for (unsigned int id = 1; id <= BENCH_GL_SCAN_IDS; id++)
        if ((id != rlGetShaderIdDefault()) && BENCH_GL_REAL_IS_PROGRAM(id)) n++;
    return n;
}
#else
bool BenchGlWrapped(void) { return false; }
void BenchGlReset(void) { }
long long BenchGlTotal(void) { return 0; }
long long BenchGlUniformTotal(void) { return 0; }
void BenchGlPrintCalled(int frames) { (void)frames; }
int BenchGlLivePrograms(void) { return -1; }
#endif

// RblLoadLitShader of one desc for 16 Materials whose values differ: registry entries added
static int ValuesOnlyMaterials(void)
{
    BenchApiResult before, after;
    CountRegistry(&before);
    RblLitShaderDesc desc = { 0 };
    desc.shading.brdf = RBL_BRDF_GGX;
    Shader shaders[VALUES_MATERIALS];
    Material materials[VALUES_MATERIALS];
    for (int i = 0; i < VALUES_MATERIALS; i++)
    {
        shaders[i] = RblLoadLitShader(desc);
        materials[i] = LoadMaterialDefault();
        materials[i].shader = shaders[i];
        rtSetMaterialValues(&materials[i], (RtMaterialValues){ .roughness = 0.05f + 0.06f*(float)i, .metalness = (float)(i%4)/3.0f });
        materials[i].maps[MATERIAL_MAP_ALBEDO].color = (Color){ (unsigned char)(40 + 13*i), (unsigned char)(200 - 9*i), (unsigned char)(90 + 7*(i%5)), 255 };
    }
    CountRegistry(&after);
    int ids = 0;
    for (int i = 0; i < VALUES_MATERIALS; i++)
    {
        bool seen = false;
        for (int k = 0; (k < i) && !seen; k++) seen = (shaders[k].id == shaders[i].id);
        ids += !seen;
    }
    printf("values_only_materials_16: %d registry entries added, %d distinct Shader ids among the %d materials\n",
           after.programs - before.programs, ids, VALUES_MATERIALS);
    for (int i = 0; i < VALUES_MATERIALS; i++)
    {
        RblUnloadLitShader(&shaders[i]);
        materials[i].shader.id = rlGetShaderIdDefault();        // the program and its locs went with the handle
        materials[i].shader.locs = rlGetShaderLocsDefault();
        UnloadMaterial(materials[i]);
    }
    return after.programs - before.programs;
}

// RBLAPI functions and struct/enum typedefs of the public section; false if the file is unreadable
static bool CountPublic(const char *path, int *functions, int *types)
{
    FILE *f = fopen(path, "r");
    *functions = *types = 0;
    if (f == NULL) return false;
    char line[4096];
    bool ended = false;
    while (!ended && (fgets(line, sizeof(line), f) != NULL))
    {
        if (strncmp(line, "#if defined(RBILLBOARD_LIT_IMPLEMENTATION)", 42) == 0) ended = true;
        else if (strncmp(line, "RBLAPI ", 7) == 0) (*functions)++;
        else if ((strncmp(line, "typedef struct", 14) == 0) || (strncmp(line, "typedef enum", 12) == 0)) (*types)++;
    }
    fclose(f);
    return ended;
}

static void PrintExample(const char *name, const BenchApiResult *r)
{
    printf("%s: %d programs (registry: %d lit, %d caster, %d pass; GL program objects alive: %d)",
           name, r->programs, r->lit, r->caster, r->pass, r->glPrograms);
    if (r->glCalls >= 0.0) printf(", %.1f GL calls per frame (min %lld, max %lld), %.1f glUniform*", r->glCalls, r->glCallsMin, r->glCallsMax, r->uniformCalls);
    printf("\n");
}

int main(int argc, char **argv)
{
    const char *headerPath = (argc > 1)? argv[1] : "rbillboard_lit.h";
    int functions = 0, types = 0;
    if (CountPublic(headerPath, &functions, &types))
    {
        printf("public: %d RBLAPI functions, %d struct/enum typedefs (%s)\n", functions, types, headerPath);
        BenchCsvRow(SUITE, "public", "functions", functions, "count");
        BenchCsvRow(SUITE, "public", "types", types, "count");
    }
    else printf("bench_api: %s unreadable or without an implementation section: public rows skipped\n", headerPath);

    const char *backend = rtInitContext(FRAME_W, FRAME_H);
    if (backend == NULL) { printf("bench_api: no headless GL context, GPU rows skipped\n"); return 0; }
    int problems = 0;
#if BENCH_GL_WRAPPED
    int wrapped = benchGlInstall();
    printf("GL: %d of %d glad_gl* pointers non-NULL and wrapped (%d NULL); rlgl.h references %d of them (%s)\n",
           wrapped, BENCH_GL_COUNT, benchGlNull(), BENCH_GL_RLGL_REFERENCED, backend);
#else
    printf("bench_api: built without raylib's glad.h: GL calls not counted, those rows skipped\n");
#endif

    int valuesOnly = ValuesOnlyMaterials();
    BenchCsvRow(SUITE, "values_only_materials_16", "programs", valuesOnly, "count");

    BenchApiResult showcase, deferred;
    BenchApiShowcase(&showcase);
    PrintExample("showcase", &showcase);
    BenchApiDeferred(&deferred);
    PrintExample("deferred_example", &deferred);
    BenchCsvRow(SUITE, "showcase", "programs", showcase.programs, "count");
    BenchCsvRow(SUITE, "deferred_example", "programs", deferred.programs, "count");

#if BENCH_GL_WRAPPED
    int replaced = benchGlReplacedSince();
    if (replaced != 0)
    {
        printf("bench_api: %d glad_gl* pointers were set again after wrapping: GL call rows not written\n", replaced);
        problems++;
    }
    else
    {
        BenchCsvRow(SUITE, "showcase", "uniform_calls_per_frame", showcase.uniformCalls, "count");
        BenchCsvRow(SUITE, "showcase", "gl_calls_per_frame", showcase.glCalls, "count");
    }
#endif
    rtCloseContext();
    return (problems == 0)? 0 : 1;
}
#endif // BENCH_API_PART

#endif // BENCH_API_GEN
