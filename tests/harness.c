// Test support implementation; see harness.h.
#include "harness.h"
#include "rlgl.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#if defined(__EMSCRIPTEN__)
#include <emscripten/html5.h>
#include <webgl/webgl2.h>
#else
#include <dlfcn.h>
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/osmesa.h>
#endif

// ---- runner ---------------------------------------------------------------------------------
static const char *rtTestName = "";
static int rtTestFailures = 0;

void rtCheck(bool ok, const char *file, int line, const char *fmt, ...)
{
    if (ok) return;
    rtTestFailures++;
    if (rtTestFailures > 12) return;    // a broken loop should not flood the log
    fprintf(stdout, "    %s:%d: ", file, line);
    va_list ap;
    va_start(ap, fmt);
    vfprintf(stdout, fmt, ap);
    va_end(ap);
    fputc('\n', stdout);
}

const char *rtCurrentTest(void) { return rtTestName; }
int rtFailuresInCurrentTest(void) { return rtTestFailures; }

int rtRun(const char *suite, const RtTest *tests, int count, int argc, char **argv)
{
    const char *filter = (argc > 1)? argv[1] : NULL;
    int passed = 0, failed = 0, skipped = 0;
    bool glsl3 = rtGlsl3();
    for (int i = 0; i < count; i++)
    {
        if ((filter != NULL) && (strstr(tests[i].name, filter) == NULL)) continue;
        if (tests[i].glsl3 && !glsl3) { skipped++; printf("  n/a   %s (needs GLSL 3)\n", tests[i].name); continue; }
        rtTestName = tests[i].name;
        rtTestFailures = 0;
        tests[i].fn();
        if (rtTestFailures == 0) { passed++; printf("  ok    %s\n", tests[i].name); }
        else { failed++; printf("  FAIL  %s (%d failed checks)\n", tests[i].name, rtTestFailures); }
        fflush(stdout);
    }
    if (skipped > 0) printf("  %d tests need GLSL 3 (GL 3.3 / ES 3) and do not apply to this context; the refusals are tested\n", skipped);
    printf("%s: %d passed, %d failed\n", suite, passed, failed);
    return (failed == 0)? 0 : 1;
}

// ---- numeric helpers ------------------------------------------------------------------------
bool rtFinite(float x) { return isfinite(x) != 0; }
bool rtNear(double a, double b, double tol) { return fabs(a - b) <= tol; }

unsigned int rtRandom(unsigned int *s)
{
    unsigned int x = *s;
    x ^= x << 13; x ^= x >> 17; x ^= x << 5;
    return *s = x;
}

float rtRandomRange(unsigned int *s, float lo, float hi)
{
    return lo + (hi - lo)*(float)(rtRandom(s) & 0xFFFFFF)/(float)0xFFFFFF;
}

// ---- headless GL ----------------------------------------------------------------------------
#if defined(__EMSCRIPTEN__)
// Browser: the page's #canvas gets a WebGL2 context made here, not by raylib's RGFW web platform,
// which asks for WebGL1 (raylib 6.0 sets no context version for ES 3). rlgl is then started on it
// the same way as on the desktop contexts.
static EMSCRIPTEN_WEBGL_CONTEXT_HANDLE rtWebContext = 0;

// ISO C has no cast between function pointers and void *: both travel through memcpy
typedef void *(*RtWebGetProc)(const char *);
static void *rtWebLoaderPtr(void) { RtWebGetProc f = emscripten_webgl_get_proc_address; void *p; memcpy(&p, &f, sizeof(p)); return p; }

const char *rtInitContext(int width, int height)
{
    EmscriptenWebGLContextAttributes attrs;
    emscripten_webgl_init_context_attributes(&attrs);
    attrs.majorVersion = 2;
    attrs.minorVersion = 0;
    attrs.antialias = EM_FALSE;     // tests compare exact coverage; MSAA would blend quad edges
    attrs.preserveDrawingBuffer = EM_TRUE;
    emscripten_set_canvas_element_size("#canvas", width, height);
    rtWebContext = emscripten_webgl_create_context("#canvas", &attrs);
    if (rtWebContext <= 0) { printf("    context: webgl2: refused (%d)\n", (int)rtWebContext); return NULL; }
    emscripten_webgl_make_context_current(rtWebContext);
    // Float render targets (deferred light accumulation, linear readbacks) need this on WebGL2
    if (!emscripten_webgl_enable_extension(rtWebContext, "EXT_color_buffer_float")) printf("    context: webgl2: no EXT_color_buffer_float\n");
    emscripten_webgl_enable_extension(rtWebContext, "OES_texture_float_linear");
    SetTraceLogLevel(LOG_WARNING);
    rlLoadExtensions(rtWebLoaderPtr());
    rlglInit(width, height);
    // InitWindow would also give the shapes functions a texture (the default font's white rectangle);
    // raylib's 1x1 white default texture serves the same purpose
    SetShapesTexture((Texture2D){ rlGetTextureIdDefault(), 1, 1, 1, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8 }, (Rectangle){ 0, 0, 1, 1 });
    return "webgl2";
}

