// Headless showcase: renders examples/shaders_lit_billboards.c offscreen (EGL surfaceless or
// OSMesa, see tests/harness.h) and writes the last frame as a PNG.
//   usage: showcase_headless [out.png]      (default build/showcase.png)
// Frames are rendered at t = frame/60 s, so the picture is reproducible. The first frame is a
// warm-up (shader compilation happens at first use) and is not timed; the timed frames end with
// one readback of the target, which waits for the GPU, so the average covers all their work.
#define RBL_SHOWCASE_NO_MAIN
#include "../../examples/shaders_lit_billboards.c"
#include "harness.h"

#include <stdio.h>
#include <time.h>

#define SHOWCASE_WIDTH   800
#define SHOWCASE_HEIGHT  450
#define SHOWCASE_FRAMES  60

static double NowMs(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec*1000.0 + ts.tv_nsec/1.0e6;
}

static void RenderFrame(RenderTexture2D target, int frame)
{
    ShowcaseUpdate((float)frame/60.0f);
    ShowcaseDrawShadows();                      // Shadow pass (binds its own framebuffer: outside BeginTextureMode), then RblSetScene
    BeginTextureMode(target);
        ClearBackground(showcaseBackground);
        BeginMode3D(showcaseCamera);
            ShowcaseDraw();
        EndMode3D();
    EndTextureMode();
}

int main(int argc, char **argv)
{
    const char *outPath = (argc > 1)? argv[1] : "build/showcase.png";

    const char *backend = rtInitContext(SHOWCASE_WIDTH, SHOWCASE_HEIGHT);
    if (backend == NULL)
    {
        fprintf(stderr, "showcase: no headless GL 3.3 core context (EGL or OSMesa); nothing rendered\n");
        return 1;
    }

    ShowcaseInit();
    RenderTexture2D target = LoadRenderTexture(SHOWCASE_WIDTH, SHOWCASE_HEIGHT);

    // Warm-up frame (not timed), finished by a readback
    RenderFrame(target, 0);
    Image warm = rtReadTarget(target);
    UnloadImage(warm);

    double start = NowMs();
    for (int frame = 1; frame <= SHOWCASE_FRAMES; frame++) RenderFrame(target, frame);
    Image image = rtReadTarget(target);        // Waits for every frame above to finish
    double elapsed = NowMs() - start;

    int rc = 0;
    ImageFormat(&image, PIXELFORMAT_UNCOMPRESSED_R8G8B8);     // As a window shows it: blending leaves the target's alpha below 255
    if (ExportImage(image, outPath))
    {
        printf("showcase: wrote %s (%dx%d), average frame %.2f ms over %d frames (%s)\n",
               outPath, SHOWCASE_WIDTH, SHOWCASE_HEIGHT, elapsed/SHOWCASE_FRAMES, SHOWCASE_FRAMES, backend);
    }
    else
    {
        fprintf(stderr, "showcase: could not write %s\n", outPath);
        rc = 1;
    }

    UnloadImage(image);
    UnloadRenderTexture(target);
    ShowcaseUnload();
    rtCloseContext();
    return rc;
}
