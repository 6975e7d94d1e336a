// Test support: a tiny runner (checks, counts, one closing line), a headless context (GL 3.3 core by
// EGL surfaceless, OSMesa fallback; RBL_TEST_CONTEXT=egl|osmesa|gles3|gles2|gl21 forces one) and render/readback
// helpers that save the actual image under build/test-output/ when a check fails.
#ifndef RBL_TEST_HARNESS_H
#define RBL_TEST_HARNESS_H

#include "raylib.h"
#include <stdbool.h>

// ---- runner ---------------------------------------------------------------------------------
// A test is a void function; RBL_CHECK records a failure (with file:line and a message) and goes on.
typedef void (*RtTestFn)(void);
typedef struct { const char *name; RtTestFn fn; bool glsl3; } RtTest;

void rtCheck(bool ok, const char *file, int line, const char *fmt, ...);
#define RT_CHECK(cond, ...) rtCheck((cond), __FILE__, __LINE__, __VA_ARGS__)
#define RT_TEST(fn) { #fn, fn, false }
// A test of what needs GLSL 3 (instanced draws, the G-buffer, transform feedback): run on GL 3.3 and
// ES 3 contexts; on ES 2 / GL 2.1 the runner lists it as not applicable (the suite tests the refusal)
#define RT_TEST_GLSL3(fn) { #fn, fn, true }
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

// ---- atlas fixtures -----------------------------------------------------------------------------
// The hand-written atlas fixtures of tests/fuzz/corpus/ (also the fuzz seeds) copied under
// build/tests/atlas/<format>/ beside the sheets they name (deterministic noise PNGs, written here:
// RblLoadAtlas refuses a sheet it cannot find). Returns "build/tests/atlas" (NULL on failure).
const char *rtAtlasFixtures(void);

// ---- headless GL ----------------------------------------------------------------------------
// Creates the context (EGL first unless forced), loads GL through rlLoadExtensions and calls
// rlglInit(width, height). Returns the backend name ("egl"/"osmesa"; "webgl2" in the browser build,
// tests/web/) or NULL with a reason printed.
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
// The context is OpenGL ES (gles3 / gles2): float and depth readback differ there
bool rtContextIsEs(void);
// The context runs GLSL 3 (GL 3.3 or ES 3): instanced draws and the G-buffer exist
bool rtGlsl3(void);
// RGBA float texels of a colour texture (any float or 8-bit format), GL row order (bottom row first),
// through a framebuffer and glReadPixels(GL_RGBA, GL_FLOAT): rlReadTexturePixels reads RGBA8 only on ES.
// malloc'ed; NULL on failure
float *rtReadFloatPixels(unsigned int textureId, int width, int height);
// Window depths 0..1 of framebuffer fbo, GL row order: GL_FLOAT on desktop; on ES GL_FLOAT where the
// depth buffer is float, else GL_UNSIGNED_INT (a 24-bit depth comes back scaled to 32 bits). false on failure
bool rtReadDepth(unsigned int fbo, int width, int height, float *out);

// ---- lit material values ----------------------------------------------------------------------
// The values 0.3's RblLitShaderDesc held, written where 1.0 reads them: raylib's Material fields
// (see RblMaterialParam in the header). Zero fields keep the header's defaults.
typedef struct RtMaterialValues {
    float specular;          // params[1] (RBL_PARAM_SPECULAR; raylib's SPECULAR map is the METALNESS map)
    float shininess;         // MATERIAL_MAP_NORMAL.value
    Color specularColor;     // MATERIAL_MAP_SPECULAR.color
    float roughness;         // MATERIAL_MAP_ROUGHNESS.value
    float metalness;         // MATERIAL_MAP_METALNESS.value
    Color emissiveColor;     // MATERIAL_MAP_EMISSION.color
    float emissiveIntensity; // MATERIAL_MAP_EMISSION.value
    float alphaCutoff;       // params[0]
    float transmission;      // params[3] (RBL_PARAM_TRANSMISSION)
} RtMaterialValues;
static inline void rtSetMaterialValues(Material *m, RtMaterialValues v)
{
    m->maps[MATERIAL_MAP_NORMAL].value = v.shininess;
    m->maps[MATERIAL_MAP_SPECULAR].color = v.specularColor;
    m->maps[MATERIAL_MAP_ROUGHNESS].value = v.roughness;
    m->maps[MATERIAL_MAP_METALNESS].value = v.metalness;
    m->maps[MATERIAL_MAP_EMISSION].color = v.emissiveColor;
    m->maps[MATERIAL_MAP_EMISSION].value = v.emissiveIntensity;
    m->params[0] = v.alphaCutoff;
    m->params[1] = v.specular;
    m->params[3] = v.transmission;
}

#endif
