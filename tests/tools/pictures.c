// Renders the README's pictures headlessly: one small image per facing mode (same scene, same
// camera, only the mode changes), one of the lighting models (raylib sphere Models next to
// round-normal billboards, Blinn-Phong and GGX) and one of shadows (cut-out sprites and a Model
// under a directional and a spot light) into examples/resources/. Run by `make pictures`.
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "harness.h"

#include <stdio.h>
#include <string.h>

#define W 320
#define H 200

// A sign texture: coloured card with an "F" (shows mirroring) and an arrow pointing up the image
// As a window shows it: blending leaves the target's alpha below 255 where a PNG would show through
static bool ExportOpaque(Image image, const char *path)
{
    Image copy = ImageCopy(image);
    ImageFormat(&copy, PIXELFORMAT_UNCOMPRESSED_R8G8B8);
    const bool ok = ExportImage(copy, path);
    UnloadImage(copy);
    return ok;
}

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

// Blinn-Phong (top row, shininess 8..512) and GGX (bottom row, roughness 0.1..0.9): in each cell a
// raylib sphere Model and a billboard disc with spherical normals (roundness 1), same program, same
// lights. One program per row: the cells differ only in their Material's values
static bool lightingPicture(const char *dir)
{
    const int w = 640, h = 300;
    Image disc = GenImageColor(64, 64, BLANK);
    ImageDrawCircle(&disc, 32, 32, 31, WHITE);
    Texture2D discTexture = LoadTextureFromImage(disc);
    UnloadImage(disc);
    SetTextureFilter(discTexture, TEXTURE_FILTER_BILINEAR);
    Mesh sphereMesh = GenMeshSphere(0.5f, 32, 32);
    Model sphere = LoadModelFromMesh(sphereMesh);
    Material sphereDefault = sphere.materials[0];       // restored before UnloadModel (the cells' materials are freed per cell)
    RblLight lights[3];
    memset(lights, 0, sizeof(lights));
    lights[0].position = (Vector3){ -2.0f, 3.0f, 4.0f }; lights[0].color = (Color){ 255, 236, 210, 255 }; lights[0].intensity = 30.0f; lights[0].range = 20.0f;
    lights[1].type = RBL_LIGHT_DIRECTIONAL; lights[1].direction = (Vector3){ -1.0f, 0.2f, -0.3f }; lights[1].color = (Color){ 110, 150, 255, 255 }; lights[1].intensity = 0.5f;
    lights[2].type = RBL_LIGHT_SPOT; lights[2].position = (Vector3){ 4.0f, 4.0f, 3.0f }; lights[2].direction = (Vector3){ -1.0f, -1.0f, -1.0f };
    lights[2].innerAngle = 15.0f; lights[2].outerAngle = 40.0f; lights[2].color = (Color){ 255, 120, 80, 255 }; lights[2].intensity = 20.0f; lights[2].range = 20.0f;
    Camera3D cam;
    memset(&cam, 0, sizeof(cam));
    cam.position = (Vector3){ 0.0f, 0.0f, 9.0f };
    cam.target = (Vector3){ 0.0f, 0.0f, 0.0f };
    cam.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    cam.fovy = 32.0f;
    cam.projection = CAMERA_PERSPECTIVE;
    Shader shaders[2];                                  // [row]: Blinn-Phong, GGX
    for (int row = 0; row < 2; row++)
    {
        RblLitShaderDesc d;
        memset(&d, 0, sizeof(d));
        d.maxLights = 3;
        d.lightFeatures = RblLightFeatures(lights, 3);
        d.brdf = row? RBL_BRDF_GGX : RBL_BRDF_BLINN_PHONG;
        d.tonemap = RBL_TONEMAP_ACES;
        shaders[row] = RblLoadLitShader(d);
    }
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = lights;
    scene.lightCount = 3;
    scene.ambient = (Color){ 30, 30, 36, 255 };
    bool sceneSet = RblSetScene(&scene);
    RenderTexture2D rt = LoadRenderTexture(w, h);
    BeginTextureMode(rt);
    ClearBackground((Color){ 24, 26, 32, 255 });
    BeginMode3D(cam);
    const float shininess[4] = { 8.0f, 32.0f, 128.0f, 512.0f }, roughness[4] = { 0.1f, 0.3f, 0.6f, 0.9f };
    for (int row = 0; row < 2; row++)
        for (int col = 0; col < 4; col++)
        {
            if (!RblIsLitShaderValid(shaders[row])) continue;
            Material m = LoadMaterialDefault();
            m.shader = shaders[row];
            rtSetMaterialValues(&m, (RtMaterialValues){ .specular = 0.6f, .shininess = shininess[col], .roughness = roughness[col] });
            m.maps[MATERIAL_MAP_ALBEDO].color = row? (Color){ 200, 80, 60, 255 } : (Color){ 70, 130, 200, 255 };
            float x = -4.2f + col*2.8f, y = row? -0.9f : 0.9f;
            sphere.materials[0] = m;
            RblDrawModel(sphere, (Vector3){ x - 0.55f, y, 0.0f }, 1.0f, WHITE);
            m.maps[MATERIAL_MAP_ALBEDO].texture = discTexture;
            RblBillboard b;
            memset(&b, 0, sizeof(b));
            b.position = (Vector3){ x + 0.55f, y, 0.0f };
            b.size = (Vector2){ 1.0f, 1.0f };
            b.origin = (Vector2){ 0.5f, 0.5f };
            b.roundness = 1.0f;
            RblDrawBillboard(cam, m, b);
            MemFree(m.maps);
        }
    EndMode3D();
    DrawText("Blinn-Phong  n = 8, 32, 128, 512   (sphere Model | billboard, same shader)", 8, 6, 10, RAYWHITE);
    DrawText("GGX  roughness = 0.1, 0.3, 0.6, 0.9", 8, h - 16, 10, RAYWHITE);
    EndTextureMode();
    Image img = rtReadTarget(rt);
    char path[512];
    snprintf(path, sizeof(path), "%s/rbl_lighting.png", dir);
    bool ok = sceneSet && RblIsLitShaderValid(shaders[0]) && RblIsLitShaderValid(shaders[1]) && ExportOpaque(img, path);
    printf("pictures: %s %s\n", ok? "wrote" : "could not write", path);
    UnloadImage(img);
    UnloadRenderTexture(rt);
    for (int i = 0; i < 2; i++) RblUnloadLitShader(&shaders[i]);
    sphere.materials[0] = sphereDefault;                // the drawn materials were freed above
    UnloadModel(sphere);
    UnloadTexture(discTexture);
    return ok;
}

