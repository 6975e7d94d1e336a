// API suite under ASan+UBSan+LSan (the raylib-habitual unload sequence must draw and exit clean).
// The same tests also run in test_gpu under both contexts. The context is left open at exit: Mesa's
// EGL teardown leaks 240 bytes inside a driver module it has already unloaded, which LeakSanitizer
// cannot attribute or suppress; with the context alive it reports no leak at all.
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "rlgl.h"
#include "harness.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TARGET 64

static int warnings = 0;
static char lastWarning[512];
static void countingLog(int level, const char *text, va_list args)
{
    (void)level;
    char line[512];
    vsnprintf(line, sizeof(line), text, args);
    if (strncmp(line, "RBL:", 4) == 0) { warnings++; memcpy(lastWarning, line, sizeof(line)); }
}

static Camera3D frontCamera(void)
{
    Camera3D c;
    memset(&c, 0, sizeof(c));
    c.position = (Vector3){ 0.0f, 0.0f, 5.0f };
    c.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    c.fovy = 45.0f;
    c.projection = CAMERA_PERSPECTIVE;
    return c;
}

static Texture2D solidTexture(Color c)
{
    Image img = GenImageColor(4, 4, c);
    Texture2D t = LoadTextureFromImage(img);
    UnloadImage(img);
    return t;
}

#include "test_api.c"

int main(int argc, char **argv)
{
    static const RtTest tests[] = { RBL_API_TESTS };
    const char *backend = rtInitContext(256, 256);
    if (backend == NULL) { printf("api_san: 0 passed, 1 failed\n"); return 1; }
    printf("  context: %s\n", backend);
    SetTraceLogCallback(countingLog);
    int rc = rtRun("api_san", tests, (int)(sizeof(tests)/sizeof(tests[0])), argc, argv);
    RblClose();
    return rc;
}
