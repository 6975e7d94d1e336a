/*******************************************************************************************
*
*   raylib [shaders] example - lit sprite sheet
*
*   Example complexity rating: [★★★☆] 3/4
*
*   NOTE: This example requires rbillboard_lit.h (single header, beside this file)
*
*   Example originally created with raylib 6.0, last time updated with raylib 6.0
*
*   Example shows a sprite-sheet workflow with rbillboard_lit.h: a walking character drawn into a
*   sheet at startup, described by an Aseprite-style JSON atlas (written here, as an exporter would)
*   and imported with RblLoadAtlasFromMemory; its normal sheet shares the frames, so it is packed
*   and lit like any card. It walks among lit crates (raylib Models), and soft smoke rises from a
*   chimney: blended puffs sorted back to front that fade where they meet the world's depth.
*
*   Example licensed under an unmodified zlib/libpng license, which is an OSI-certified,
*   BSD-like license that allows static linking with closed source software
*
*   Copyright (c) 2026 rbillboard_lit contributors
*
********************************************************************************************/

#include "raylib.h"

#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"

#include <math.h>           // sinf, cosf, fmodf
#include <stdio.h>          // snprintf

//----------------------------------------------------------------------------------
// Defines and Macros
//----------------------------------------------------------------------------------
#define FRAME_W         48          // Sheet frame size in pixels
#define FRAME_H         64
#define WALK_FRAMES     6
#define CRATE_COUNT     6
#define PUFF_COUNT      40
#define LIGHT_COUNT     3

//----------------------------------------------------------------------------------
// Global Variables Definition (statics start zeroed, in C and C++ alike)
//----------------------------------------------------------------------------------
static Camera3D camera;
static RblAtlas atlas;
static RblSpritePlayer walk;
static Material heroMaterial, smokeMaterial;
static Model floorModel, crateModel;
static Texture2D floorTexture, crateTexture, smokeTexture;
static RblBatch heroBatch, smokeBatch;
static RenderTexture2D world;               // Colour + depth texture: the smoke reads the depth
static RblLight lights[LIGHT_COUNT];
static RblScene scene;
static float heroAngle, now;

//----------------------------------------------------------------------------------
// Module Functions Declaration
//----------------------------------------------------------------------------------
static void SpritesInit(int width, int height);    // Sheet, atlas, materials, models, targets
static void SpritesUpdate(float time, float dt);   // Walk, lights, scene (a function of time and dt)
static void SpritesDrawWorld(void);                // Opaque world into the world target
static void SpritesDrawOver(int width, int height); // World image, then the smoke (inside a drawing target)
static void SpritesUnload(void);

//------------------------------------------------------------------------------------
// Program main entry point
//------------------------------------------------------------------------------------
#if !defined(RBL_SPRITES_NO_MAIN)
int main(void)
{
    // Initialization
    //--------------------------------------------------------------------------------------
    const int screenWidth = 800;
    const int screenHeight = 450;

    InitWindow(screenWidth, screenHeight, "raylib [shaders] example - lit sprite sheet");
    SpritesInit(screenWidth, screenHeight);
    SetTargetFPS(60);
    //--------------------------------------------------------------------------------------

    // Main game loop
    while (!WindowShouldClose())        // Detect window close button or ESC key
    {
        // Update
        //----------------------------------------------------------------------------------
        SpritesUpdate((float)GetTime(), GetFrameTime());
        SpritesDrawWorld();
        //----------------------------------------------------------------------------------

        // Draw
        //----------------------------------------------------------------------------------
        BeginDrawing();
            ClearBackground(BLACK);
            SpritesDrawOver(screenWidth, screenHeight);
            DrawText("Aseprite-style atlas, packed normal sheet, sorted soft smoke", 10, 10, 20, RAYWHITE);
        EndDrawing();
        //----------------------------------------------------------------------------------
    }

    // De-Initialization
    //--------------------------------------------------------------------------------------
    SpritesUnload();
    CloseWindow();        // Close window and OpenGL context
    //--------------------------------------------------------------------------------------

    return 0;
}
#endif

