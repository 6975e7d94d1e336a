// GPU test suite: runs headless under the context named by RBL_TEST_CONTEXT (egl or osmesa).
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "rlgl.h"
#include "raymath.h"
#include "harness.h"

#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gpu_tests.h"

int main(int argc, char **argv)
{
    const char *backend = rtInitContext(256, 256);
    if (backend == NULL) { printf("gpu: 0 passed, 1 failed\n"); return 1; }
    printf("  context: %s\n", backend);
    SetTraceLogCallback(countingLog);
    int rc = rtRun("gpu", rblGpuTests, RBL_GPU_TEST_COUNT, argc, argv);
    RblClose();
    rtCloseContext();
    return rc;
}
