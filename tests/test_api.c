// The 1.0 API's shape: materials are values (one program for materials that differ only in values),
// the scene is set once per frame and reaches every program (raylib's own DrawModel included), and
// every GL object has one owner (raylib's UnloadMaterial on a lit program is survivable, double and
// stale unloads are refused). Needs gpu_common.h (included by gpu_tests.h
// and by test_api_main.c).

// Live lit programs in the registry (what users' materials share)
static int apiLitPrograms(void)
{
    int n = 0;
    for (int i = 0; i < rbl__state.programCount; i++)
        if (rbl__state.programs[i]->key.kind == RBL__KIND_LIT) n++;
    return n;
}

static RblLight apiFrontLight(float intensity)
{
    RblLight l;
    memset(&l, 0, sizeof(l));
    l.type = RBL_LIGHT_POINT;
    l.position = (Vector3){ 0.5f, 1.0f, 3.0f };
    l.color = WHITE;
    l.intensity = intensity;
    return l;
}

// Value set i of 16: GGX roughness and metalness, albedo colour, emission and alpha cutoff all vary
static void apiValues(Material *m, int i)
{
    m->maps[MATERIAL_MAP_ALBEDO].color = (Color){ (unsigned char)(60 + 12*i), (unsigned char)(220 - 9*i), (unsigned char)(90 + 7*(i % 5)), 255 };
    m->maps[MATERIAL_MAP_ROUGHNESS].value = 0.05f + 0.06f*(float)i;
    m->maps[MATERIAL_MAP_METALNESS].value = (float)(i % 4)/3.0f;
    m->maps[MATERIAL_MAP_EMISSION].color = (i % 3 == 0)? (Color){ (unsigned char)(10*i), 20, 0, 255 } : (Color){ 0, 0, 0, 0 };
    m->maps[MATERIAL_MAP_EMISSION].value = (i % 3 == 0)? 0.5f : 0.0f;
    m->params[RBL_PARAM_ALPHA_CUTOFF] = (i % 2 == 0)? 0.25f : -1.0f;
}

// Billboard filling cell i of a 4x4 grid of the front camera's view at z = 0
static RblBillboard apiCell(int i)
{
    float h = (float)(2.0*5.0*tan(22.5*PI/180.0)), c = h/4.0f;
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.position = (Vector3){ -h*0.5f + c*(float)(i % 4), h*0.5f - c*(float)(i/4 + 1), 0.0f };
    b.size = (Vector2){ c, c };
    return b;
}

// Cell 5 drawn alone with material m by the immediate path; its centre pixel
static Color apiCellPixel(Material m)
{
    RenderTexture2D rt = LoadRenderTexture(TARGET, TARGET);
    RblBillboard b = apiCell(5);
    BeginTextureMode(rt);
    ClearBackground(BLACK);
    BeginMode3D(frontCamera());
    RblDrawBillboard(frontCamera(), m, b);
    EndMode3D();
    EndTextureMode();
    Image img = rtReadTarget(rt);
    Color c = rtPixel(img, 16 + 8, 16 + 8);
    UnloadImage(img);
    UnloadRenderTexture(rt);
    return c;
}

static RblLitShaderDesc apiGgxDesc(void)
{
    RblLitShaderDesc d;
    memset(&d, 0, sizeof(d));
    d.shading.brdf = RBL_BRDF_GGX;
    d.maxLights = 1;
    return d;
}

