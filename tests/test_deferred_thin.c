// Deferred against forward where forward has more (GPU, headless; issues #26 item 6, #27 item 7):
// - overdraw: 1k and 10k overlapping opaque sprites (packed occlusion, emission, a hemisphere
//   ambient, GGX): the ambient is added once per pixel by the resolve, from the stored surface and
//   the occlusion in the accumulation's alpha; deferred equals forward within 1/255;
// - thin sprites on a G-buffer with RblGBufferDesc.thin: transmission, relief self-shadow and the
//   blended casters' transmittance (RblGBufferDesc.shadowTransmittance) against forward within 1/255.
// Included by gpu_tests.h after test_thin.c (its relief fields and blended-caster scene).

#define DT_SIZE 64

// One size x size frame drawn by draw(shaders, ctx) forward or into g and lit, read back
typedef void (*DtDraw)(const Shader *shaders, void *ctx);

static Image dtFrame(int size, bool deferred, RblGBuffer *g, Camera3D camera, DtDraw draw, const Shader *shaders, void *ctx)
{
    RenderTexture2D rt = LoadRenderTexture(size, size);
    bool ok = true;
    if (deferred)
    {
        ok = RblBeginGBuffer(g, camera);
        if (ok) { draw(shaders, ctx); RblEndGBuffer(g); ok = RblDrawDeferredLights(g); }
        BeginTextureMode(rt);
        ClearBackground(BLANK);
        if (ok) RblResolveGBuffer(g);
        EndTextureMode();
    }
    else
    {
        BeginTextureMode(rt);
        ClearBackground(BLANK);
        BeginMode3D(camera);
        draw(shaders, ctx);
        EndMode3D();
        EndTextureMode();
    }
    RT_CHECK(ok, "deferred frame refused");
    Image img = rtReadTarget(rt);
    UnloadRenderTexture(rt);
    return img;
}

typedef struct DtOverdraw { RblInstanceBuffer *ib; Camera3D camera; Material m; const RblInstance *in; int count; } DtOverdraw;

static void dtOverdrawDraw(const Shader *shaders, void *ctx)
{
    (void)shaders;
    DtOverdraw *o = (DtOverdraw *)ctx;
    RblInstancedDesc id;
    memset(&id, 0, sizeof(id));
    RblDrawInstanced(o->ib, o->camera, o->m, id, o->in, o->count);
}

// Forward or deferred frame of count overlapping instanced sprites; desc holds the compiled features
static Image dtOverdrawFrame(const RblLitShaderDesc *desc, bool deferred, RblGBuffer *g, Camera3D camera, const RblInstance *in, int count, Material m)
{
    RblLitShaderDesc d = *desc;
    d.instanced = true;
    d.deferred = deferred;
    Shader s = RblLoadLitShader(d);
    RT_CHECK(RblIsLitShaderValid(s), "%s sprite variant failed to load", deferred? "deferred" : "forward");
    m.shader = s;
    RblInstanceBuffer ib = RblLoadInstanceBuffer(count);
    DtOverdraw o = { &ib, camera, m, in, count };
    Image img = dtFrame(DT_SIZE, deferred, g, camera, dtOverdrawDraw, NULL, &o);
    RblUnloadInstanceBuffer(&ib);
    RblUnloadLitShader(&s);
    return img;
}

