// Compile check, built by tests/run.sh as C99 (gcc, clang) and C++ (g++, clang++) with
// -Wall -Wextra -pedantic -Werror: declarations only, and with -DCHECK_IMPLEMENTATION the
// implementation too (included after the declarations, as a user's one .c file would).
#include "rbillboard_lit.h"
#include "rbillboard_lit.h"        // the include guard holds
#if defined(CHECK_IMPLEMENTATION)
    #define RBILLBOARD_LIT_IMPLEMENTATION
    #include "rbillboard_lit.h"
#endif
#include <string.h>

int main(void)
{
    Camera3D camera;
    RblBillboard billboard;
    memset(&camera, 0, sizeof(camera));
    memset(&billboard, 0, sizeof(billboard));
#if defined(CHECK_IMPLEMENTATION)
    RblVertex quad[4];
    RblCameraFrame view = RblGetCameraFrame(camera);
    return RblBillboardVertices(&view, 1, 1, &billboard, quad)? 0 : 1;
#else
    return (int)sizeof(RblVertex) - 52;     // the layout the vertex attributes describe
#endif
}
