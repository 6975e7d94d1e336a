// The showcase as a web page: examples' showcase (RBL_WEB_SHOWCASE, without its main) drawn each
// animation frame into the page's #canvas. RBL_WEB_GL=2 is the WebGL2 build (raylib ES 3), 1 the
// WebGL1 fallback (raylib ES 2); tests/web/index.html picks one.
// The context is made here, not by InitWindow: raylib 6.0's RGFW web platform asks for WebGL1 whatever
// the GL version it was built for, and an ES 3 rlgl needs WebGL2. Like the headless showcase, a frame
// is rendered into a target (BeginMode3D reads the target's aspect) and then copied to the canvas.
// What a page needs beyond that, done here:
//   size      the canvas's backing store follows its CSS box times devicePixelRatio (checked every
//             frame: window resizes, container changes, zoom and fullscreen alike), capped at
//             WEB_MAX_PIXELS; the target is reloaded at the new size, so the camera's aspect follows
//   opaque    the context has no alpha channel: the page behind can never show through
//   input     drag (mouse, one finger) orbits, wheel and pinch zoom, arrows/WASD orbit, +/- (Q/E) zoom,
//             Space toggles the slow automatic orbit (any other input stops it); keys only while the
//             canvas has focus, so the page around keeps its keyboard
//   loss      on webglcontextlost the frames stop and the loss is accepted for restoring; on
//             webglcontextrestored every GL object is gone: the CPU-side records are dropped (deleting
//             a dead name does nothing), rlgl and the showcase are loaded again, and the page reloads
//             itself only if that fails
// The page reads WebFrames/WebRestores/WebCamera* (exported) for its status line and its tests.
#define RBL_SHOWCASE_NO_MAIN
#include RBL_WEB_SHOWCASE
#include "rlgl.h"
#include "raymath.h"

#include <emscripten/emscripten.h>
#include <emscripten/html5.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define WEB_MAX_PIXELS  (2560*1600)     // Backing-store cap: a 4K screen at devicePixelRatio 2 draws at most this
#define WEB_CANVAS      "#canvas"

static EMSCRIPTEN_WEBGL_CONTEXT_HANDLE webContext;
static RenderTexture2D webTarget;
static int webWidth, webHeight;         // Backing-store size in device pixels (the target's size)
static bool webLost;                    // Between webglcontextlost and a successful restore: no drawing
static int webFrames, webRestores;
static double webStart, webLastTime;

// Orbit about the showcase's target: yaw about +Y from +Z, pitch above the floor, distance
static struct { float yaw, pitch, distance; bool automatic; } orbit;
static struct { bool dragging; float lastX, lastY; int touches; float pinch; } pointer;
static bool keyHeld[6];                 // left, right, up, down, zoom in, zoom out

// ISO C has no cast between function pointers and void *: it travels through memcpy
typedef void *(*WebGetProc)(const char *);
static void *WebLoader(void) { WebGetProc f = emscripten_webgl_get_proc_address; void *p; memcpy(&p, &f, sizeof(p)); return p; }

EMSCRIPTEN_KEEPALIVE int WebFrames(void) { return webFrames; }
EMSCRIPTEN_KEEPALIVE int WebRestores(void) { return webRestores; }
EMSCRIPTEN_KEEPALIVE float WebCameraYaw(void) { return orbit.yaw; }
EMSCRIPTEN_KEEPALIVE float WebCameraDistance(void) { return orbit.distance; }
EMSCRIPTEN_KEEPALIVE int WebCameraAutomatic(void) { return orbit.automatic; }

static void WebTellPage(const char *what)
{
    char js[160];
    snprintf(js, sizeof(js), "if (Module.onShowcase) Module.onShowcase('%s', %d, %d);", what, webWidth, webHeight);
    emscripten_run_script(js);
}

static void WebStopAutomatic(void) { orbit.automatic = false; }

static void WebOrbitBy(float dyaw, float dpitch, float zoom)
{
    orbit.yaw += dyaw;
    orbit.pitch = Clamp(orbit.pitch + dpitch, 0.08f, 1.40f);
    orbit.distance = Clamp(orbit.distance*zoom, 2.2f, 14.0f);
}

