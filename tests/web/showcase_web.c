// The showcase as a web page: examples' showcase (RBL_WEB_SHOWCASE, without its main) drawn each
// animation frame into the page's #canvas. RBL_WEB_GL=2 is the WebGL2 build (raylib ES 3), 1 the
// WebGL1 fallback (raylib ES 2); tests/web/index.html picks one.
// The context is made here, not by InitWindow: raylib 6.0's RGFW web platform asks for WebGL1 whatever
// the GL version it was built for, and an ES 3 rlgl needs WebGL2. Like the headless showcase, a frame
// is rendered into a target (BeginMode3D reads the target's aspect) and then copied to the canvas.
#define RBL_SHOWCASE_NO_MAIN
#include RBL_WEB_SHOWCASE
#include "rlgl.h"
#include "raymath.h"

#include <emscripten/emscripten.h>
#include <emscripten/html5.h>
#include <stdio.h>
#include <string.h>

#define WEB_WIDTH   800
#define WEB_HEIGHT  450

static RenderTexture2D webTarget;
static Vector3 webEye;          // the showcase's camera position at t = 0, orbited about the target
static double webStart;

// ISO C has no cast between function pointers and void *: it travels through memcpy
typedef void *(*WebGetProc)(const char *);
static void *WebLoader(void) { WebGetProc f = emscripten_webgl_get_proc_address; void *p; memcpy(&p, &f, sizeof(p)); return p; }

static void WebFrame(void)
{
    float t = (float)((emscripten_get_now() - webStart)/1000.0);
    // A slow orbit (the desktop example's CAMERA_ORBITAL needs raylib's window clock)
    Vector3 offset = Vector3Subtract(webEye, showcaseCamera.target);
    showcaseCamera.position = Vector3Add(showcaseCamera.target, Vector3RotateByAxisAngle(offset, (Vector3){ 0.0f, 1.0f, 0.0f }, 0.25f*t));
    ShowcaseUpdate(t);
    ShowcaseDrawShadows();
    BeginTextureMode(webTarget);
        ClearBackground(showcaseBackground);
        BeginMode3D(showcaseCamera);
            ShowcaseDraw();
        EndMode3D();
    EndTextureMode();

    // Copy to the canvas (the default framebuffer), target rows flipped
    rlViewport(0, 0, WEB_WIDTH, WEB_HEIGHT);
    rlMatrixMode(RL_PROJECTION); rlLoadIdentity();
    rlOrtho(0, WEB_WIDTH, WEB_HEIGHT, 0, 0.0, 1.0);
    rlMatrixMode(RL_MODELVIEW); rlLoadIdentity();
    rlClearColor(0, 0, 0, 255);
    rlClearScreenBuffers();
    DrawTextureRec(webTarget.texture, (Rectangle){ 0, 0, (float)WEB_WIDTH, -(float)WEB_HEIGHT }, (Vector2){ 0, 0 }, WHITE);
    rlDrawRenderBatchActive();
}

// Leaving the page: free what the showcase made (the browser drops the context anyway)
static const char *WebUnload(int type, const void *event, void *user)
{
    (void)type; (void)event; (void)user;
    emscripten_cancel_main_loop();
    UnloadRenderTexture(webTarget);
    ShowcaseUnload();
    return NULL;
}

int main(void)
{
    EmscriptenWebGLContextAttributes attrs;
    emscripten_webgl_init_context_attributes(&attrs);
    attrs.majorVersion = RBL_WEB_GL;
    attrs.minorVersion = 0;
    attrs.preserveDrawingBuffer = EM_TRUE;      // a headless screenshot reads the canvas after the frame
    emscripten_set_canvas_element_size("#canvas", WEB_WIDTH, WEB_HEIGHT);
    EMSCRIPTEN_WEBGL_CONTEXT_HANDLE ctx = emscripten_webgl_create_context("#canvas", &attrs);
    if (ctx <= 0) { printf("showcase: WebGL%d context refused (%d)\n", RBL_WEB_GL, (int)ctx); return 1; }
    emscripten_webgl_make_context_current(ctx);
    emscripten_webgl_enable_extension(ctx, "EXT_color_buffer_float");
    emscripten_webgl_enable_extension(ctx, "OES_texture_float_linear");
    rlLoadExtensions(WebLoader());
    rlglInit(WEB_WIDTH, WEB_HEIGHT);
    // What InitWindow would do for the shapes functions: a white texel to draw them with
    SetShapesTexture((Texture2D){ rlGetTextureIdDefault(), 1, 1, 1, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8 }, (Rectangle){ 0, 0, 1, 1 });

    ShowcaseInit();
    webEye = showcaseCamera.position;
    webTarget = LoadRenderTexture(WEB_WIDTH, WEB_HEIGHT);
    webStart = emscripten_get_now();
    printf("showcase: WebGL%d (rlgl version %d)\n", RBL_WEB_GL, rlGetVersion());
    emscripten_set_beforeunload_callback(NULL, WebUnload);
    emscripten_set_main_loop(WebFrame, 0, 0);
    return 0;
}