static void test_deferred_overlapping_sprites_1k_and_10k_match_forward_ambient_once_per_pixel(void)
{
    // Material texture: hemi-oct normal varying per texel, occlusion 0.16..0.89 in A
    Image pm = GenImageColor(16, 16, BLANK);
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++)
        {
            unsigned char rg[3];
            Vector3 n = Vector3Normalize((Vector3){ 0.4f*sinf(x*0.7f), 0.3f*cosf(y*0.5f), 1.0f });
            RblEncodeNormal(n, RBL_NORMAL_HEMIOCT, rg);
            ImageDrawPixel(&pm, x, y, (Color){ rg[0], rg[1], 150, (unsigned char)(40 + 12*x) });
        }
    Texture2D packed = LoadTextureFromImage(pm);
    UnloadImage(pm);
    Texture2D albedo = solidTexture((Color){ 210, 180, 150, 255 });
    RblLight lights[2];
    lights[0] = litDirectional((Vector3){ -0.3f, -0.5f, -0.8f }, 1.2f);
    lights[1] = litPoint((Vector3){ 1.0f, 0.8f, 3.0f }, 3.0f, 6.0f);
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = lights; scene.lightCount = 2;
    scene.ambient = (Color){ 110, 130, 170, 255 }; scene.ambientGround = (Color){ 90, 60, 30, 255 }; scene.ambientUp = (Vector3){ 0.0f, 1.0f, 0.0f };
    RT_CHECK(RblSetScene(&scene), "scene rejected");
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = 2; desc.shading.lightFeatures = RblGetLightFeatures(lights, 2); desc.shading.brdf = RBL_BRDF_GGX;
    desc.material.normalEncoding = RBL_NORMAL_HEMIOCT; desc.material.occlusion = true; desc.material.specular = true;
    RblGBufferDesc gd;
    memset(&gd, 0, sizeof(gd));
    gd.width = DT_SIZE; gd.height = DT_SIZE; gd.shading.brdf = desc.shading.brdf; gd.shading.lightFeatures = desc.shading.lightFeatures;
    RblGBuffer g = RblLoadGBuffer(gd);
    RT_CHECK(RblIsGBufferValid(g), "G-buffer failed");
    Material m = LoadMaterialDefault();
    m.maps[MATERIAL_MAP_ALBEDO].texture = albedo;
    m.maps[MATERIAL_MAP_NORMAL].texture = packed;
    m.maps[MATERIAL_MAP_METALNESS].value = 0.4f;
    m.maps[MATERIAL_MAP_EMISSION].color = (Color){ 30, 10, 0, 255 };
    Camera3D camera;
    memset(&camera, 0, sizeof(camera));
    camera.position = (Vector3){ 0.0f, 0.0f, 10.0f }; camera.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    camera.fovy = 30.0f; camera.projection = CAMERA_PERSPECTIVE;
    const int counts[2] = { 1000, 10000 };
    RblInstance *in = (RblInstance *)calloc(10000, sizeof(RblInstance));
    unsigned int seed = 777u;
    for (int i = 0; i < 10000; i++)
    {
        float r[4];
        for (int k = 0; k < 4; k++) { seed = seed*1664525u + 1013904223u; r[k] = (float)(seed >> 8)/16777216.0f; }
        in[i].position = (Vector3){ (r[0] - 0.5f)*4.0f, (r[1] - 0.5f)*4.0f, (r[2] - 0.5f)*3.0f };
        in[i].size = (Vector2){ 0.8f, 0.8f }; in[i].origin = (Vector2){ 0.4f, 0.4f };
        in[i].rotation = r[3]*360.0f;
    }
    for (int c = 0; c < 2; c++)
    {
        Image fwd = dtOverdrawFrame(&desc, false, &g, camera, in, counts[c], m);
        Image def = dtOverdrawFrame(&desc, true, &g, camera, in, counts[c], m);
        DefDiff d = defCompare(fwd, def);
        // Mean layers per pixel: sprites x card area / the view's area at the box's middle depth (10)
        double layers = counts[c]*0.64/pow(2.0*10.0*tan(15.0*DEG2RAD), 2.0);
        printf("    %5d sprites (~%.0f layers per pixel): %d pixels, worst %d/255, mean %.3f/255, coverage differs in %d\n",
               counts[c], layers, d.covered, d.worst, d.mean, d.coverage);
        RT_CHECK(d.covered > DT_SIZE*DT_SIZE*3/4 && d.coverage == 0, "%d sprites: %d pixels covered, coverage differs in %d", counts[c], d.covered, d.coverage);
        RT_CHECK(d.worst <= 1, "%d overlapping sprites: deferred differs from forward by %d/255", counts[c], d.worst);
        if (rtFailuresInCurrentTest() > 0) { rtSaveImage(fwd, "overdraw-forward"); rtSaveImage(def, "overdraw-deferred"); }
        UnloadImage(fwd); UnloadImage(def);
    }
    free(in);
    MemFree(m.maps);
    UnloadTexture(packed); UnloadTexture(albedo);
    RblUnloadGBuffer(&g);
}