// ---- input (html5 callbacks on the canvas; returning true keeps the browser's default away) ----
static EM_BOOL WebMouse(int type, const EmscriptenMouseEvent *e, void *user)
{
    (void)user;
    if ((type == EMSCRIPTEN_EVENT_MOUSEDOWN) && (e->button == 0)) { pointer.dragging = true; WebStopAutomatic(); }
    else if (type == EMSCRIPTEN_EVENT_MOUSEUP) pointer.dragging = false;
    else if ((type == EMSCRIPTEN_EVENT_MOUSEMOVE) && pointer.dragging && (e->buttons & 1))
        WebOrbitBy(-0.008f*(float)e->movementX, 0.006f*(float)e->movementY, 1.0f);
    return EM_FALSE;       // The defaults stay: a press focuses the canvas (its keys), the page keeps its clicks
}

static EM_BOOL WebWheel(int type, const EmscriptenWheelEvent *e, void *user)
{
    (void)type; (void)user;
    const double lines = (e->deltaMode == DOM_DELTA_PIXEL)? e->deltaY/40.0 : (e->deltaMode == DOM_DELTA_LINE)? e->deltaY : 10.0*e->deltaY;
    WebStopAutomatic();
    WebOrbitBy(0.0f, 0.0f, powf(1.1f, (float)Clamp((float)lines, -10.0f, 10.0f)));
    return EM_TRUE;
}

static EM_BOOL WebTouch(int type, const EmscriptenTouchEvent *e, void *user)
{
    (void)user;
    // The fingers still down: on touchend/cancel the changed ones have just lifted
    const bool lifting = (type == EMSCRIPTEN_EVENT_TOUCHEND) || (type == EMSCRIPTEN_EVENT_TOUCHCANCEL);
    int n = 0; float x[2] = { 0 }, y[2] = { 0 };
    for (int i = 0; (i < e->numTouches) && (n < 2); i++)
    {
        if (lifting && e->touches[i].isChanged) continue;
        x[n] = (float)e->touches[i].targetX; y[n] = (float)e->touches[i].targetY; n++;
    }
    const float cx = (n == 2)? 0.5f*(x[0] + x[1]) : x[0], cy = (n == 2)? 0.5f*(y[0] + y[1]) : y[0];
    const float spread = (n == 2)? sqrtf((x[1] - x[0])*(x[1] - x[0]) + (y[1] - y[0])*(y[1] - y[0])) : 0.0f;
    if ((type == EMSCRIPTEN_EVENT_TOUCHMOVE) && (n == pointer.touches) && (n > 0))
    {
        WebOrbitBy(-0.008f*(cx - pointer.lastX), 0.006f*(cy - pointer.lastY), ((n == 2) && (spread > 1.0f) && (pointer.pinch > 1.0f))? pointer.pinch/spread : 1.0f);
    }
    if (type == EMSCRIPTEN_EVENT_TOUCHSTART) WebStopAutomatic();
    pointer.touches = n; pointer.lastX = cx; pointer.lastY = cy; pointer.pinch = spread;
    return EM_TRUE;        // No scrolling or page zoom while the fingers are on the scene
}

static int WebKeyIndex(const char *code)
{
    static const char *const names[6][2] = { { "ArrowLeft", "KeyA" }, { "ArrowRight", "KeyD" }, { "ArrowUp", "KeyW" },
                                             { "ArrowDown", "KeyS" }, { "Equal", "KeyE" }, { "Minus", "KeyQ" } };
    for (int i = 0; i < 6; i++) if ((strcmp(code, names[i][0]) == 0) || (strcmp(code, names[i][1]) == 0)) return i;
    if ((strcmp(code, "NumpadAdd") == 0)) return 4;
    if ((strcmp(code, "NumpadSubtract") == 0)) return 5;
    return -1;
}

static EM_BOOL WebKey(int type, const EmscriptenKeyboardEvent *e, void *user)
{
    (void)user;
    if (e->ctrlKey || e->altKey || e->metaKey) return EM_FALSE;       // The browser's shortcuts stay
    const int k = WebKeyIndex(e->code);
    if (k >= 0) { keyHeld[k] = (type == EMSCRIPTEN_EVENT_KEYDOWN); if (keyHeld[k]) WebStopAutomatic(); return EM_TRUE; }
    if ((strcmp(e->code, "Space") == 0) && (type == EMSCRIPTEN_EVENT_KEYDOWN) && !e->repeat) { orbit.automatic = !orbit.automatic; return EM_TRUE; }
    return EM_FALSE;
}

static EM_BOOL WebBlur(int type, const EmscriptenFocusEvent *e, void *user)
{
    (void)type; (void)e; (void)user;
    memset(keyHeld, 0, sizeof(keyHeld));      // A key released elsewhere must not keep turning the camera
    pointer.dragging = false;
    return EM_FALSE;
}

