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

#include "gpu_common.h"
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