// ---- thin sprites: forward against deferred ---------------------------------------------------
// Both frames compared (and kept under build/test-output/ when the test has failed)
static DefDiff dtCompare(Image fwd, Image def, const char *tag)
{
    DefDiff d = defCompare(fwd, def);
    if (rtFailuresInCurrentTest() > 0)
    {
        char name[64];
        snprintf(name, sizeof(name), "%s-forward", tag); rtSaveImage(fwd, name);
        snprintf(name, sizeof(name), "%s-deferred", tag); rtSaveImage(def, name);
    }
    return d;
}

static RblGBufferDesc dtGBufferDesc(const RblLitShaderDesc *d)
{
    RblGBufferDesc g;
    memset(&g, 0, sizeof(g));
    g.width = SH_TARGET; g.height = SH_TARGET;
    g.shading.brdf = d->shading.brdf; g.shading.lightFeatures = d->shading.lightFeatures; g.shading.shadowMaps = d->shading.shadowMaps;
    g.transmission = d->transmission; g.relief = d->relief; g.shadowTransmittance = d->shadowTransmittance;
    return g;
}

// Transmission: a leaf card (thickness in A, a gradient) seen from above, lit from below by a
// directional light (full-screen pass) and a bounded point light (volume), from above by a grazing
// spot (wrap zone); an opaque card of a program without transmission lies half over it, nearer the
// eye (its geometry variant writes transmission 0 over the leaf's)
typedef struct DtLeaf { Texture2D albedo, material, white; float transmission; } DtLeaf;

static void dtLeafDraw(const Shader *shaders, void *ctx)
{
    const DtLeaf *leaf = (const DtLeaf *)ctx;
    Material m = LoadMaterialDefault();
    m.shader = shaders[0];
    m.maps[MATERIAL_MAP_ALBEDO].texture = leaf->albedo;
    m.maps[MATERIAL_MAP_NORMAL].texture = leaf->material;
    m.params[RBL_PARAM_TRANSMISSION] = leaf->transmission;
    RblBillboard b = litPlane();
    b.size = (Vector2){ 5.0f, 5.0f }; b.origin = (Vector2){ 2.5f, 2.5f };
    RblDrawBillboard(shTopDown(), m, b);
    Material plain = LoadMaterialDefault();
    plain.shader = shaders[1];
    plain.maps[MATERIAL_MAP_ALBEDO].texture = leaf->white;
    RblBillboard over = b;
    over.position = (Vector3){ 2.6f, 1.6f, 0.5f };
    RblDrawBillboard(shTopDown(), plain, over);
    MemFree(m.maps); MemFree(plain.maps);
}

