// Test support: a tiny runner (checks, counts, one closing line), a headless GL 3.3 core context
// (EGL surfaceless, OSMesa fallback; RBL_TEST_CONTEXT=egl|osmesa forces one) and render/readback
// helpers that save the actual image under build/test-output/ when a check fails.
#ifndef RBL_TEST_HARNESS_H
#define RBL_TEST_HARNESS_H

#include "raylib.h"
#include <stdbool.h>

// ---- runner ---------------------------------------------------------------------------------
// A test is a void function; RBL_CHECK records a failure (with file:line and a message) and goes on.
typedef void (*RtTestFn)(void);
typedef struct { const char *name; RtTestFn fn; } RtTest;

void rtCheck(bool ok, const char *file, int line, const char *fmt, ...);
#define RT_CHECK(cond, ...) rtCheck((cond), __FILE__, __LINE__, __VA_ARGS__)
#define RT_TEST(fn) { #fn, fn }
// Runs the tests (a filter from argv[1] keeps names containing it), prints one line per test and
// "<suite>: N passed, N failed"; returns the process exit code.
int rtRun(const char *suite, const RtTest *tests, int count, int argc, char **argv);
const char *rtCurrentTest(void);
int rtFailuresInCurrentTest(void);

// ---- numeric helpers ------------------------------------------------------------------------
bool rtFinite(float x);
bool rtNear(double a, double b, double tol);
unsigned int rtRandom(unsigned int *state);           // xorshift32, fixed seeds in tests
float rtRandomRange(unsigned int *state, float lo, float hi);

// ---- headless GL ----------------------------------------------------------------------------
// Creates the context (EGL first unless forced), loads GL through rlLoadExtensions and calls
// rlglInit(width, height). Returns the backend name ("egl"/"osmesa") or NULL with a reason printed.
const char *rtInitContext(int width, int height);
void rtCloseContext(void);

// Render target of the given size; rtReadPixels() returns the image top row first (as on screen).
Image rtReadTarget(RenderTexture2D target);
Color rtPixel(Image image, int x, int y);
// Saves image to build/test-output/<current test>-<tag>.png (called on failure)
void rtSaveImage(Image image, const char *tag);

// ---- timing support -------------------------------------------------------------------------
// Blocks until the GL has executed every command issued so far (glFinish through the context's loader).
void rtFinish(void);

// GL entry point of the current context (for tests that need GL beyond rlgl, e.g. transform feedback)
void *rtGlProc(const char *name);

#endif