static void test_api_16_value_only_materials_share_one_program_and_match_separate_programs(void)
{
    RblLight light = apiFrontLight(6.0f);
    RT_CHECK(renderSetLights(&light, 1, (Color){ 40, 40, 60, 255 }), "scene rejected");
    int before = apiLitPrograms();
    Texture2D white = solidTexture(WHITE);
    Material m[16];
    Shader lit = RblLoadLitShader(apiGgxDesc());        // one handle in 16 materials (as raylib shares a Shader)
    for (int i = 0; i < 16; i++)
    {
        m[i] = LoadMaterialDefault();
        m[i].maps[MATERIAL_MAP_ALBEDO].texture = white;
        m[i].shader = lit;
        apiValues(&m[i], i);
        RT_CHECK(RblIsLitShaderValid(m[i].shader), "material %d: no program", i);
    }
    RT_CHECK(apiLitPrograms() - before == 1, "16 value-only materials hold %d programs, want 1", apiLitPrograms() - before);

    // All 16 in one batch: values switch run by run in the one program
    RenderTexture2D rt = LoadRenderTexture(TARGET, TARGET);
    RblBatch batch = RblLoadBatch(16);
    BeginTextureMode(rt);
    ClearBackground(BLACK);
    BeginMode3D(frontCamera());
    RblBeginBatch(&batch, frontCamera());
    for (int i = 0; i < 16; i++) { RblBillboard b = apiCell(i); RblBatchAdd(&batch, m[i], &b); }
    RblEndBatch(&batch);
    EndMode3D();
    EndTextureMode();
    Image shared = rtReadTarget(rt);

    // Each material alone, with a program compiled afresh for it (the registry is emptied in between)
    int worst = 0;
    for (int i = 0; i < 16; i++)
    {
        Shader own = m[0].shader;
        RblUnloadLitShader(&own);
        RT_CHECK(apiLitPrograms() == before, "material %d: program not released", i);
        Material alone = m[i];
        alone.shader = RblLoadLitShader(apiGgxDesc());
        BeginTextureMode(rt);
        ClearBackground(BLACK);
        BeginMode3D(frontCamera());
        RblBillboard b = apiCell(i);
        RblDrawBillboard(frontCamera(), alone, b);
        EndMode3D();
        EndTextureMode();
        Image img = rtReadTarget(rt);
        int x0 = (i % 4)*16, y0 = (i/4)*16;
        for (int y = y0 + 2; y < y0 + 14; y++)
            for (int x = x0 + 2; x < x0 + 14; x++)
            {
                Color a = rtPixel(shared, x, y), c = rtPixel(img, x, y);
                int d = abs(a.r - c.r); if (abs(a.g - c.g) > d) d = abs(a.g - c.g); if (abs(a.b - c.b) > d) d = abs(a.b - c.b);
                if (d > worst) worst = d;
            }
        for (int k = 0; k < 16; k++) m[k].shader = alone.shader;
        UnloadImage(img);
    }
    RT_CHECK(worst <= 1, "one shared program vs a program per material: worst %d/255 (limit 1)", worst);
    // The cells really differ (values reached the GPU): cell 0 and cell 15 centres
    Color c0 = rtPixel(shared, 8, 8), c15 = rtPixel(shared, 56, 56);
    RT_CHECK(abs(c0.r - c15.r) + abs(c0.g - c15.g) > 40, "cells 0 and 15 look alike: (%d,%d,%d) vs (%d,%d,%d)", c0.r, c0.g, c0.b, c15.r, c15.g, c15.b);
    if (rtFailuresInCurrentTest() > 0) rtSaveImage(shared, "shared");
    UnloadImage(shared);
    RblUnloadBatch(&batch);
    UnloadRenderTexture(rt);
    RblUnloadLitShader(&m[0].shader);
    for (int i = 0; i < 16; i++) { m[i].maps[MATERIAL_MAP_ALBEDO].texture.id = 0; m[i].shader = (Shader){ 0, NULL }; MemFree(m[i].maps); }
    UnloadTexture(white);
    RT_CHECK(apiLitPrograms() == before, "programs left after every holder unloaded: %d", apiLitPrograms() - before);
}

