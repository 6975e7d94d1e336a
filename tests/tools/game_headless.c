// Headless lit sprite game: renders examples/shaders_lit_sprite_game.c offscreen (EGL surfaceless or
// OSMesa, see tests/harness.h) after 150 frames at 60 fps, from the example's folder (it loads
// resources/kenney_*), and writes the picture.
//   usage: game_headless [out.png] [examples folder]     (defaults build/game.png, examples)
// Checks what the example promises, on its own rendered frames (the exit code says): both atlases
// read as exported (frames, tags, the robot's pivot slice), the walk cycle advances, and each part
// shows in the picture: the robot (the frame with it against the same frame with it moved away),
// the moon's shadows (against the frame drawn without the shadow map: darker pixels), the smoke
// (against the frame without the smoke: lighter pixels).
#define RBL_GAME_NO_MAIN
#include "../../examples/shaders_lit_sprite_game.c"
#include "harness.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>         // chdir, getcwd

#define W 800
#define H 450

static Image Render(RenderTexture2D target, bool shadows, bool smoke)
{
    if (shadows) GameDrawShadows();
    else { scene.shadowMaps = NULL; scene.shadowMapCount = 0; RblSetScene(&scene); }
    BeginTextureMode(target);
        ClearBackground(night);
        BeginMode3D(camera);
            GameDrawWorld();
            if (smoke) GameDrawSmoke();
        EndMode3D();
    EndTextureMode();
    return rtReadTarget(target);
}

// Pixels where b is brighter than a by more than `by` (sum of channels), and the other way round
static int Brighter(Image a, Image b, int by)
{
    int n = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
        {
            Color p = GetImageColor(a, x, y), q = GetImageColor(b, x, y);
            if (q.r + q.g + q.b > p.r + p.g + p.b + by) n++;
        }
    return n;
}

int main(int argc, char **argv)
{
    char outPath[4096];
    const char *out = (argc > 1)? argv[1] : "build/game.png";
    if (out[0] == '/') snprintf(outPath, sizeof(outPath), "%s", out);
    else { char cwd[2048]; if (getcwd(cwd, sizeof(cwd)) == NULL) return 1; snprintf(outPath, sizeof(outPath), "%s/%s", cwd, out); }
    if (rtInitContext(W, H) == NULL) { fprintf(stderr, "game: no headless context; nothing rendered\n"); return 1; }
    if (chdir((argc > 2)? argv[2] : "examples") != 0) { fprintf(stderr, "game: no examples folder\n"); return 1; }
    GameInit();
    RenderTexture2D target = LoadRenderTexture(W, H);

    const bool atlases = (robotAtlas.frameCount == 9) && (propAtlas.frameCount == 8) && (walkTag >= 0) && (idleTag >= 0) &&
                         (fabsf(robotAtlas.frames[0].pivot.x - 45.0f/96.0f) < 1e-6f) && (fabsf(robotAtlas.frames[0].pivot.y - 127.0f/128.0f) < 1e-6f) &&
                         (RblAtlasFindFrame(&propAtlas, "torch_1") >= 0);
    int framesSeen = 0, lastFrame = -1;
    for (int frame = 0; frame < 150; frame++)
    {
        GameUpdate(1.0f/60.0f, CLITERAL(Vector2){ 0.0f, 0.0f });
        if (robotAnim.frame != lastFrame) { framesSeen++; lastFrame = robotAnim.frame; }
    }
    Image full = Render(target, true, true);
    Image noSmoke = Render(target, true, false);
    Image noShadow = Render(target, false, true);
    const Vector3 at = robot;
    robot.x = 1000.0f;
    Image noRobot = Render(target, true, true);
    robot = at;
    const int smoke = Brighter(noSmoke, full, 24), shadow = Brighter(full, noShadow, 24), robotPixels = Brighter(noRobot, full, 30) + Brighter(full, noRobot, 30);
    ImageFormat(&full, PIXELFORMAT_UNCOMPRESSED_R8G8B8);     // As a window shows it: blending leaves the target's alpha below 255
    const bool ok = ExportImage(full, outPath);
    printf("game: %s, atlases %s, %d walk frames shown, robot %d px, moon shadow %d px darker, smoke %d px lighter\n",
           outPath, atlases? "as exported" : "WRONG", framesSeen, robotPixels, shadow, smoke);
    UnloadImage(full); UnloadImage(noSmoke); UnloadImage(noShadow); UnloadImage(noRobot);
    UnloadRenderTexture(target);
    GameUnload();
    rtCloseContext();
    return (ok && atlases && (framesSeen >= 8) && (robotPixels > 2000) && (shadow > 5000) && (smoke > 2000))? 0 : 1;
}
