/*******************************************************************************************
*
*   raylib [models] example - lit billboards showcase
*
*   Example complexity rating: [★★★☆] 3/4
*
*   Example originally created with raylib 6.0, last time updated with raylib 6.0
*
*   Example shows rbillboard_lit.h: playing cards drawn as billboards that carry normals and
*   tangents, so a normal map embosses their symbols under moving coloured point lights, a
*   sweeping spot light and a bluish directional moonlight that casts the cards' shadows.
*   Everything is generated in code (no asset files):
*     - the card faces (white rounded cards, red hearts / black spades, corner indices) are
*       drawn with raylib Image functions into one atlas, each card in its own frame with a
*       gutter around it,
*     - a height map of the same cards (raised symbols, slightly raised frame) gives the normal
*       map (RblGenNormalMapFromHeight) and a subtle cavity occlusion (RblGenOcclusionFromHeight),
*     - RblPackMaterial packs albedo + normal + occlusion into two textures (albedo and one
*       RGBA8 material texture: hemi-octahedral normal, occlusion), dilates the gutters around
*       the card frames and builds the mip chains; RblLoadPackedTextures uploads them and the
*       card program is compiled for exactly that layout (packed.layout),
*     - the cards are glossy (Blinn-Phong), the floor is a GenMeshPlane() Model with a polished GGX
*       program (roughness 0.3). A lit program holds compiled features only (light types from
*       RblLightFeatures(), BRDF, maps, fog mode, tonemap, shadow maps received); the per-material
*       values (specular, shininess, roughness) are set on each raylib Material, and the lights,
*       the sky/ground hemispheric ambient, the exp2 fog toward the background colour, the
*       exposure and the shadow map live in one RblScene set once per frame (RblSetScene), which
*       reaches both programs at once. The floor Model is drawn with RblDrawModel(), which uploads
*       its Material's values and then calls raylib's DrawMesh.
*   The cards go through the batched path (RblBeginBatch/RblBatchAdd/RblEndBatch): five cards
*   stand upright turning around +Y toward the camera (RBL_FACING_AXIS) and one lies flat on
*   the floor (RBL_FACING_FIXED); all six share one material, so the batch draws them at once.
*   The moonlight casts the cards' shadows (it comes from behind the ring, so the shadows stretch
*   toward the viewer instead of hiding behind the cards): each frame, before BeginDrawing(), the
*   same card batch is drawn into a shadow map (between RblBeginShadowMap and RblEndShadowMap the
*   library swaps in a depth-only caster program that keeps the cards' alpha test, so the
*   transparent rounded corners stay cut out of the shadows), then the scene lists the map and
*   RblSetScene() hands it to the floor and card programs, compiled to receive one
*   (desc.shadowMaps = 1).
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

//----------------------------------------------------------------------------------
// Defines and Macros
//----------------------------------------------------------------------------------
#define CARD_COUNT              6           // Cards in the atlas (A to 6)
#define CARD_ATLAS_COLUMNS      3
#define CARD_W                  256         // Card size in the atlas, pixels
#define CARD_H                  360
#define CARD_GUTTER             8           // Empty pixels around each card (filled by RblPackMaterial)
#define CARD_SUPERSAMPLE        2           // Cards are drawn at 2x and scaled down (anti-aliasing)
#define CARD_EMBOSS_BEVEL       3           // Height map blurs (pixels): a narrow bevel on a wide,
#define CARD_EMBOSS_PILLOW      10          // pillow-like dome, so the symbols read as embossed
#define CARD_EMBOSS_STRENGTH    10.0f       // Surface z = strength*height (texels): heights 0..1 rise 10 texels
#define CARD_OCCLUSION_RADIUS   12          // Cavity window (texels): about the width of the emboss slopes
#define CARD_OCCLUSION_STRENGTH 2.0f        // Ambient darkening per unit of depth below the surroundings (~25% at most)

#define LIGHT_COUNT             4           // Moving coloured point lights
#define SCENE_LIGHTS            (LIGHT_COUNT + 2)   // + a spot light and a directional moonlight
#define SPOT_LIGHT              LIGHT_COUNT         // Index of the spot light in showcaseLights
#define MOON_LIGHT              (LIGHT_COUNT + 1)   // Index of the moonlight (the shadow caster)

#define SHADOW_MAP_SIZE         1024        // Moon shadow map texels per side: 6.4/1023 = 0.006 units a texel,
                                            // finer than a floor pixel at the camera's distance
#define SHADOW_FOCUS_RADIUS     3.2f        // Sphere the moon's shadow map covers: the ring of cards and the
                                            // floor their shadows fall on (cards 1.8 out, shadows ~1.4 long)

//----------------------------------------------------------------------------------
// Types and Structures Definition
//----------------------------------------------------------------------------------
typedef enum { SUIT_HEART = 0, SUIT_SPADE } Suit;

// A light circles the scene centre; everything is a function of time (reproducible frames)
typedef struct LightPath {
    Color color;
    float intensity;
    float radius;           // Orbit radius around the centre
    float height;           // Mean height above the floor
    float bob;              // Height variation
    float speed;            // Radians per second (negative: clockwise seen from above)
    float phase;            // Angle at time 0
} LightPath;

//----------------------------------------------------------------------------------
// Global Variables Definition
//----------------------------------------------------------------------------------
static Camera3D showcaseCamera = { 0 };
static const Color showcaseBackground = { 18, 20, 28, 255 };

static Shader cardLit = { 0 };              // Card program: Blinn-Phong, the packed layout (normal + occlusion)
static Shader floorLit = { 0 };             // Floor program: GGX, albedo only
static RblBatch showcaseBatch = { 0 };
static Material cardMaterial = { 0 };       // Packed card atlas (albedo + material texture), cardLit, card stock values
static Model floorModel = { 0 };
static Texture2D floorAlbedo = { 0 };
static RblLight showcaseLights[SCENE_LIGHTS] = { 0 };
static RblScene showcaseScene = { 0 };      // The frame's lights, ambient, fog, exposure and shadow map
static RblShadowMap moonShadow = { 0 };     // Depth map of the moonlight (cast by the cards)

static const LightPath lightPaths[LIGHT_COUNT] = {
    { { 255, 164,  72, 255 }, 3.2f, 3.0f, 1.0f, 0.30f,  0.55f, 0.2f },    // Warm orange, outer orbit
    { {  72, 140, 255, 255 }, 3.6f, 3.0f, 1.4f, 0.35f,  0.55f, 3.3f },    // Blue, outer orbit, opposite
    { { 255,  64, 176, 255 }, 1.6f, 0.8f, 1.0f, 0.25f, -0.90f, 2.0f },    // Magenta, inside the ring of cards
    { {  96, 255, 136, 255 }, 2.4f, 2.8f, 0.5f, 0.15f, -0.40f, 2.76f },   // Green, low, grazing the floor
};

// 5x7 bitmap glyphs for the card ranks (drawn without a font, so headless renders work too)
static const char *rankGlyphs[CARD_COUNT][7] = {
    { " ### ", "#   #", "#   #", "#####", "#   #", "#   #", "#   #" },    // A
    { " ### ", "#   #", "    #", "   # ", "  #  ", " #   ", "#####" },    // 2
    { "#####", "   # ", "  #  ", "   # ", "    #", "#   #", " ### " },    // 3
    { "   # ", "  ## ", " # # ", "#  # ", "#####", "   # ", "   # " },    // 4
    { "#####", "#    ", "#### ", "    #", "    #", "#   #", " ### " },    // 5
    { "  ## ", " #   ", "#    ", "#### ", "#   #", "#   #", " ### " },    // 6
};

//----------------------------------------------------------------------------------
// Module Functions Declaration
//----------------------------------------------------------------------------------
static void ShowcaseInit(void);             // Generate textures, load shader, batch and floor
static void ShowcaseUpdate(float time);     // Move the lights and fill the scene (a function of time only)
static void ShowcaseDrawShadows(void);      // Render the shadow map, then set the scene (outside BeginDrawing/BeginTextureMode)
static void ShowcaseDraw(void);             // Draw the 3D scene (inside BeginMode3D)
static void DrawCards(void);                // The card batch (colour pass and shadow pass alike)
static void ShowcaseUnload(void);           // Unload everything ShowcaseInit() loaded

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

    InitWindow(screenWidth, screenHeight, "raylib [models] example - lit billboards showcase");

    ShowcaseInit();                 // Card atlas, packed maps, lit shaders, floor, camera

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
        // Shadow map first: a shadow pass binds its own framebuffer and restores the default
        // one, so it runs before BeginDrawing() (never inside BeginMode3D/BeginTextureMode);
        // it ends by setting the frame's scene (lights, ambient, fog, exposure, shadow map)
        ShowcaseDrawShadows();

        BeginDrawing();

            ClearBackground(showcaseBackground);

            BeginMode3D(showcaseCamera);
                ShowcaseDraw();
            EndMode3D();

            DrawText("Lit billboards: packed normal maps, sprite shadows (wheel: zoom)", 10, 40, 20, RAYWHITE);
            DrawFPS(10, 10);

        EndDrawing();
        //----------------------------------------------------------------------------------
    }

    // De-Initialization
    //--------------------------------------------------------------------------------------
    ShowcaseUnload();               // Unload textures, lit programs, shadow map, batch and floor; RblClose()

    CloseWindow();                  // Close window and OpenGL context
    //--------------------------------------------------------------------------------------

    return 0;
}
#endif

//----------------------------------------------------------------------------------
// Module Functions Definition: card generation
//----------------------------------------------------------------------------------
// Fill a suit symbol of width size centred at (cx, cy); flipped turns it 180 degrees
// (the lower pips of a playing card). A heart is two circles and the triangle between the
// tangents from its tip; a spade is an upside-down heart on a triangular stem.
static void DrawSuit(Image *image, Suit suit, float cx, float cy, float size, bool flipped, Color color)
{
    const float r = size/3.2f;          // Lobe radius
    const float d = 0.6f*r;             // Lobe centre offset from the axis
    const float tip = 2.2f*r;           // Tip distance below the lobe centres
    const float f = flipped? -1.0f : 1.0f;
    float lobeY = -0.6f*r;              // Heart: lobes up, tip down (local y grows downward)
    float dir = 1.0f;                   // +1: tip below the lobes, -1: tip above (spade)

    if (suit == SUIT_SPADE) { lobeY = 0.45f*r; dir = -1.0f; }

    // Outer tangent point on the right lobe as seen from the tip
    float dist = sqrtf(d*d + tip*tip);
    float angle = atan2f(tip, -d) - acosf(r/dist);
    float tx = d + r*cosf(angle), ty = r*sinf(angle);

    Vector2 lobeL = { cx - f*d, cy + f*lobeY };
    Vector2 lobeR = { cx + f*d, cy + f*lobeY };
    Vector2 tipP = { cx, cy + f*(lobeY + dir*tip) };
    Vector2 tanL = { cx - f*tx, cy + f*(lobeY + dir*ty) };
    Vector2 tanR = { cx + f*tx, cy + f*(lobeY + dir*ty) };

    ImageDrawCircleV(image, lobeL, (int)(r + 0.5f), color);
    ImageDrawCircleV(image, lobeR, (int)(r + 0.5f), color);
    ImageDrawTriangle(image, tanL, tanR, tipP, color);

    if (suit == SUIT_SPADE)
    {
        Vector2 top = { cx, cy + f*0.3f*r };
        Vector2 footL = { cx - f*0.6f*r, cy + f*1.85f*r };
        Vector2 footR = { cx + f*0.6f*r, cy + f*1.85f*r };
        ImageDrawTriangle(image, top, footL, footR, color);
    }
}

// Draw a 5x7 rank glyph with its top-left corner at (x, y); flipped turns it 180 degrees
static void DrawRank(Image *image, int rank, int x, int y, int cell, bool flipped, Color color)
{
    for (int row = 0; row < 7; row++)
    {
        for (int col = 0; col < 5; col++)
        {
            int gr = flipped? 6 - row : row, gc = flipped? 4 - col : col;
            if (rankGlyphs[rank][gr][gc] == '#') ImageDrawRectangle(image, x + col*cell, y + row*cell, cell, cell, color);
        }
    }
}

// Draw card `rank` (0 = ace) at (ox, oy) in image, at scale s (pixels per atlas pixel).
// The same call draws the albedo (colours) and the height map (grey levels): `bodyColor`,
// `frameColor` and `inkColor` are either colours or heights.
static void DrawCard(Image *image, int rank, int ox, int oy, int s, Color bodyColor, Color frameColor, Color inkColor)
{
    Suit suit = ((rank%2) == 0)? SUIT_SPADE : SUIT_HEART;    // A, 3, 5 spades; 2, 4, 6 hearts
    const int w = CARD_W*s, h = CARD_H*s, radius = 22*s;

    // Rounded white card: two overlapping rectangles and four corner circles
    ImageDrawRectangle(image, ox + radius, oy, w - 2*radius, h, bodyColor);
    ImageDrawRectangle(image, ox, oy + radius, w, h - 2*radius, bodyColor);
    ImageDrawCircle(image, ox + radius, oy + radius, radius, bodyColor);
    ImageDrawCircle(image, ox + w - radius - 1, oy + radius, radius, bodyColor);
    ImageDrawCircle(image, ox + radius, oy + h - radius - 1, radius, bodyColor);
    ImageDrawCircle(image, ox + w - radius - 1, oy + h - radius - 1, radius, bodyColor);

    // Frame around the pip area
    Rectangle frame = { (float)(ox + 44*s), (float)(oy + 40*s), (float)(w - 88*s), (float)(h - 80*s) };
    ImageDrawRectangleLines(image, frame, 3*s, frameColor);

    // Corner indices: rank and a small pip, top-left and (turned) bottom-right
    const int cell = 4*s;
    DrawRank(image, rank, ox + 12*s, oy + 12*s, cell, false, inkColor);
    DrawSuit(image, suit, (float)(ox + 22*s), (float)(oy + 60*s), 20.0f*s, false, inkColor);
    DrawRank(image, rank, ox + w - 12*s - 5*cell, oy + h - 12*s - 7*cell, cell, true, inkColor);
    DrawSuit(image, suit, (float)(ox + w - 22*s), (float)(oy + h - 60*s), 20.0f*s, true, inkColor);

    // Pips: columns 1/3, 1/2, 2/3 of the width, rows 1/4, 1/2, 3/4 of the height
    const float colX[3] = { 0.33f*w, 0.5f*w, 0.67f*w };
    const float rowY[3] = { 0.25f*h, 0.5f*h, 0.75f*h };
    const float pip = 46.0f*s;
    const int n = rank + 1;

    if (n == 1) DrawSuit(image, suit, ox + colX[1], oy + rowY[1], 120.0f*s, false, inkColor);
    if ((n == 2) || (n == 3))
    {
        DrawSuit(image, suit, ox + colX[1], oy + rowY[0], pip, false, inkColor);
        DrawSuit(image, suit, ox + colX[1], oy + rowY[2], pip, true, inkColor);
    }
    if (n >= 4)
    {
        DrawSuit(image, suit, ox + colX[0], oy + rowY[0], pip, false, inkColor);
        DrawSuit(image, suit, ox + colX[2], oy + rowY[0], pip, false, inkColor);
        DrawSuit(image, suit, ox + colX[0], oy + rowY[2], pip, true, inkColor);
        DrawSuit(image, suit, ox + colX[2], oy + rowY[2], pip, true, inkColor);
    }
    if ((n == 3) || (n == 5)) DrawSuit(image, suit, ox + colX[1], oy + rowY[1], pip, false, inkColor);
    if (n == 6)
    {
        DrawSuit(image, suit, ox + colX[0], oy + rowY[1], pip, false, inkColor);
        DrawSuit(image, suit, ox + colX[2], oy + rowY[1], pip, false, inkColor);
    }
}

// Atlas source rectangle (frame) of card `rank`: cells of CARD_W x CARD_H plus a gutter on every side
static Rectangle CardSource(int rank)
{
    Rectangle source = { (float)((rank%CARD_ATLAS_COLUMNS)*(CARD_W + 2*CARD_GUTTER) + CARD_GUTTER),
                         (float)((rank/CARD_ATLAS_COLUMNS)*(CARD_H + 2*CARD_GUTTER) + CARD_GUTTER), (float)CARD_W, (float)CARD_H };
    return source;
}

// Blur a float image in place: repeated box blurs (running sums) approach a gaussian; float
// precision keeps the slopes free of the 8-bit steps an Image blur would leave
static void BlurHeights(float *data, int w, int h, int radius)
{
    float *line = (float *)MemAlloc((unsigned int)((w > h)? w : h)*sizeof(float));
    for (int pass = 0; pass < 4; pass++)
    {
        for (int axis = 0; axis < 2; axis++)
        {
            int count = (axis == 0)? h : w, length = (axis == 0)? w : h;
            int step = (axis == 0)? 1 : w, stride = (axis == 0)? w : 1;
            for (int l = 0; l < count; l++)
            {
                float *p = data + l*stride;
                float sum = 0.0f;
                for (int k = -radius; k <= radius; k++) sum += p[((k < 0)? 0 : ((k >= length)? length - 1 : k))*step];
                for (int i = 0; i < length; i++)
                {
                    line[i] = sum/(float)(2*radius + 1);
                    int add = i + radius + 1, sub = i - radius;
                    sum += p[((add >= length)? length - 1 : add)*step] - p[((sub < 0)? 0 : sub)*step];
                }
                for (int i = 0; i < length; i++) p[i*step] = line[i];
            }
        }
    }
    MemFree(line);
}

// Emboss height map from a height mask (red channel, 0..255 = 0..1): the mask is blurred twice
// (a narrow bevel and a wide pillow) and the two are averaged. The result stays in float
// (PIXELFORMAT_UNCOMPRESSED_R32), which RblGenNormalMapFromHeight and RblGenOcclusionFromHeight
// read as stored, so the gentle slopes keep no 8-bit steps.
static Image GenEmbossHeights(Image mask)
{
    Color *maskColors = LoadImageColors(mask);
    const int w = mask.width, h = mask.height;
    float *heights = (float *)MemAlloc((unsigned int)(w*h)*sizeof(float));
    float *pillow = (float *)MemAlloc((unsigned int)(w*h)*sizeof(float));
    for (int i = 0; i < w*h; i++) heights[i] = pillow[i] = maskColors[i].r/255.0f;
    UnloadImageColors(maskColors);
    BlurHeights(heights, w, h, CARD_EMBOSS_BEVEL);
    BlurHeights(pillow, w, h, CARD_EMBOSS_PILLOW);
    for (int i = 0; i < w*h; i++) heights[i] = 0.5f*(heights[i] + pillow[i]);
    MemFree(pillow);

    Image emboss = { 0 };
    emboss.data = heights;                              // MemAlloc'ed: UnloadImage() frees it
    emboss.width = w;
    emboss.height = h;
    emboss.mipmaps = 1;
    emboss.format = PIXELFORMAT_UNCOMPRESSED_R32;
    return emboss;
}

//----------------------------------------------------------------------------------
// Module Functions Definition: scene
//----------------------------------------------------------------------------------
static void ShowcaseInit(void)
{
    // Camera: orbits the scene centre (CAMERA_ORBITAL in the window)
    showcaseCamera.position = (Vector3){ 0.0f, 3.0f, 5.0f };
    showcaseCamera.target = (Vector3){ 0.0f, 0.45f, 0.0f };
    showcaseCamera.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    showcaseCamera.fovy = 45.0f;
    showcaseCamera.projection = CAMERA_PERSPECTIVE;

    // Card atlas (albedo and height), drawn at CARD_SUPERSAMPLE x and scaled down
    const int s = CARD_SUPERSAMPLE;
    const int atlasW = CARD_ATLAS_COLUMNS*(CARD_W + 2*CARD_GUTTER);
    const int atlasH = ((CARD_COUNT + CARD_ATLAS_COLUMNS - 1)/CARD_ATLAS_COLUMNS)*(CARD_H + 2*CARD_GUTTER);
    const Color paper = { 250, 248, 240, 255 };
    Color clear = paper;
    clear.a = 0;                                        // Transparent corners keep the paper colour (no dark fringes)
    Image albedo = GenImageColor(atlasW*s, atlasH*s, clear);
    Image mask = GenImageColor(atlasW*s, atlasH*s, BLACK);
    Rectangle frames[CARD_COUNT] = { 0 };
    for (int rank = 0; rank < CARD_COUNT; rank++)
    {
        Rectangle frame = CardSource(rank);
        frames[rank] = frame;
        Color ink = ((rank%2) == 0)? (Color){ 44, 44, 56, 255 } : (Color){ 206, 24, 44, 255 };
        DrawCard(&albedo, rank, (int)frame.x*s, (int)frame.y*s, s, paper, (Color){ 214, 178, 96, 255 }, ink);
        DrawCard(&mask, rank, (int)frame.x*s, (int)frame.y*s, s, (Color){ 40, 40, 40, 255 }, (Color){ 110, 110, 110, 255 }, WHITE);
    }
    ImageResize(&albedo, atlasW, atlasH);
    ImageResize(&mask, atlasW, atlasH);

    // Maps from the height: normal (OpenGL convention, clamped at the atlas edges) and cavity occlusion
    Image height = GenEmbossHeights(mask);
    Image normal = RblGenNormalMapFromHeight(height, CARD_EMBOSS_STRENGTH, false);
    Image occlusion = RblGenOcclusionFromHeight(height, CARD_OCCLUSION_RADIUS, CARD_OCCLUSION_STRENGTH);
    UnloadImage(mask);
    UnloadImage(height);

    // Pack: albedo + one material texture (hemi-octahedral normal in RG, occlusion in A), the gutters
    // around the card frames dilated and mip chains built (normals renormalised per level)
    RblMaterialSource source = { 0 };
    source.albedo = albedo;
    source.normal = normal;
    source.occlusion = occlusion;
    source.frames = frames;
    source.frameCount = CARD_COUNT;
    source.mipmaps = true;
    RblPackedMaterial packed = { 0 };
    if (!RblPackMaterial(&source, &packed)) TraceLog(LOG_WARNING, "SHOWCASE: card maps could not be packed");
    UnloadImage(albedo);
    UnloadImage(normal);
    UnloadImage(occlusion);

    // Lights first: the programs compile exactly the light types the scene uses
    ShowcaseUpdate(0.0f);
    RblLitShaderDesc sceneDesc = { 0 };
    sceneDesc.maxLights = SCENE_LIGHTS;
    sceneDesc.lightFeatures = RblLightFeatures(showcaseLights, SCENE_LIGHTS);
    sceneDesc.fog = RBL_FOG_EXP2;               // The fog's colour and density are the scene's
    sceneDesc.tonemap = RBL_TONEMAP_ACES;
    sceneDesc.shadowMaps = 1;                   // Floor and cards receive the moon's shadow (default 2x2-texel PCF)

    // Card program: Blinn-Phong, sampling exactly the maps the packing produced
    RblLitShaderDesc cardDesc = sceneDesc;
    cardDesc.brdf = RBL_BRDF_BLINN_PHONG;
    cardDesc.material = packed.layout;
    cardLit = RblLoadLitShader(cardDesc);
    if (!RblIsLitShaderValid(cardLit)) TraceLog(LOG_WARNING, "SHOWCASE: card lit shader failed to compile");

    // Upload the packed Images (mip chains included) into the card material, then free the CPU copies
    cardMaterial = LoadMaterialDefault();
    cardMaterial.shader = cardLit;
    if ((packed.albedo.data != NULL) && !RblLoadPackedTextures(&packed, &cardMaterial)) TraceLog(LOG_WARNING, "SHOWCASE: card textures could not be uploaded");
    RblUnloadPackedMaterial(&packed);

    // Glossy card stock: the per-material values live on the Material
    cardMaterial.params[RBL_PARAM_SPECULAR] = 0.35f;            // Blinn-Phong specular intensity
    cardMaterial.maps[MATERIAL_MAP_NORMAL].value = 48.0f;       // Blinn-Phong shininess

    showcaseBatch = RblLoadBatch(16);

    // Floor: a plane with a grey checker albedo, drawn with a GGX program (albedo only: no normal
    // map, so no tangents and no flat normal texture are needed) and a polished material
    RblLitShaderDesc floorDesc = sceneDesc;
    floorDesc.brdf = RBL_BRDF_GGX;
    floorLit = RblLoadLitShader(floorDesc);
    if (!RblIsLitShaderValid(floorLit)) TraceLog(LOG_WARNING, "SHOWCASE: floor lit shader failed to compile");

    Mesh plane = GenMeshPlane(16.0f, 16.0f, 1, 1);
    floorModel = LoadModelFromMesh(plane);

    Image checker = GenImageChecked(512, 512, 32, 32, (Color){ 150, 150, 156, 255 }, (Color){ 112, 112, 120, 255 });
    floorAlbedo = LoadTextureFromImage(checker);
    GenTextureMipmaps(&floorAlbedo);
    SetTextureFilter(floorAlbedo, TEXTURE_FILTER_TRILINEAR);
    UnloadImage(checker);

    floorModel.materials[0].shader = floorLit;
    floorModel.materials[0].maps[MATERIAL_MAP_ALBEDO].texture = floorAlbedo;
    floorModel.materials[0].maps[MATERIAL_MAP_ROUGHNESS].value = 0.3f;     // GGX perceptual roughness (metalness 0)

    // Shadow map of the moonlight: a depth target (the caster programs are the library's). The default biases are in
    // texels, so they stay right at any map size; if it fails to load the scene renders unshadowed
    RblShadowDesc shadowDesc = { 0 };
    shadowDesc.size = SHADOW_MAP_SIZE;
    moonShadow = RblLoadShadowMap(shadowDesc);
    if (!RblIsShadowMapValid(moonShadow)) TraceLog(LOG_WARNING, "SHOWCASE: shadow map failed to load (no shadows)");

    ShowcaseUpdate(0.0f);
}

static void ShowcaseUpdate(float time)
{
    for (int i = 0; i < LIGHT_COUNT; i++)
    {
        const LightPath *path = &lightPaths[i];
        float angle = path->phase + path->speed*time;
        showcaseLights[i].position = (Vector3){ path->radius*cosf(angle),
                                                path->height + path->bob*sinf(2.3f*angle + path->phase),
                                                path->radius*sinf(angle) };
        showcaseLights[i].color = path->color;
        showcaseLights[i].intensity = path->intensity;
        showcaseLights[i].range = 8.0f;
    }

    // A warm spot light high above, sweeping slowly across the ring of cards
    RblLight *spot = &showcaseLights[SPOT_LIGHT];
    spot->type = RBL_LIGHT_SPOT;
    spot->position = (Vector3){ 0.0f, 5.0f, 1.0f };
    spot->direction = (Vector3){ 1.6f*cosf(0.35f*time), -5.0f, 1.6f*sinf(0.35f*time) - 1.0f };
    spot->innerAngle = 12.0f;
    spot->outerAngle = 22.0f;
    spot->color = (Color){ 255, 236, 200, 255 };
    spot->intensity = 14.0f;
    spot->range = 12.0f;

    // Bluish moonlight from the back left: bright enough that the cards' shadows read on the floor
    RblLight *moon = &showcaseLights[MOON_LIGHT];
    moon->type = RBL_LIGHT_DIRECTIONAL;
    moon->direction = (Vector3){ 0.5f, -0.8f, 0.6f };
    moon->color = (Color){ 150, 170, 255, 255 };
    moon->intensity = 0.8f;

    // The frame's scene, the same for both programs: the lights, a sky/ground hemispheric ambient,
    // exp2 fog toward the background and the exposure. ShowcaseDrawShadows() adds this frame's
    // shadow map and sets it (RblSetScene reads the map's matrices, so it runs after the pass)
    showcaseScene.lights = showcaseLights;
    showcaseScene.lightCount = SCENE_LIGHTS;
    showcaseScene.ambient = (Color){ 52, 58, 84, 255 };         // Sky
    showcaseScene.ambientGround = (Color){ 34, 28, 26, 255 };   // Ground
    showcaseScene.ambientUp = (Vector3){ 0.0f, 1.0f, 0.0f };
    showcaseScene.fog = (RblFog){ RBL_FOG_EXP2, showcaseBackground, 0.0f, 0.0f, 0.055f };
    showcaseScene.exposure = 1.4f;
    showcaseScene.shadowMaps = NULL;
    showcaseScene.shadowMapCount = 0;
}

static void ShowcaseDrawShadows(void)
{
    // The moon's map is orthographic over a sphere fixed around the scene, not one that follows the
    // camera (RblShadowFocusFromCamera): the scene is small and the camera orbits it, so every texel
    // stays on the cards and their shadows, and the shadows never shift as the camera moves
    const Vector3 focus = { 0.0f, 0.5f, 0.0f };
    if (RblIsShadowMapValid(moonShadow) && RblBeginShadowMap(&moonShadow, &showcaseScene, MOON_LIGHT, focus, SHADOW_FOCUS_RADIUS))
    {
        // The same batch and material as the colour pass: the library draws them with its caster
        // program. The floor is left out (nothing lies below it) and so are the unlit light spheres
        DrawCards();
        RblEndShadowMap(&moonShadow);

        // Receivers: both programs (compiled with shadowMaps = 1) sample the scene's map; the cards
        // receive too, so the flat card shows the shadows of the cards standing behind it
        showcaseScene.shadowMaps = &moonShadow;
        showcaseScene.shadowMapCount = 1;
    }

    // Once per frame, after the shadow pass: every live lit program gets the scene at once
    if (!RblSetScene(&showcaseScene)) TraceLog(LOG_WARNING, "SHOWCASE: scene rejected");
}

static void ShowcaseDraw(void)
{
    // Floor (a raylib Model lit by the same scene; RblDrawModel uploads its material's roughness)
    RblDrawModel(floorModel, (Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f, WHITE);

    DrawCards();

    // Lights, unlit
    for (int i = 0; i < LIGHT_COUNT; i++) DrawSphereEx(showcaseLights[i].position, 0.07f, 8, 12, showcaseLights[i].color);
}

static void DrawCards(void)
{
    // Cards: one batch, one material, two facing modes. The AXIS cards turn toward the camera in the
    // shadow pass too (the camera given to RblBeginBatch), so each shadow has the card's seen shape
    RblBeginBatch(&showcaseBatch, showcaseCamera);

    for (int i = 0; i < 5; i++)
    {
        // Five cards standing on a ring, turning around +Y toward the camera
        float angle = (126.0f + 72.0f*i)*DEG2RAD;
        RblBillboard card = { 0 };
        card.position = (Vector3){ 1.8f*cosf(angle), 0.0f, 1.8f*sinf(angle) };
        card.size = (Vector2){ 1.0f, 1.4f };
        card.origin = (Vector2){ 0.5f, 0.0f };          // Pivot at the bottom centre: stands on the floor
        card.source = CardSource(i);
        card.facing = RBL_FACING_AXIS;                  // Axis defaults to +Y
        RblBatchAdd(&showcaseBatch, cardMaterial, &card);
    }

    // The six of hearts lies on the floor in the middle of the ring
    RblBillboard flatCard = { 0 };
    flatCard.position = (Vector3){ 0.0f, 0.01f, 0.0f };
    flatCard.size = (Vector2){ 1.0f, 1.4f };
    flatCard.origin = (Vector2){ 0.5f, 0.7f };
    flatCard.source = CardSource(5);
    flatCard.facing = RBL_FACING_FIXED;
    flatCard.axis = (Vector3){ 0.0f, 1.0f, 0.0f };      // Faces up
    flatCard.up = (Vector3){ 0.34f, 0.0f, -0.94f };     // Top edge points away, turned a little
    RblBatchAdd(&showcaseBatch, cardMaterial, &flatCard);

    RblEndBatch(&showcaseBatch);
}

static void ShowcaseUnload(void)
{
    RblUnloadBatch(&showcaseBatch);

    UnloadModel(floorModel);                        // Mesh and material maps; not shaders or textures
    UnloadTexture(floorAlbedo);

    // Card textures uploaded by RblLoadPackedTextures() (albedo, material texture), as UnloadMaterial()
    // does but without its shader, which RblUnloadLitShader() releases below
    const int packedSlots[3] = { MATERIAL_MAP_ALBEDO, MATERIAL_MAP_NORMAL, MATERIAL_MAP_EMISSION };
    for (int i = 0; i < 3; i++)
    {
        Texture2D texture = cardMaterial.maps[packedSlots[i]].texture;
        if ((texture.id != 0) && (texture.id != rlGetTextureIdDefault())) UnloadTexture(texture);
    }
    MemFree(cardMaterial.maps);

    RblUnloadShadowMap(&moonShadow);                // Depth target

    RblUnloadLitShader(&cardLit);                   // Each releases its holder's reference and zeroes it
    RblUnloadLitShader(&floorLit);

    RblClose();                                     // After the Unload calls: the library's own programs and buffers
}