void rtCloseContext(void)
{
    rlglClose();
    if (rtWebContext > 0) emscripten_webgl_destroy_context(rtWebContext);
    rtWebContext = 0;
}

void rtFinish(void)
{
    void (*finish)(void) = NULL;
    void *p = emscripten_webgl_get_proc_address("glFinish");
    memcpy(&finish, &p, sizeof(p));
    if (finish != NULL) finish();
}

// WebGL2 cannot map a buffer for reading (emscripten's glMapBufferRange maps for writing only); it
// reads buffers back with getBufferSubData. A read mapping (what ES 3.0 code does, e.g. tf_capture.h)
// is emulated with it: glMapBufferRange copies into memory of ours, glUnmapBuffer frees it.
static void *rtWebMapped = NULL;
static void *rtWebMapBufferRange(GLenum target, GLintptr offset, GLsizeiptr length, GLbitfield access)
{
    if ((access != GL_MAP_READ_BIT) || (rtWebMapped != NULL) || (length <= 0)) return NULL;
    rtWebMapped = malloc((size_t)length);
    if (rtWebMapped != NULL) glGetBufferSubData(target, offset, length, rtWebMapped);
    return rtWebMapped;
}
static GLboolean rtWebUnmapBuffer(GLenum target)
{
    (void)target;
    if (rtWebMapped == NULL) return GL_FALSE;
    free(rtWebMapped);
    rtWebMapped = NULL;
    return GL_TRUE;
}

void *rtGlProc(const char *name)
{
    void *p = NULL;
    if (strcmp(name, "glMapBufferRange") == 0) { void *(*f)(GLenum, GLintptr, GLsizeiptr, GLbitfield) = rtWebMapBufferRange; memcpy(&p, &f, sizeof(p)); }
    else if (strcmp(name, "glUnmapBuffer") == 0) { GLboolean (*f)(GLenum) = rtWebUnmapBuffer; memcpy(&p, &f, sizeof(p)); }
    else p = emscripten_webgl_get_proc_address(name);
    return p;
}

#else
// Both libraries are opened at run time so one binary runs on either and reports what is missing.
// Function pointers travel through memcpy: ISO C has no cast between them and void *.
typedef void (*RtFn)(void);
typedef RtFn (*RtGetProcFn)(const char *);
typedef EGLBoolean (*RtEglInitialize)(EGLDisplay, EGLint *, EGLint *);
typedef EGLBoolean (*RtEglBindApi)(EGLenum);
typedef EGLContext (*RtEglCreateContext)(EGLDisplay, EGLConfig, EGLContext, const EGLint *);
typedef EGLBoolean (*RtEglMakeCurrent)(EGLDisplay, EGLSurface, EGLSurface, EGLContext);
typedef EGLBoolean (*RtEglDestroyContext)(EGLDisplay, EGLContext);
typedef EGLBoolean (*RtEglTerminate)(EGLDisplay);
typedef OSMesaContext (*RtOsmesaCreate)(const int *, OSMesaContext);
typedef GLboolean (*RtOsmesaMakeCurrent)(OSMesaContext, void *, GLenum, GLsizei, GLsizei);
typedef void (*RtOsmesaDestroy)(OSMesaContext);

static void *rtEglLib = NULL, *rtOsmesaLib = NULL;
static EGLDisplay rtEglDisplay = EGL_NO_DISPLAY;
static EGLContext rtEglContext = EGL_NO_CONTEXT;
static OSMesaContext rtOsmesaContext = NULL;
static unsigned char *rtOsmesaBuffer = NULL;
static RtGetProcFn rtGetProc = NULL;

// dlsym result as a function pointer of the caller's type (out points at that pointer)
static bool rtSym(void *lib, const char *name, void *out)
{
    void *p = dlsym(lib, name);
    if (p == NULL) { printf("    context: %s missing\n", name); return false; }
    memcpy(out, &p, sizeof(p));
    return true;
}

