/*******************************************************************************************
*
*   raylib [shaders] example - deferred billboards
*
*   Example complexity rating: [★★★☆] 3/4
*
*   NOTE: This example requires raylib OpenGL 3.3 and rbillboard_lit.h (single header, beside this file)
*
*   Example originally created with raylib 6.0, last time updated with raylib 6.0
*
*   Example shows the deferred helper of rbillboard_lit.h: a Model floor, sphere Models and 48
*   instanced billboard "lanterns" (rounded normals) go through one G-buffer (10 bytes per pixel
*   + depth); 400 moving point lights are drawn as light volumes (each costs only the pixels it
*   touches) and a moonlight full screen; glow sprites are drawn forward after the resolve.
*   D cycles the debug views, SPACE pauses the lights.
*   Without MRT / float targets the scene is drawn forward with 63 point lights and the moon.
*
*   Example licensed under an unmodified zlib/libpng license, which is an OSI-certified,
*   BSD-like license that allows static linking with closed source software
*
*   Copyright (c) 2026 rbillboard_lit contributors
*
********************************************************************************************/

#include "raylib.h"
#include "rlgl.h"           // rlDisableDepthMask: glow sprites test depth but do not write it

#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"

#include <math.h>           // sinf, cosf

//----------------------------------------------------------------------------------
// Defines and Macros
//----------------------------------------------------------------------------------
#define DEFERRED_LIGHTS     400         // Moving point lights (light volumes)
#define LANTERN_ROWS        6           // Billboard lanterns on a grid
#define LANTERN_COLUMNS     8
#define SPHERE_COUNT        5

//----------------------------------------------------------------------------------
// Global Variables Definition
//----------------------------------------------------------------------------------
static Camera3D deferredCamera;
static const Color deferredBackground = { 10, 12, 20, 255 };
static const Color deferredAmbient = { 14, 16, 26, 255 };

static RblGBuffer gbuffer;
static bool deferredValid = false;
static RblScene deferredScene;          // Lights, ambient and fog of every frame
static Shader sceneShader;              // Floor and spheres: G-buffer variant (desc.deferred), or forward without one
static Shader lanternShader;            // Lanterns: the same variant, instanced
static Model floorModel;
static Model sphereModel;
static Texture2D floorTexture;
static Texture2D lanternTexture;
static Texture2D glowTexture;
static Material lanternMaterial;
static RblInstanceBuffer lanternBuffer;
static RblInstance lanterns[LANTERN_ROWS*LANTERN_COLUMNS];
static RblLight deferredLights[DEFERRED_LIGHTS + 1];   // + moonlight
static float lightPhase[DEFERRED_LIGHTS];

//----------------------------------------------------------------------------------
// Module Functions Declaration
//----------------------------------------------------------------------------------
static void DeferredInit(int width, int height);   // Textures, Models, shaders, G-buffer, lights
static void DeferredUpdate(float time);            // Move the lights (a function of time only)
static void DeferredPasses(void);                  // G-buffer and lights (outside BeginTextureMode)
static void DeferredCompose(void);                 // Resolve (or the forward fallback) and glows into the current target
static void DeferredUnload(void);

