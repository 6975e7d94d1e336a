// Renders the README's pictures headlessly: one small image per facing mode (same scene, same
// camera, only the mode changes) into examples/resources/. Run by `make pictures`.
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "harness.h"

#include <stdio.h>
#include <string.h>

#define W 320
#define H 200

// A sign texture: coloured card with an "F" (shows mirroring) and an arrow pointing up the image
static Image signImage(Color base)
{
    Image img = GenImageColor(64, 96, BLANK);
    ImageDrawRectangle(&img, 2, 2, 60, 92, base);
    ImageDrawRectangleLines(&img, (Rectangle){ 2, 2, 60, 92 }, 3, RAYWHITE);
    ImageDrawTriangle(&img, (Vector2){ 32, 10 }, (Vector2){ 18, 30 }, (Vector2){ 46, 30 }, RAYWHITE);
    ImageDrawRectangle(&img, 28, 30, 8, 16, RAYWHITE);
    ImageDrawText(&img, "F", 22, 52, 40, RAYWHITE);
    return img;
}

// Rounded-card normal map so the lighting reads: normals lean outward near the edges
static Image bulgeNormals(int w, int h)
{
    Image img = GenImageColor(w, h, (Color){ 128, 128, 255, 255 });
    for (int y = 0; y < h; y++)
    for (int x = 0; x < w; x++)
    {
        float nx = (x + 0.5f)/w*2.0f - 1.0f, ny = 1.0f - (y + 0.5f)/h*2.0f;   // +Y = image up
        nx *= 0.6f; ny *= 0.6f;
        float nz = sqrtf(fmaxf(0.0f, 1.0f - nx*nx - ny*ny));
        ImageDrawPixel(&img, x, y, (Color){ (unsigned char)((nx*0.5f + 0.5f)*255), (unsigned char)((ny*0.5f + 0.5f)*255), (unsigned char)((nz*0.5f + 0.5f)*255), 255 });
    }
    return img;
}

int main(int argc, char **argv)
{
    const char *dir = (argc > 1)? argv[1] : "examples/resources";
    if (rtInitContext(W, H) == NULL) return 1;

    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = 2;
    desc.material.normalEncoding = RBL_NORMAL_RGB;
    RblLitShader lit = RblLoadLitShader(desc);
    if (!RblIsLitShaderValid(lit)) return 1;
    Image si = signImage((Color){ 40, 110, 190, 255 }), ni = bulgeNormals(64, 96);
    Texture2D sign = LoadTextureFromImage(si), normals = LoadTextureFromImage(ni);
    UnloadImage(si); UnloadImage(ni);
    Material mat = LoadMaterialDefault();
    mat.shader = lit.shader;
    mat.maps[MATERIAL_MAP_ALBEDO].texture = sign;
    mat.maps[MATERIAL_MAP_NORMAL].texture = normals;
    RblLight lights[2];
    memset(lights, 0, sizeof(lights));
    // A distant warm key light (nearly uniform over the scene) and a close blue fill on the right
    lights[0].position = (Vector3){ -20.0f, 25.0f, 30.0f }; lights[0].color = (Color){ 255, 230, 200, 255 }; lights[0].intensity = 1500.0f;
    lights[1].position = (Vector3){ 5.0f, 1.5f, 1.0f }; lights[1].color = (Color){ 90, 140, 255, 255 }; lights[1].intensity = 10.0f;
    RblSetLights(&lit, lights, 2, (Color){ 40, 40, 50, 255 });

    Camera3D cam;
    memset(&cam, 0, sizeof(cam));
    cam.position = (Vector3){ 3.0f, 5.5f, 7.5f };
    cam.target = (Vector3){ 0.0f, 0.5f, -1.0f };
    cam.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    cam.fovy = 70.0f;
    cam.projection = CAMERA_PERSPECTIVE;

    static const char *names[4] = { "camera_plane", "camera_position", "axis", "fixed" };
    static const char *labels[4] = { "RBL_FACING_CAMERA_PLANE", "RBL_FACING_CAMERA_POSITION", "RBL_FACING_AXIS (Y)", "RBL_FACING_FIXED" };
    RenderTexture2D rt = LoadRenderTexture(W, H);
    RblBatch batch = RblLoadBatch(32);
    for (int mode = 0; mode < 4; mode++)
    {
        BeginTextureMode(rt);
        ClearBackground((Color){ 24, 26, 32, 255 });
        BeginMode3D(cam);
        DrawGrid(12, 1.0f);
        RblBeginBatch(&batch, cam);
        for (int i = 0; i < 9; i++)
        {
            RblBillboard b;
            memset(&b, 0, sizeof(b));
            b.facing = mode;
            b.position = (Vector3){ -5.0f + (i%3)*5.0f, 0.0f, -5.0f + (i/3)*4.0f };
            b.size = (Vector2){ 1.2f, 1.8f };
            b.origin = (Vector2){ 0.6f, 0.0f };           // pivot at the bottom centre: stands on the grid
            if (mode == RBL_FACING_FIXED) { b.axis = (Vector3){ 0.0f, 0.0f, 1.0f }; b.rotation = 0.0f; }
            RblBatchAdd(&batch, mat, &b);
        }
        RblEndBatch(&batch);
        DrawSphere(lights[1].position, 0.12f, lights[1].color);
        EndMode3D();
        DrawText(labels[mode], 8, 8, 10, RAYWHITE);
        EndTextureMode();
        Image img = rtReadTarget(rt);
        char path[512];
        snprintf(path, sizeof(path), "%s/rbl_mode_%s.png", dir, names[mode]);
        if (!ExportImage(img, path)) { printf("pictures: could not write %s\n", path); return 1; }
        printf("pictures: wrote %s\n", path);
        UnloadImage(img);
    }
    RblUnloadBatch(&batch);
    UnloadRenderTexture(rt);
    UnloadTexture(sign); UnloadTexture(normals);
    MemFree(mat.maps);
    RblUnloadLitShader(lit);
    RblClose();
    rtCloseContext();
    return 0;
}