static void *rtFnToPtr(RtFn f) { void *p; memcpy(&p, &f, sizeof(p)); return p; }

// rlLoadExtensions wants a loader returning void *; wrap the context's own loader
static void *rtLoader(const char *name) { return rtFnToPtr(rtGetProc(name)); }

// kind: "egl" GL 3.3 core, "gles3" / "gles2" OpenGL ES 3 / 2, "gl21" GL 2.1 (compatibility). Strict
// versions come from Mesa's overrides, set by tests/run.sh: MESA_GLES_VERSION_OVERRIDE=3.0 (ES 3.0,
// GLSL ES 3.00), MESA_GL_VERSION_OVERRIDE=2.1 MESA_GLSL_VERSION_OVERRIDE=120.
static bool rtInitEgl(const char *kind)
{
    rtEglLib = dlopen("libEGL.so.1", RTLD_NOW | RTLD_GLOBAL);
    if (rtEglLib == NULL) { printf("    context: egl: libEGL.so.1 not found (%s)\n", dlerror()); return false; }
    RtGetProcFn getProc; RtEglInitialize initialize; RtEglBindApi bindApi; RtEglCreateContext createContext; RtEglMakeCurrent makeCurrent;
    if (!rtSym(rtEglLib, "eglGetProcAddress", &getProc) || !rtSym(rtEglLib, "eglInitialize", &initialize) ||
        !rtSym(rtEglLib, "eglBindAPI", &bindApi) || !rtSym(rtEglLib, "eglCreateContext", &createContext) ||
        !rtSym(rtEglLib, "eglMakeCurrent", &makeCurrent)) return false;
    PFNEGLGETPLATFORMDISPLAYEXTPROC getPlatformDisplay;
    RtFn f = getProc("eglGetPlatformDisplayEXT");
    if (f == NULL) { printf("    context: egl: no eglGetPlatformDisplayEXT\n"); return false; }
    memcpy(&getPlatformDisplay, &f, sizeof(f));
    rtEglDisplay = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    EGLint major = 0, minor = 0;
    if ((rtEglDisplay == EGL_NO_DISPLAY) || !initialize(rtEglDisplay, &major, &minor))
    {
        // Drivers without Mesa's surfaceless platform (NVIDIA's) offer their first device instead
        PFNEGLQUERYDEVICESEXTPROC queryDevices;
        EGLDeviceEXT device; EGLint count = 0;
        f = getProc("eglQueryDevicesEXT");
        memcpy(&queryDevices, &f, sizeof(f));
        rtEglDisplay = ((f != NULL) && queryDevices(1, &device, &count) && (count > 0))? getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, NULL) : EGL_NO_DISPLAY;
        if ((rtEglDisplay == EGL_NO_DISPLAY) || !initialize(rtEglDisplay, &major, &minor)) { printf("    context: egl: no surfaceless or device display\n"); return false; }
    }
    bool es = (strncmp(kind, "gles", 4) == 0), gl21 = (strcmp(kind, "gl21") == 0);
    if (!bindApi(es? EGL_OPENGL_ES_API : EGL_OPENGL_API)) { printf("    context: %s: API unavailable\n", kind); return false; }
    const EGLint core[] = { EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE };
    const EGLint compat21[] = { EGL_CONTEXT_MAJOR_VERSION, 2, EGL_CONTEXT_MINOR_VERSION, 1, EGL_NONE };
    const EGLint gles[] = { EGL_CONTEXT_MAJOR_VERSION, (strcmp(kind, "gles2") == 0)? 2 : 3, EGL_NONE };
    rtEglContext = createContext(rtEglDisplay, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, es? gles : (gl21? compat21 : core));
    if (rtEglContext == EGL_NO_CONTEXT) { printf("    context: %s: context refused\n", kind); return false; }
    if (!makeCurrent(rtEglDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, rtEglContext)) { printf("    context: egl: make current failed\n"); return false; }
    rtGetProc = getProc;
    return true;
}