static void test_deferred_transmission_matches_forward_within_1_of_255(void)
{
    RblLight lights[3];
    lights[0] = litDirectional((Vector3){ 0.3f, -0.2f, 1.0f }, 1.5f);               // travels +Z: behind the card
    lights[1] = litPoint((Vector3){ -1.0f, 0.8f, -1.2f }, 3.0f, 5.0f);              // below: behind, bounded
    lights[2] = litSpot((Vector3){ -4.0f, -1.0f, 0.5f }, (Vector3){ 1.0f, 0.2f, -0.12f }, 20.0f, 50.0f, 6.0f);
    RT_CHECK(renderSetLights(lights, 3, (Color){ 30, 34, 40, 255 }), "scene rejected");
    Image mi = GenImageColor(16, 16, BLANK);
    for (int y = 0; y < 16; y++) for (int x = 0; x < 16; x++) ImageDrawPixel(&mi, x, y, (Color){ 0, 0, 0, (unsigned char)(10*x + 3*y) });
    DtLeaf leaf;
    leaf.material = LoadTextureFromImage(mi);
    UnloadImage(mi);
    leaf.albedo = solidTexture((Color){ 120, 200, 80, 255 });
    leaf.white = solidTexture((Color){ 230, 230, 230, 255 });
    for (int brdf = RBL_BRDF_LAMBERT; brdf <= RBL_BRDF_GGX; brdf += 2)
    {
        RblLitShaderDesc d;
        memset(&d, 0, sizeof(d));
        d.maxLights = 3; d.shading.lightFeatures = RblGetLightFeatures(lights, 3); d.shading.brdf = brdf;
        d.transmission = true; d.material.thickness = RBL_CHANNEL_A;
        RblLitShaderDesc plainDesc = d;
        plainDesc.transmission = false; plainDesc.material.thickness = RBL_CHANNEL_NONE;
        Shader fwd[2] = { RblLoadLitShader(d), RblLoadLitShader(plainDesc) };
        d.deferred = plainDesc.deferred = true;
        Shader geo[2] = { RblLoadLitShader(d), RblLoadLitShader(plainDesc) };
        RblGBuffer g = RblLoadGBuffer(dtGBufferDesc(&d));
        RT_CHECK(RblIsLitShaderValid(fwd[0]) && RblIsLitShaderValid(fwd[1]) && RblIsLitShaderValid(geo[0]) && RblIsLitShaderValid(geo[1]) && RblIsGBufferValid(g),
                 "programs or the transmission G-buffer failed to load");
        leaf.transmission = 0.7f;
        Image f = dtFrame(SH_TARGET, false, &g, shTopDown(), dtLeafDraw, fwd, &leaf);
        Image df = dtFrame(SH_TARGET, true, &g, shTopDown(), dtLeafDraw, geo, &leaf);
        leaf.transmission = 0.0f;
        Image none = dtFrame(SH_TARGET, false, &g, shTopDown(), dtLeafDraw, fwd, &leaf);
        DefDiff diff = dtCompare(f, df, "transmission");
        int through = litDifferingPixels(f, none);
        printf("    brdf %d: %d pixels, worst %d/255, mean %.3f/255, coverage differs in %d; %d pixels lit through the leaf; %d volumes + %d full-screen lights; %d bytes/pixel\n",
               brdf, diff.covered, diff.worst, diff.mean, diff.coverage, through, g.lightsInVolumes, g.lightsFullscreen, RblGBufferBytesPerPixel(&g));
        RT_CHECK(through > diff.covered/3, "transmission lit only %d of %d pixels: the scene tests nothing", through, diff.covered);
        RT_CHECK(g.lightsInVolumes == 2 && g.lightsFullscreen == 1, "volumes %d, full screen %d", g.lightsInVolumes, g.lightsFullscreen);
        RT_CHECK(diff.coverage == 0 && diff.worst <= 1, "deferred transmission differs from forward by %d/255 (coverage %d)", diff.worst, diff.coverage);
        UnloadImage(f); UnloadImage(df); UnloadImage(none);
        for (int i = 0; i < 2; i++) { RblUnloadLitShader(&fwd[i]); RblUnloadLitShader(&geo[i]); }
        RblUnloadGBuffer(&g);
    }
    // A transmission variant in a G-buffer loaded without it: refused at draw with one line
    RblLitShaderDesc d;
    memset(&d, 0, sizeof(d));
    d.transmission = true; d.deferred = true;
    Shader geo = RblLoadLitShader(d);
    d.transmission = false;
    RblGBuffer plain = RblLoadGBuffer(dtGBufferDesc(&d));
    RT_CHECK(RblIsLitShaderValid(geo) && RblIsGBufferValid(plain), "variant or G-buffer failed");
    RT_CHECK(plain.thin.id == 0, "a G-buffer without transmission or relief has a thin target");
    if (RblBeginGBuffer(&plain, shTopDown()))
    {
        Material m = LoadMaterialDefault();
        m.shader = geo;
        int before = warnings;
        RblDrawBillboard(shTopDown(), m, litPlane());
        RT_CHECK(warnings == before + 1 && strstr(lastWarning, "loaded without it") != NULL, "not refused with one line: %s", lastWarning);
        RblEndGBuffer(&plain);
        MemFree(m.maps);
    }
    RblUnloadLitShader(&geo);
    RblUnloadGBuffer(&plain);
    // A context with 4 draw buffers (ES 3 / WebGL2's minimum): the thin G-buffer and a deferred
    // transmission variant are refused with one line each; a plain G-buffer still loads
    rbl__state.gbufferFourDrawBuffers = true;
    d.transmission = true; d.maxLights = 2;                 // a desc not compiled yet
    int before = warnings;
    RblGBuffer thin = RblLoadGBuffer(dtGBufferDesc(&d));
    RT_CHECK(!RblIsGBufferValid(thin) && warnings == before + 1, "a thin G-buffer loaded with 4 draw buffers (%d lines)", warnings - before);
    geo = RblLoadLitShader(d);
    RT_CHECK(!RblIsLitShaderValid(geo) && warnings == before + 2 && strstr(lastWarning, "5th render target") != NULL, "a deferred transmission variant loaded with 4 draw buffers: %s", lastWarning);
    d.transmission = false;
    plain = RblLoadGBuffer(dtGBufferDesc(&d));
    RT_CHECK(RblIsGBufferValid(plain) && warnings == before + 2, "a plain G-buffer failed with 4 draw buffers");
    RblUnloadGBuffer(&plain);
    rbl__state.gbufferFourDrawBuffers = false;
    UnloadTexture(leaf.albedo); UnloadTexture(leaf.material); UnloadTexture(leaf.white);
}

