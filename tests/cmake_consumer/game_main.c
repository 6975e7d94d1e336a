// The game of the README's CMake snippets (tests/run.sh copies it as game/main.c beside each
// snippet, as printed): the one file with the implementation. Checks the version macros (RBL_* and
// the RBILLBOARD_LIT_* aliases agree, RBL_VERSION spells MAJOR.MINOR.PATCH) and RblGetCameraFrame
// against raylib's GetCameraMatrix; no window or GL context needed.
#include "raylib.h"
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

int main(void)
{
    char spelled[32];
    snprintf(spelled, sizeof(spelled), "%d.%d.%d", RBL_VERSION_MAJOR, RBL_VERSION_MINOR, RBL_VERSION_PATCH);
    const bool versionOk = (strcmp(spelled, RBL_VERSION) == 0) && (strcmp(RBILLBOARD_LIT_VERSION, RBL_VERSION) == 0) &&
                           (RBILLBOARD_LIT_VERSION_MAJOR == RBL_VERSION_MAJOR) && (RBILLBOARD_LIT_VERSION_MINOR == RBL_VERSION_MINOR) &&
                           (RBILLBOARD_LIT_VERSION_PATCH == RBL_VERSION_PATCH);
    Camera3D camera = RBL_ZERO;
    camera.position = CLITERAL(Vector3){ -2.0f, 8.0f, 1.0f };
    camera.target = CLITERAL(Vector3){ 0.5f, 0.0f, -3.0f };
    camera.up = CLITERAL(Vector3){ 0.2f, 1.0f, 0.1f };
    camera.fovy = 45.0f;
    const RblCameraFrame f = RblGetCameraFrame(camera);
    const Matrix v = GetCameraMatrix(camera);
    const double d[9] = { f.right.x - v.m0, f.right.y - v.m4, f.right.z - v.m8, f.up.x - v.m1, f.up.y - v.m5, f.up.z - v.m9,
                          f.back.x - v.m2, f.back.y - v.m6, f.back.z - v.m10 };
    double e = 0.0;
    for (int i = 0; i < 9; i++) e = (fabs(d[i]) > e)? fabs(d[i]) : e;
    const bool ok = versionOk && (e < 1e-6);
    printf("cmake_consumer: README game, rbillboard_lit %s (%s), camera frame vs GetCameraMatrix max %.2g: %s\n",
           RBL_VERSION, versionOk? "version macros agree" : "VERSION MACROS DISAGREE", e, ok? "ok" : "FAIL");
    return ok? 0 : 1;
}
