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
        d.shading.lightFeatures = RblGetLightFeatures(lights, 3);
        d.shading.brdf = row? RBL_BRDF_GGX : RBL_BRDF_BLINN_PHONG;
        d.shading.tonemap = RBL_TONEMAP_ACES;
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
    d.shading.lightFeatures = RblGetLightFeatures(lights, 2);
    d.shading.brdf = RBL_BRDF_BLINN_PHONG;
    d.shading.tonemap = RBL_TONEMAP_ACES;
    d.shading.shadowMaps = 2;                                   // every receiver samples both maps
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

// A character sprite (opaque body, transparent around it) and its height for a normal map: limbs
// and head bulge, so the normal map bends the normal along arms, legs and outline
static Image characterImage(bool height)
{
    const int w = 64, h = 128;
    Image img = GenImageColor(w, h, height? BLACK : BLANK);
    Color skin = height? (Color){ 255, 255, 255, 255 } : (Color){ 236, 196, 160, 255 };
    Color shirt = height? (Color){ 230, 230, 230, 255 } : (Color){ 200, 70, 60, 255 };
    Color pants = height? (Color){ 210, 210, 210, 255 } : (Color){ 60, 80, 150, 255 };
    ImageDrawRectangle(&img, 22, 84, 8, 42, pants);                 // legs
    ImageDrawRectangle(&img, 34, 84, 8, 42, pants);
    ImageDrawRectangle(&img, 19, 40, 26, 46, shirt);               // body
    ImageDrawRectangle(&img, 10, 42, 8, 36, shirt);                // arms
    ImageDrawRectangle(&img, 46, 42, 8, 36, shirt);
    ImageDrawCircle(&img, 14, 80, 4, skin);                         // hands
    ImageDrawCircle(&img, 50, 80, 4, skin);
    ImageDrawCircle(&img, 32, 24, 14, skin);                        // head
    if (!height) { ImageDrawCircle(&img, 27, 22, 2, (Color){ 40, 30, 30, 255 }); ImageDrawCircle(&img, 37, 22, 2, (Color){ 40, 30, 30, 255 }); }
    return img;
}