// Relief: the dome and the ridge of tests/relief_reference.h on a card facing the camera, lit by
// three directional lights from three sides (full-screen pass) and a bounded point light (volume)
typedef struct DtRelief { Texture2D albedo, material; } DtRelief;

static void dtReliefDraw(const Shader *shaders, void *ctx)
{
    const DtRelief *r = (const DtRelief *)ctx;
    Material m = LoadMaterialDefault();
    m.shader = shaders[0];
    m.maps[MATERIAL_MAP_ALBEDO].texture = r->albedo;
    m.maps[MATERIAL_MAP_NORMAL].texture = r->material;
    m.maps[MATERIAL_MAP_HEIGHT].value = 6.0f;
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.size = (Vector2){ THIN_CARD, THIN_CARD }; b.origin = (Vector2){ THIN_CARD*0.5f, THIN_CARD*0.5f };
    b.facing = RBL_FACING_FIXED; b.axis = (Vector3){ 0.0f, 0.0f, 1.0f }; b.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    RblDrawBillboard(thinCamera(), m, b);
    MemFree(m.maps);
}

static void test_deferred_relief_matches_forward_within_1_of_255(void)
{
    RblLight lights[4];
    lights[0] = litDirectional((Vector3){ -1.0f, 0.0f, -1.0f }, 0.6f);
    lights[1] = litDirectional((Vector3){ 0.0f, 1.0f, -0.6f }, 0.5f);
    lights[2] = litDirectional((Vector3){ 0.7f, -0.5f, -0.9f }, 0.4f);
    lights[3] = litPoint((Vector3){ 0.5f, -0.4f, 0.6f }, 1.5f, 3.0f);
    RT_CHECK(renderSetLights(lights, 4, (Color){ 30, 30, 30, 255 }), "scene rejected");
    for (int f = THIN_DOME; f <= THIN_RIDGE; f++)
    {
        DtRelief r;
        r.material = thinHeightTexture(f);
        r.albedo = solidTexture((Color){ 200, 190, 180, 255 });
        RblLitShaderDesc d;
        memset(&d, 0, sizeof(d));
        d.maxLights = 4; d.shading.lightFeatures = RblGetLightFeatures(lights, 4); d.shading.brdf = RBL_BRDF_BLINN_PHONG;
        d.material.height = RBL_CHANNEL_A; d.relief = true;
        Shader fwd = RblLoadLitShader(d);
        d.relief = false;
        Shader flat = RblLoadLitShader(d);
        d.relief = true; d.deferred = true;
        Shader geo = RblLoadLitShader(d);
        RblGBuffer g = RblLoadGBuffer(dtGBufferDesc(&d));
        RT_CHECK(RblIsLitShaderValid(fwd) && RblIsLitShaderValid(flat) && RblIsLitShaderValid(geo) && RblIsGBufferValid(g), "programs or the relief G-buffer failed to load");
        Image fi = dtFrame(SH_TARGET, false, &g, thinCamera(), dtReliefDraw, &fwd, &r);
        Image di = dtFrame(SH_TARGET, true, &g, thinCamera(), dtReliefDraw, &geo, &r);
        Image ni = dtFrame(SH_TARGET, false, &g, thinCamera(), dtReliefDraw, &flat, &r);
        DefDiff diff = dtCompare(fi, di, thinFieldNames[f]);
        int shadowed = litDifferingPixels(fi, ni);
        printf("    %-6s %d pixels, worst %d/255, mean %.3f/255, coverage differs in %d; %d pixels shadowed by relief; %d volumes + %d full-screen lights\n",
               thinFieldNames[f], diff.covered, diff.worst, diff.mean, diff.coverage, shadowed, g.lightsInVolumes, g.lightsFullscreen);
        RT_CHECK(shadowed > diff.covered/20, "relief shadowed only %d of %d pixels: the scene tests nothing", shadowed, diff.covered);
        RT_CHECK(g.lightsInVolumes == 1 && g.lightsFullscreen == 3, "volumes %d, full screen %d", g.lightsInVolumes, g.lightsFullscreen);
        RT_CHECK(diff.coverage == 0 && diff.worst <= 1, "%s: deferred relief differs from forward by %d/255 (coverage %d)", thinFieldNames[f], diff.worst, diff.coverage);
        UnloadImage(fi); UnloadImage(di); UnloadImage(ni);
        RblUnloadLitShader(&fwd); RblUnloadLitShader(&flat); RblUnloadLitShader(&geo);
        RblUnloadGBuffer(&g);
        UnloadTexture(r.material); UnloadTexture(r.albedo);
    }
}

