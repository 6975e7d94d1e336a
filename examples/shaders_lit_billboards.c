/*******************************************************************************************
*
*   raylib [shaders] example - lit billboards
*
*   Example complexity rating: [★★★☆] 3/4
*
*   NOTE: This example requires raylib OpenGL 3.3 and rbillboard_lit.h (single header, beside this file)
*
*   Example originally created with raylib 6.0, last time updated with raylib 6.0
*
*   Example shows playing cards drawn as billboards that carry normals and tangents, so a normal
*   map embosses their pips under moving point lights, a sweeping spot light and a moonlight that
*   casts the cards' shadows (their cut-out corners included). Everything is generated in code:
*   card atlas -> height -> normal map and cavity occlusion -> packed into two textures.
*   Cards: one batch, two facing modes; floor: a raylib Model lit by the same scene.
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

#include <math.h>           // sinf, cosf, atan2f, acosf, sqrtf

#define CARD_COUNT      6           // Cards in the atlas (A to 6)
#define CARD_COLUMNS    3
#define CARD_W          256         // Card size in the atlas, pixels
#define CARD_H          360
#define CARD_GUTTER     8           // Empty pixels around each card (dilated by RblPackMaterial)
#define LIGHT_COUNT     4           // Moving coloured point lights
#define SCENE_LIGHTS    (LIGHT_COUNT + 2)   // + a spot light and the moonlight
#define MOON_LIGHT      (LIGHT_COUNT + 1)   // Index of the moonlight (the shadow caster)

//----------------------------------------------------------------------------------
// Global Variables Definition (statics start zeroed, in C and C++ alike)
//----------------------------------------------------------------------------------
static Camera3D showcaseCamera;
static const Color showcaseBackground = { 18, 20, 28, 255 };
static Shader floorLit;                     // GGX, albedo only (the cards' program goes with their Material)
static Material cardMaterial;
static Model floorModel;
static Texture2D floorAlbedo;
static RblBatch showcaseBatch;
static RblLight showcaseLights[SCENE_LIGHTS];
static RblScene showcaseScene;              // The frame's lights, ambient, fog, exposure and shadow map
static RblShadowMap moonShadow;

// Point lights circle the centre: colour, intensity, radius, height, bob, speed (rad/s), phase
static const float lightPaths[LIGHT_COUNT][6] = {
    { 3.2f, 3.0f, 1.0f, 0.30f,  0.55f, 0.2f }, { 3.6f, 3.0f, 1.4f, 0.35f,  0.55f, 3.3f },
    { 1.6f, 0.8f, 1.0f, 0.25f, -0.90f, 2.0f }, { 2.4f, 2.8f, 0.5f, 0.15f, -0.40f, 2.76f },
};
static const Color lightColors[LIGHT_COUNT] = {
    { 255, 164, 72, 255 }, { 72, 140, 255, 255 }, { 255, 64, 176, 255 }, { 96, 255, 136, 255 }
};

//----------------------------------------------------------------------------------
// Module Functions Declaration
//----------------------------------------------------------------------------------
static void ShowcaseInit(void);             // Generate the card maps, load programs, batch, floor, shadow map
static void ShowcaseUpdate(float time);     // Move the lights, fill the scene (a function of time only)
static void ShowcaseDrawShadows(void);      // Shadow pass, then RblSetScene (before BeginDrawing)
static void ShowcaseDraw(void);             // The 3D scene (inside BeginMode3D)
static void ShowcaseUnload(void);

//------------------------------------------------------------------------------------
// Program main entry point
//------------------------------------------------------------------------------------
#if !defined(RBL_SHOWCASE_NO_MAIN)
int main(void)
{
    // Initialization
    //--------------------------------------------------------------------------------------
    const int screenWidth = 800;
    const int screenHeight = 450;

    InitWindow(screenWidth, screenHeight, "raylib [shaders] example - lit billboards");

    ShowcaseInit();

    SetTargetFPS(60);               // Set our game to run at 60 frames-per-second
    //--------------------------------------------------------------------------------------

    // Main game loop
    while (!WindowShouldClose())    // Detect window close button or ESC key
    {
        // Update
        //----------------------------------------------------------------------------------
        UpdateCamera(&showcaseCamera, CAMERA_ORBITAL);
        ShowcaseUpdate((float)GetTime());
        //----------------------------------------------------------------------------------

        // Draw
        //----------------------------------------------------------------------------------
        ShowcaseDrawShadows();      // Binds its own framebuffer: before BeginDrawing()

        BeginDrawing();

            ClearBackground(showcaseBackground);

            BeginMode3D(showcaseCamera);
                ShowcaseDraw();
            EndMode3D();

            DrawText("Lit billboards: packed normal maps, sprite shadows", 10, 40, 20, RAYWHITE);
            DrawFPS(10, 10);

        EndDrawing();
        //----------------------------------------------------------------------------------
    }

    // De-Initialization
    //--------------------------------------------------------------------------------------
    ShowcaseUnload();

    CloseWindow();                  // Close window and OpenGL context
    //--------------------------------------------------------------------------------------

    return 0;
}
#endif

//----------------------------------------------------------------------------------
// Module Functions Definition
//----------------------------------------------------------------------------------
// Suit symbol of width size centred at (cx, cy), turned 180 degrees when flipped. A heart is two
// circles and the triangle between the tangents from its tip; a spade is a flipped heart on a stem
static void DrawSuit(Image *image, bool spade, float cx, float cy, float size, bool flipped, Color color)
{
    const float r = size/3.2f, d = 0.6f*r, tip = 2.2f*r, f = flipped? -1.0f : 1.0f;
    const float lobeY = spade? 0.45f*r : -0.6f*r, dir = spade? -1.0f : 1.0f;
    const float angle = atan2f(tip, -d) - acosf(r/sqrtf(d*d + tip*tip));
    const float tx = d + r*cosf(angle), ty = r*sinf(angle);

    ImageDrawCircleV(image, CLITERAL(Vector2){ cx - f*d, cy + f*lobeY }, (int)(r + 0.5f), color);
    ImageDrawCircleV(image, CLITERAL(Vector2){ cx + f*d, cy + f*lobeY }, (int)(r + 0.5f), color);
    ImageDrawTriangle(image, CLITERAL(Vector2){ cx - f*tx, cy + f*(lobeY + dir*ty) }, CLITERAL(Vector2){ cx + f*tx, cy + f*(lobeY + dir*ty) },
                      CLITERAL(Vector2){ cx, cy + f*(lobeY + dir*tip) }, color);
    if (spade) ImageDrawTriangle(image, CLITERAL(Vector2){ cx, cy + f*0.3f*r }, CLITERAL(Vector2){ cx - f*0.6f*r, cy + f*1.85f*r },
                                 CLITERAL(Vector2){ cx + f*0.6f*r, cy + f*1.85f*r }, color);
}

// Card `rank` (0 = ace) at (ox, oy), s image pixels per atlas pixel. The same call draws the
// albedo (colours) and the height mask (grey levels as heights)
static void DrawCard(Image *image, int rank, int ox, int oy, int s, Color body, Color frame, Color ink)
{
    const bool spade = ((rank%2) == 0);             // A, 3, 5 spades; 2, 4, 6 hearts
    const int w = CARD_W*s, h = CARD_H*s, rad = 22*s;

    ImageDrawRectangle(image, ox + rad, oy, w - 2*rad, h, body);    // Rounded card: two rectangles, four circles
    ImageDrawRectangle(image, ox, oy + rad, w, h - 2*rad, body);
    for (int c = 0; c < 4; c++) ImageDrawCircle(image, ox + ((c%2)? w - rad - 1 : rad), oy + ((c/2)? h - rad - 1 : rad), rad, body);
    ImageDrawRectangle(image, ox + 44*s, oy + 40*s, w - 88*s, h - 80*s, frame);     // Frame around the pips: a filled
    ImageDrawRectangle(image, ox + 47*s, oy + 43*s, w - 94*s, h - 86*s, body);      // rectangle, hollowed out
    DrawSuit(image, spade, (float)(ox + 22*s), (float)(oy + 30*s), 20.0f*s, false, ink);     // Corner pips
    DrawSuit(image, spade, (float)(ox + w - 22*s), (float)(oy + h - 30*s), 20.0f*s, true, ink);

    // Pips on a 3x3 grid (columns 1/3, 1/2, 2/3; rows 1/4, 1/2, 3/4); the lower row is turned
    const float colX[3] = { 0.33f*w, 0.5f*w, 0.67f*w }, rowY[3] = { 0.25f*h, 0.5f*h, 0.75f*h };
    const int n = rank + 1;
    const bool pip[3][3] = {            // [row][column] for n = 1..6
        { n >= 4, (n == 2) || (n == 3), n >= 4 }, { n == 6, (n == 3) || (n == 5), n == 6 }, { n >= 4, (n == 2) || (n == 3), n >= 4 } };
    if (n == 1) DrawSuit(image, spade, ox + colX[1], oy + rowY[1], 120.0f*s, false, ink);
    for (int row = 0; row < 3; row++)
        for (int col = 0; col < 3; col++)
            if (pip[row][col]) DrawSuit(image, spade, ox + colX[col], oy + rowY[row], 46.0f*s, row == 2, ink);
}

// Atlas frame of card `rank`: cells of CARD_W x CARD_H with a gutter on every side
static Rectangle CardSource(int rank)
{
    Rectangle source = { (float)((rank%CARD_COLUMNS)*(CARD_W + 2*CARD_GUTTER) + CARD_GUTTER),
                         (float)((rank/CARD_COLUMNS)*(CARD_H + 2*CARD_GUTTER) + CARD_GUTTER), (float)CARD_W, (float)CARD_H };
    return source;
}

static void ShowcaseInit(void)
{
    showcaseCamera.position = CLITERAL(Vector3){ 0.0f, 3.0f, 5.0f };
    showcaseCamera.target = CLITERAL(Vector3){ 0.0f, 0.45f, 0.0f };
    showcaseCamera.up = CLITERAL(Vector3){ 0.0f, 1.0f, 0.0f };
    showcaseCamera.fovy = 45.0f;
    showcaseCamera.projection = CAMERA_PERSPECTIVE;
    // Card atlas (albedo and height mask), drawn at 2x and scaled down (anti-aliasing)
    const int s = 2, atlasW = CARD_COLUMNS*(CARD_W + 2*CARD_GUTTER), atlasH = 2*(CARD_H + 2*CARD_GUTTER);
    const Color paper = { 250, 248, 240, 255 }, clear = { 250, 248, 240, 0 };  // Transparent corners keep the paper colour
    Image albedo = GenImageColor(atlasW*s, atlasH*s, clear);
    Image height = GenImageColor(atlasW*s, atlasH*s, BLACK);
    Rectangle frames[CARD_COUNT];
    for (int rank = 0; rank < CARD_COUNT; rank++)
    {
        frames[rank] = CardSource(rank);
        const int x = (int)frames[rank].x*s, y = (int)frames[rank].y*s;
        DrawCard(&albedo, rank, x, y, s, paper, CLITERAL(Color){ 214, 178, 96, 255 }, ((rank%2) == 0)? CLITERAL(Color){ 44, 44, 56, 255 } : CLITERAL(Color){ 206, 24, 44, 255 });
        DrawCard(&height, rank, x, y, s, CLITERAL(Color){ 40, 40, 40, 255 }, CLITERAL(Color){ 110, 110, 110, 255 }, WHITE);
    }
    ImageResize(&albedo, atlasW, atlasH);
    ImageResize(&height, atlasW, atlasH);
    ImageBlurGaussian(&height, 6);          // Soft slopes: the symbols read as embossed

    // Normal map (OpenGL convention, clamped at the edges) and cavity occlusion from the height,
    // packed with the albedo: the gutters dilated, mip chains built (normals renormalised per level)
    RblMaterialSource source = RBL_ZERO;
    source.albedo = albedo;
    source.normal = RblGenNormalMapFromHeight(height, 10.0f, false);
    source.occlusion = RblGenOcclusionFromHeight(height, 12, 2.0f);
    source.frames = frames;
    source.frameCount = CARD_COUNT;
    source.mipmaps = true;
    RblPackedMaterial packed = RBL_ZERO;
    if (!RblPackMaterial(&source, &packed)) TraceLog(LOG_WARNING, "SHOWCASE: card maps could not be packed");
    UnloadImage(albedo);                    // The packed copies live on in `packed`
    UnloadImage(height);
    UnloadImage(source.normal);
    UnloadImage(source.occlusion);

    // Programs compile features only (light types, BRDF, maps, fog, tonemap, shadow maps received);
    // the per-material values live on each raylib Material, the lights etc. in the frame's RblScene
    ShowcaseUpdate(0.0f);
    RblLitShaderDesc desc = RBL_ZERO;
    desc.maxLights = SCENE_LIGHTS;
    desc.shading.lightFeatures = RblGetLightFeatures(showcaseLights, SCENE_LIGHTS);
    desc.shading.fog = RBL_FOG_EXP2;
    desc.shading.tonemap = RBL_TONEMAP_ACES;
    desc.shading.shadowMaps = 1;                    // Floor and cards receive the moon's shadow
    desc.shading.brdf = RBL_BRDF_GGX;
    floorLit = RblLoadLitShader(desc);      // Floor: albedo only (no tangents needed)
    desc.shading.brdf = RBL_BRDF_BLINN_PHONG;
    desc.material = packed.layout;          // Cards: exactly the maps the packing produced
    cardMaterial = LoadMaterialDefault();
    cardMaterial.shader = RblLoadLitShader(desc);
    if (!RblIsLitShaderValid(cardMaterial.shader) || !RblIsLitShaderValid(floorLit)) TraceLog(LOG_WARNING, "SHOWCASE: lit shaders failed to compile");
    if ((packed.albedo.data != NULL) && !RblLoadPackedTextures(&packed, &cardMaterial)) TraceLog(LOG_WARNING, "SHOWCASE: card textures could not be uploaded");
    RblUnloadPackedMaterial(&packed);
    cardMaterial.params[RBL_PARAM_SPECULAR] = 0.35f;            // Glossy card stock (Blinn-Phong)
    cardMaterial.maps[MATERIAL_MAP_NORMAL].value = 48.0f;       // Shininess
    showcaseBatch = RblLoadBatch(16);

    floorModel = LoadModelFromMesh(GenMeshPlane(16.0f, 16.0f, 1, 1));
    Image checker = GenImageChecked(512, 512, 32, 32, CLITERAL(Color){ 150, 150, 156, 255 }, CLITERAL(Color){ 112, 112, 120, 255 });
    floorAlbedo = LoadTextureFromImage(checker);
    UnloadImage(checker);
    GenTextureMipmaps(&floorAlbedo);
    SetTextureFilter(floorAlbedo, TEXTURE_FILTER_TRILINEAR);
    floorModel.materials[0].shader = floorLit;
    floorModel.materials[0].maps[MATERIAL_MAP_ALBEDO].texture = floorAlbedo;
    floorModel.materials[0].maps[MATERIAL_MAP_ROUGHNESS].value = 0.3f;     // Polished (GGX roughness)

    // The moon's depth target: 1024 texels over a 6.4-unit sphere, finer than a floor pixel here
    RblShadowDesc shadowDesc = RBL_ZERO;
    shadowDesc.size = 1024;
    moonShadow = RblLoadShadowMap(shadowDesc);
    if (!RblIsShadowMapValid(moonShadow)) TraceLog(LOG_WARNING, "SHOWCASE: no shadow map (rendered unshadowed)");
}

static void ShowcaseUpdate(float time)
{
    for (int i = 0; i < LIGHT_COUNT; i++)
    {
        const float *p = lightPaths[i], angle = p[5] + p[4]*time;
        showcaseLights[i].position = CLITERAL(Vector3){ p[1]*cosf(angle), p[2] + p[3]*sinf(2.3f*angle + p[5]), p[1]*sinf(angle) };
        showcaseLights[i].color = lightColors[i];
        showcaseLights[i].intensity = p[0];
        showcaseLights[i].range = 8.0f;
    }

    RblLight *spot = &showcaseLights[LIGHT_COUNT];      // Warm spot high above, sweeping the ring of cards
    spot->type = RBL_LIGHT_SPOT;
    spot->position = CLITERAL(Vector3){ 0.0f, 5.0f, 1.0f };
    spot->direction = CLITERAL(Vector3){ 1.6f*cosf(0.35f*time), -5.0f, 1.6f*sinf(0.35f*time) - 1.0f };
    spot->innerAngle = 12.0f;
    spot->outerAngle = 22.0f;
    spot->color = CLITERAL(Color){ 255, 236, 200, 255 };
    spot->intensity = 14.0f;
    spot->range = 12.0f;

    RblLight *moon = &showcaseLights[MOON_LIGHT];       // From behind the ring: shadows stretch toward the viewer
    moon->type = RBL_LIGHT_DIRECTIONAL;
    moon->direction = CLITERAL(Vector3){ 0.5f, -0.8f, 0.6f };
    moon->color = CLITERAL(Color){ 150, 170, 255, 255 };
    moon->intensity = 0.8f;

    showcaseScene.lights = showcaseLights;
    showcaseScene.lightCount = SCENE_LIGHTS;
    showcaseScene.ambient = CLITERAL(Color){ 52, 58, 84, 255 };         // Sky
    showcaseScene.ambientGround = CLITERAL(Color){ 34, 28, 26, 255 };   // Ground (ambientUp zero: +Y)
    showcaseScene.fog = CLITERAL(RblFog){ RBL_FOG_EXP2, showcaseBackground, 0.0f, 0.0f, 0.055f };
    showcaseScene.exposure = 1.4f;
    showcaseScene.shadowMaps = NULL;                    // ShowcaseDrawShadows() adds this frame's map
    showcaseScene.shadowMapCount = 0;
}

// One batch, one material, two facing modes; the AXIS cards turn toward the camera in the shadow
// pass too, so each shadow has the card's seen shape
static void DrawCards(void)
{
    RblBeginBatch(&showcaseBatch, showcaseCamera);
    for (int i = 0; i < CARD_COUNT; i++)
    {
        const float angle = (126.0f + 72.0f*i)*DEG2RAD;
        RblBillboard card = RBL_ZERO;
        card.size = CLITERAL(Vector2){ 1.0f, 1.4f };
        card.source = CardSource(i);
        if (i < 5)                      // Five cards standing on a ring, turning around +Y
        {
            card.position = CLITERAL(Vector3){ 1.8f*cosf(angle), 0.0f, 1.8f*sinf(angle) };
            card.origin = CLITERAL(Vector2){ 0.5f, 0.0f };         // Pivot at the bottom centre
            card.facing = RBL_FACING_AXIS;
        }
        else                            // The six lies on the floor, facing up, turned a little
        {
            card.position = CLITERAL(Vector3){ 0.0f, 0.01f, 0.0f };
            card.origin = CLITERAL(Vector2){ 0.5f, 0.7f };
            card.facing = RBL_FACING_FIXED;
            card.axis = CLITERAL(Vector3){ 0.0f, 1.0f, 0.0f };
            card.up = CLITERAL(Vector3){ 0.34f, 0.0f, -0.94f };
        }
        RblBatchAdd(&showcaseBatch, cardMaterial, &card);
    }
    RblEndBatch(&showcaseBatch);
}

static void ShowcaseDrawShadows(void)
{
    // A fixed sphere around the small scene (not RblShadowFocusFromCamera): the orbiting camera
    // never makes the shadows shift. The floor casts nothing, so only the cards are drawn
    if (RblIsShadowMapValid(moonShadow) && RblBeginShadowMap(&moonShadow, &showcaseScene, MOON_LIGHT, CLITERAL(Vector3){ 0.0f, 0.5f, 0.0f }, 3.2f))
    {
        DrawCards();
        RblEndShadowMap(&moonShadow);
        showcaseScene.shadowMaps = &moonShadow;
        showcaseScene.shadowMapCount = 1;
    }
    if (!RblSetScene(&showcaseScene)) TraceLog(LOG_WARNING, "SHOWCASE: scene rejected");  // Every lit program at once
}

static void ShowcaseDraw(void)
{
    RblDrawModel(floorModel, CLITERAL(Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f, WHITE);      // Uploads its roughness, then DrawMesh
    DrawCards();
    for (int i = 0; i < LIGHT_COUNT; i++) DrawSphereEx(showcaseLights[i].position, 0.07f, 8, 12, showcaseLights[i].color);
}

static void ShowcaseUnload(void)
{
    RblUnloadBatch(&showcaseBatch);
    UnloadModel(floorModel);                        // Mesh and material maps; not shaders or textures
    UnloadTexture(floorAlbedo);
    UnloadMaterial(cardMaterial);                   // Its textures and its lit program (allowed for lit programs)
    RblUnloadShadowMap(&moonShadow);
    RblUnloadLitShader(&floorLit);                  // Releases this holder's reference and zeroes it
    RblClose();                                     // After the Unload calls: the library's own buffers
}
