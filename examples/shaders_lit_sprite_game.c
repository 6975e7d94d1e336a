/*******************************************************************************************
*
*   raylib [shaders] example - lit sprite game
*
*   Example complexity rating: [★★★★] 4/4
*
*   NOTE: This example requires rbillboard_lit.h (single header, beside this file) and the
*         resources/kenney_* files: Kenney's CC0 art (www.kenney.nl, see resources/LICENSE-kenney.txt)
*
*   Example originally created with raylib 6.0, last time updated with raylib 6.0
*
*   Example shows a night yard built from sprite art as a small game would: Kenney's robot walks (an
*   Aseprite sheet: tags, durations, a pivot slice), torches, bushes and rocks stand about (a trimmed
*   TexturePacker sheet with pivots), crates and paving are raylib Models; every texture gets a normal
*   map from its luminance. Torches flicker, wisps drift, the moon casts the sprites' cut-out shadows,
*   fog swallows the far side, lit smoke rises. Arrow keys or WASD walk the robot (else it wanders).
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

#include <math.h>           // sinf, cosf, fmodf, sqrtf, fminf, fmaxf, fabsf

//----------------------------------------------------------------------------------
// Defines and Macros
//----------------------------------------------------------------------------------
#define TORCH_COUNT     3
#define WISP_COUNT      2
#define MOON            (TORCH_COUNT + WISP_COUNT)     // Light index of the moon (the shadow caster)
#define LIGHT_COUNT     (MOON + 1)
#define CRATE_COUNT     6
#define PROP_COUNT      12
#define PUFFS_PER_TORCH 14
#define SPRITE_SCALE    (1.0f/72.0f)                    // World units per sheet pixel (the robot: 1.8 tall)

//----------------------------------------------------------------------------------
// Global Variables Definition (statics start zeroed, in C and C++ alike)
//----------------------------------------------------------------------------------
static Camera3D camera;
static const Color night = { 12, 16, 32, 255 };
static RblAtlas robotAtlas, propAtlas;
static RblSpritePlayer robotAnim;
static int walkTag, idleTag;
static Material robotMaterial, propMaterial, smokeMaterial;
static Shader modelLit;                     // Floor and crates: albedo + RGB normal map
static Model floorModel, crateModel;
static Texture2D floorTextures[2], crateTextures[2], puffTexture;   // [0] albedo, [1] normal map
static RblBatch spriteBatch, smokeBatch;
static RblLight lights[LIGHT_COUNT];
static RblScene scene;
static RblShadowMap moonShadow;
static Vector3 robot = { 2.2f, 0.0f, 0.0f };
static float wanderAngle, now;
static bool robotWalking, robotMirrored;

// Crates: x, z, height of their base; the first TORCH_COUNT carry a torch
static const float crates[CRATE_COUNT][3] = {
    { -3.4f, -2.6f, 0.0f }, { 3.6f, -1.8f, 0.0f }, { 0.4f, 3.6f, 0.0f }, { -4.4f, 1.2f, 0.0f }, { -4.4f, 1.2f, 1.0f }, { 4.6f, 2.4f, 0.0f } };
static const struct { const char *frame; float x, z, scale; } props[PROP_COUNT] = {      // Props: sheet frame, place, size
    { "bush", -1.6f, -3.8f, 1.2f }, { "bush", 2.4f, -4.2f, 1.0f }, { "bush", 5.6f, 0.4f, 1.1f }, { "rock", -2.6f, 2.6f, 0.8f },
    { "rock", 1.8f, 1.9f, 0.6f }, { "grass", -0.6f, -1.9f, 1.0f }, { "grass", 3.0f, 3.2f, 1.0f }, { "grass", -3.0f, 0.2f, 1.0f },
    { "mushroom", -1.2f, 3.1f, 0.8f }, { "mushroom", 2.6f, -2.9f, 0.7f }, { "crystal", 0.0f, 0.0f, 1.0f }, { "sign", -2.0f, -0.6f, 1.0f } };

//----------------------------------------------------------------------------------
// Module Functions Declaration
//----------------------------------------------------------------------------------
static void GameInit(void);                             // Sheets, atlases, materials, models, shadow map
static void GameUpdate(float dt, Vector2 input);        // Robot, animation, lights, camera (input: -1..1 x, z)
static void GameDrawShadows(void);                      // Moon shadow pass, then RblSetScene (before BeginDrawing)
static void GameDrawWorld(void);                        // Paving, crates, sprites, wisps (inside BeginMode3D)
static void GameDrawSmoke(void);                        // Lit smoke, sorted back to front (inside BeginMode3D, last)
static void GameUnload(void);

//------------------------------------------------------------------------------------
// Program main entry point
//------------------------------------------------------------------------------------
#if !defined(RBL_GAME_NO_MAIN)
int main(void)
{
    // Initialization
    //--------------------------------------------------------------------------------------
    const int screenWidth = 800;
    const int screenHeight = 450;

    InitWindow(screenWidth, screenHeight, "raylib [shaders] example - lit sprite game");
    GameInit();
    SetTargetFPS(60);
    //--------------------------------------------------------------------------------------

    // Main game loop
    while (!WindowShouldClose())        // Detect window close button or ESC key
    {
        // Update
        //----------------------------------------------------------------------------------
        Vector2 input = { (float)((IsKeyDown(KEY_RIGHT) || IsKeyDown(KEY_D)) - (IsKeyDown(KEY_LEFT) || IsKeyDown(KEY_A))),
                          (float)((IsKeyDown(KEY_DOWN) || IsKeyDown(KEY_S)) - (IsKeyDown(KEY_UP) || IsKeyDown(KEY_W))) };
        GameUpdate(GetFrameTime(), input);
        GameDrawShadows();              // Binds its own framebuffer: before BeginDrawing()
        //----------------------------------------------------------------------------------

        // Draw
        //----------------------------------------------------------------------------------
        BeginDrawing();
            ClearBackground(night);
            BeginMode3D(camera);
                GameDrawWorld();
                GameDrawSmoke();
            EndMode3D();
            DrawText("Arrow keys / WASD: walk the robot", 10, 10, 20, RAYWHITE);
        EndDrawing();
        //----------------------------------------------------------------------------------
    }

    // De-Initialization
    //--------------------------------------------------------------------------------------
    GameUnload();
    CloseWindow();        // Close window and OpenGL context
    //--------------------------------------------------------------------------------------

    return 0;
}
#endif

//------------------------------------------------------------------------------------
// Module Functions Definition
//------------------------------------------------------------------------------------
// A sheet as a lit sprite material: its albedo and a normal map made from its luminance, packed
// (frame edges dilated, mips that keep the cut-out's coverage) for a program of exactly those maps
static Material LoadSheetMaterial(const RblAtlas *atlas, float bumpiness, RblLitShaderDesc desc)
{
    Image sheet = LoadImage(atlas->pages[0].image);     // Beside the atlas file (RblLoadAtlas joins the folder)
    Image height = RblGenHeightFromLuminance(sheet);
    Rectangle frames[16];                               // Dilated into the gutters around each frame
    const int count = (atlas->frameCount < 16)? atlas->frameCount : 16;
    for (int i = 0; i < count; i++) frames[i] = atlas->frames[i].block;
    RblMaterialSource source = RBL_ZERO;
    source.albedo = sheet;
    source.normal = RblGenNormalMapFromHeight(height, bumpiness, false);
    source.frames = frames; source.frameCount = count;
    source.mipmaps = true; source.alphaCoverage = 0.5f;
    RblPackedMaterial packed = RBL_ZERO;
    RblPackMaterial(&source, &packed);
    desc.material = packed.layout;
    Material material = LoadMaterialDefault();
    material.shader = RblLoadLitShader(desc);
    RblLoadPackedTextures(&packed, &material);
    RblUnloadPackedMaterial(&packed);
    UnloadImage(sheet); UnloadImage(height); UnloadImage(source.normal);
    return material;
}

// A Model of the mesh with a lit program, a texture and its normal map (from luminance, wrapped
// at the edges); the mesh gets its tangents
static Model LoadTexturedModel(Mesh mesh, Shader shader, const char *fileName, Color grout, Texture2D textures[2])
{
    Image image = LoadImage(fileName);
    ImageFormat(&image, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
    ImageAlphaPremultiply(&image);                      // Soft edges darken toward the grout
    ImageAlphaClear(&image, grout, 0.0f);               // Transparent corners become grout
    ImageFormat(&image, PIXELFORMAT_UNCOMPRESSED_R8G8B8);
    Image height = RblGenHeightFromLuminance(image);
    Image normal = RblGenNormalMapFromHeight(height, 4.0f, true);
    textures[0] = LoadTextureFromImage(image); textures[1] = LoadTextureFromImage(normal);
    for (int i = 0; i < 2; i++) { GenTextureMipmaps(&textures[i]); SetTextureFilter(textures[i], TEXTURE_FILTER_TRILINEAR); }
    UnloadImage(image); UnloadImage(height); UnloadImage(normal);
    GenMeshTangents(&mesh);
    Model model = LoadModelFromMesh(mesh);
    model.materials[0].shader = shader;
    model.materials[0].maps[MATERIAL_MAP_ALBEDO].texture = textures[0];
    model.materials[0].maps[MATERIAL_MAP_NORMAL].texture = textures[1];
    model.materials[0].maps[MATERIAL_MAP_NORMAL].value = 24.0f;         // Blinn-Phong shininess
    model.materials[0].params[RBL_PARAM_SPECULAR] = 0.25f;
    return model;
}

static void GameInit(void)
{
    camera.up = CLITERAL(Vector3){ 0.0f, 1.0f, 0.0f };
    camera.fovy = 45.0f;
    camera.projection = CAMERA_PERSPECTIVE;
    robotAtlas = RblLoadAtlas("resources/kenney_robot.json");   // Aseprite: frameTags, durations, a "feet" pivot slice
    propAtlas = RblLoadAtlas("resources/kenney_props.json");    // TexturePacker: trimmed frames with pivots
    walkTag = RblAtlasFindTag(&robotAtlas, "walk"); idleTag = RblAtlasFindTag(&robotAtlas, "idle");
    robotAnim = RblPlaySprite(&robotAtlas, walkTag, 0);
    GameUpdate(0.0f, CLITERAL(Vector2){ 0.0f, 0.0f });     // Lights and camera at t = 0, for the programs' features
    RblLitShaderDesc desc = RBL_ZERO;
    desc.maxLights = LIGHT_COUNT;
    desc.shading.lightFeatures = RblGetLightFeatures(lights, LIGHT_COUNT);
    desc.shading.brdf = RBL_BRDF_BLINN_PHONG;
    desc.shading.fog = RBL_FOG_EXP2; desc.shading.tonemap = RBL_TONEMAP_ACES;
    desc.shading.shadowMaps = 1;                    // The moon's
    robotMaterial = LoadSheetMaterial(&robotAtlas, 3.0f, desc);
    propMaterial = LoadSheetMaterial(&propAtlas, 3.0f, desc);
    robotMaterial.params[RBL_PARAM_SPECULAR] = 0.6f;             // A metal robot: shiny
    robotMaterial.maps[MATERIAL_MAP_NORMAL].value = 40.0f;

    // Paving and crates: raylib Models with an RGB normal map (tangents from GenMeshTangents)
    RblLitShaderDesc modelDesc = desc;
    modelDesc.material.normalEncoding = RBL_NORMAL_RGB;
    modelLit = RblLoadLitShader(modelDesc);
    Mesh paving = GenMeshPlane(24.0f, 24.0f, 1, 1);
    for (int i = 0; i < 2*paving.vertexCount; i++) paving.texcoords[i] *= 12.0f;     // One stone every 2 units
    UpdateMeshBuffer(paving, 1, paving.texcoords, 2*paving.vertexCount*(int)sizeof(float), 0);
    floorModel = LoadTexturedModel(paving, modelLit, "resources/kenney_ground.png", CLITERAL(Color){ 40, 42, 48, 255 }, floorTextures);
    crateModel = LoadTexturedModel(GenMeshCube(1.0f, 1.0f, 1.0f), modelLit, "resources/kenney_crate.png", CLITERAL(Color){ 90, 60, 36, 255 }, crateTextures);

    // Smoke: a soft round puff, never cut (low alpha is the point), lit and fogged like the rest
    Image puff = GenImageGradientRadial(64, 64, 0.0f, CLITERAL(Color){ 200, 200, 210, 150 }, CLITERAL(Color){ 200, 200, 210, 0 });
    puffTexture = LoadTextureFromImage(puff); UnloadImage(puff);
    smokeMaterial = LoadMaterialDefault();
    smokeMaterial.shader = RblLoadLitShader(desc);      // The sprites' features, albedo only
    smokeMaterial.maps[MATERIAL_MAP_ALBEDO].texture = puffTexture;
    smokeMaterial.params[RBL_PARAM_ALPHA_CUTOFF] = -1.0f;
    smokeMaterial.maps[MATERIAL_MAP_EMISSION].color = CLITERAL(Color){ 96, 96, 108, 255 };    // Faint: it shows against the night sky
    spriteBatch = RblLoadBatch(32);
    smokeBatch = RblLoadBatch(TORCH_COUNT*PUFFS_PER_TORCH);
    smokeBatch.sort = RBL_SORT_BACK_TO_FRONT;
    RblShadowDesc shadowDesc = RBL_ZERO;
    shadowDesc.size = 2048;                 // 2048 texels over the 17-unit yard
    moonShadow = RblLoadShadowMap(shadowDesc);
}

static void GameUpdate(float dt, Vector2 input)
{
    now += dt;
    // The robot: the keys walk it (screen directions); alone it wanders a slow loop round the crystal
    Vector2 step = input;
    if ((input.x == 0.0f) && (input.y == 0.0f))
    {
        wanderAngle += 0.35f*dt;
        step = CLITERAL(Vector2){ 2.4f*cosf(wanderAngle) - robot.x, 2.4f*sinf(wanderAngle) - robot.z };
    }
    const float length = sqrtf(step.x*step.x + step.y*step.y);
    const bool walking = (length > 1e-3f);
    if (walking)
    {
        const float speed = fminf(1.6f*dt, length);
        robot.x = fmaxf(-6.0f, fminf(6.0f, robot.x + speed*step.x/length));
        robot.z = fmaxf(-6.0f, fminf(6.0f, robot.z + speed*step.y/length));
        if (fabsf(step.x) > 0.05f*length) robotMirrored = (step.x < 0.0f);     // The sheet walks to the right
    }
    if (walking != robotWalking) robotAnim = RblPlaySprite(&robotAtlas, walking? walkTag : idleTag, 0);
    robotWalking = walking;
    RblUpdateSprite(&robotAnim, &robotAtlas, dt);
    // Lights: flickering torches on their crates, two wisps drifting about, the moon
    for (int i = 0; i < TORCH_COUNT + WISP_COUNT; i++)
    {
        const bool torch = (i < TORCH_COUNT);
        const float flicker = 0.8f + 0.12f*sinf(13.0f*now + 2.0f*i) + 0.08f*sinf(31.0f*now + 5.0f*i), a = 0.5f*now*((i%2)? -1.0f : 1.0f) + 3.0f*i;
        lights[i].position = torch? CLITERAL(Vector3){ crates[i][0] + 0.04f*sinf(9.0f*now + i), 1.75f, crates[i][1] + 0.04f*cosf(7.0f*now + i) }
                                  : CLITERAL(Vector3){ 4.2f*cosf(a) + 0.8f*sinf(2.3f*a), 0.9f + 0.35f*sinf(1.7f*now + i), 3.6f*sinf(a) };
        lights[i].color = torch? CLITERAL(Color){ 255, 150, 60, 255 } : (i%2)? CLITERAL(Color){ 90, 170, 255, 255 } : CLITERAL(Color){ 120, 255, 170, 255 };
        lights[i].intensity = torch? 5.0f*flicker : 3.0f;
        lights[i].range = torch? 6.0f : 4.5f;
    }
    lights[MOON].type = RBL_LIGHT_DIRECTIONAL;
    lights[MOON].direction = CLITERAL(Vector3){ -0.55f, -0.6f, 0.55f };      // From behind: shadows fall toward the viewer
    lights[MOON].color = CLITERAL(Color){ 140, 160, 255, 255 };
    lights[MOON].intensity = 0.55f;
    scene.lights = lights;
    scene.lightCount = LIGHT_COUNT;
    scene.ambient = CLITERAL(Color){ 50, 56, 88, 255 };
    scene.ambientGround = CLITERAL(Color){ 24, 20, 22, 255 };
    scene.fog = CLITERAL(RblFog){ RBL_FOG_EXP2, night, 0.0f, 0.0f, 0.085f };
    scene.exposure = 1.35f;
    // The camera follows the robot from above and behind
    camera.target = CLITERAL(Vector3){ robot.x, 0.9f, robot.z };
    camera.position = CLITERAL(Vector3){ robot.x, 3.9f, robot.z + 7.0f };
}

// Every sprite of the frame through one batch (two materials: two runs). The AXIS sprites turn to
// the camera in the shadow pass too, so each shadow has the shape the viewer sees
static void DrawSprites(void)
{
    RblBeginBatch(&spriteBatch, camera);
    RblBillboard sprite = RBL_ZERO;
    sprite.facing = RBL_FACING_AXIS;
    RblAtlasBillboard(&robotAtlas, robotAnim.frame, 1.3f*SPRITE_SCALE, &sprite);    // Size and the feet pivot
    sprite.position = robot;
    if (robotMirrored) sprite.size.x = -sprite.size.x;
    RblBatchAdd(&spriteBatch, robotMaterial, &sprite);
    for (int i = 0; i < PROP_COUNT + TORCH_COUNT; i++)
    {
        const bool torch = (i >= PROP_COUNT);
        const int t = i - PROP_COUNT;
        const char *name = torch? ((fmodf(now*6.0f + 1.7f*t, 2.0f) < 1.0f)? "torch_0" : "torch_1") : props[i].frame;
        RblAtlasBillboard(&propAtlas, RblAtlasFindFrame(&propAtlas, name), SPRITE_SCALE*(torch? 0.8f : props[i].scale), &sprite);
        sprite.position = torch? CLITERAL(Vector3){ crates[t][0], 1.0f, crates[t][1] } : CLITERAL(Vector3){ props[i].x, 0.0f, props[i].z };
        RblBatchAdd(&spriteBatch, propMaterial, &sprite);
    }
    RblEndBatch(&spriteBatch);
}

static void GameDrawShadows(void)
{
    // A fixed sphere round the yard: the shadows never swim as the camera follows the robot
    scene.shadowMaps = NULL; scene.shadowMapCount = 0;
    if (RblIsShadowMapValid(moonShadow) && RblBeginShadowMap(&moonShadow, &scene, MOON, CLITERAL(Vector3){ 0.0f, 0.5f, 0.0f }, 8.5f))
    {
        for (int i = 0; i < CRATE_COUNT; i++) RblDrawModel(crateModel, CLITERAL(Vector3){ crates[i][0], crates[i][2] + 0.5f, crates[i][1] }, 1.0f, WHITE);
        DrawSprites();
        RblEndShadowMap(&moonShadow);
        scene.shadowMaps = &moonShadow;
        scene.shadowMapCount = 1;
    }
    RblSetScene(&scene);
}

static void GameDrawWorld(void)
{
    RblDrawModel(floorModel, CLITERAL(Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f, CLITERAL(Color){ 150, 150, 160, 255 });     // Darker stones
    for (int i = 0; i < CRATE_COUNT; i++) RblDrawModel(crateModel, CLITERAL(Vector3){ crates[i][0], crates[i][2] + 0.5f, crates[i][1] }, 1.0f, WHITE);
    DrawSprites();
    for (int i = 0; i < WISP_COUNT; i++) DrawSphereEx(lights[TORCH_COUNT + i].position, 0.09f, 8, 10, lights[TORCH_COUNT + i].color);
}

static void GameDrawSmoke(void)
{
    RblBeginBatch(&smokeBatch, camera);
    for (int t = 0; t < TORCH_COUNT; t++)
        for (int i = 0; i < PUFFS_PER_TORCH; i++)
        {
            const float life = fmodf(0.3f*now + (float)i/PUFFS_PER_TORCH + 0.37f*t, 1.0f);   // 0 at the flame, 1 gone
            RblBillboard puff = RBL_ZERO;
            puff.position = CLITERAL(Vector3){ crates[t][0] + 0.5f*life*sinf(2.1f*i + t) + 0.6f*life*life, 1.7f + 2.6f*life, crates[t][1] + 0.4f*life*cosf(1.3f*i) };
            puff.size.x = puff.size.y = 0.25f + 1.1f*life;
            puff.origin.x = puff.origin.y = 0.5f*puff.size.x;
            puff.rotation = 77.0f*i + 40.0f*life;
            puff.roundness = 1.0f;                      // Rounded normals: lit from the sides and behind too
            const float warm = fmaxf(0.0f, 1.0f - 4.0f*life), alpha = fminf(1.0f, 5.0f*life*(1.0f - life)*(1.0f - life));   // Orange over the flame
            puff.tint = CLITERAL(Color){ 255, (unsigned char)(255.0f - 90.0f*warm), (unsigned char)(255.0f - 150.0f*warm), (unsigned char)(255.0f*alpha) };
            RblBatchAdd(&smokeBatch, smokeMaterial, &puff);
        }
    RblEndBatch(&smokeBatch);
}

static void GameUnload(void)
{
    RblUnloadBatch(&spriteBatch); RblUnloadBatch(&smokeBatch);
    RblUnloadShadowMap(&moonShadow);
    RblUnloadAtlas(&robotAtlas); RblUnloadAtlas(&propAtlas);
    UnloadMaterial(robotMaterial);          // Their packed textures and lit programs
    UnloadMaterial(propMaterial);
    smokeMaterial.maps[MATERIAL_MAP_ALBEDO].texture.id = 0;
    UnloadMaterial(smokeMaterial);
    UnloadModel(floorModel);                // Meshes and material maps; not the shader or the textures
    UnloadModel(crateModel);
    for (int i = 0; i < 2; i++) { UnloadTexture(floorTextures[i]); UnloadTexture(crateTextures[i]); }
    UnloadTexture(puffTexture);
    RblUnloadLitShader(&modelLit);
    RblClose();
}