//------------------------------------------------------------------------------------
// Program main entry point
//------------------------------------------------------------------------------------
#if !defined(RBL_DEFERRED_NO_MAIN)
int main(void)
{
    // Initialization
    //--------------------------------------------------------------------------------------
    const int screenWidth = 800;
    const int screenHeight = 450;

    InitWindow(screenWidth, screenHeight, "raylib [shaders] example - deferred billboards");

    DeferredInit(GetRenderWidth(), GetRenderHeight());

    const char *viewNames[RBL_GBUFFER_OUTPUT_COUNT] = { "lit", "albedo", "normal", "roughness", "occlusion", "depth", "position", "lights per pixel" };
    bool paused = false;
    float time = 0.0f;

    SetTargetFPS(60);               // Set our game to run at 60 frames-per-second
    //--------------------------------------------------------------------------------------

    // Main game loop
    while (!WindowShouldClose())    // Detect window close button or ESC key
    {
        // Update
        //----------------------------------------------------------------------------------
        UpdateCamera(&deferredCamera, CAMERA_ORBITAL);
        if (IsKeyPressed(KEY_SPACE)) paused = !paused;
        if (IsKeyPressed(KEY_D))
        {
            int view = (gbuffer.output + 1)%RBL_GBUFFER_OUTPUT_COUNT;
            RblSetGBufferOutput(&gbuffer, view, (view == RBL_GBUFFER_OUTPUT_LIGHT_COUNT)? 32.0f : 20.0f);
        }
        if (!paused) time += GetFrameTime();
        DeferredUpdate(time);
        //----------------------------------------------------------------------------------

        // Draw
        //----------------------------------------------------------------------------------
        DeferredPasses();               // Off-screen: geometry pass and lights

        BeginDrawing();
            DeferredCompose();          // Resolve into the screen, then forward glows

            DrawText(TextFormat("%s: %i lights, view: %s (D)", deferredValid? "deferred" : "forward fallback", DEFERRED_LIGHTS + 1,
                                viewNames[gbuffer.output]), 10, 40, 20, RAYWHITE);
            DrawFPS(10, 10);
        EndDrawing();
        //----------------------------------------------------------------------------------
    }

    // De-Initialization
    //--------------------------------------------------------------------------------------
    DeferredUnload();
    CloseWindow();                  // Close window and OpenGL context
    //--------------------------------------------------------------------------------------

    return 0;
}
#endif