// The user's 2.5D scene (issue #26): an AXIS-facing character sprite (pivot at its feet, normal map
// from its height, so limbs and outline bend the normal), a sun from +X at 37 degrees elevation and a
// crate beside it; the camera in front. Left: casters facing the light (the default); right: facing
// the camera. Neither darkens the sprite with its own caster (caster identities); the ground shadow
// is the light-facing card's (a full figure stretching away from the sun) or the camera-facing
// card's (edge-on to a side sun: tilted back to the minimum angle, a leaning parallelogram)
static bool spriteShadowsPicture(const char *dir)
{
    const int w = 640, h = 300, panel = w/2;
    Image ci = characterImage(false), hi = characterImage(true);
    ImageBlurGaussian(&hi, 3);
    Image ni = RblGenNormalMapFromHeight(hi, 6.0f, false);
    Image fi = GenImageChecked(256, 256, 32, 32, (Color){ 196, 190, 178, 255 }, (Color){ 172, 166, 154, 255 });
    Texture2D character = LoadTextureFromImage(ci), normals = LoadTextureFromImage(ni), floorTexture = LoadTextureFromImage(fi);
    UnloadImage(ci); UnloadImage(hi); UnloadImage(ni); UnloadImage(fi);
    GenTextureMipmaps(&floorTexture);
    SetTextureFilter(floorTexture, TEXTURE_FILTER_TRILINEAR);

    RblLight sun;
    memset(&sun, 0, sizeof(sun));
    const float e = 37.0f*DEG2RAD;
    sun.type = RBL_LIGHT_DIRECTIONAL; sun.direction = (Vector3){ -cosf(e), -sinf(e), 0.0f };
    sun.color = (Color){ 255, 236, 210, 255 }; sun.intensity = 1.0f;
    RblLitShaderDesc d;
    memset(&d, 0, sizeof(d));
    d.maxLights = 1; d.shading.lightFeatures = RblGetLightFeatures(&sun, 1); d.shading.shadowMaps = 1;
    Shader flat = RblLoadLitShader(d);
    d.material.normalEncoding = RBL_NORMAL_RGB;
    Shader bent = RblLoadLitShader(d);
    RblShadowDesc sd[2];
    memset(sd, 0, sizeof(sd));
    sd[0].size = sd[1].size = 2048;
    sd[1].faceCamera = true;
    RblShadowMap maps[2] = { RblLoadShadowMap(sd[0]), RblLoadShadowMap(sd[1]) };
    if (!RblIsLitShaderValid(flat) || !RblIsLitShaderValid(bent) || !RblIsShadowMapValid(maps[0]) || !RblIsShadowMapValid(maps[1])) { printf("pictures: sprite shadows unavailable\n"); return false; }
    Material sprite = LoadMaterialDefault();
    sprite.shader = bent;
    sprite.maps[MATERIAL_MAP_ALBEDO].texture = character;
    sprite.maps[MATERIAL_MAP_NORMAL].texture = normals;
    Model ground = LoadModelFromMesh(GenMeshPlane(12.0f, 12.0f, 1, 1));
    ground.materials[0].shader = flat;
    ground.materials[0].maps[MATERIAL_MAP_ALBEDO].texture = floorTexture;
    Model crate = LoadModelFromMesh(GenMeshCube(0.8f, 0.8f, 0.8f));
    crate.materials[0].shader = flat;
    crate.materials[0].maps[MATERIAL_MAP_ALBEDO].color = (Color){ 170, 120, 70, 255 };
    const Vector3 crateAt = { 1.05f, 0.4f, 0.1f };     // its shadow reaches the sprite's legs
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.size = (Vector2){ 1.0f, 2.0f }; b.origin = (Vector2){ 0.5f, 0.0f }; b.facing = RBL_FACING_AXIS;
    Camera3D cam;
    memset(&cam, 0, sizeof(cam));
    cam.position = (Vector3){ -0.4f, 2.4f, 5.4f }; cam.target = (Vector3){ -0.7f, 0.7f, 0.0f }; cam.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    cam.fovy = 46.0f; cam.projection = CAMERA_PERSPECTIVE;
    RenderTexture2D rt = LoadRenderTexture(panel, h), out = LoadRenderTexture(w, h);
    bool ok = true;
    BeginTextureMode(out);
    ClearBackground(BLACK);
    EndTextureMode();
    for (int k = 0; k < 2; k++)
    {
        RblScene scene;
        memset(&scene, 0, sizeof(scene));
        scene.lights = &sun; scene.lightCount = 1; scene.ambient = (Color){ 70, 76, 92, 255 };
        if (RblBeginShadowMap(&maps[k], &scene, 0, (Vector3){ -1.0f, 0.8f, 0.0f }, 3.5f))
        {
            RblDrawBillboard(cam, sprite, b);
            RblDrawModel(crate, crateAt, 1.0f, WHITE);
            RblDrawModel(ground, (Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f, WHITE);
            RblEndShadowMap(&maps[k]);
            scene.shadowMaps = &maps[k]; scene.shadowMapCount = 1;
        }
        ok = ok && RblSetScene(&scene);
        BeginTextureMode(rt);
        ClearBackground((Color){ 24, 26, 32, 255 });
        BeginMode3D(cam);
        RblDrawModel(ground, (Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f, WHITE);
        RblDrawModel(crate, crateAt, 1.0f, WHITE);
        RblDrawBillboard(cam, sprite, b);
        EndMode3D();
        DrawText(k? "casters face the camera (faceCamera)" : "casters face the light (default)", 8, 6, 10, RAYWHITE);
        EndTextureMode();
        BeginTextureMode(out);
        DrawTextureRec(rt.texture, (Rectangle){ 0.0f, 0.0f, (float)panel, (float)-h }, (Vector2){ (float)(k*panel), 0.0f }, WHITE);
        EndTextureMode();
    }
    BeginTextureMode(out);
    DrawText("AXIS sprite, sun from +X at 37 degrees, a crate: no self-shadow in either mode", 8, h - 16, 10, RAYWHITE);
    EndTextureMode();
    Image img = rtReadTarget(out);
    char path[512];
    snprintf(path, sizeof(path), "%s/rbl_sprite_shadows.png", dir);
    ok = ok && ExportImage(img, path);
    printf("pictures: %s %s\n", ok? "wrote" : "could not write", path);
    UnloadImage(img);
    RblScene none;
    memset(&none, 0, sizeof(none));
    RblSetScene(&none);
    UnloadRenderTexture(rt); UnloadRenderTexture(out);
    for (int k = 0; k < 2; k++) RblUnloadShadowMap(&maps[k]);
    MemFree(sprite.maps);
    UnloadModel(ground); UnloadModel(crate);
    RblUnloadLitShader(&flat); RblUnloadLitShader(&bent);
    UnloadTexture(character); UnloadTexture(normals); UnloadTexture(floorTexture);
    return ok;
}

// The self-shadowing sweep's contact sheet (tests/test_self_shadow.c): the character sprite (AXIS,
// default light-facing casters) under a directional light from azimuth 0 (the viewer's side) to 315
// in columns and elevation 5 to 85 in rows, with its ground shadow; no cell darkens the sprite itself
static bool sweepPicture(const char *dir)
{
    const int cols = 8, rows = 5, cw = 96, ch = 96, w = cols*cw, h = rows*ch + 20;
    Image ci = characterImage(false), hi = characterImage(true);
    ImageBlurGaussian(&hi, 3);
    Image ni = RblGenNormalMapFromHeight(hi, 6.0f, false);
    Texture2D character = LoadTextureFromImage(ci), normals = LoadTextureFromImage(ni), white = LoadTextureFromImage(hi);
    UnloadImage(ci); UnloadImage(hi); UnloadImage(ni);
    RblLight sun;
    memset(&sun, 0, sizeof(sun));
    sun.type = RBL_LIGHT_DIRECTIONAL; sun.color = (Color){ 255, 240, 220, 255 }; sun.intensity = 0.7f; sun.direction = (Vector3){ 0.0f, -1.0f, 0.0f };
    RblLitShaderDesc d;
    memset(&d, 0, sizeof(d));
    d.maxLights = 1; d.shading.lightFeatures = RblGetLightFeatures(&sun, 1); d.shading.shadowMaps = 1;
    Shader flat = RblLoadLitShader(d);
    d.material.normalEncoding = RBL_NORMAL_RGB;
    Shader bent = RblLoadLitShader(d);
    RblShadowDesc sd;
    memset(&sd, 0, sizeof(sd));
    sd.size = 1024;
    RblShadowMap map = RblLoadShadowMap(sd);
    if (!RblIsLitShaderValid(flat) || !RblIsLitShaderValid(bent) || !RblIsShadowMapValid(map)) { printf("pictures: sweep unavailable\n"); return false; }
    Material sprite = LoadMaterialDefault(), floorMat = LoadMaterialDefault();
    sprite.shader = bent;
    sprite.maps[MATERIAL_MAP_ALBEDO].texture = character;
    sprite.maps[MATERIAL_MAP_NORMAL].texture = normals;
    floorMat.shader = flat;
    floorMat.maps[MATERIAL_MAP_ALBEDO].color = (Color){ 200, 196, 186, 255 };
    RblBillboard b, fl;
    memset(&b, 0, sizeof(b));
    b.size = (Vector2){ 1.0f, 2.0f }; b.origin = (Vector2){ 0.5f, 0.0f }; b.facing = RBL_FACING_AXIS;
    memset(&fl, 0, sizeof(fl));
    fl.size = (Vector2){ 16.0f, 16.0f }; fl.origin = (Vector2){ 8.0f, 8.0f }; fl.facing = RBL_FACING_FIXED;
    fl.axis = (Vector3){ 0.0f, 1.0f, 0.0f }; fl.up = (Vector3){ 0.0f, 0.0f, -1.0f };
    Camera3D cam;
    memset(&cam, 0, sizeof(cam));
    cam.position = (Vector3){ 0.0f, 3.2f, 4.6f }; cam.target = (Vector3){ 0.0f, 0.5f, -0.6f }; cam.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    cam.fovy = 58.0f; cam.projection = CAMERA_PERSPECTIVE;
    RenderTexture2D cell = LoadRenderTexture(cw, ch), out = LoadRenderTexture(w, h);
    BeginTextureMode(out);
    ClearBackground(BLACK);
    EndTextureMode();
    bool ok = true;
    for (int r = 0; r < rows; r++)
        for (int c = 0; c < cols; c++)
        {
            double az = c*45.0*PI/180.0, el = (5.0 + 20.0*r)*PI/180.0;
            sun.direction = (Vector3){ (float)(-cos(el)*sin(az)), (float)-sin(el), (float)(-cos(el)*cos(az)) };
            RblScene scene;
            memset(&scene, 0, sizeof(scene));
            scene.lights = &sun; scene.lightCount = 1; scene.ambient = (Color){ 60, 64, 76, 255 };
            if (RblBeginShadowMap(&map, &scene, 0, (Vector3){ 0.0f, 1.0f, 0.0f }, 6.0f))
            {
                RblDrawBillboard(cam, floorMat, fl);
                RblDrawBillboard(cam, sprite, b);
                RblEndShadowMap(&map);
                scene.shadowMaps = &map; scene.shadowMapCount = 1;
            }
            ok = ok && RblSetScene(&scene);
            BeginTextureMode(cell);
            ClearBackground((Color){ 24, 26, 32, 255 });
            BeginMode3D(cam);
            RblDrawBillboard(cam, floorMat, fl);
            RblDrawBillboard(cam, sprite, b);
            EndMode3D();
            DrawText(TextFormat("%d/%d", c*45, 5 + 20*r), 3, 3, 10, RAYWHITE);
            EndTextureMode();
            BeginTextureMode(out);
            DrawTextureRec(cell.texture, (Rectangle){ 0.0f, 0.0f, (float)cw, (float)-ch }, (Vector2){ (float)(c*cw), (float)(r*ch) }, WHITE);
            EndTextureMode();
        }
    BeginTextureMode(out);
    DrawText("light azimuth/elevation (0 = from the viewer's side, 90 = from +X): AXIS sprite, light-facing casters", 4, h - 15, 10, RAYWHITE);
    EndTextureMode();
    Image img = rtReadTarget(out);
    char path[512];
    snprintf(path, sizeof(path), "%s/rbl_shadow_sweep.png", dir);
    ok = ok && ExportImage(img, path);
    printf("pictures: %s %s\n", ok? "wrote" : "could not write", path);
    UnloadImage(img);
    RblScene none;
    memset(&none, 0, sizeof(none));
    RblSetScene(&none);
    UnloadRenderTexture(cell); UnloadRenderTexture(out);
    RblUnloadShadowMap(&map);
    MemFree(sprite.maps); MemFree(floorMat.maps);
    RblUnloadLitShader(&flat); RblUnloadLitShader(&bent);
    UnloadTexture(character); UnloadTexture(normals); UnloadTexture(white);
    return ok;
}

// Point-light shadows (omni maps): a warm lamp and a blue lamp, each with an omni map (six cube
// faces of 512), over character sprites (AXIS, light-facing casters), a cut-out tree and crates on a
// floor; the shadows radiate from each lamp in every direction, across the cube faces' seams
static bool omniPicture(const char *dir)
{
    const int w = 640, h = 320;
    Image ci = characterImage(false), ti = treeImage();
    Image fi = GenImageChecked(256, 256, 32, 32, (Color){ 196, 190, 178, 255 }, (Color){ 172, 166, 154, 255 });
    Texture2D character = LoadTextureFromImage(ci), tree = LoadTextureFromImage(ti), floorTexture = LoadTextureFromImage(fi);
    UnloadImage(ci); UnloadImage(ti); UnloadImage(fi);
    GenTextureMipmaps(&floorTexture);
    SetTextureFilter(floorTexture, TEXTURE_FILTER_TRILINEAR);
    RblLight lamps[2];
    memset(lamps, 0, sizeof(lamps));
    lamps[0].type = lamps[1].type = RBL_LIGHT_POINT;
    lamps[0].position = (Vector3){ -1.2f, 1.6f, 0.2f }; lamps[0].color = (Color){ 255, 190, 120, 255 }; lamps[0].intensity = 5.0f; lamps[0].range = 12.0f;
    lamps[1].position = (Vector3){ 2.0f, 1.1f, -0.8f }; lamps[1].color = (Color){ 120, 170, 255, 255 }; lamps[1].intensity = 3.0f; lamps[1].range = 12.0f;
    RblLitShaderDesc d;
    memset(&d, 0, sizeof(d));
    d.maxLights = 2; d.shading.lightFeatures = RblGetLightFeatures(lamps, 2); d.shading.shadowMaps = 2;
    Shader lit = RblLoadLitShader(d);
    RblShadowDesc sd;
    memset(&sd, 0, sizeof(sd));
    sd.size = 512; sd.omni = true;
    RblShadowMap maps[2] = { RblLoadShadowMap(sd), RblLoadShadowMap(sd) };
    if (!RblIsLitShaderValid(lit) || !RblIsShadowMapValid(maps[0]) || !RblIsShadowMapValid(maps[1])) { printf("pictures: omni shadows unavailable\n"); return false; }
    Material mc = LoadMaterialDefault(), mt = LoadMaterialDefault();
    mc.shader = mt.shader = lit;
    mc.maps[MATERIAL_MAP_ALBEDO].texture = character; mt.maps[MATERIAL_MAP_ALBEDO].texture = tree;
    Model ground = LoadModelFromMesh(GenMeshPlane(14.0f, 10.0f, 1, 1));
    ground.materials[0].shader = lit;
    ground.materials[0].maps[MATERIAL_MAP_ALBEDO].texture = floorTexture;
    Model crate = LoadModelFromMesh(GenMeshCube(0.6f, 0.6f, 0.6f));
    crate.materials[0].shader = lit;
    crate.materials[0].maps[MATERIAL_MAP_ALBEDO].color = (Color){ 170, 120, 70, 255 };
    const Vector3 people[4] = { { -2.4f, 0.0f, 0.9f }, { 0.3f, 0.0f, 0.6f }, { 0.9f, 0.0f, -1.9f }, { -1.0f, 0.0f, -1.6f } };
    const Vector3 crates[2] = { { -0.2f, 0.3f, -0.5f }, { 3.0f, 0.3f, 0.4f } };
    Camera3D cam;
    memset(&cam, 0, sizeof(cam));
    cam.position = (Vector3){ 0.0f, 4.6f, 6.6f }; cam.target = (Vector3){ 0.2f, 0.3f, -0.4f }; cam.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    cam.fovy = 48.0f; cam.projection = CAMERA_PERSPECTIVE;
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = lamps; scene.lightCount = 2; scene.ambient = (Color){ 34, 36, 46, 255 };
    bool ok = true;
    for (int l = 0; l < 2; l++)
        for (int f = 0; f < RblShadowMapPasses(maps[l]); f++)
        {
            if (!RblBeginShadowMapPass(&maps[l], &scene, l, f, (Vector3){ 0 }, 0.0f)) { ok = false; continue; }
            for (int i = 0; i < 4; i++)
            {
                RblBillboard b;
                memset(&b, 0, sizeof(b));
                b.position = people[i]; b.size = (i == 3)? (Vector2){ 1.3f, 1.95f } : (Vector2){ 0.6f, 1.2f }; b.origin = (Vector2){ b.size.x*0.5f, 0.0f }; b.facing = RBL_FACING_AXIS;
                RblDrawBillboard(cam, (i == 3)? mt : mc, b);
            }
            for (int i = 0; i < 2; i++) RblDrawModel(crate, crates[i], 1.0f, WHITE);
            RblDrawModel(ground, (Vector3){ 0 }, 1.0f, WHITE);
            RblEndShadowMap(&maps[l]);
        }
    scene.shadowMaps = maps; scene.shadowMapCount = 2;
    ok = ok && RblSetScene(&scene);
    RenderTexture2D rt = LoadRenderTexture(w, h);
    BeginTextureMode(rt);
    ClearBackground((Color){ 20, 22, 28, 255 });
    BeginMode3D(cam);
    RblDrawModel(ground, (Vector3){ 0 }, 1.0f, WHITE);
    for (int i = 0; i < 2; i++) RblDrawModel(crate, crates[i], 1.0f, WHITE);
    for (int i = 0; i < 4; i++)
    {
        RblBillboard b;
        memset(&b, 0, sizeof(b));
        b.position = people[i]; b.size = (i == 3)? (Vector2){ 1.3f, 1.95f } : (Vector2){ 0.6f, 1.2f }; b.origin = (Vector2){ b.size.x*0.5f, 0.0f }; b.facing = RBL_FACING_AXIS;
        RblDrawBillboard(cam, (i == 3)? mt : mc, b);
    }
    for (int l = 0; l < 2; l++) DrawSphere(lamps[l].position, 0.06f, lamps[l].color);
    EndMode3D();
    DrawText("two point lights, an omni map each (six cube faces of 512): sprites, a cut-out tree, crates", 8, h - 16, 10, RAYWHITE);
    EndTextureMode();
    Image img = rtReadTarget(rt);
    char path[512];
    snprintf(path, sizeof(path), "%s/rbl_omni_shadows.png", dir);
    ok = ok && ExportImage(img, path);
    printf("pictures: %s %s\n", ok? "wrote" : "could not write", path);
    UnloadImage(img);
    RblScene none;
    memset(&none, 0, sizeof(none));
    RblSetScene(&none);
    UnloadRenderTexture(rt);
    RblUnloadShadowMap(&maps[0]); RblUnloadShadowMap(&maps[1]);
    MemFree(mc.maps); MemFree(mt.maps);
    UnloadModel(ground); UnloadModel(crate);
    RblUnloadLitShader(&lit);
    UnloadTexture(character); UnloadTexture(tree); UnloadTexture(floorTexture);
    return ok;
}

// Cascaded sun shadows: a street of trees and characters 60 units long seen from eye height.
// Top left: 4 cascades of 1024 (4096 x 1024 texels); top right: one 2048 map over the same 0.3..60
// (the same memory); bottom: the 4 cascades' debug view (RblDrawShadowCascades) from above and
// behind, over the same street
static bool cascadesPicture(const char *dir)
{
    const int w = 640, h = 520, pw = w/2, ph = 240;
    Image ci = characterImage(false), ti = treeImage();
    Image fi = GenImageChecked(256, 256, 32, 32, (Color){ 196, 190, 178, 255 }, (Color){ 172, 166, 154, 255 });
    Texture2D character = LoadTextureFromImage(ci), tree = LoadTextureFromImage(ti), floorTexture = LoadTextureFromImage(fi);
    UnloadImage(ci); UnloadImage(ti); UnloadImage(fi);
    GenTextureMipmaps(&floorTexture);
    SetTextureFilter(floorTexture, TEXTURE_FILTER_TRILINEAR);
    RblLight sun;
    memset(&sun, 0, sizeof(sun));
    sun.type = RBL_LIGHT_DIRECTIONAL; sun.direction = (Vector3){ -0.55f, -0.6f, -0.35f }; sun.color = (Color){ 255, 236, 210, 255 }; sun.intensity = 1.0f;
    RblLitShaderDesc d;
    memset(&d, 0, sizeof(d));
    d.maxLights = 1; d.shading.lightFeatures = RblGetLightFeatures(&sun, 1); d.shading.shadowMaps = 1;
    Shader lit = RblLoadLitShader(d);
    RblShadowDesc cd, od;
    memset(&cd, 0, sizeof(cd)); memset(&od, 0, sizeof(od));
    cd.size = 1024; cd.cascades = 4; od.size = 2048;
    RblShadowMap cascades = RblLoadShadowMap(cd), one = RblLoadShadowMap(od);
    if (!RblIsLitShaderValid(lit) || !RblIsShadowMapValid(cascades) || !RblIsShadowMapValid(one)) { printf("pictures: cascades unavailable\n"); return false; }
    Material mc = LoadMaterialDefault(), mt = LoadMaterialDefault();
    mc.shader = mt.shader = lit;
    mc.maps[MATERIAL_MAP_ALBEDO].texture = character; mt.maps[MATERIAL_MAP_ALBEDO].texture = tree;
    Model ground = LoadModelFromMesh(GenMeshPlane(30.0f, 140.0f, 1, 1));
    ground.materials[0].shader = lit;
    ground.materials[0].maps[MATERIAL_MAP_ALBEDO].texture = floorTexture;
    Camera3D cam;
    memset(&cam, 0, sizeof(cam));
    cam.position = (Vector3){ 0.0f, 1.7f, 4.0f }; cam.target = (Vector3){ 0.0f, 1.0f, -6.0f }; cam.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    cam.fovy = 50.0f; cam.projection = CAMERA_PERSPECTIVE;
    Camera3D over = cam;
    over.position = (Vector3){ 30.0f, 38.0f, 24.0f }; over.target = (Vector3){ 0.0f, 0.0f, -18.0f }; over.fovy = 55.0f;
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = &sun; scene.lightCount = 1; scene.ambient = (Color){ 70, 76, 92, 255 };
    bool ok = RblFitShadowCascades(&cascades, cam, (float)pw/ph, 0.3f, 60.0f);
    Vector3 focus; float radius;
    ok = ok && RblShadowFocusFromCamera(cam, (float)pw/ph, 0.3f, 60.0f, &focus, &radius);
    RblShadowMap *maps[2] = { &cascades, &one };
    RenderTexture2D rt = LoadRenderTexture(pw, ph), big = LoadRenderTexture(w, h - 2*ph + ph), out = LoadRenderTexture(w, h);
    BeginTextureMode(out); ClearBackground(BLACK); EndTextureMode();
    for (int k = 0; k < 3; k++)
    {
        RblShadowMap *m = maps[(k == 1)? 1 : 0];
        if (k < 2)
            for (int pass = 0; pass < RblShadowMapPasses(*m); pass++)
            {
                if (!RblBeginShadowMapPass(m, &scene, 0, pass, focus, radius)) { ok = false; continue; }
                for (int i = 0; i < 24; i++)
                {
                    RblBillboard b;
                    memset(&b, 0, sizeof(b));
                    float z = 2.0f - 2.6f*i, x = (i & 1)? 2.6f : -2.6f;
                    b.position = (Vector3){ x + ((i%3) - 1)*0.4f, 0.0f, z }; b.facing = RBL_FACING_AXIS;
                    b.size = (i%4 == 1)? (Vector2){ 0.6f, 1.2f } : (Vector2){ 2.0f, 3.0f }; b.origin = (Vector2){ b.size.x*0.5f, 0.0f };
                    RblDrawBillboard(cam, (i%4 == 1)? mc : mt, b);
                }
                RblDrawModel(ground, (Vector3){ 0.0f, 0.0f, -60.0f }, 1.0f, WHITE);
                RblEndShadowMap(m);
            }
        scene.shadowMaps = m; scene.shadowMapCount = 1;
        ok = ok && RblSetScene(&scene);
        Camera3D view = (k == 2)? over : cam;
        RenderTexture2D *target = (k == 2)? &big : &rt;
        BeginTextureMode(*target);
        ClearBackground((Color){ 150, 180, 215, 255 });
        BeginMode3D(view);
        RblDrawModel(ground, (Vector3){ 0.0f, 0.0f, -60.0f }, 1.0f, WHITE);
        for (int i = 0; i < 24; i++)
        {
            RblBillboard b;
            memset(&b, 0, sizeof(b));
            float z = 2.0f - 2.6f*i, x = (i & 1)? 2.6f : -2.6f;
            b.position = (Vector3){ x + ((i%3) - 1)*0.4f, 0.0f, z }; b.facing = RBL_FACING_AXIS;
            b.size = (i%4 == 1)? (Vector2){ 0.6f, 1.2f } : (Vector2){ 2.0f, 3.0f }; b.origin = (Vector2){ b.size.x*0.5f, 0.0f };
            RblDrawBillboard(view, (i%4 == 1)? mc : mt, b);
        }
        if (k == 2) RblDrawShadowCascades(cascades);
        EndMode3D();
        DrawText((k == 0)? "4 cascades of 1024 (fitted, snapped, blended)" : ((k == 1)? "one 2048 map over the same 0.3..60 (equal memory)" :
                 "debug view: each cascade's camera slice and light window (red, green, blue, yellow)"), 8, 6, 10, (k == 2)? BLACK : RAYWHITE);
        EndTextureMode();
        BeginTextureMode(out);
        if (k < 2) DrawTextureRec(rt.texture, (Rectangle){ 0.0f, 0.0f, (float)pw, (float)-ph }, (Vector2){ (float)(k*pw), 0.0f }, WHITE);
        else DrawTextureRec(big.texture, (Rectangle){ 0.0f, 0.0f, (float)w, (float)-(h - ph) }, (Vector2){ 0.0f, (float)ph }, WHITE);
        EndTextureMode();
    }
    Image img = rtReadTarget(out);
    char path[512];
    snprintf(path, sizeof(path), "%s/rbl_shadow_cascades.png", dir);
    ok = ok && ExportImage(img, path);
    printf("pictures: %s %s\n", ok? "wrote" : "could not write", path);
    UnloadImage(img);
    RblScene none;
    memset(&none, 0, sizeof(none));
    RblSetScene(&none);
    UnloadRenderTexture(rt); UnloadRenderTexture(big); UnloadRenderTexture(out);
    RblUnloadShadowMap(&cascades); RblUnloadShadowMap(&one);
    MemFree(mc.maps); MemFree(mt.maps);
    UnloadModel(ground);
    RblUnloadLitShader(&lit);
    UnloadTexture(character); UnloadTexture(tree); UnloadTexture(floorTexture);
    return ok;
}

// Thin sprites: a row of leafy trees lit from behind by a low sun (transmission 0 on the left, 0.7
// on the right: the leaves glow through; the trunks are thick, a thickness of 1 in the material
// texture's alpha, and stay dark), and an embossed stone tile under a
// grazing light without and with the relief self-shadow march (16 steps)
static bool thinPictures(const char *dir)
{
    const int w = 640, h = 300;
    RenderTexture2D rt = LoadRenderTexture(w, h);
    // ---- transmission
    Image ti = treeImage();
    Texture2D tree = LoadTextureFromImage(ti);
    // Thickness: 1 where the bark is (brown texels), 0 in the leaves
    Image thick = ImageCopy(ti);
    ImageFormat(&thick, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
    Color *tp = (Color *)thick.data;
    for (int i = 0; i < thick.width*thick.height; i++) tp[i] = (Color){ 0, 0, 0, (unsigned char)((tp[i].r > tp[i].g)? 255 : 0) };
    Texture2D thickness = LoadTextureFromImage(thick);
    UnloadImage(thick);
    UnloadImage(ti);
    SetTextureFilter(tree, TEXTURE_FILTER_BILINEAR);
    RblLight sun;
    memset(&sun, 0, sizeof(sun));
    sun.type = RBL_LIGHT_DIRECTIONAL; sun.direction = (Vector3){ 0.3f, -0.35f, 1.0f };     // low, behind the trees
    sun.color = (Color){ 255, 220, 160, 255 }; sun.intensity = 2.2f;
    RblLitShaderDesc d;
    memset(&d, 0, sizeof(d));
    d.maxLights = 1; d.shading.lightFeatures = RBL_LIGHT_FEATURE_DIRECTIONAL; d.transmission = true; d.material.thickness = RBL_CHANNEL_A;
    Shader lit = RblLoadLitShader(d);
    if (!RblIsLitShaderValid(lit)) { printf("pictures: transmission variant unavailable\n"); return false; }
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = &sun; scene.lightCount = 1; scene.ambient = (Color){ 36, 42, 56, 255 };
    RblSetScene(&scene);
    Material mats[2] = { LoadMaterialDefault(), LoadMaterialDefault() };
    for (int i = 0; i < 2; i++) { mats[i].shader = lit; mats[i].maps[MATERIAL_MAP_ALBEDO].texture = tree; mats[i].maps[MATERIAL_MAP_NORMAL].texture = thickness; mats[i].params[RBL_PARAM_TRANSMISSION] = i? 0.7f : 0.0f; }
    Camera3D cam;
    memset(&cam, 0, sizeof(cam));
    cam.position = (Vector3){ 0.0f, 1.6f, 7.0f }; cam.target = (Vector3){ 0.0f, 1.4f, 0.0f };
    cam.up = (Vector3){ 0.0f, 1.0f, 0.0f }; cam.fovy = 45.0f; cam.projection = CAMERA_PERSPECTIVE;
    BeginTextureMode(rt);
    ClearBackground((Color){ 20, 22, 30, 255 });
    BeginMode3D(cam);
    for (int i = 0; i < 6; i++)
    {
        RblBillboard b;
        memset(&b, 0, sizeof(b));
        b.facing = RBL_FACING_FIXED; b.axis = (Vector3){ 0.0f, 0.0f, 1.0f }; b.up = (Vector3){ 0.0f, 1.0f, 0.0f };
        b.position = (Vector3){ -4.1f + i*1.64f, 0.0f, 0.0f };
        b.size = (Vector2){ 1.6f, 2.4f }; b.origin = (Vector2){ 0.8f, 0.0f };
        RblDrawBillboard(cam, mats[i >= 3], b);
    }
    EndMode3D();
    DrawText("transmission 0", 8, 8, 10, RAYWHITE);
    DrawText("transmission 0.7 (sun behind the trees)", w/2 + 8, 8, 10, RAYWHITE);
    EndTextureMode();
    Image img = rtReadTarget(rt);
    char path[512];
    snprintf(path, sizeof(path), "%s/rbl_transmission.png", dir);
    bool ok = ExportOpaque(img, path);
    printf("pictures: %s %s\n", ok? "wrote" : "could not write", path);
    UnloadImage(img);
    MemFree(mats[0].maps); MemFree(mats[1].maps);
    RblUnloadLitShader(&lit);
    UnloadTexture(tree); UnloadTexture(thickness);
    if (!ok) return false;

    // ---- relief: bricks and a raised disc; normals from the height, the height in the alpha
    const int ts = 128;
    Image height = GenImageColor(ts, ts, BLACK);
    for (int row = 0; row < 8; row++)
        for (int col = -1; col < 5; col++)
        {
            int x0 = col*32 + ((row & 1)? 16 : 0) + 2, y0 = row*16 + 2;
            ImageDrawRectangle(&height, x0, y0, 28, 12, (Color){ 150, 150, 150, 255 });
        }
    ImageDrawCircle(&height, 64, 64, 26, (Color){ 255, 255, 255, 255 });
    ImageDrawCircle(&height, 64, 64, 14, (Color){ 90, 90, 90, 255 });
    Image normals = RblGenNormalMapFromHeight(height, 6.0f, true);
    ImageFormat(&normals, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
    Color *np = (Color *)normals.data, *hp = NULL;
    Image hcopy = ImageCopy(height);
    ImageFormat(&hcopy, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8);
    hp = (Color *)hcopy.data;
    for (int i = 0; i < ts*ts; i++) np[i].a = hp[i].r;
    Texture2D material = LoadTextureFromImage(normals);
    UnloadImage(normals); UnloadImage(hcopy); UnloadImage(height);
    Image stone = GenImageColor(4, 4, (Color){ 186, 170, 150, 255 });
    Texture2D albedo = LoadTextureFromImage(stone);
    UnloadImage(stone);
    RblLight graze;
    memset(&graze, 0, sizeof(graze));
    graze.type = RBL_LIGHT_DIRECTIONAL; graze.direction = (Vector3){ 0.8f, -0.45f, -0.75f };    // 39 degrees up, from the upper left
    graze.color = (Color){ 255, 236, 210, 255 }; graze.intensity = 1.6f;
    scene.lights = &graze;
    scene.ambient = (Color){ 70, 74, 86, 255 };
    RblSetScene(&scene);
    Shader relief[2];
    for (int i = 0; i < 2; i++)
    {
        memset(&d, 0, sizeof(d));
        d.maxLights = 1; d.shading.lightFeatures = RBL_LIGHT_FEATURE_DIRECTIONAL;
        d.material.normalEncoding = RBL_NORMAL_RGB; d.material.height = RBL_CHANNEL_A;
        d.relief = (i == 1);
        relief[i] = RblLoadLitShader(d);
        if (!RblIsLitShaderValid(relief[i])) { printf("pictures: relief variant unavailable\n"); return false; }
    }
    memset(&cam, 0, sizeof(cam));
    cam.position = (Vector3){ 0.0f, 0.0f, 6.0f }; cam.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    cam.fovy = 3.0f; cam.projection = CAMERA_ORTHOGRAPHIC;
    BeginTextureMode(rt);
    ClearBackground((Color){ 20, 22, 30, 255 });
    BeginMode3D(cam);
    for (int i = 0; i < 2; i++)
    {
        Material m = LoadMaterialDefault();
        m.shader = relief[i];
        m.maps[MATERIAL_MAP_ALBEDO].texture = albedo;
        m.maps[MATERIAL_MAP_NORMAL].texture = material;
        m.maps[MATERIAL_MAP_HEIGHT].value = 6.0f;
        RblBillboard b;
        memset(&b, 0, sizeof(b));
        b.facing = RBL_FACING_FIXED; b.axis = (Vector3){ 0.0f, 0.0f, 1.0f }; b.up = (Vector3){ 0.0f, 1.0f, 0.0f };
        b.position = (Vector3){ i? 1.6f : -1.6f, 0.0f, 0.0f };
        b.size = (Vector2){ 2.8f, 2.8f }; b.origin = (Vector2){ 1.4f, 1.4f };
        RblDrawBillboard(cam, m, b);
        MemFree(m.maps);
    }
    EndMode3D();
    DrawText("normal map only", 8, 8, 10, RAYWHITE);
    DrawText("+ relief self-shadow (16 steps, height 6 texels)", w/2 + 8, 8, 10, RAYWHITE);
    EndTextureMode();
    img = rtReadTarget(rt);
    snprintf(path, sizeof(path), "%s/rbl_relief.png", dir);
    ok = ExportOpaque(img, path);
    printf("pictures: %s %s\n", ok? "wrote" : "could not write", path);
    UnloadImage(img);
    RblUnloadLitShader(&relief[0]); RblUnloadLitShader(&relief[1]);
    UnloadTexture(material); UnloadTexture(albedo);
    UnloadRenderTexture(rt);
    return ok;
}

// Blended casters: a red and a blue glass pane, a grey smoke puff and an opaque crate on a checked
// floor under a low sun; the glass and smoke are drawn between RblBeginShadowBlend/RblEndShadowBlend
// (coloured for the glass, coverage only for the smoke) and blended in the colour pass; the smoke's
// program receives no shadows (a blended billboard's light-facing caster would tint the billboard)
static bool glassPicture(const char *dir)
{
    const int w = 640, h = 360;
    Image fi = GenImageChecked(256, 256, 32, 32, (Color){ 200, 196, 186, 255 }, (Color){ 176, 170, 160, 255 });
    Texture2D floorTexture = LoadTextureFromImage(fi);
    UnloadImage(fi);
    Image pi = GenImageColor(64, 64, BLANK);
    ImageDrawCircle(&pi, 32, 32, 30, (Color){ 120, 120, 120, 90 });
    ImageDrawCircle(&pi, 32, 32, 20, (Color){ 110, 110, 110, 150 });
    Texture2D puff = LoadTextureFromImage(pi);
    UnloadImage(pi);
    SetTextureFilter(puff, TEXTURE_FILTER_BILINEAR);
    Image ri = GenImageColor(4, 4, (Color){ 230, 40, 40, 140 }), bi = GenImageColor(4, 4, (Color){ 40, 90, 240, 140 }), wi = GenImageColor(4, 4, WHITE);
    Texture2D red = LoadTextureFromImage(ri), blue = LoadTextureFromImage(bi), white = LoadTextureFromImage(wi);
    UnloadImage(ri); UnloadImage(bi); UnloadImage(wi);
    RblLight sun;
    memset(&sun, 0, sizeof(sun));
    sun.type = RBL_LIGHT_DIRECTIONAL; sun.direction = (Vector3){ -0.6f, -0.75f, -0.45f };
    sun.color = (Color){ 255, 240, 220, 255 }; sun.intensity = 1.2f;
    RblLitShaderDesc d;
    memset(&d, 0, sizeof(d));
    d.maxLights = 1; d.shading.lightFeatures = RBL_LIGHT_FEATURE_DIRECTIONAL; d.shading.shadowMaps = 1; d.shadowTransmittance = true;
    Shader lit = RblLoadLitShader(d);
    d.shading.shadowMaps = 0; d.shadowTransmittance = false;
    Shader unshadowed = RblLoadLitShader(d);            // the smoke receives nothing (its light-facing caster would tint it)
    RblShadowDesc sd;
    memset(&sd, 0, sizeof(sd));
    sd.size = 2048; sd.transmittance = true;
    RblShadowMap map = RblLoadShadowMap(sd);
    if (!RblIsLitShaderValid(lit) || !RblIsShadowMapValid(map)) { printf("pictures: blended casters unavailable\n"); return false; }
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = &sun; scene.lightCount = 1; scene.ambient = (Color){ 60, 64, 78, 255 };
    Material glass[2] = { LoadMaterialDefault(), LoadMaterialDefault() }, smoke = LoadMaterialDefault(), crateMat = LoadMaterialDefault();
    glass[0].maps[MATERIAL_MAP_ALBEDO].texture = red; glass[1].maps[MATERIAL_MAP_ALBEDO].texture = blue;
    smoke.maps[MATERIAL_MAP_ALBEDO].texture = puff;
    crateMat.maps[MATERIAL_MAP_ALBEDO].texture = white;
    crateMat.maps[MATERIAL_MAP_ALBEDO].color = (Color){ 180, 130, 80, 255 };
    glass[0].shader = glass[1].shader = crateMat.shader = lit;
    smoke.shader = unshadowed;
    glass[0].params[RBL_PARAM_ALPHA_CUTOFF] = glass[1].params[RBL_PARAM_ALPHA_CUTOFF] = smoke.params[RBL_PARAM_ALPHA_CUTOFF] = -1.0f;   // blended in the colour pass
    Model ground = LoadModelFromMesh(GenMeshPlane(12.0f, 12.0f, 1, 1));
    ground.materials[0].shader = lit;
    ground.materials[0].maps[MATERIAL_MAP_ALBEDO].texture = floorTexture;
    Model crate = LoadModelFromMesh(GenMeshCube(0.9f, 0.9f, 0.9f));
    crate.materials[0].shader = lit;
    crate.materials[0].maps[MATERIAL_MAP_ALBEDO].color = (Color){ 180, 130, 80, 255 };
    Camera3D cam;
    memset(&cam, 0, sizeof(cam));
    cam.position = (Vector3){ 0.5f, 4.2f, 6.5f }; cam.target = (Vector3){ -0.6f, 0.4f, -0.4f };
    cam.up = (Vector3){ 0.0f, 1.0f, 0.0f }; cam.fovy = 45.0f; cam.projection = CAMERA_PERSPECTIVE;
    RblBillboard panes[2], puffs[3];
    for (int i = 0; i < 2; i++)
    {
        memset(&panes[i], 0, sizeof(panes[i]));
        panes[i].facing = RBL_FACING_FIXED; panes[i].axis = (Vector3){ 0.0f, 0.0f, 1.0f }; panes[i].up = (Vector3){ 0.0f, 1.0f, 0.0f };
        panes[i].position = (Vector3){ -2.2f + i*1.6f, 0.0f, -0.6f + i*0.4f };
        panes[i].size = (Vector2){ 1.2f, 1.6f }; panes[i].origin = (Vector2){ 0.6f, 0.0f };
    }
    for (int i = 0; i < 3; i++)
    {
        memset(&puffs[i], 0, sizeof(puffs[i]));
        puffs[i].facing = RBL_FACING_CAMERA_PLANE;
        puffs[i].position = (Vector3){ 1.6f + 0.3f*i, 0.6f + 0.55f*i, 0.6f - 0.2f*i };
        puffs[i].size = (Vector2){ 1.1f - 0.15f*i, 1.1f - 0.15f*i }; puffs[i].origin = (Vector2){ puffs[i].size.x*0.5f, puffs[i].size.y*0.5f };
    }
    const Vector3 crateAt = { -0.4f, 0.45f, 1.3f };
    if (RblBeginShadowMap(&map, &scene, 0, (Vector3){ -0.3f, 0.5f, 0.0f }, 4.5f))
    {
        RblDrawModel(ground, (Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f, WHITE);
        RblDrawModel(crate, crateAt, 1.0f, WHITE);
        RblBeginShadowBlend(true);
        for (int i = 0; i < 2; i++) RblDrawBillboard(cam, glass[i], panes[i]);
        RblEndShadowBlend();
        RblBeginShadowBlend(false);
        for (int i = 0; i < 3; i++) RblDrawBillboard(cam, smoke, puffs[i]);
        RblEndShadowBlend();
        RblEndShadowMap(&map);
    }
    scene.shadowMaps = &map; scene.shadowMapCount = 1;
    RblSetScene(&scene);
    RenderTexture2D rt = LoadRenderTexture(w, h);
    BeginTextureMode(rt);
    ClearBackground((Color){ 24, 26, 32, 255 });
    BeginMode3D(cam);
    RblDrawModel(ground, (Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f, WHITE);
    RblDrawModel(crate, crateAt, 1.0f, WHITE);
    for (int i = 0; i < 3; i++) RblDrawBillboard(cam, smoke, puffs[2 - i]);
    for (int i = 0; i < 2; i++) RblDrawBillboard(cam, glass[i], panes[i]);
    EndMode3D();
    DrawText("blended casters: coloured glass, grey smoke, opaque crate", 8, 8, 10, RAYWHITE);
    EndTextureMode();
    Image img = rtReadTarget(rt);
    char path[512];
    snprintf(path, sizeof(path), "%s/rbl_glass_shadow.png", dir);
    bool ok = ExportOpaque(img, path);
    printf("pictures: %s %s\n", ok? "wrote" : "could not write", path);
    UnloadImage(img);
    UnloadRenderTexture(rt);
    RblUnloadShadowMap(&map);
    MemFree(glass[0].maps); MemFree(glass[1].maps); MemFree(smoke.maps); MemFree(crateMat.maps);
    UnloadModel(ground); UnloadModel(crate);             // meshes and material maps, not the shader or textures
    RblUnloadLitShader(&lit); RblUnloadLitShader(&unshadowed);
    UnloadTexture(floorTexture); UnloadTexture(puff); UnloadTexture(red); UnloadTexture(blue); UnloadTexture(white);
    return ok;
}


// Many lights: 256 small coloured lights over two floors with smoke puffs above them; the left
// floor's programs have 64 light slots (the scene's first 64 lights, wherever they are), the right
// floor's are clustered (every light of the scene through the light grid), smoke included
static bool clusteredPicture(const char *dir)
{
    const int w = 800, h = 360, count = 256;
    RblLight *lights = (RblLight *)MemAlloc(count*sizeof(RblLight));
    unsigned int seed = 12345u;
    for (int i = 0; i < count; i++)
    {
        seed = seed*1664525u + 1013904223u; float u = (float)(seed >> 8)/16777216.0f;
        seed = seed*1664525u + 1013904223u; float v = (float)(seed >> 8)/16777216.0f;
        seed = seed*1664525u + 1013904223u; unsigned int hue = seed >> 29;
        static const Color palette[8] = { { 255, 90, 60, 255 }, { 255, 180, 60, 255 }, { 90, 255, 120, 255 }, { 60, 160, 255, 255 },
                                          { 200, 90, 255, 255 }, { 255, 255, 200, 255 }, { 60, 255, 230, 255 }, { 255, 120, 200, 255 } };
        lights[i].position = (Vector3){ (i & 1)? 0.4f + u*5.2f : -5.6f + u*5.2f, 0.25f, -2.6f + v*5.2f };
        lights[i].color = palette[hue];
        lights[i].intensity = 0.12f;
        lights[i].range = 1.0f;
    }
    Camera3D cam;
    memset(&cam, 0, sizeof(cam));
    cam.position = (Vector3){ 0.0f, 6.5f, 7.0f };
    cam.target = (Vector3){ 0.0f, 0.0f, 0.0f };
    cam.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    cam.fovy = 45.0f;
    cam.projection = CAMERA_PERSPECTIVE;
    Shader floorShader[2], smokeShader[2];
    for (int k = 0; k < 2; k++)
    {
        RblLitShaderDesc d;
        memset(&d, 0, sizeof(d));
        d.maxLights = 64;
        d.clustered = (k == 1);
        d.shading.tonemap = RBL_TONEMAP_ACES;
        floorShader[k] = RblLoadLitShader(d);
        d.shading.brdf = RBL_BRDF_LAMBERT;
        smokeShader[k] = RblLoadLitShader(d);
    }
    Image puff = GenImageGradientRadial(64, 64, 0.0f, (Color){ 235, 235, 235, 220 }, (Color){ 235, 235, 235, 0 });
    Texture2D puffTexture = LoadTextureFromImage(puff);
    UnloadImage(puff);
    SetTextureFilter(puffTexture, TEXTURE_FILTER_BILINEAR);
    Model floor = LoadModelFromMesh(GenMeshPlane(5.6f, 5.6f, 1, 1));
    Material floorDefault = floor.materials[0];
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = lights;
    scene.lightCount = count;
    scene.ambient = (Color){ 14, 14, 18, 255 };
    bool ok = RblSetScene(&scene);
    RenderTexture2D rt = LoadRenderTexture(w, h);
    BeginTextureMode(rt);
    ClearBackground((Color){ 8, 8, 12, 255 });
    BeginMode3D(cam);
    for (int k = 0; k < 2; k++)
    {
        ok = ok && RblIsLitShaderValid(floorShader[k]) && RblIsLitShaderValid(smokeShader[k]);
        Material fm = LoadMaterialDefault();
        fm.shader = floorShader[k];
        fm.maps[MATERIAL_MAP_ALBEDO].color = (Color){ 200, 200, 200, 255 };
        floor.materials[0] = fm;
        RblDrawModel(floor, (Vector3){ k? 3.0f : -3.0f, 0.0f, 0.0f }, 1.0f, WHITE);
        MemFree(fm.maps);
    }
    for (int k = 0; k < 2; k++)
    {
        Material sm = LoadMaterialDefault();
        sm.shader = smokeShader[k];
        sm.maps[MATERIAL_MAP_ALBEDO].texture = puffTexture;
        sm.params[RBL_PARAM_ALPHA_CUTOFF] = -1.0f;          // never cut: soft edges blend
        rlDisableDepthMask();
        for (int j = 0; j < 9; j++)
        {
            RblBillboard b;
            memset(&b, 0, sizeof(b));
            b.position = (Vector3){ (k? 3.0f : -3.0f) + (float)(j%3 - 1)*1.6f, 0.45f, (float)(j/3 - 1)*1.6f };
            b.size = (Vector2){ 1.3f, 1.3f };
            b.origin = (Vector2){ 0.65f, 0.65f };
            b.roundness = 1.0f;
            RblDrawBillboard(cam, sm, b);
        }
        rlEnableDepthMask();
        MemFree(sm.maps);
    }
    EndMode3D();
    DrawText("64 light slots: the scene's first 64 of 256 lights", 8, 6, 10, RAYWHITE);
    DrawText("desc.clustered: all 256 (the floor and the smoke over it)", w/2 + 8, 6, 10, RAYWHITE);
    EndTextureMode();
    Image img = rtReadTarget(rt);
    char path[512];
    snprintf(path, sizeof(path), "%s/rbl_clustered.png", dir);
    ok = ok && ExportOpaque(img, path);
    printf("pictures: %s %s\n", ok? "wrote" : "could not write", path);
    UnloadImage(img);
    UnloadRenderTexture(rt);
    floor.materials[0] = floorDefault;
    UnloadModel(floor);
    UnloadTexture(puffTexture);
    for (int k = 0; k < 2; k++) { RblUnloadLitShader(&floorShader[k]); RblUnloadLitShader(&smokeShader[k]); }
    MemFree(lights);
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
    if (!spriteShadowsPicture(dir)) return 1;
    if (!sweepPicture(dir)) return 1;
    if (!omniPicture(dir)) return 1;
    if (!cascadesPicture(dir)) return 1;
    if (!thinPictures(dir)) return 1;
    if (!glassPicture(dir)) return 1;
    if (!clusteredPicture(dir)) return 1;
    UnloadTexture(sign); UnloadTexture(normals);
    MemFree(mat.maps);
    RblUnloadLitShader(&lit);
    RblClose();                                         // after the Unload calls
    rtCloseContext();
    return 0;
}