// A leafy tree sprite: a trunk and overlapping leaf clusters, with gaps and a few holes punched
// through the canopy (transparent: the shadow must show them)
static Image treeImage(void)
{
    const int w = 128, h = 192;
    Image img = GenImageColor(w, h, BLANK);
    ImageDrawRectangle(&img, 57, 110, 14, 82, (Color){ 112, 78, 50, 255 });          // trunk
    ImageDrawTriangle(&img, (Vector2){ 64, 150 }, (Vector2){ 64, 132 }, (Vector2){ 34, 118 }, (Color){ 112, 78, 50, 255 });   // branch
    const int leaves[][3] = { { 64, 40, 30 }, { 34, 62, 24 }, { 94, 62, 24 }, { 46, 96, 22 }, { 84, 98, 24 }, { 64, 72, 26 },
                              { 24, 100, 14 }, { 106, 92, 14 }, { 40, 30, 16 }, { 90, 28, 16 } };
    const Color greens[3] = { { 58, 128, 52, 255 }, { 76, 150, 60, 255 }, { 46, 110, 48, 255 } };
    for (int i = 0; i < (int)(sizeof(leaves)/sizeof(leaves[0])); i++) ImageDrawCircle(&img, leaves[i][0], leaves[i][1], leaves[i][2], greens[i%3]);
    const int holes[][3] = { { 56, 58, 7 }, { 80, 80, 8 }, { 40, 84, 6 }, { 70, 30, 5 }, { 96, 60, 5 } };
    for (int i = 0; i < (int)(sizeof(holes)/sizeof(holes[0])); i++) ImageDrawCircle(&img, holes[i][0], holes[i][1], holes[i][2], BLANK);
    return img;
}