//----------------------------------------------------------------------------------
// Module Functions Definition
//----------------------------------------------------------------------------------
static void DeferredInit(int width, int height)
{
    deferredCamera.position = CLITERAL(Vector3){ 9.0f, 6.0f, 9.0f };
    deferredCamera.target = CLITERAL(Vector3){ 0.0f, 0.5f, 0.0f };
    deferredCamera.up = CLITERAL(Vector3){ 0.0f, 1.0f, 0.0f };
    deferredCamera.fovy = 45.0f;
    deferredCamera.projection = CAMERA_PERSPECTIVE;

    // Lights first: the shading desc compiles the light types they use
    for (int i = 0; i < DEFERRED_LIGHTS; i++)
    {
        float hue = 360.0f*(float)i/DEFERRED_LIGHTS;
        deferredLights[i].color = ColorFromHSV(hue, 0.75f, 1.0f);
        deferredLights[i].intensity = 0.35f + 0.25f*(float)(i%3);
        deferredLights[i].range = 1.2f + 0.4f*(float)(i%4);
        lightPhase[i] = 0.731f*(float)i;
    }
    RblLight *moon = &deferredLights[DEFERRED_LIGHTS];
    moon->type = RBL_LIGHT_DIRECTIONAL;
    moon->direction = CLITERAL(Vector3){ -0.4f, -1.0f, -0.3f };
    moon->color = CLITERAL(Color){ 120, 140, 255, 255 };
    moon->intensity = 0.15f;
    DeferredUpdate(0.0f);

    // The scene: lights, ambient and a little fog (its parameters; the programs compile its mode)
    deferredScene.lights = deferredLights;
    deferredScene.lightCount = DEFERRED_LIGHTS + 1;
    deferredScene.ambient = deferredAmbient;
    deferredScene.fog = CLITERAL(RblFog){ RBL_FOG_EXP2, deferredBackground, 0.0f, 0.0f, 0.03f };

    // One shading description for the lighting passes: GGX, ACES, exp2 fog
    RblGBufferDesc gdesc = RBL_ZERO;
    gdesc.width = width;
    gdesc.height = height;
    gdesc.shading.brdf = RBL_BRDF_GGX;
    gdesc.shading.lightFeatures = RblGetLightFeatures(deferredLights, DEFERRED_LIGHTS + 1);
    gdesc.shading.tonemap = RBL_TONEMAP_ACES;
    gdesc.shading.fog = RBL_FOG_EXP2;
    gbuffer = RblLoadGBuffer(gdesc);
    deferredValid = RblIsGBufferValid(gbuffer);

    // Programs: geometry-pass variants lit as the G-buffer lights, or forward ones when there is none
    RblLitShaderDesc desc = RBL_ZERO;
    desc.shading = gdesc.shading;
    if (deferredValid) desc.deferred = true;
    else desc.maxLights = RBL_MAX_LIGHTS;
    sceneShader = RblLoadLitShader(desc);
    desc.instanced = true;
    lanternShader = RblLoadLitShader(desc);

    Image checker = GenImageChecked(256, 256, 32, 32, CLITERAL(Color){ 120, 120, 126, 255 }, CLITERAL(Color){ 90, 90, 98, 255 });
    floorTexture = LoadTextureFromImage(checker);
    UnloadImage(checker);
    GenTextureMipmaps(&floorTexture);
    SetTextureFilter(floorTexture, TEXTURE_FILTER_TRILINEAR);
    floorModel = LoadModelFromMesh(GenMeshPlane(24.0f, 24.0f, 1, 1));
    floorModel.materials[0].maps[MATERIAL_MAP_ALBEDO].texture = floorTexture;
    floorModel.materials[0].maps[MATERIAL_MAP_ROUGHNESS].value = 0.35f;   // Floor and spheres (GGX roughness)
    sphereModel = LoadModelFromMesh(GenMeshSphere(0.6f, 24, 24));

    // Lantern sprite: a rounded cut-out (alpha-tested in the G-buffer), lit as a ball by rounded normals
    Image lantern = GenImageColor(64, 64, BLANK);
    ImageDrawCircle(&lantern, 32, 32, 30, CLITERAL(Color){ 230, 210, 170, 255 });
    ImageDrawCircle(&lantern, 32, 32, 18, CLITERAL(Color){ 250, 240, 220, 255 });
    lanternTexture = LoadTextureFromImage(lantern);
    UnloadImage(lantern);
    lanternMaterial = LoadMaterialDefault();
    lanternMaterial.maps[MATERIAL_MAP_ALBEDO].texture = lanternTexture;
    lanternMaterial.maps[MATERIAL_MAP_ROUGHNESS].value = 0.6f;
    lanternMaterial.maps[MATERIAL_MAP_EMISSION].color = CLITERAL(Color){ 40, 24, 8, 255 };   // A faint glow of their own
    for (int i = 0; i < LANTERN_ROWS*LANTERN_COLUMNS; i++)
    {
        lanterns[i].position = CLITERAL(Vector3){ -7.0f + 2.0f*(float)(i%LANTERN_COLUMNS), 0.0f, -5.0f + 2.0f*(float)(i/LANTERN_COLUMNS) };
        lanterns[i].size = CLITERAL(Vector2){ 0.8f, 0.8f };
        lanterns[i].origin = CLITERAL(Vector2){ 0.4f, 0.0f };               // Stands on the floor
    }
    lanternBuffer = RblLoadInstanceBuffer(LANTERN_ROWS*LANTERN_COLUMNS);

    // Glow sprites, drawn forward and alpha-blended after the resolve (they sort against its depth)
    Image glow = GenImageGradientRadial(32, 32, 0.0f, CLITERAL(Color){ 255, 255, 255, 160 }, BLANK);
    glowTexture = LoadTextureFromImage(glow);
    UnloadImage(glow);
}

static void DeferredUpdate(float time)
{
    // Lights wander over the floor on Lissajous paths, low enough to graze it
    for (int i = 0; i < DEFERRED_LIGHTS; i++)
    {
        float p = lightPhase[i], speed = 0.15f + 0.05f*(float)(i%5);
        deferredLights[i].position = CLITERAL(Vector3){ 10.0f*sinf(speed*time*1.3f + p), 0.25f + 0.2f*(float)(i%3), 10.0f*cosf(speed*time + 1.7f*p) };
    }
}

