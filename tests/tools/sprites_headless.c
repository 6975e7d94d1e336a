// Headless sprite-sheet example: renders examples/shaders_lit_sprite_sheet.c offscreen (EGL
// surfaceless or OSMesa, see tests/harness.h) after 90 frames at 60 fps and writes the picture.
//   usage: sprites_headless [out.png]      (default build/sprites.png)
// Checks what the example promises, on the rendered image: the character is lit (pixels of its coat
// colour family), and the smoke is visible over the world (lighter than the world image alone where
// it rises); the exit code says.
#define RBL_SPRITES_NO_MAIN
#include "../../examples/shaders_lit_sprite_sheet.c"
#include "harness.h"

#include <stdio.h>

#define W 800
#define H 450

int main(int argc, char **argv)
{
    const char *outPath = (argc > 1)? argv[1] : "build/sprites.png";
    if (rtInitContext(W, H) == NULL) { fprintf(stderr, "sprites: no headless context; nothing rendered\n"); return 1; }
    SpritesInit(W, H);
    RenderTexture2D target = LoadRenderTexture(W, H);
    Image bare = { 0 };
    for (int frame = 0; frame <= 90; frame++)
    {
        SpritesUpdate(frame/60.0f, 1.0f/60.0f);
        SpritesDrawWorld();
        BeginTextureMode(target);
            ClearBackground(BLACK);
            SpritesDrawOver(W, H);
        EndTextureMode();
    }
    Image image = rtReadTarget(target);
    bare = rtReadTarget(world);                 // the world alone (bottom-up: flip like the composite)
    ImageFlipVertical(&bare);
    int smoky = 0, coat = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
        {
            Color a = GetImageColor(image, x, y), b = GetImageColor(bare, x, y);
            if (a.r + a.g + a.b > b.r + b.g + b.b + 30) smoky++;
            if ((a.b > a.r + 40) && (a.b > 90)) coat++;
        }
    ImageFormat(&image, PIXELFORMAT_UNCOMPRESSED_R8G8B8);     // As a window shows it: blending leaves the target's alpha below 255
    bool ok = ExportImage(image, outPath);
    printf("sprites: %s, %d pixels lighter than the bare world (smoke), %d coat-blue pixels (character)\n", outPath, smoky, coat);
    UnloadImage(image); UnloadImage(bare);
    UnloadRenderTexture(target);
    SpritesUnload();
    rtCloseContext();
    return (ok && (smoky > 2000) && (coat > 100))? 0 : 1;
}
