// Runs the README's code as printed, headlessly (EGL surfaceless or OSMesa, tests/harness.h): the
// quick start (a whole program) and every how-to (the body of a main given a camera), extracted by
// tests/tools/readme_code.sh into build/tests/readme_code.inc. Window calls go to an offscreen
// target: InitWindow makes it, BeginDrawing/EndDrawing draw into it, WindowShouldClose ends the loop
// after RD_FRAMES frames of 1/60 s. Each program's last frame is checked:
//   - not empty: at least 3 % of its pixels differ from the most common colour (the background),
//     and it holds at least 16 distinct colours (lit, not flat);
//   - no "RBL:" warning logged while it ran (the README's code is used as the header means it);
//   - the header's state is gone after the program's own cleanup (RblClose), as the next one starts.
// Run from examples/ (the programs load resources/... as raylib's examples do).
//   usage: readme_run [picture folder]   (writes quickstart.png and howto_NAME.png there; default none)
#include "raylib.h"
#include "harness.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct { const char *name; void (*run)(Model model, Camera3D camera); } ReadmeProgram;

#define RD_FRAMES 30
#define RD_HOWTO_W 480
#define RD_HOWTO_H 270

static RenderTexture2D rdTarget;
static int rdFrames;
static Image rdShot;
static int rdWarnings;
static char rdFirstWarning[512];

static void rdLog(int level, const char *text, va_list args)
{
    char line[512];
    vsnprintf(line, sizeof(line), text, args);
    if ((level >= LOG_WARNING) && (strncmp(line, "RBL:", 4) == 0))
    {
        if (rdWarnings == 0) snprintf(rdFirstWarning, sizeof(rdFirstWarning), "%s", line);
        rdWarnings++;
    }
    if (level >= LOG_WARNING) fprintf(stderr, "    log: %s\n", line);
}

static void rdInitWindow(int width, int height, const char *title)
{
    (void)title;
    if (rdTarget.id != 0) UnloadRenderTexture(rdTarget);
    rdTarget = LoadRenderTexture(width, height);
}
static bool rdShouldClose(void) { return rdFrames >= RD_FRAMES; }
static void rdBeginDrawing(void) { BeginTextureMode(rdTarget); }
static void rdEndDrawing(void)
{
    EndTextureMode();
    rdFrames++;
    if (rdFrames == RD_FRAMES) { if (rdShot.data != NULL) UnloadImage(rdShot); rdShot = rtReadTarget(rdTarget); }
}
static void rdCloseWindow(void) { }
static float rdFrameTime(void) { return 1.0f/60.0f; }
static double rdTime(void) { return rdFrames/60.0; }

#define InitWindow rdInitWindow
#define WindowShouldClose rdShouldClose
#define BeginDrawing rdBeginDrawing
#define EndDrawing rdEndDrawing
#define CloseWindow rdCloseWindow
#define GetFrameTime rdFrameTime
#define GetTime rdTime
#include "readme_code.inc"
#undef InitWindow
#undef WindowShouldClose
#undef BeginDrawing
#undef EndDrawing
#undef CloseWindow
#undef GetFrameTime
#undef GetTime

// Pixels off the most common colour (by more than 8 summed over RGB), and distinct colours
static void rdMeasure(Image image, int *off, int *distinct)
{
    const int n = image.width*image.height;
    unsigned int *keys = (unsigned int *)malloc((size_t)n*sizeof(unsigned int));
    for (int i = 0; i < n; i++) { Color c = GetImageColor(image, i%image.width, i/image.width); keys[i] = ((unsigned int)c.r << 16) | ((unsigned int)c.g << 8) | c.b; }
    // counting sort by key would need 16M counters: sort instead
    for (int gap = n/2; gap > 0; gap /= 2)
        for (int i = gap; i < n; i++) { unsigned int v = keys[i]; int j = i; for (; (j >= gap) && (keys[j - gap] > v); j -= gap) keys[j] = keys[j - gap]; keys[j] = v; }
    unsigned int mode = keys[0]; int best = 0, run = 0;
    *distinct = 0;
    for (int i = 0; i < n; i++)
    {
        if ((i == 0) || (keys[i] != keys[i - 1])) { run = 0; (*distinct)++; }
        run++;
        if (run > best) { best = run; mode = keys[i]; }
    }
    *off = 0;
    const int mr = (int)(mode >> 16), mg = (int)((mode >> 8) & 255), mb = (int)(mode & 255);
    for (int i = 0; i < n; i++)
    {
        const int r = (int)(keys[i] >> 16), g = (int)((keys[i] >> 8) & 255), b = (int)(keys[i] & 255);
        if (abs(r - mr) + abs(g - mg) + abs(b - mb) > 8) (*off)++;
    }
    free(keys);
}

static bool rdCheck(const char *name, const char *folder)
{
    bool ok = (rdShot.data != NULL) && (rdFrames == RD_FRAMES);
    int off = 0, distinct = 0;
    if (rdShot.data != NULL) rdMeasure(rdShot, &off, &distinct);
    const double share = (rdShot.data != NULL)? (double)off/(rdShot.width*rdShot.height) : 0.0;
    ok = ok && (share >= 0.03) && (distinct >= 16) && (rdWarnings == 0);
    printf("  %s  README %s: %d frames, %.1f %% of pixels off the background, %d colours, %d RBL warnings%s%s\n",
        ok? "ok  " : "FAIL", name, rdFrames, 100.0*share, distinct, rdWarnings, (rdWarnings > 0)? ": " : "", (rdWarnings > 0)? rdFirstWarning : "");
    if (rdShot.data != NULL)
    {
        if (folder != NULL)
        {
            char path[1024];
            snprintf(path, sizeof(path), "%s/%s%s.png", folder, (strcmp(name, "quickstart") == 0)? "" : "howto_", name);
            if (ExportImage(rdShot, path)) printf("    wrote %s\n", path);
        }
        else if (!ok) rtSaveImage(rdShot, name);
        UnloadImage(rdShot);
        rdShot.data = NULL;
    }
    return ok;
}

int main(int argc, char **argv)
{
    const char *folder = (argc > 1)? argv[1] : NULL;
    SetTraceLogLevel(LOG_WARNING);
    SetTraceLogCallback(rdLog);
    if (rtInitContext(800, 450) == NULL) { printf("readme: 0 passed, 1 failed (no headless context)\n"); return 1; }
    int pass = 0, fail = 0;

    rdFrames = 0; rdWarnings = 0;
    readme_quickstart();
    if (rdCheck("quickstart", folder)) pass++; else fail++;

    const int count = (int)(sizeof(readmePrograms)/sizeof(readmePrograms[0]));
    for (int i = 0; i < count; i++)
    {
        Camera3D camera = { { 4.0f, 3.0f, 6.0f }, { 0.0f, 1.0f, 0.0f }, { 0.0f, 1.0f, 0.0f }, 45.0f, CAMERA_PERSPECTIVE };
        Model model = LoadModelFromMesh(GenMeshCube(1.0f, 1.0f, 1.0f));
        rdInitWindow(RD_HOWTO_W, RD_HOWTO_H, readmePrograms[i].name);
        rdFrames = 0; rdWarnings = 0;
        readmePrograms[i].run(model, camera);
        UnloadModel(model);
        if (rdCheck(readmePrograms[i].name, folder)) pass++; else fail++;
    }
    if (rdTarget.id != 0) UnloadRenderTexture(rdTarget);
    rtCloseContext();
    printf("readme: %d passed, %d failed\n", pass, fail);
    return (fail == 0)? 0 : 1;
}
