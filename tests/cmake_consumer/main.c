// CMake consumer: the one file with RBILLBOARD_LIT_IMPLEMENTATION. Checks RblGetCameraFrame, called
// from this C file and from the C++ one, against raylib's own view matrix (GetCameraMatrix: its rows
// are right, up and back) for a few cameras; no window or GL context needed.
#include "raylib.h"
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"

#include <math.h>
#include <stdio.h>

RblCameraFrame ConsumerFrameFromCpp(Camera3D camera);      // frame.cpp

static double FrameError(RblCameraFrame f, Matrix v)
{
    const double d[9] = { f.right.x - v.m0, f.right.y - v.m4, f.right.z - v.m8,
                          f.up.x - v.m1, f.up.y - v.m5, f.up.z - v.m9,
                          f.back.x - v.m2, f.back.y - v.m6, f.back.z - v.m10 };
    double e = 0.0;
    for (int i = 0; i < 9; i++) e = (fabs(d[i]) > e)? fabs(d[i]) : e;
    return e;
}

int main(void)
{
    const float cams[3][9] = { { 4, 3, 6, 0, 1, 0, 0, 1, 0 }, { -2, 8, 1, 0.5f, 0, -3, 0.2f, 1, 0.1f }, { 0, 0, 5, 0, 0, 0, 1, 0, 0 } };
    double errC = 0.0, errCpp = 0.0;
    for (int i = 0; i < 3; i++)
    {
        Camera3D camera = RBL_ZERO;
        camera.position = CLITERAL(Vector3){ cams[i][0], cams[i][1], cams[i][2] };
        camera.target = CLITERAL(Vector3){ cams[i][3], cams[i][4], cams[i][5] };
        camera.up = CLITERAL(Vector3){ cams[i][6], cams[i][7], cams[i][8] };
        camera.fovy = 45.0f;
        Matrix view = GetCameraMatrix(camera);
        double e = FrameError(RblGetCameraFrame(camera), view), ep = FrameError(ConsumerFrameFromCpp(camera), view);
        errC = (e > errC)? e : errC;
        errCpp = (ep > errCpp)? ep : errCpp;
    }
    const bool ok = (errC < 1e-6) && (errCpp < 1e-6);
    printf("cmake_consumer: rbillboard_lit %s, camera frame vs GetCameraMatrix: C max %.2g, C++ max %.2g: %s\n",
           RBL_VERSION, errC, errCpp, ok? "ok" : "FAIL");
    return ok? 0 : 1;
}
