// C++ translation unit: the header's declarations only (the implementation is main.c's)
#include "rbillboard_lit.h"

extern "C" RblCameraFrame ConsumerFrameFromCpp(Camera3D camera);

RblCameraFrame ConsumerFrameFromCpp(Camera3D camera)
{
    return RblGetCameraFrame(camera);
}