static bool rtInitOsmesa(int width, int height)
{
    rtOsmesaLib = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_GLOBAL);
    if (rtOsmesaLib == NULL) rtOsmesaLib = dlopen("libOSMesa.so", RTLD_NOW | RTLD_GLOBAL);
    if (rtOsmesaLib == NULL) { printf("    context: osmesa: libOSMesa not found (%s)\n", dlerror()); return false; }
    RtOsmesaCreate create; RtOsmesaMakeCurrent makeCurrent; RtGetProcFn getProc;
    if (!rtSym(rtOsmesaLib, "OSMesaCreateContextAttribs", &create) || !rtSym(rtOsmesaLib, "OSMesaMakeCurrent", &makeCurrent) ||
        !rtSym(rtOsmesaLib, "OSMesaGetProcAddress", &getProc)) return false;
    const int attribs[] = { OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0 };
    rtOsmesaContext = create(attribs, NULL);
    if (rtOsmesaContext == NULL) { printf("    context: osmesa: 3.3 core context refused\n"); return false; }
    rtOsmesaBuffer = (unsigned char *)malloc((size_t)width*height*4);
    if (!makeCurrent(rtOsmesaContext, rtOsmesaBuffer, 0x1401 /* GL_UNSIGNED_BYTE */, width, height)) { printf("    context: osmesa: make current failed\n"); return false; }
    rtGetProc = getProc;
    return true;
}

const char *rtInitContext(int width, int height)
{
    const char *force = getenv("RBL_TEST_CONTEXT");
    const char *name = NULL;
    if ((force == NULL) || (strcmp(force, "egl") == 0)) { if (rtInitEgl("egl")) name = "egl"; }
    else if ((strcmp(force, "gles3") == 0) || (strcmp(force, "gles2") == 0) || (strcmp(force, "gl21") == 0)) { if (rtInitEgl(force)) name = force; }
    if ((name == NULL) && ((force == NULL) || (strcmp(force, "osmesa") == 0))) { if (rtInitOsmesa(width, height)) name = "osmesa"; }
    if (name == NULL) { printf("    context: no headless GL 3.3 core context (RBL_TEST_CONTEXT=%s)\n", force? force : "any"); return NULL; }
    SetTraceLogLevel(LOG_WARNING);     // raylib's INFO lines would bury the test output
    rlLoadExtensions(rtFnToPtr((RtFn)rtLoader));
    rlglInit(width, height);
    typedef const unsigned char *(*RtGetString)(unsigned int);
    RtGetString getString; void *p = rtGlProc("glGetString"); memcpy(&getString, &p, sizeof(p));
    const unsigned char *version = (getString != NULL)? getString(0x1F02 /* GL_VERSION */) : NULL;
    const unsigned char *renderer = (getString != NULL)? getString(0x1F01 /* GL_RENDERER */) : NULL;
    printf("    context: %s: GL_VERSION %s, GL_RENDERER %s, rlGetVersion %i\n", name, (version != NULL)? (const char *)version : "?",
           (renderer != NULL)? (const char *)renderer : "?", rlGetVersion());
    return name;
}