//------------------------------------------------------------------------------------
// Module Functions Definition
//------------------------------------------------------------------------------------
// One walk frame at x: a head, a body and two legs swinging with the phase
static void DrawWalkFrame(Image *sheet, int frame)
{
    int x = frame*FRAME_W, cx = x + FRAME_W/2;
    float swing = sinf(2.0f*PI*(float)frame/WALK_FRAMES);
    Color skin = { 240, 200, 160, 255 }, coat = { 60, 110, 200, 255 }, boots = { 70, 45, 30, 255 };
    for (int leg = -1; leg <= 1; leg += 2)
    {
        int foot = cx + (int)(leg*swing*9.0f);
        ImageDrawLineEx(sheet, CLITERAL(Vector2){ (float)cx + leg*4.0f, 40.0f }, CLITERAL(Vector2){ (float)foot, 58.0f }, 6, boots);
    }
    ImageDrawRectangle(sheet, cx - 9, 20, 18, 24, coat);
    ImageDrawCircle(sheet, cx, 12, 9, skin);
    ImageDrawRectangle(sheet, cx - 13 + (int)(swing*3.0f), 24, 5, 14, skin);    // the near arm swings too
}

static void SpritesInit(int width, int height)
{
    camera.position = CLITERAL(Vector3){ 0.0f, 4.5f, 9.0f };
    camera.target = CLITERAL(Vector3){ 0.0f, 1.0f, 0.0f };
    camera.up = CLITERAL(Vector3){ 0.0f, 1.0f, 0.0f };
    camera.fovy = 45.0f;
    camera.projection = CAMERA_PERSPECTIVE;

    // The sheet, drawn as an artist would export it, and the atlas an exporter would write beside it
    Image sheet = GenImageColor(FRAME_W*WALK_FRAMES, FRAME_H, BLANK);
    for (int f = 0; f < WALK_FRAMES; f++) DrawWalkFrame(&sheet, f);
    char json[4096];
    int n = snprintf(json, sizeof(json), "{\"frames\":[");
    for (int f = 0; f < WALK_FRAMES; f++)
        n += snprintf(json + n, sizeof(json) - n, "%s{\"filename\":\"hero %d\",\"frame\":{\"x\":%d,\"y\":0,\"w\":%d,\"h\":%d},\"rotated\":false,\"trimmed\":false,"
                      "\"spriteSourceSize\":{\"x\":0,\"y\":0,\"w\":%d,\"h\":%d},\"sourceSize\":{\"w\":%d,\"h\":%d},\"duration\":110}",
                      (f > 0)? "," : "", f, f*FRAME_W, FRAME_W, FRAME_H, FRAME_W, FRAME_H, FRAME_W, FRAME_H);
    snprintf(json + n, sizeof(json) - n, "],\"meta\":{\"app\":\"http://www.aseprite.org/\",\"image\":\"hero.png\",\"size\":{\"w\":%d,\"h\":%d},"
             "\"frameTags\":[{\"name\":\"walk\",\"from\":0,\"to\":%d,\"direction\":\"forward\"}]}}", FRAME_W*WALK_FRAMES, FRAME_H, WALK_FRAMES - 1);
    atlas = RblLoadAtlasFromMemory(json, (int)TextLength(json), RBL_ATLAS_AUTO);
    walk = RblPlaySprite(&atlas, RblAtlasFindTag(&atlas, "walk"), -1);

    // The normal sheet shares the layout; packing dilates each frame's edge and keeps the
    // alpha-tested coverage in every mip (the character does not thin out at a distance)
    Image bumps = RblGenHeightFromLuminance(sheet);
    Image normals = RblGenNormalMapFromHeight(bumps, 2.0f, false);
    Rectangle frames[WALK_FRAMES];
    for (int f = 0; f < WALK_FRAMES; f++) frames[f] = CLITERAL(Rectangle){ (float)(f*FRAME_W), 0.0f, (float)FRAME_W, (float)FRAME_H };
    RblMaterialSource source = RBL_ZERO;
    source.albedo = sheet;
    source.normal = normals;
    source.frames = frames;
    source.frameCount = WALK_FRAMES;
    source.mipmaps = true;
    source.alphaCoverage = 0.5f;
    RblPackedMaterial packed = RBL_ZERO;
    RblPackMaterial(&source, &packed);
    RblLitShaderDesc desc = RBL_ZERO;
    desc.material = packed.layout;
    desc.shading.brdf = RBL_BRDF_BLINN_PHONG;
    heroMaterial = LoadMaterialDefault();
    heroMaterial.shader = RblLoadLitShader(desc);
    RblLoadPackedTextures(&packed, &heroMaterial);
    RblUnloadPackedMaterial(&packed);
    UnloadImage(sheet); UnloadImage(bumps); UnloadImage(normals);

    // Floor and crates: raylib Models lit by the same scene
    RblLitShaderDesc plain = RBL_ZERO;
    plain.shading.brdf = RBL_BRDF_BLINN_PHONG;
    Image checks = GenImageChecked(256, 256, 32, 32, CLITERAL(Color){ 90, 100, 80, 255 }, CLITERAL(Color){ 70, 80, 60, 255 });
    floorTexture = LoadTextureFromImage(checks);
    UnloadImage(checks);
    floorModel = LoadModelFromMesh(GenMeshPlane(16.0f, 16.0f, 1, 1));
    floorModel.materials[0].shader = RblLoadLitShader(plain);
    floorModel.materials[0].maps[MATERIAL_MAP_ALBEDO].texture = floorTexture;
    Image wood = GenImageColor(4, 4, CLITERAL(Color){ 150, 105, 60, 255 });
    crateTexture = LoadTextureFromImage(wood);
    UnloadImage(wood);
    crateModel = LoadModelFromMesh(GenMeshCube(1.0f, 1.0f, 1.0f));
    crateModel.materials[0].shader = RblLoadLitShader(plain);
    crateModel.materials[0].maps[MATERIAL_MAP_ALBEDO].texture = crateTexture;

    // Smoke: a soft round puff, never cut (low alpha is the point), fading into the world's depth
    Image puff = GenImageGradientRadial(64, 64, 0.0f, CLITERAL(Color){ 210, 210, 220, 170 }, CLITERAL(Color){ 210, 210, 220, 0 });
    smokeTexture = LoadTextureFromImage(puff);
    UnloadImage(puff);
    RblLitShaderDesc soft = RBL_ZERO;
    soft.softParticles = true;
    smokeMaterial = LoadMaterialDefault();
    smokeMaterial.shader = RblLoadLitShader(soft);
    smokeMaterial.maps[MATERIAL_MAP_ALBEDO].texture = smokeTexture;
    smokeMaterial.params[RBL_PARAM_ALPHA_CUTOFF] = -1.0f;
    smokeMaterial.params[RBL_PARAM_SOFT_DISTANCE] = 0.6f;

    heroBatch = RblLoadBatch(8);
    smokeBatch = RblLoadBatch(PUFF_COUNT);
    smokeBatch.sort = RBL_SORT_BACK_TO_FRONT;
    world = RblLoadSceneTarget(width, height);
}

