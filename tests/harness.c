// Test support implementation; see harness.h.
#define RT_HARNESS_IMPLEMENTATION
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
#include <GLES3/gl3.h>
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
    int passed = 0, failed = 0;
    for (int i = 0; i < count; i++)
    {
        if ((filter != NULL) && (strstr(tests[i].name, filter) == NULL)) continue;
        rtTestName = tests[i].name;
        rtTestFailures = 0;
        tests[i].fn();
        if (rtTestFailures == 0) { passed++; printf("  ok    %s\n", tests[i].name); }
        else { failed++; printf("  FAIL  %s (%d failed checks)\n", tests[i].name, rtTestFailures); }
        fflush(stdout);
    }
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

void *rtGlProc(const char *name) { return emscripten_webgl_get_proc_address(name); }

// IEEE half from float, round to nearest even (values read from half targets convert exactly)
static unsigned short rtHalfFromFloat(float f)
{
    unsigned int x; memcpy(&x, &f, sizeof(x));
    unsigned int sign = (x >> 16) & 0x8000u, mant = x & 0x7FFFFFu;
    int e = (int)((x >> 23) & 0xFF);
    if (e == 0xFF) return (unsigned short)(sign | 0x7C00u | (mant? 0x200u : 0u));   // inf, NaN
    e = e - 127 + 15;
    if (e >= 0x1F) return (unsigned short)(sign | 0x7C00u);                          // overflow to inf
    if (e <= 0)
    {
        if (e < -10) return (unsigned short)sign;                                     // below half subnormals
        mant |= 0x800000u;
        int shift = 14 - e;
        unsigned int h = mant >> shift, rest = mant & ((1u << shift) - 1u), halfway = 1u << (shift - 1);
        if ((rest > halfway) || ((rest == halfway) && (h & 1u))) h++;
        return (unsigned short)(sign | h);
    }
    unsigned int h = ((unsigned int)e << 10) | (mant >> 13), rest = mant & 0x1FFFu;
    if ((rest > 0x1000u) || ((rest == 0x1000u) && (h & 1u))) h++;                    // may carry into the exponent: correct
    return (unsigned short)(sign | h);
}

void *rtWebReadTexturePixels(unsigned int id, int width, int height, int format)
{
    int channels = 0; bool half = false;
    switch (format)
    {
        case PIXELFORMAT_UNCOMPRESSED_R32: channels = 1; break;
        case PIXELFORMAT_UNCOMPRESSED_R32G32B32: channels = 3; break;
        case PIXELFORMAT_UNCOMPRESSED_R32G32B32A32: channels = 4; break;
        case PIXELFORMAT_UNCOMPRESSED_R16: channels = 1; half = true; break;
        case PIXELFORMAT_UNCOMPRESSED_R16G16B16: channels = 3; half = true; break;
        case PIXELFORMAT_UNCOMPRESSED_R16G16B16A16: channels = 4; half = true; break;
        default: break;
    }
    size_t count = (size_t)width*height;
    if (channels == 0)
    {
        // 8-bit formats: raylib's FBO readback gives RGBA8; keep the channels the format names
        unsigned char *rgba = (unsigned char *)rlReadTexturePixels(id, width, height, format);
        if ((rgba == NULL) || (format == PIXELFORMAT_UNCOMPRESSED_R8G8B8A8)) return rgba;
        int keep = (format == PIXELFORMAT_UNCOMPRESSED_GRAYSCALE)? 1 : (format == PIXELFORMAT_UNCOMPRESSED_GRAY_ALPHA)? 2 :
                   (format == PIXELFORMAT_UNCOMPRESSED_R8G8B8)? 3 : 4;
        for (size_t i = 0; i < count; i++)
            for (int c = 0; c < keep; c++) rgba[i*keep + c] = rgba[i*4 + ((keep == 2) && (c == 1)? 3 : c)];
        return rgba;
    }
    float *rgba = (float *)malloc(count*4*sizeof(float));
    if (rgba == NULL) return NULL;
    GLint previous = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);
    GLuint fbo = 0;
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, id, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, rgba);    // the one float readback WebGL2 guarantees
    glBindFramebuffer(GL_FRAMEBUFFER, (GLuint)previous);
    glDeleteFramebuffers(1, &fbo);
    if (!half)
    {
        for (size_t i = 0; i < count; i++) for (int c = 0; c < channels; c++) rgba[i*channels + c] = rgba[i*4 + c];
        return rgba;
    }
    unsigned short *out = (unsigned short *)malloc(count*channels*sizeof(unsigned short));
    if (out != NULL) for (size_t i = 0; i < count; i++) for (int c = 0; c < channels; c++) out[i*channels + c] = rtHalfFromFloat(rgba[i*4 + c]);
    free(rgba);
    return out;
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

static bool rtInitEgl(void)
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
    if ((rtEglDisplay == EGL_NO_DISPLAY) || !initialize(rtEglDisplay, &major, &minor)) { printf("    context: egl: surfaceless display unavailable\n"); return false; }
    if (!bindApi(EGL_OPENGL_API)) { printf("    context: egl: no desktop GL API\n"); return false; }
    const EGLint attribs[] = { EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE };
    rtEglContext = createContext(rtEglDisplay, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
    if (rtEglContext == EGL_NO_CONTEXT) { printf("    context: egl: 3.3 core context refused\n"); return false; }
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
    if ((force == NULL) || (strcmp(force, "egl") == 0)) { if (rtInitEgl()) name = "egl"; }
    if ((name == NULL) && ((force == NULL) || (strcmp(force, "osmesa") == 0))) { if (rtInitOsmesa(width, height)) name = "osmesa"; }
    if (name == NULL) { printf("    context: no headless GL 3.3 core context (RBL_TEST_CONTEXT=%s)\n", force? force : "any"); return NULL; }
    SetTraceLogLevel(LOG_WARNING);     // raylib's INFO lines would bury the test output
    rlLoadExtensions(rtFnToPtr((RtFn)rtLoader));
    rlglInit(width, height);
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
#endif