// Models go through RblDrawModel (DrawModel's arguments): it uploads each material's lit values
static void DrawScene(Material floorMaterial, Material sphereMaterial, Material lanternMat)
{
    Shader keepShader = floorModel.materials[0].shader;  // raylib's default: UnloadModel leaves it alone
    floorModel.materials[0].shader = floorMaterial.shader;
    RblDrawModel(floorModel, CLITERAL(Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f, WHITE);
    floorModel.materials[0].shader = keepShader;
    Material keep = sphereModel.materials[0];
    sphereModel.materials[0] = sphereMaterial;
    for (int i = 0; i < SPHERE_COUNT; i++) RblDrawModel(sphereModel, CLITERAL(Vector3){ -6.0f + 3.0f*(float)i, 0.6f, 3.0f }, 1.0f, WHITE);
    sphereModel.materials[0] = keep;
    RblInstancedDesc desc = RBL_ZERO;
    desc.facing = RBL_FACING_AXIS;                      // Upright, turning toward the camera
    desc.roundness = 1.0f;                              // Lit like a ball
    RblDrawInstanced(&lanternBuffer, deferredCamera, lanternMat, desc, lanterns, LANTERN_ROWS*LANTERN_COLUMNS);
}

static void DeferredPasses(void)
{
    if (!deferredValid) return;
    Material floorMaterial = floorModel.materials[0], sphereMaterial = floorModel.materials[0], lanternMat = lanternMaterial;
    floorMaterial.shader = sceneShader;
    sphereMaterial.shader = sceneShader;
    lanternMat.shader = lanternShader;
    RblSetScene(&deferredScene);                // This frame's lights and ambient, before the passes read them
    // 1. Geometry pass: billboards and Models write the G-buffer (and add the ambient)
    RblBeginGBuffer(&gbuffer, deferredCamera);
        DrawScene(floorMaterial, sphereMaterial, lanternMat);
    RblEndGBuffer(&gbuffer);
    // 2. Lights: the scene's moon full screen, every point light as a volume
    RblDrawDeferredLights(&gbuffer);
}

static void DeferredCompose(void)
{
    ClearBackground(deferredBackground);
    if (deferredValid)
    {
        // 3. Resolve (fog, tonemap, depth) into the current target
        RblResolveGBuffer(&gbuffer);
    }
    else
    {
        // Forward fallback: the first 63 point lights and the moon
        RblLight some[RBL_MAX_LIGHTS];
        for (int i = 0; i < RBL_MAX_LIGHTS - 1; i++) some[i] = deferredLights[i];
        some[RBL_MAX_LIGHTS - 1] = deferredLights[DEFERRED_LIGHTS];
        RblScene scene = deferredScene;
        scene.lights = some;
        scene.lightCount = RBL_MAX_LIGHTS;
        RblSetScene(&scene);
        Material floorMaterial = floorModel.materials[0], sphereMaterial = floorModel.materials[0], lanternMat = lanternMaterial;
        floorMaterial.shader = sceneShader;
        sphereMaterial.shader = sceneShader;
        lanternMat.shader = lanternShader;
        BeginMode3D(deferredCamera);
            DrawScene(floorMaterial, sphereMaterial, lanternMat);
        EndMode3D();
    }

    // 4. Forward after the resolve: additive glow sprites at the lights, hidden behind deferred geometry
    BeginMode3D(deferredCamera);
        rlDisableDepthMask();
        BeginBlendMode(BLEND_ADDITIVE);
        for (int i = 0; i < DEFERRED_LIGHTS; i += 2)
            DrawBillboard(deferredCamera, glowTexture, deferredLights[i].position, 0.35f, deferredLights[i].color);
        EndBlendMode();
        rlEnableDepthMask();
    EndMode3D();
}

static void DeferredUnload(void)
{
    RblUnloadGBuffer(&gbuffer);
    RblUnloadLitShader(&sceneShader);
    RblUnloadLitShader(&lanternShader);
    RblUnloadInstanceBuffer(&lanternBuffer);
    RblClose();
    UnloadModel(floorModel);                        // Meshes and material maps; shaders and textures are unloaded here
    UnloadModel(sphereModel);
    UnloadTexture(floorTexture);
    UnloadTexture(lanternTexture);
    UnloadTexture(glowTexture);
    MemFree(lanternMaterial.maps);
}