static void SpritesUpdate(float time, float dt)
{
    RblUpdateSprite(&walk, &atlas, dt);
    now = time;
    heroAngle = time*0.45f;
    const Color colors[LIGHT_COUNT] = { { 255, 170, 90, 255 }, { 90, 150, 255, 255 }, { 255, 90, 170, 255 } };
    for (int i = 0; i < LIGHT_COUNT; i++)
    {
        float a = time*(0.4f + 0.2f*i) + 2.1f*i;
        lights[i].position = CLITERAL(Vector3){ 4.0f*cosf(a), 1.6f + 0.4f*i, 4.0f*sinf(a) };
        lights[i].color = colors[i];
        lights[i].intensity = 6.0f;
        lights[i].range = 9.0f;
    }
    scene.lights = lights;
    scene.lightCount = LIGHT_COUNT;
    scene.ambient = CLITERAL(Color){ 64, 68, 86, 255 };
    scene.depth = world.depth;          // read by the soft smoke only (the world's own draws ignore it)
    RblSetScene(&scene);
}

static void SpritesDrawWorld(void)
{
    BeginTextureMode(world);
        ClearBackground(CLITERAL(Color){ 24, 26, 36, 255 });
        BeginMode3D(camera);
            RblDrawModel(floorModel, CLITERAL(Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f, WHITE);
            for (int i = 0; i < CRATE_COUNT; i++)
            {
                float a = 2.0f*PI*i/CRATE_COUNT + 0.4f;
                RblDrawModel(crateModel, CLITERAL(Vector3){ 2.0f*cosf(a), 0.5f, 2.0f*sinf(a) }, 0.9f, WHITE);
            }
            // The character walks a circle of radius 3.2; mirrored when it moves left on screen
            RblBillboard hero = RBL_ZERO;
            hero.facing = RBL_FACING_AXIS;
            RblAtlasBillboard(&atlas, walk.frame, 1.0f/28.0f, &hero);  // no pivot in the atlas: it stands on its feet
            hero.position = CLITERAL(Vector3){ 3.2f*cosf(heroAngle), 0.0f, 3.2f*sinf(heroAngle) };
            Vector3 velocity = { -sinf(heroAngle), 0.0f, cosf(heroAngle) };
            RblCameraFrame view = RblGetCameraFrame(camera);
            if (velocity.x*view.right.x + velocity.z*view.right.z < 0.0f) hero.size.x = -hero.size.x;
            RblBeginBatch(&heroBatch, camera);
            RblBatchAdd(&heroBatch, heroMaterial, &hero);
            RblEndBatch(&heroBatch);
        EndMode3D();
    EndTextureMode();
}

static void SpritesDrawOver(int width, int height)
{
    // The world image (render textures are stored bottom-up), then the smoke over it: no depth test
    // against the screen, the fade against the world's depth does the occlusion
    DrawTextureRec(world.texture, CLITERAL(Rectangle){ 0.0f, 0.0f, (float)width, -(float)height }, CLITERAL(Vector2){ 0.0f, 0.0f }, WHITE);
    BeginMode3D(camera);
        RblBeginBatch(&smokeBatch, camera);
        for (int i = 0; i < PUFF_COUNT; i++)
        {
            float life = fmodf(now*0.35f + (float)i/PUFF_COUNT, 1.0f);     // 0 at the chimney, 1 gone
            RblBillboard puff = RBL_ZERO;
            puff.position = CLITERAL(Vector3){ -2.0f + 0.6f*sinf(i*2.3f)*life + 0.8f*life, 1.0f + 3.5f*life, -1.0f + 0.5f*cosf(i*1.7f)*life };
            puff.size.x = puff.size.y = 0.6f + 1.4f*life;
            puff.origin.x = puff.origin.y = 0.5f*puff.size.x;
            puff.rotation = 90.0f*i;
            puff.tint = CLITERAL(Color){ 255, 255, 255, (unsigned char)(255.0f*(1.0f - life)) };
            RblBatchAdd(&smokeBatch, smokeMaterial, &puff);
        }
        RblEndBatch(&smokeBatch);
    EndMode3D();
}

static void SpritesUnload(void)
{
    RblUnloadBatch(&heroBatch);
    RblUnloadBatch(&smokeBatch);
    RblUnloadAtlas(&atlas);
    UnloadRenderTexture(world);
    UnloadModel(floorModel);            // meshes and maps; the lit programs go with RblClose
    UnloadModel(crateModel);
    UnloadMaterial(heroMaterial);       // its program handle and packed textures
    smokeMaterial.maps[MATERIAL_MAP_ALBEDO].texture.id = 0;
    UnloadMaterial(smokeMaterial);
    UnloadTexture(floorTexture);
    UnloadTexture(crateTexture);
    UnloadTexture(smokeTexture);
    RblClose();
}