// Blended casters: a red glass card and an opaque card over a white floor (test_thin.c's scene),
// a directional light (full-screen pass) and a spot light (volume), each with its transmittance map
typedef struct DtFloor { Texture2D white; } DtFloor;

static void dtFloorDraw(const Shader *shaders, void *ctx)
{
    const DtFloor *fl = (const DtFloor *)ctx;
    Material floor = LoadMaterialDefault();
    floor.shader = shaders[0];
    floor.maps[MATERIAL_MAP_ALBEDO].texture = fl->white;
    RblDrawBillboard(shTopDown(), floor, litPlane());
    MemFree(floor.maps);
}

static void test_deferred_blended_casters_tint_like_forward_within_1_of_255(void)
{
    for (int kind = 0; kind < 2; kind++)
    {
        RblLight light = (kind == 0)? litDirectional((Vector3){ 0.5f, 0.3f, -1.0f }, 1.0f) : litSpot((Vector3){ -2.0f, -1.2f, 4.0f }, (Vector3){ 0.5f, 0.3f, -1.0f }, 40.0f, 70.0f, 14.0f);
        RblLitShaderDesc d;
        memset(&d, 0, sizeof(d));
        d.maxLights = 1; d.shading.lightFeatures = RblGetLightFeatures(&light, 1); d.shading.shadowMaps = 1; d.shadowTransmittance = true;
        Shader fwd = RblLoadLitShader(d);
        RblGBufferDesc gd = dtGBufferDesc(&d);
        d.shadowTransmittance = false; d.deferred = true;
        Shader geo = RblLoadLitShader(d);
        RblGBuffer g = RblLoadGBuffer(gd);
        RblShadowDesc sd;
        memset(&sd, 0, sizeof(sd));
        sd.size = SH_MAP; sd.transmittance = true;
        RblShadowMap map = RblLoadShadowMap(sd);
        DtFloor fl;
        fl.white = solidTexture(WHITE);
        Texture2D glass = solidTexture((Color){ 255, 40, 40, 128 });
        RT_CHECK(RblIsLitShaderValid(fwd) && RblIsLitShaderValid(geo) && RblIsGBufferValid(g) && RblIsShadowMapValid(map), "programs, G-buffer or map failed to load");
        Material opaqueMat = LoadMaterialDefault(), glassMat = LoadMaterialDefault();
        opaqueMat.shader = glassMat.shader = fwd;
        opaqueMat.maps[MATERIAL_MAP_ALBEDO].texture = fl.white;
        glassMat.maps[MATERIAL_MAP_ALBEDO].texture = glass;
        RblScene scene;
        memset(&scene, 0, sizeof(scene));
        scene.lights = &light; scene.lightCount = 1; scene.ambient = (Color){ 40, 40, 40, 255 };
        RT_CHECK(RblBeginShadowMap(&map, &scene, 0, (Vector3){ 0.0f, 0.0f, 0.0f }, SH_FOCUS), "shadow pass refused");
        ShCard opaqueCard = { { 1.8f, 0.0f, 1.0f }, 1.4f, 0 }, glassCard = { { -1.5f, 0.0f, 1.0f }, 1.6f, 0 };
        shCardCasters(opaqueMat, shTopDown(), &opaqueCard);
        RT_CHECK(RblBeginShadowBlend(true), "blend pass refused");
        shCardCasters(glassMat, shTopDown(), &glassCard);
        RblEndShadowBlend();
        RblEndShadowMap(&map);
        scene.shadowMaps = &map; scene.shadowMapCount = 1;
        RT_CHECK(RblSetScene(&scene), "scene rejected");
        Image fi = dtFrame(SH_TARGET, false, &g, shTopDown(), dtFloorDraw, &fwd, &fl);
        Image di = dtFrame(SH_TARGET, true, &g, shTopDown(), dtFloorDraw, &geo, &fl);
        DefDiff diff = dtCompare(fi, di, (kind == 0)? "tint-directional" : "tint-spot");
        int red = 0;
        for (int y = 0; y < SH_TARGET; y++)
            for (int x = 0; x < SH_TARGET; x++) { Color c = rtPixel(fi, x, y); red += (c.r > c.g + 30); }
        printf("    %-11s %d pixels, worst %d/255, mean %.3f/255, coverage differs in %d; %d floor pixels tinted red; %d volumes + %d full-screen lights\n",
               (kind == 0)? "directional" : "spot", diff.covered, diff.worst, diff.mean, diff.coverage, red, g.lightsInVolumes, g.lightsFullscreen);
        RT_CHECK(red > 300, "the glass tinted only %d floor pixels: the scene tests nothing", red);
        RT_CHECK((kind == 0)? (g.lightsFullscreen == 1) : (g.lightsInVolumes == 1), "the light took the other pass (%d volumes, %d full screen)", g.lightsInVolumes, g.lightsFullscreen);
        RT_CHECK(diff.coverage == 0 && diff.worst <= 1, "deferred tint differs from forward by %d/255 (coverage %d)", diff.worst, diff.coverage);
        UnloadImage(fi); UnloadImage(di);
        shClearScene();
        MemFree(opaqueMat.maps); MemFree(glassMat.maps);
        UnloadTexture(fl.white); UnloadTexture(glass);
        RblUnloadShadowMap(&map);
        RblUnloadGBuffer(&g);
        RblUnloadLitShader(&fwd); RblUnloadLitShader(&geo);
    }
    // Refused: a G-buffer that reads transmittance without shadow maps
    RblGBufferDesc bad;
    memset(&bad, 0, sizeof(bad));
    bad.width = bad.height = 16; bad.shadowTransmittance = true;
    int before = warnings;
    RblGBuffer g = RblLoadGBuffer(bad);
    RT_CHECK(!RblIsGBufferValid(g) && warnings == before + 1, "shadowTransmittance without shadowMaps was not refused with one line");
}

#define RBL_DEFERRED_THIN_TESTS \
    RT_TEST_GLSL3(test_deferred_overlapping_sprites_1k_and_10k_match_forward_ambient_once_per_pixel), \
    RT_TEST_GLSL3(test_deferred_transmission_matches_forward_within_1_of_255), \
    RT_TEST_GLSL3(test_deferred_relief_matches_forward_within_1_of_255), \
    RT_TEST_GLSL3(test_deferred_blended_casters_tint_like_forward_within_1_of_255)
