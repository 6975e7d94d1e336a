// Headless deferred example: renders examples/shaders_deferred_billboards.c offscreen and writes the lit
// frame and a strip of its debug views as PNGs (README pictures, `make pictures`).
//   usage: deferred_headless [lit.png] [views.png]
// Frames are rendered at t = frame/60 s (reproducible); the average frame time covers geometry pass,
// 401 lights (400 volumes + a full-screen moon) and resolve at 800x450 on this machine's GL.
#define RBL_DEFERRED_NO_MAIN
#include "../../examples/shaders_deferred_billboards.c"
#include "harness.h"

#include <stdio.h>
#include <time.h>

#define W 800
#define H 450
#define FRAMES 20

static double NowMs(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec*1000.0 + ts.tv_nsec/1.0e6;
}

static void Frame(RenderTexture2D target, float time)
{
    DeferredUpdate(time);
    DeferredPasses();                   // G-buffer and lights, off-screen
    BeginTextureMode(target);
        DeferredCompose();              // resolve + forward glows into the target
    EndTextureMode();
}

static Image RenderFrame(RenderTexture2D target, float time)
{
    Frame(target, time);
    return rtReadTarget(target);
}

int main(int argc, char **argv)
{
    const char *litPath = (argc > 1)? argv[1] : "build/deferred.png";
    const char *viewsPath = (argc > 2)? argv[2] : "build/deferred_views.png";
    const char *backend = rtInitContext(W, H);
    if (backend == NULL) { fprintf(stderr, "deferred: no headless GL context\n"); return 1; }
    DeferredInit(W, H);
    if (!deferredValid) fprintf(stderr, "deferred: G-buffer unavailable, the forward fallback renders\n");
    RenderTexture2D target = LoadRenderTexture(W, H);
    Image warm = RenderFrame(target, 0.0f);
    UnloadImage(warm);
    double start = NowMs();
    for (int f = 1; f < FRAMES; f++) Frame(target, f/60.0f);
    Image lit = RenderFrame(target, FRAMES/60.0f);
    double ms = (NowMs() - start)/FRAMES;
    int rc = ExportImage(lit, litPath)? 0 : 1;
    printf("deferred: wrote %s (%dx%d, %s), %.1f ms per frame over %d frames with %d lights (%d volumes, %d full screen)\n",
           litPath, W, H, backend, ms, FRAMES, DEFERRED_LIGHTS + 1, gbuffer.lightsInVolumes, gbuffer.lightsFullscreen);
    // Debug views, 4 x 2 tiles at half size
    Image strip = GenImageColor(W*2, H, BLACK);
    for (int v = 0; v < RBL_GBUFFER_OUTPUT_COUNT; v++)
    {
        RblSetGBufferOutput(&gbuffer, v, (v == RBL_GBUFFER_OUTPUT_LIGHT_COUNT)? 32.0f : 20.0f);
        Image img = RenderFrame(target, FRAMES/60.0f);
        ImageResize(&img, W/2, H/2);
        ImageDraw(&strip, img, (Rectangle){ 0, 0, W/2, H/2 }, (Rectangle){ (float)((v%4)*W/2), (float)((v/4)*H/2), W/2, H/2 }, WHITE);
        UnloadImage(img);
    }
    RblSetGBufferOutput(&gbuffer, RBL_GBUFFER_OUTPUT_LIT, 1.0f);
    if (!ExportImage(strip, viewsPath)) rc = 1;
    else printf("deferred: wrote %s (lit, albedo, normal, roughness / occlusion, depth, position, lights per pixel)\n", viewsPath);
    UnloadImage(strip);
    UnloadImage(lit);
    UnloadRenderTexture(target);
    DeferredUnload();
    rtCloseContext();
    return rc;
}