void rtCloseContext(void)
{
    rlglClose();
    if (rtEglContext != EGL_NO_CONTEXT)
    {
        RtEglMakeCurrent makeCurrent; RtEglDestroyContext destroy; RtEglTerminate terminate;
        if (rtSym(rtEglLib, "eglMakeCurrent", &makeCurrent) && rtSym(rtEglLib, "eglDestroyContext", &destroy) && rtSym(rtEglLib, "eglTerminate", &terminate))
        {
            makeCurrent(rtEglDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            destroy(rtEglDisplay, rtEglContext);
            terminate(rtEglDisplay);
        }
        rtEglContext = EGL_NO_CONTEXT;
    }
    if (rtOsmesaContext != NULL)
    {
        RtOsmesaDestroy destroy;
        if (rtSym(rtOsmesaLib, "OSMesaDestroyContext", &destroy)) destroy(rtOsmesaContext);
        rtOsmesaContext = NULL;
        free(rtOsmesaBuffer);
        rtOsmesaBuffer = NULL;
    }
}

#endif  // __EMSCRIPTEN__

Image rtReadTarget(RenderTexture2D target)
{
    Image image = LoadImageFromTexture(target.texture);
    ImageFlipVertical(&image);      // GL rows start at the bottom; tests think in screen rows
    return image;
}

Color rtPixel(Image image, int x, int y)
{
    return GetImageColor(image, x, y);
}

void rtSaveImage(Image image, const char *tag)
{
    mkdir("build", 0755);
    mkdir("build/test-output", 0755);
    char path[512];
    snprintf(path, sizeof(path), "build/test-output/%s-%s.png", rtTestName, tag);
    if (ExportImage(image, path)) printf("    image written: %s\n", path);
}

// ---- atlas fixtures -----------------------------------------------------------------------------
const char *rtAtlasFixtures(void)
{
    static const char *dir = NULL;
    if (dir != NULL) return dir;
    static const char *const files[] = {
        "texturepacker/hash.json", "texturepacker/array.json", "texturepacker/multi-0.json", "texturepacker/multi-1.json",
        "texturepacker/phaser3.json", "texturepacker/polygon.json", "aseprite/tags.json", "aseprite/slices.json",
        "libgdx/old.atlas", "libgdx/new.atlas", "libgdx/rotations.atlas" };
    static const struct { const char *name; int w, h; } sheets[] = {
        { "texturepacker/sheet.png", 128, 64 }, { "texturepacker/multi-0.png", 16, 16 }, { "texturepacker/multi-1.png", 16, 16 },
        { "texturepacker/phaser-0.png", 64, 32 }, { "texturepacker/phaser-0_n.png", 64, 32 }, { "texturepacker/phaser-1.png", 32, 32 },
        { "texturepacker/phaser-1_n.png", 32, 32 }, { "texturepacker/poly.png", 64, 64 }, { "aseprite/s.png", 64, 16 },
        { "aseprite/slices.png", 64, 32 }, { "libgdx/page1.png", 64, 64 }, { "libgdx/sheet.png", 64, 32 }, { "libgdx/second.png", 8, 8 },
        { "libgdx/rot.png", 64, 64 } };
    static const char *const formats[3] = { "texturepacker", "aseprite", "libgdx" };
    char path[256];
    for (int i = 0; i < 3; i++)
    {
        snprintf(path, sizeof(path), "build/tests/atlas/%s", formats[i]);
        MakeDirectory(path);
    }
    for (int i = 0; i < (int)(sizeof(files)/sizeof(files[0])); i++)
    {
        int size = 0;
        snprintf(path, sizeof(path), "tests/fuzz/corpus/%s", files[i]);
        unsigned char *data = LoadFileData(path, &size);
        snprintf(path, sizeof(path), "build/tests/atlas/%s", files[i]);
        bool ok = (data != NULL) && SaveFileData(path, data, size);
        UnloadFileData(data);
        if (!ok) { printf("    rtAtlasFixtures: cannot copy %s\n", files[i]); return NULL; }
    }
    for (int i = 0; i < (int)(sizeof(sheets)/sizeof(sheets[0])); i++)
    {
        unsigned int seed = 2166136261u;
        for (const char *c = sheets[i].name; *c; c++) seed = (seed ^ (unsigned char)*c)*16777619u;
        Image img = GenImageColor(sheets[i].w, sheets[i].h, BLANK);
        Color *px = (Color *)img.data;
        for (int k = 0; k < sheets[i].w*sheets[i].h; k++)
        {
            unsigned int r = rtRandom(&seed);
            px[k] = (Color){ (unsigned char)r, (unsigned char)(r >> 8), (unsigned char)(r >> 16), 255 };
        }
        snprintf(path, sizeof(path), "build/tests/atlas/%s", sheets[i].name);
        bool ok = ExportImage(img, path);
        UnloadImage(img);
        if (!ok) { printf("    rtAtlasFixtures: cannot write %s\n", path); return NULL; }
    }
    dir = "build/tests/atlas";
    return dir;
}

// ---- timing support -------------------------------------------------------------------------
#if !defined(__EMSCRIPTEN__)
// glFinish through the current context's loader (looked up again if the context changed)
void rtFinish(void)
{
    static RtGetProcFn loadedFrom = NULL;
    static RtFn finish = NULL;
    if (rtGetProc == NULL) return;
    if (loadedFrom != rtGetProc)
    {
        finish = rtGetProc("glFinish");
        loadedFrom = rtGetProc;
    }
    if (finish != NULL) finish();
}

void *rtGlProc(const char *name)
{
    return (rtGetProc != NULL)? rtFnToPtr(rtGetProc(name)) : NULL;
}
#endif  // !__EMSCRIPTEN__

bool rtContextIsEs(void)
{
    return (rlGetVersion() == RL_OPENGL_ES_20) || (rlGetVersion() == RL_OPENGL_ES_30);
}

// Half float (IEEE binary16) to float, exactly
static float rtHalfToFloat(unsigned short h)
{
    int e = (h >> 10) & 31, m = h & 1023;
    float v = (e == 0)? ldexpf((float)m, -24) : ((e == 31)? ((m == 0)? INFINITY : NAN) : ldexpf((float)(m | 1024), e - 25));
    return (h & 0x8000)? -v : v;
}

bool rtGlsl3(void)
{
    int v = rlGetVersion();
    return (v == RL_OPENGL_33) || (v == RL_OPENGL_43) || (v == RL_OPENGL_ES_30);
}

typedef void (*RtReadPixelsFn)(int, int, int, int, unsigned int, unsigned int, void *);

float *rtReadFloatPixels(unsigned int textureId, int width, int height)
{
    RtReadPixelsFn readPixels; void *p = rtGlProc("glReadPixels"); memcpy(&readPixels, &p, sizeof(p));
    float *out = (float *)malloc(sizeof(float)*4*(size_t)width*height);
    unsigned int fbo = rlLoadFramebuffer();
    if ((readPixels == NULL) || (out == NULL) || (fbo == 0)) { free(out); if (fbo != 0) rlUnloadFramebuffer(fbo); return NULL; }
    rlFramebufferAttach(fbo, textureId, RL_ATTACHMENT_COLOR_CHANNEL0, RL_ATTACHMENT_TEXTURE2D, 0);
    rlEnableFramebuffer(fbo);
    int readType = 0x1406 /* GL_FLOAT */;
    if (rlGetVersion() == RL_OPENGL_ES_20)
    {
        // ES 2 reads a half-float target only in the implementation's own format/type
        void (*getIntegerv)(unsigned int, int *); void *q = rtGlProc("glGetIntegerv"); memcpy(&getIntegerv, &q, sizeof(q));
        getIntegerv(0x8B9A /* GL_IMPLEMENTATION_COLOR_READ_TYPE */, &readType);
    }
    if ((readType == 0x8D61 /* GL_HALF_FLOAT_OES */) || (readType == 0x140B /* GL_HALF_FLOAT */))
    {
        unsigned short *half = (unsigned short *)malloc(sizeof(unsigned short)*4*(size_t)width*height);
        if (half != NULL)
        {
            readPixels(0, 0, width, height, 0x1908 /* GL_RGBA */, (unsigned int)readType, half);
            for (size_t i = 0; i < 4*(size_t)width*height; i++) out[i] = rtHalfToFloat(half[i]);
        }
        free(half);
    }
    else readPixels(0, 0, width, height, 0x1908 /* GL_RGBA */, 0x1406 /* GL_FLOAT */, out);
    rlDisableFramebuffer();
    // Detach before deleting: rlUnloadFramebuffer would delete the attached texture too
    rlFramebufferAttach(fbo, 0, RL_ATTACHMENT_COLOR_CHANNEL0, RL_ATTACHMENT_TEXTURE2D, 0);
    rlUnloadFramebuffer(fbo);
    return out;
}

bool rtReadDepth(unsigned int fbo, int width, int height, float *out)
{
#if defined(__EMSCRIPTEN__)
    // WebGL2 has no depth readback at all (readPixels takes no DEPTH_COMPONENT format)
    (void)fbo; (void)width; (void)height; (void)out;
    return false;
#endif
    RtReadPixelsFn readPixels; void *p = rtGlProc("glReadPixels"); memcpy(&readPixels, &p, sizeof(p));
    if (readPixels == NULL) return false;
    rlEnableFramebuffer(fbo);
    if (rtContextIsEs())
    {
        // A float depth buffer reads back only as floats (NV_read_depth); a fixed-point one as integers
        unsigned int (*getError)(void) = NULL; void *e = rtGlProc("glGetError"); memcpy(&getError, &e, sizeof(e));
        for (int k = 0; (k < 16) && (getError != NULL) && (getError() != 0); k++) { }     // earlier errors
        readPixels(0, 0, width, height, 0x1902 /* GL_DEPTH_COMPONENT */, 0x1406 /* GL_FLOAT */, out);
        if ((getError == NULL) || (getError() != 0))
        {
            unsigned int *raw = (unsigned int *)malloc(sizeof(unsigned int)*(size_t)width*height);
            if (raw == NULL) { rlDisableFramebuffer(); return false; }
            readPixels(0, 0, width, height, 0x1902 /* GL_DEPTH_COMPONENT */, 0x1405 /* GL_UNSIGNED_INT */, raw);
            for (size_t i = 0; i < (size_t)width*height; i++) out[i] = (float)(raw[i]/4294967295.0);
            free(raw);
        }
    }
    else readPixels(0, 0, width, height, 0x1902 /* GL_DEPTH_COMPONENT */, 0x1406 /* GL_FLOAT */, out);
    rlDisableFramebuffer();
    return true;
}