// A plane Model facing the front camera, drawn by raylib's own DrawModel with a lit material
static Color apiDrawModelPixel(Model model)
{
    RenderTexture2D rt = LoadRenderTexture(TARGET, TARGET);
    BeginTextureMode(rt);
    ClearBackground(BLACK);
    BeginMode3D(frontCamera());
    DrawModel(model, (Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f, WHITE);
    EndMode3D();
    EndTextureMode();
    Image img = rtReadTarget(rt);
    Color c = rtPixel(img, TARGET/2, TARGET/2);
    UnloadImage(img);
    UnloadRenderTexture(rt);
    return c;
}

static Model apiFacingPlane(Shader lit)
{
    Mesh mesh = GenMeshPlane(2.0f, 2.0f, 1, 1);
    Model model = LoadModelFromMesh(mesh);
    model.transform = (Matrix){ 1, 0, 0, 0,  0, 0, -1, 0,  0, 1, 0, 0,  0, 0, 0, 1 };   // +Y normal turned to +Z
    model.materials[0].shader = lit;
    model.materials[0].maps[MATERIAL_MAP_ALBEDO].color = (Color){ 200, 200, 200, 255 };
    return model;
}

static void test_api_scene_reaches_raylib_drawmodel_and_programs_loaded_later(void)
{
    RblLitShaderDesc d;
    memset(&d, 0, sizeof(d));
    Shader lambert = RblLoadLitShader(d);
    d.shading.brdf = RBL_BRDF_BLINN_PHONG;
    Shader phong = RblLoadLitShader(d);
    Model a = apiFacingPlane(lambert), b = apiFacingPlane(phong);
    RblLight light = apiFrontLight(4.0f);
    RT_CHECK(renderSetLights(&light, 1, BLACK), "scene 1 rejected");
    Color a1 = apiDrawModelPixel(a), b1 = apiDrawModelPixel(b);
    light.intensity = 1.0f;
    light.color = (Color){ 255, 128, 0, 255 };
    RT_CHECK(renderSetLights(&light, 1, BLACK), "scene 2 rejected");
    Color a2 = apiDrawModelPixel(a), b2 = apiDrawModelPixel(b);
    // One RblSetScene changed both programs: the light's blue went, its intensity fell
    RT_CHECK((a1.b > 60) && (a2.b <= 1) && (a2.r < a1.r), "Lambert DrawModel did not follow the scene: (%d,%d,%d) then (%d,%d,%d)", a1.r, a1.g, a1.b, a2.r, a2.g, a2.b);
    RT_CHECK((b1.b > 60) && (b2.b <= 1) && (b2.r < b1.r), "Blinn-Phong DrawModel did not follow the scene: (%d,%d,%d) then (%d,%d,%d)", b1.r, b1.g, b1.b, b2.r, b2.g, b2.b);
    // A program loaded after the scene was set draws with it at once
    RblUnloadLitShader(&lambert);
    RT_CHECK(apiLitPrograms() >= 1, "registry lost the Blinn-Phong program");
    RblLitShaderDesc d0;
    memset(&d0, 0, sizeof(d0));
    Shader fresh = RblLoadLitShader(d0);
    a.materials[0].shader = fresh;
    Color a3 = apiDrawModelPixel(a);
    RT_CHECK((abs(a3.r - a2.r) <= 1) && (abs(a3.g - a2.g) <= 1) && (abs(a3.b - a2.b) <= 1), "program loaded after the scene: (%d,%d,%d), want (%d,%d,%d)", a3.r, a3.g, a3.b, a2.r, a2.g, a2.b);
    // raylib's UnloadModel frees maps only (it leaves shaders to their owner)
    a.materials[0].shader = (Shader){ 0, NULL }; b.materials[0].shader = (Shader){ 0, NULL };
    UnloadModel(a); UnloadModel(b);
    RblUnloadLitShader(&fresh);
    RblUnloadLitShader(&phong);
}

// The sequence raylib users write: LoadMaterialDefault, set the lit shader, UnloadMaterial (which
// unloads the shader), load again, draw, unload, close. It must draw and leave nothing dead behind.
static void test_api_raylib_habitual_unload_material_sequence_draws(void)
{
    RblLight light = apiFrontLight(4.0f);
    RT_CHECK(renderSetLights(&light, 1, BLACK), "scene rejected");
    RblLitShaderDesc d;
    memset(&d, 0, sizeof(d));
    d.maxLights = 3;                        // a variant no other test holds
    int before = apiLitPrograms();
    Material m = LoadMaterialDefault();
    m.shader = RblLoadLitShader(d);
    Shader stale = m.shader;
    RT_CHECK(RblIsLitShaderValid(m.shader), "first load failed");
    UnloadMaterial(m);                      // raylib: UnloadShader (program deleted, locs freed) + maps freed
    RT_CHECK(!RblIsLitShaderValid(stale), "a program raylib deleted still reports valid");
    RT_CHECK(apiLitPrograms() == before, "the registry still holds the deleted program");

    m = LoadMaterialDefault();
    m.shader = RblLoadLitShader(d);
    RT_CHECK(RblIsLitShaderValid(m.shader), "loading again after UnloadMaterial gave no live program");
    Color c = apiCellPixel(m);
    RT_CHECK(c.r > 40, "nothing drawn after the reload: (%d,%d,%d)", c.r, c.g, c.b);
    UnloadMaterial(m);
    RT_CHECK(apiLitPrograms() == before || !RblIsLitShaderValid(m.shader), "second UnloadMaterial left a live entry");
    // Once the registry looked again (any load or scene), the dead entry is gone
    RT_CHECK(renderSetLights(&light, 1, BLACK), "scene rejected");
    RT_CHECK(apiLitPrograms() == before, "dead program still registered after RblSetScene");
}

static void test_api_double_and_stale_unloads_are_refused_with_one_log_line(void)
{
    RblLitShaderDesc d;
    memset(&d, 0, sizeof(d));
    Shader s = RblLoadLitShader(d);
    Shader copy = s;
    RblUnloadLitShader(&s);
    RT_CHECK((s.id == 0) && (s.locs == NULL), "unload did not zero the shader");
    warnings = 0;
    RblUnloadLitShader(&s);
    RT_CHECK(warnings == 1, "second unload of a zeroed shader: %d log lines, want 1", warnings);
    warnings = 0;
    RblUnloadLitShader(&copy);                  // stale copy: its locs were freed, it must not be touched
    RT_CHECK(warnings == 1, "unload of a stale copy: %d log lines, want 1", warnings);
    RT_CHECK(!RblIsLitShaderValid(copy), "a stale copy reports valid");
    warnings = 0;
    RblUnloadLitShader(NULL);
    RT_CHECK(warnings == 1, "unload of NULL: %d log lines, want 1", warnings);
    // raylib's default shader is not ours: refused, not deleted
    Shader def = { rlGetShaderIdDefault(), rlGetShaderLocsDefault() };
    warnings = 0;
    RblUnloadLitShader(&def);
    RT_CHECK((warnings == 1) && (def.id == rlGetShaderIdDefault()), "unloading raylib's default shader was not refused");
    RT_CHECK(!RblIsLitShaderValid(def), "raylib's default shader reports as a lit program");
    // A stale copy of an unloaded batch is recognised without being read: invalid, and unloading it
    // again is refused with one line
    RblBatch batch = RblLoadBatch(4);
    RblBatch batchCopy = batch;
    RT_CHECK(RblIsBatchValid(batch) && RblIsBatchValid(batchCopy), "batch did not load");
    RblUnloadBatch(&batch);
    RT_CHECK((batch.state == NULL) && !RblIsBatchValid(batch), "unloaded batch not zeroed");
    RT_CHECK(!RblIsBatchValid(batchCopy), "a stale copy of an unloaded batch reports valid");
    warnings = 0;
    RblUnloadBatch(&batchCopy);
    RT_CHECK((warnings == 1) && (batchCopy.state == NULL), "unloading a stale batch copy: %d log lines, want 1", warnings);
    warnings = 0;
    RblBeginBatch(&batchCopy, frontCamera());
    RT_CHECK(warnings == 1, "beginning an unloaded batch: %d log lines, want 1", warnings);
    // Shadow maps and G-buffers: the second unload of a zeroed object is harmless
    RblShadowDesc sd;
    memset(&sd, 0, sizeof(sd));
    sd.size = 64;
    RblShadowMap map = RblLoadShadowMap(sd);
    RT_CHECK(RblIsShadowMapValid(map), "shadow map did not load");
    RblShadowMap mapCopy = map;
    RblUnloadShadowMap(&map);
    RblUnloadShadowMap(&map);
    RT_CHECK(!RblIsShadowMapValid(map), "unloaded shadow map reports valid");
    RT_CHECK(!RblIsShadowMapValid(mapCopy), "a stale copy of an unloaded shadow map reports valid");
    warnings = 0;
    RblUnloadShadowMap(&mapCopy);
    RT_CHECK((warnings == 1) && (mapCopy.state == NULL), "unloading a stale shadow map copy: %d log lines, want 1", warnings);
    warnings = 0;
    RblEndShadowMap(&mapCopy);
    RT_CHECK(warnings == 1, "ending a shadow pass never begun: %d log lines, want 1", warnings);
    RblGBufferDesc gd;
    memset(&gd, 0, sizeof(gd));
    gd.width = 32; gd.height = 32;
    if (!rtGlsl3())
    {
        // ES 2 / GL 2.1: no G-buffer; refused with one line, and the zeroed result unloads harmlessly
        warnings = 0;
        RblGBuffer none = RblLoadGBuffer(gd);
        RT_CHECK(!RblIsGBufferValid(none) && (warnings == 1), "G-buffer on a GLSL 1 context: %d log lines, want 1", warnings);
        warnings = 0;
        RblUnloadGBuffer(&none);
        RT_CHECK(warnings == 1, "unloading the refused G-buffer: %d log lines, want 1", warnings);
        return;
    }
    RblGBuffer g = RblLoadGBuffer(gd);
    RT_CHECK(RblIsGBufferValid(g), "G-buffer did not load");
    RblGBuffer gCopy = g;
    RblUnloadGBuffer(&g);
    RblUnloadGBuffer(&g);
    RT_CHECK(!RblIsGBufferValid(g), "unloaded G-buffer reports valid");
    RT_CHECK(!RblIsGBufferValid(gCopy), "a stale copy of an unloaded G-buffer reports valid");
    warnings = 0;
    RblUnloadGBuffer(&gCopy);
    RT_CHECK((warnings == 1) && (gCopy.state == NULL), "unloading a stale G-buffer copy: %d log lines, want 1", warnings);
    warnings = 0;
    RT_CHECK(!RblBeginGBuffer(&gCopy, frontCamera()) && (warnings == 1), "beginning a zeroed G-buffer: %d log lines, want 1", warnings);
    warnings = 0;
    RblEndGBuffer(&gCopy);
    RT_CHECK(warnings == 1, "ending a G-buffer pass never begun: %d log lines, want 1", warnings);
}

// Renders the lit cell 5 with a fresh Lambert program under the current scene
static Color apiLitCell(void)
{
    RblLitShaderDesc d;
    memset(&d, 0, sizeof(d));
    Material m = LoadMaterialDefault();
    m.shader = RblLoadLitShader(d);
    Color c = apiCellPixel(m);
    RblUnloadLitShader(&m.shader);
    m.shader = (Shader){ 0, NULL };
    MemFree(m.maps);
    return c;
}

static void test_api_bad_scenes_are_refused_with_one_log_line_and_keep_the_previous_scene(void)
{
    RblLight good = apiFrontLight(3.0f);
    RT_CHECK(renderSetLights(&good, 1, (Color){ 30, 30, 30, 255 }), "good scene rejected");
    Color ref = apiLitCell();
    RblLight nanLight = good; nanLight.position.x = NAN;
    RblLight hugeLight = good; hugeLight.range = -1.0f;
    RblLight spot = good; spot.type = RBL_LIGHT_SPOT; spot.direction = (Vector3){ 0, 0, -1 }; spot.innerAngle = 40.0f; spot.outerAngle = 30.0f;
    RblLight zeroDir = good; zeroDir.type = RBL_LIGHT_DIRECTIONAL; zeroDir.direction = (Vector3){ 0, 0, 0 };
    RblLight badType = good; badType.type = 7;
    RblShadowMap never;
    memset(&never, 0, sizeof(never));
    for (int c = 0; c < 14; c++)
    {
        RblScene s;
        memset(&s, 0, sizeof(s));
        s.lights = &good; s.lightCount = 1;
        const RblScene *arg = &s;
        switch (c)
        {
            case 0: arg = NULL; break;
            case 1: s.lightCount = -1; break;
            case 2: s.lights = NULL; break;
            case 3: s.lights = &nanLight; break;
            case 4: s.lights = &hugeLight; break;
            case 5: s.lights = &spot; break;
            case 6: s.lights = &zeroDir; break;
            case 7: s.lights = &badType; break;
            case 8: s.exposure = -1.0f; break;
            case 9: s.exposure = INFINITY; break;
            case 10: s.fog.mode = RBL_FOG_LINEAR; s.fog.start = 5.0f; s.fog.end = 5.0f; break;
            case 11: s.ambientUp = (Vector3){ NAN, 1.0f, 0.0f }; break;
            case 12: s.shadowMaps = &never; s.shadowMapCount = 1; break;
            default: s.shadowMaps = &never; s.shadowMapCount = RBL_MAX_SHADOWS + 1; break;
        }
        warnings = 0;
        bool ok = RblSetScene(arg);
        RT_CHECK(!ok, "bad scene %d accepted", c);
        RT_CHECK(warnings == 1, "bad scene %d: %d log lines, want 1 (%s)", c, warnings, lastWarning);
        Color now = apiLitCell();
        RT_CHECK((now.r == ref.r) && (now.g == ref.g) && (now.b == ref.b), "bad scene %d changed the picture: (%d,%d,%d) vs (%d,%d,%d)", c, now.r, now.g, now.b, ref.r, ref.g, ref.b);
    }
}

#define RBL_API_TESTS \
    RT_TEST(test_api_16_value_only_materials_share_one_program_and_match_separate_programs), \
    RT_TEST(test_api_scene_reaches_raylib_drawmodel_and_programs_loaded_later), \
    RT_TEST(test_api_raylib_habitual_unload_material_sequence_draws), \
    RT_TEST(test_api_double_and_stale_unloads_are_refused_with_one_log_line), \
    RT_TEST(test_api_bad_scenes_are_refused_with_one_log_line_and_keep_the_previous_scene)