// A hoop on a post: an opaque ring around a transparent hole
static Image hoopImage(void)
{
    Image img = GenImageColor(128, 256, BLANK);
    ImageDrawRectangle(&img, 58, 100, 12, 156, (Color){ 150, 150, 160, 255 });       // post
    ImageDrawCircle(&img, 64, 60, 56, (Color){ 220, 90, 50, 255 });
    ImageDrawCircle(&img, 64, 60, 44, (Color){ 245, 200, 80, 255 });
    ImageDrawCircle(&img, 64, 60, 34, BLANK);                                          // the hole
    return img;
}

// Shadows: a sun (directional, orthographic map over a fixed focus sphere) and a spot light (its own
// perspective map) cast a hoop sprite with a hole (FIXED facing), a leafy tree (AXIS facing, cut-out
// leaves) and a raylib cube Model onto a lit floor Model; the casters are drawn into each map with
// the same calls and materials as the colour pass
static bool shadowsPicture(const char *dir)
{
    const int w = 640, h = 360;
    Image ti = treeImage(), hi = hoopImage();
    Image fi = GenImageChecked(256, 256, 32, 32, (Color){ 196, 190, 178, 255 }, (Color){ 172, 166, 154, 255 });
    Texture2D tree = LoadTextureFromImage(ti), hoop = LoadTextureFromImage(hi), floorTexture = LoadTextureFromImage(fi);
    UnloadImage(ti); UnloadImage(hi); UnloadImage(fi);
    SetTextureFilter(tree, TEXTURE_FILTER_BILINEAR);
    SetTextureFilter(hoop, TEXTURE_FILTER_BILINEAR);
    GenTextureMipmaps(&floorTexture);
    SetTextureFilter(floorTexture, TEXTURE_FILTER_TRILINEAR);

    RblLight lights[2];
    memset(lights, 0, sizeof(lights));
    lights[0].type = RBL_LIGHT_DIRECTIONAL; lights[0].direction = (Vector3){ 0.75f, -0.72f, -0.5f };
    lights[0].color = (Color){ 255, 226, 180, 255 }; lights[0].intensity = 0.75f;
    lights[1].type = RBL_LIGHT_SPOT; lights[1].position = (Vector3){ 3.0f, 4.2f, 2.6f }; lights[1].direction = (Vector3){ -3.0f, -4.2f, -3.2f };
    lights[1].innerAngle = 26.0f; lights[1].outerAngle = 38.0f; lights[1].color = (Color){ 110, 160, 255, 255 }; lights[1].intensity = 60.0f; lights[1].range = 16.0f;

    RblLitShaderDesc d;
    memset(&d, 0, sizeof(d));
    d.maxLights = 2;
    d.lightFeatures = RblLightFeatures(lights, 2);
    d.brdf = RBL_BRDF_BLINN_PHONG;
    d.tonemap = RBL_TONEMAP_ACES;
    d.shadowMaps = 2;                                   // every receiver samples both maps
    Shader lit = RblLoadLitShader(d);
    const RtMaterialValues values = { .specular = 0.2f };   // every material: Blinn-Phong specular intensity 0.2
    RblShadowDesc sd;
    memset(&sd, 0, sizeof(sd));
    sd.size = 2048;
    RblShadowMap maps[2] = { RblLoadShadowMap(sd), RblLoadShadowMap(sd) };
    if (!RblIsLitShaderValid(lit) || !RblIsShadowMapValid(maps[0]) || !RblIsShadowMapValid(maps[1])) { printf("pictures: shadows unavailable\n"); return false; }
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = lights;
    scene.lightCount = 2;
    scene.ambient = (Color){ 44, 48, 60, 255 };

    Material treeMat = LoadMaterialDefault(), hoopMat = LoadMaterialDefault();
    treeMat.shader = hoopMat.shader = lit;
    rtSetMaterialValues(&treeMat, values);
    rtSetMaterialValues(&hoopMat, values);
    treeMat.maps[MATERIAL_MAP_ALBEDO].texture = tree;
    hoopMat.maps[MATERIAL_MAP_ALBEDO].texture = hoop;
    Model ground = LoadModelFromMesh(GenMeshPlane(14.0f, 14.0f, 1, 1));
    ground.materials[0].shader = lit;
    rtSetMaterialValues(&ground.materials[0], values);
    ground.materials[0].maps[MATERIAL_MAP_ALBEDO].texture = floorTexture;
    Model cube = LoadModelFromMesh(GenMeshCube(0.9f, 0.9f, 0.9f));
    cube.materials[0].shader = lit;
    rtSetMaterialValues(&cube.materials[0], values);
    cube.materials[0].maps[MATERIAL_MAP_ALBEDO].color = (Color){ 70, 130, 200, 255 };
    const float turn = 35.0f*DEG2RAD;                   // turned about +Y (raymath's MatrixRotateY)
    cube.transform.m0 = cosf(turn); cube.transform.m2 = -sinf(turn); cube.transform.m8 = sinf(turn); cube.transform.m10 = cosf(turn);
    const Vector3 cubeAt = { 2.3f, 0.45f, 0.5f };

    Camera3D cam;
    memset(&cam, 0, sizeof(cam));
    cam.position = (Vector3){ 0.3f, 3.5f, 5.8f };
    cam.target = (Vector3){ 0.0f, 0.6f, -1.1f };
    cam.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    cam.fovy = 44.0f;
    cam.projection = CAMERA_PERSPECTIVE;

    RblBillboard sprites[2];
    memset(sprites, 0, sizeof(sprites));
    sprites[0].position = (Vector3){ -2.6f, 0.0f, -0.9f }; sprites[0].size = (Vector2){ 1.7f, 2.55f }; sprites[0].origin = (Vector2){ 0.85f, 0.0f };
    sprites[0].facing = RBL_FACING_AXIS;                // turns about +Y toward the camera
    sprites[1].position = (Vector3){ 0.0f, 0.0f, 0.2f }; sprites[1].size = (Vector2){ 1.0f, 2.0f }; sprites[1].origin = (Vector2){ 0.5f, 0.0f };
    sprites[1].facing = RBL_FACING_FIXED; sprites[1].axis = (Vector3){ -0.25f, 0.0f, 0.97f };  // toward the viewer, so both lights see it at an angle
    const Material *spriteMat[2] = { &treeMat, &hoopMat };

    // Shadow passes (outside BeginTextureMode: they bind their own framebuffer): the sun over a fixed
    // sphere around the scene, the spot over its cone out to its range; then the scene lists both maps
    // and is set (after the passes: RblSetScene reads their matrices)
    for (int k = 0; k < 2; k++)
    {
        if (!RblBeginShadowMap(&maps[k], &scene, k, (Vector3){ 0.0f, 0.8f, 0.0f }, 4.5f)) continue;
        for (int i = 0; i < 2; i++) RblDrawBillboard(cam, *spriteMat[i], sprites[i]);
        RblDrawModel(cube, cubeAt, 1.0f, WHITE);       // inside a shadow pass: drawn as a caster
        RblEndShadowMap(&maps[k]);
    }
    scene.shadowMaps = maps;
    scene.shadowMapCount = 2;
    bool ok = RblSetScene(&scene);

    RenderTexture2D rt = LoadRenderTexture(w, h);
    BeginTextureMode(rt);
    ClearBackground((Color){ 24, 26, 32, 255 });
    BeginMode3D(cam);
    RblDrawModel(ground, (Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f, WHITE);
    RblDrawModel(cube, cubeAt, 1.0f, WHITE);
    for (int i = 0; i < 2; i++) RblDrawBillboard(cam, *spriteMat[i], sprites[i]);
    EndMode3D();
    DrawText("Shadows: warm sun (directional) + blue spot, one map each: the sun's shadows look blue, the spot's warm", 8, 6, 10, RAYWHITE);
    DrawText("leafy tree (AXIS, cut-out) | hoop with a hole (FIXED) | cube Model", 8, h - 16, 10, RAYWHITE);
    EndTextureMode();
    Image img = rtReadTarget(rt);
    char path[512];
    snprintf(path, sizeof(path), "%s/rbl_shadows.png", dir);
    ok = ok && ExportOpaque(img, path);
    printf("pictures: %s %s\n", ok? "wrote" : "could not write", path);
    UnloadImage(img);
    UnloadRenderTexture(rt);
    for (int k = 0; k < 2; k++) RblUnloadShadowMap(&maps[k]);
    MemFree(treeMat.maps); MemFree(hoopMat.maps);
    UnloadModel(ground); UnloadModel(cube);             // meshes and material maps, not the shader or textures
    RblUnloadLitShader(&lit);
    UnloadTexture(tree); UnloadTexture(hoop); UnloadTexture(floorTexture);
    return ok;
}

int main(int argc, char **argv)
{
    const char *dir = (argc > 1)? argv[1] : "examples/resources";
    if (rtInitContext(W, H) == NULL) return 1;

    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = 2;
    desc.material.normalEncoding = RBL_NORMAL_RGB;
    Shader lit = RblLoadLitShader(desc);
    if (!RblIsLitShaderValid(lit)) return 1;
    Image si = signImage((Color){ 40, 110, 190, 255 }), ni = bulgeNormals(64, 96);
    Texture2D sign = LoadTextureFromImage(si), normals = LoadTextureFromImage(ni);
    UnloadImage(si); UnloadImage(ni);
    Material mat = LoadMaterialDefault();
    mat.shader = lit;
    mat.maps[MATERIAL_MAP_ALBEDO].texture = sign;
    mat.maps[MATERIAL_MAP_NORMAL].texture = normals;
    RblLight lights[2];
    memset(lights, 0, sizeof(lights));
    // A distant warm key light (nearly uniform over the scene) and a close blue fill on the right
    lights[0].position = (Vector3){ -20.0f, 25.0f, 30.0f }; lights[0].color = (Color){ 255, 230, 200, 255 }; lights[0].intensity = 1500.0f;
    lights[1].position = (Vector3){ 5.0f, 1.5f, 1.0f }; lights[1].color = (Color){ 90, 140, 255, 255 }; lights[1].intensity = 10.0f;
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = lights;
    scene.lightCount = 2;
    scene.ambient = (Color){ 40, 40, 50, 255 };
    if (!RblSetScene(&scene)) return 1;

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
        if (!ExportOpaque(img, path)) { printf("pictures: could not write %s\n", path); return 1; }
        printf("pictures: wrote %s\n", path);
        UnloadImage(img);
    }
    RblUnloadBatch(&batch);
    UnloadRenderTexture(rt);
    if (!lightingPicture(dir)) return 1;
    if (!shadowsPicture(dir)) return 1;
    UnloadTexture(sign); UnloadTexture(normals);
    MemFree(mat.maps);
    RblUnloadLitShader(&lit);
    RblClose();                                         // after the Unload calls
    rtCloseContext();
    return 0;
}
