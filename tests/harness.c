// Test support implementation; see harness.h.
#include "harness.h"
#include "rlgl.h"

#include <dlfcn.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/osmesa.h>

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