// ---- size: backing store = CSS box x devicePixelRatio, capped; the target follows ----
static void WebFollowSize(void)
{
    double cssW = 0.0, cssH = 0.0;
    emscripten_get_element_css_size(WEB_CANVAS, &cssW, &cssH);
    double scale = emscripten_get_device_pixel_ratio();
    if (cssW*cssH*scale*scale > WEB_MAX_PIXELS) scale = sqrt(WEB_MAX_PIXELS/(cssW*cssH));
    int w = (int)floor(cssW*scale + 0.5), h = (int)floor(cssH*scale + 0.5);
    w = (w < 1)? 1 : w; h = (h < 1)? 1 : h;
    if ((w == webWidth) && (h == webHeight) && (webTarget.id != 0)) return;
    emscripten_set_canvas_element_size(WEB_CANVAS, w, h);
    if (webTarget.id != 0) UnloadRenderTexture(webTarget);
    webTarget = LoadRenderTexture(w, h);
    webWidth = w; webHeight = h;
    rlSetFramebufferWidth(w);
    rlSetFramebufferHeight(h);
    WebTellPage("size");
}

static void WebFrame(void)
{
    if (webLost || emscripten_is_webgl_context_lost(webContext)) return;
    const double now = emscripten_get_now();
    const float t = (float)((now - webStart)/1000.0), dt = Clamp((float)((now - webLastTime)/1000.0), 0.0f, 0.1f);
    webLastTime = now;
    WebFollowSize();

    const float turn = 1.6f*dt;
    WebOrbitBy(turn*((keyHeld[1]? 1.0f : 0.0f) - (keyHeld[0]? 1.0f : 0.0f)) + (orbit.automatic? 0.25f*dt : 0.0f),
               turn*((keyHeld[2]? 1.0f : 0.0f) - (keyHeld[3]? 1.0f : 0.0f)),
               powf(1.8f, dt*((keyHeld[5]? 1.0f : 0.0f) - (keyHeld[4]? 1.0f : 0.0f))));
    const float c = cosf(orbit.pitch);
    showcaseCamera.position = Vector3Add(showcaseCamera.target,
        CLITERAL(Vector3){ orbit.distance*c*sinf(orbit.yaw), orbit.distance*sinf(orbit.pitch), orbit.distance*c*cosf(orbit.yaw) });

    ShowcaseUpdate(t);
    ShowcaseDrawShadows();
    BeginTextureMode(webTarget);
        ClearBackground(showcaseBackground);
        BeginMode3D(showcaseCamera);
            ShowcaseDraw();
        EndMode3D();
    EndTextureMode();

    // Copy to the canvas (the default framebuffer), target rows flipped
    rlViewport(0, 0, webWidth, webHeight);
    rlMatrixMode(RL_PROJECTION); rlLoadIdentity();
    rlOrtho(0, webWidth, webHeight, 0, 0.0, 1.0);
    rlMatrixMode(RL_MODELVIEW); rlLoadIdentity();
    rlClearColor(0, 0, 0, 255);
    rlClearScreenBuffers();
    DrawTextureRec(webTarget.texture, CLITERAL(Rectangle){ 0, 0, (float)webWidth, -(float)webHeight }, CLITERAL(Vector2){ 0, 0 }, WHITE);
    rlDrawRenderBatchActive();
    if (++webFrames == 1) WebTellPage("first-frame");
}

// ---- GL: everything that lives in the context, loaded at start and again after a restore ----
static bool WebLoadGL(void)
{
    emscripten_webgl_make_context_current(webContext);
    emscripten_webgl_enable_extension(webContext, "EXT_color_buffer_float");
    emscripten_webgl_enable_extension(webContext, "OES_texture_float_linear");
    rlLoadExtensions(WebLoader());
    rlglInit(1, 1);
    // What InitWindow would do for the shapes functions: a white texel to draw them with
    SetShapesTexture(CLITERAL(Texture2D){ rlGetTextureIdDefault(), 1, 1, 1, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8 }, CLITERAL(Rectangle){ 0, 0, 1, 1 });
    ShowcaseInit();
    webWidth = webHeight = 0;
    webTarget.id = 0;
    WebFollowSize();
    return RblIsLitShaderValid(cardMaterial.shader) && RblIsLitShaderValid(floorLit) && (webTarget.id != 0) && !emscripten_is_webgl_context_lost(webContext);
}

static EM_BOOL WebContextLost(int type, const void *reserved, void *user)
{
    (void)type; (void)reserved; (void)user;
    webLost = true;
    WebTellPage("lost");
    return EM_TRUE;        // preventDefault: asks the browser to restore the context
}

static EM_BOOL WebContextRestored(int type, const void *reserved, void *user)
{
    (void)type; (void)reserved; (void)user;
    // The restored context holds no objects. Drop the records of the dead ones (their deletes do
    // nothing), let emscripten enable its extensions on the new context, then load everything again
    ShowcaseUnload();
    UnloadRenderTexture(webTarget);
    webTarget.id = 0;
    rlglClose();
    emscripten_run_script("if (typeof GL !== 'undefined' && GL.currentContext) { GL.currentContext.initExtensionsDone = false; GL.initExtensions(GL.currentContext); }");
    if (!WebLoadGL()) { WebTellPage("restore-failed"); emscripten_run_script("location.reload();"); return EM_TRUE; }
    webLost = false;
    webRestores++;
    webFrames = 0;         // The page waits for the first frame again
    WebTellPage("restored");
    return EM_TRUE;
}

// Leaving the page: free what the showcase made (the browser drops the context anyway)
static const char *WebUnload(int type, const void *event, void *user)
{
    (void)type; (void)event; (void)user;
    emscripten_cancel_main_loop();
    if (!webLost) { UnloadRenderTexture(webTarget); ShowcaseUnload(); }
    return NULL;
}

int main(void)
{
    EmscriptenWebGLContextAttributes attrs;
    emscripten_webgl_init_context_attributes(&attrs);
    attrs.majorVersion = RBL_WEB_GL;
    attrs.minorVersion = 0;
    attrs.alpha = EM_FALSE;                     // Opaque canvas: nothing of the page shows through
    attrs.preserveDrawingBuffer = EM_TRUE;      // Screenshots and the page's tests read the canvas after the frame
    webContext = emscripten_webgl_create_context(WEB_CANVAS, &attrs);
    if (webContext <= 0) { printf("showcase: WebGL%d context refused (%d)\n", RBL_WEB_GL, (int)webContext); WebTellPage("no-context"); return 1; }
    emscripten_set_webglcontextlost_callback(WEB_CANVAS, NULL, EM_FALSE, WebContextLost);
    emscripten_set_webglcontextrestored_callback(WEB_CANVAS, NULL, EM_FALSE, WebContextRestored);

    if (!WebLoadGL()) printf("showcase: the lit programs or the target failed to load\n");
    const Vector3 offset = Vector3Subtract(showcaseCamera.position, showcaseCamera.target);
    orbit.distance = Vector3Length(offset);
    orbit.yaw = atan2f(offset.x, offset.z);
    orbit.pitch = asinf(offset.y/orbit.distance);
    orbit.automatic = true;

    emscripten_set_mousedown_callback(WEB_CANVAS, NULL, EM_FALSE, WebMouse);
    emscripten_set_mouseup_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, NULL, EM_FALSE, WebMouse);      // Released outside the canvas too
    emscripten_set_mousemove_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, NULL, EM_FALSE, WebMouse);
    emscripten_set_wheel_callback(WEB_CANVAS, NULL, EM_FALSE, WebWheel);
    emscripten_set_touchstart_callback(WEB_CANVAS, NULL, EM_FALSE, WebTouch);
    emscripten_set_touchmove_callback(WEB_CANVAS, NULL, EM_FALSE, WebTouch);
    emscripten_set_touchend_callback(WEB_CANVAS, NULL, EM_FALSE, WebTouch);
    emscripten_set_touchcancel_callback(WEB_CANVAS, NULL, EM_FALSE, WebTouch);
    emscripten_set_keydown_callback(WEB_CANVAS, NULL, EM_FALSE, WebKey);
    emscripten_set_keyup_callback(WEB_CANVAS, NULL, EM_FALSE, WebKey);
    emscripten_set_blur_callback(WEB_CANVAS, NULL, EM_FALSE, WebBlur);

    webStart = webLastTime = emscripten_get_now();
    printf("showcase: WebGL%d (rlgl version %d), %dx%d\n", RBL_WEB_GL, rlGetVersion(), webWidth, webHeight);
    emscripten_set_beforeunload_callback(NULL, WebUnload);
    emscripten_set_main_loop(WebFrame, 0, 0);
    return 0;
}
