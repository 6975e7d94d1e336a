// Render specification (GPU, headless): shader variants, the lit billboard against an analytic
// Lambert reference, normal-map sides under every flip, batch behaviour, parity with raylib's
// DrawBillboardPro captured from rlgl's own batch. Included by test_gpu_main.c.

#include "gpu_common.h"

// Normal-map texel for a unit tangent-space normal (OpenGL convention), rounded like an 8-bit map
static Color normalTexel(float x, float y, float z)
{
    Color c = { (unsigned char)lroundf((x*0.5f + 0.5f)*255.0f), (unsigned char)lroundf((y*0.5f + 0.5f)*255.0f),
                (unsigned char)lroundf((z*0.5f + 0.5f)*255.0f), 255 };
    return c;
}

typedef struct { Material material; Texture2D albedo, normal; Shader lit; } Scene;

static Scene sceneLoad(Color albedo, Color normal, bool normalMap)
{
    Scene s;
    memset(&s, 0, sizeof(s));
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = 2;
    desc.material.normalEncoding = normalMap? RBL_NORMAL_RGB : RBL_NORMAL_NONE;
    s.lit = RblLoadLitShader(desc);
    s.albedo = solidTexture(albedo);
    s.normal = solidTexture(normal);
    s.material = LoadMaterialDefault();
    s.material.shader = s.lit;
    s.material.maps[MATERIAL_MAP_ALBEDO].texture = s.albedo;
    if (normalMap) s.material.maps[MATERIAL_MAP_NORMAL].texture = s.normal;
    return s;
}

static void sceneUnload(Scene s)
{
    RblUnloadLitShader(&s.lit);
    UnloadTexture(s.albedo);
    UnloadTexture(s.normal);
    MemFree(s.material.maps);       // not UnloadMaterial: the shader and textures are unloaded above
}

// Draws one billboard (immediate path) into a fresh target and returns the image
static Image renderOne(Scene *s, Camera3D cam, RblBillboard b)
{
    RenderTexture2D rt = LoadRenderTexture(TARGET, TARGET);
    BeginTextureMode(rt);
    ClearBackground(BLACK);
    BeginMode3D(cam);
    RblDrawBillboard(cam, s->material, b);
    EndMode3D();
    EndTextureMode();
    Image img = rtReadTarget(rt);
    UnloadRenderTexture(rt);
    return img;
}

static int luminance(Color c) { return c.r + c.g + c.b; }

static RblBillboard centredQuad(void)
{
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.size = (Vector2){ 2.0f, 2.0f };
    b.origin = (Vector2){ 1.0f, 1.0f };
    return b;
}

static RblLight pointLight(Vector3 p, float intensity)
{
    RblLight l;
    memset(&l, 0, sizeof(l));
    l.position = p; l.color = WHITE; l.intensity = intensity; l.range = 0.0f;
    return l;
}

// ---- shaders ------------------------------------------------------------------------------------
static void test_shaders_every_lit_variant_compiles_and_links(void)
{
    const int lights[] = { 0, 1, 2, RBL_MAX_LIGHTS };
    for (int li = 0; li < 4; li++)
    for (int nm = 0; nm < 2; nm++)
    for (int inst = 0; inst < 2; inst++)
    {
        RblLitShaderDesc desc;
        memset(&desc, 0, sizeof(desc));
        desc.maxLights = lights[li];
        desc.material.normalEncoding = nm? RBL_NORMAL_RGB : RBL_NORMAL_NONE;
        desc.instanced = inst;
        if (inst && !rtGlsl3())
        {
            // ES 2 / GL 2.1 have no instancing: refused with one line, nothing compiled
            warnings = 0;
            Shader refused = RblLoadLitShader(desc);
            RT_CHECK((refused.id == 0) && (warnings == 1), "instanced variant on a GLSL 1 context: id %u, %d log lines", refused.id, warnings);
            continue;
        }
        Shader s = RblLoadLitShader(desc);
        RT_CHECK(RblIsLitShaderValid(s), "variant lights=%d normalMap=%d instanced=%d failed", lights[li], nm, inst);
        RT_CHECK(s.id != 0 && s.locs != NULL, "variant lights=%d normalMap=%d instanced=%d came back empty", lights[li], nm, inst);
        if (s.id == 0 || s.locs == NULL) continue;
        RT_CHECK(s.id != rlGetShaderIdDefault(), "variant fell back to raylib's default shader");
        RT_CHECK(rlGetLocationUniform(s.id, "rblLightPosition") != -1 && rlGetLocationUniform(s.id, "rblAmbient") != -1 &&
                 rlGetLocationUniform(s.id, "rblAlphaCutoff") != -1, "uniform locations missing");
        // The tangent is only an active attribute where a normal map uses it; then at raylib's location 4
        if (nm && !inst) RT_CHECK(s.locs[SHADER_LOC_VERTEX_TANGENT] == 4, "vertexTangent not at raylib's location 4 (%d)", s.locs[SHADER_LOC_VERTEX_TANGENT]);
        RT_CHECK((s.locs[SHADER_LOC_MAP_NORMAL] != -1) == (nm != 0), "normal map slot should exist only in the normal-map variant");
        RblUnloadLitShader(&s);
        RT_CHECK(s.id == 0 && s.locs == NULL, "RblUnloadLitShader did not zero the holder");
    }
}

static void test_shaders_compile_failure_is_reported_not_replaced_by_the_default(void)
{
    warnings = 0;
    const char *const broken[] = { "void main() { this is not glsl; }\n", NULL };
    const char *const *const parts[2] = { broken, NULL };
    Shader bad = rbl__loadShaderVariant(rbl__pass_lit_vs, parts, "");
    RT_CHECK(bad.id == 0, "a broken shader must come back invalid, not as raylib's default (id %u)", bad.id);
    // The internal step records why; its public caller logs that once under its own name
    RT_CHECK(warnings == 0 && strstr(rbl__state.problem, "failed to compile") != NULL, "internal step logged %d lines or recorded '%s'", warnings, rbl__state.problem);
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = RBL_MAX_LIGHTS + 1;
    RT_CHECK(!RblIsLitShaderValid(RblLoadLitShader(desc)), "too many light slots must be refused");
    desc.maxLights = -1;
    RT_CHECK(!RblIsLitShaderValid(RblLoadLitShader(desc)), "negative light slots must be refused");
}

// ---- the lit billboard ---------------------------------------------------------------------------
static void test_lit_normal_map_tilted_toward_plus_u_is_brighter_lit_from_plus_u(void)
{
    Camera3D cam = frontCamera();
    const float tilt[2] = { 0.6f, -0.6f };      // the map tilts toward +U, then the mirrored map
    for (int k = 0; k < 2; k++)
    {
        Scene s = sceneLoad(WHITE, normalTexel(tilt[k], 0.0f, 0.8f), true);
        int lum[2];
        for (int side = 0; side < 2; side++)
        {
            RblLight l = pointLight((Vector3){ side? -3.0f : 3.0f, 0.0f, 1.0f }, 6.0f);
            RT_CHECK(renderSetLights(&l, 1, BLACK), "scene rejected");
            Image img = renderOne(&s, cam, centredQuad());
            lum[side] = luminance(rtPixel(img, TARGET/2, TARGET/2));
            if (rtFailuresInCurrentTest() > 0) rtSaveImage(img, side? "minusU" : "plusU");
            UnloadImage(img);
        }
        if (k == 0) RT_CHECK(lum[0] > lum[1] + 30, "tilt +U: lit from +U %d should beat lit from -U %d", lum[0], lum[1]);
        else RT_CHECK(lum[1] > lum[0] + 30, "tilt -U: lit from -U %d should beat lit from +U %d", lum[1], lum[0]);
        sceneUnload(s);
    }
    // The map's +Y is image-up: a map tilting up is brighter lit from above
    Scene s = sceneLoad(WHITE, normalTexel(0.0f, 0.6f, 0.8f), true);
    int lum[2];
    for (int side = 0; side < 2; side++)
    {
        RblLight l = pointLight((Vector3){ 0.0f, side? -3.0f : 3.0f, 1.0f }, 6.0f);
        RT_CHECK(renderSetLights(&l, 1, BLACK), "scene rejected");
        Image img = renderOne(&s, cam, centredQuad());
        lum[side] = luminance(rtPixel(img, TARGET/2, TARGET/2));
        UnloadImage(img);
    }
    RT_CHECK(lum[0] > lum[1] + 30, "tilt image-up: lit from above %d should beat from below %d", lum[0], lum[1]);
    sceneUnload(s);
}

// Double-precision Lambert at the world point seen through pixel (px, py) of the front camera
static double refLambertChannel(int px, int py, Vector3 lightPos, double lightColor, double intensity, double range,
                                double ambient, double albedo, const double nTangent[3])
{
    // Unproject the pixel centre onto the billboard plane z = 0 (camera at z = 5, fovy 45, square target)
    double t = tan(45.0*PI/360.0);
    double ndcX = ((px + 0.5)/TARGET)*2.0 - 1.0, ndcY = 1.0 - ((py + 0.5)/TARGET)*2.0;
    D3 p = d3(ndcX*t*5.0, ndcY*t*5.0, 0.0);
    // Tangent frame of an unflipped camera-facing quad: T = +X, +V = -Y (so image-up = +Y), N = +Z
    D3 n = dNorm(d3(nTangent[0], nTangent[1], nTangent[2]));
    D3 l = dSub(d3f(lightPos), p);
    double d2 = dDot(l, l);
    double ndotl = fmax(dDot(n, dNorm(l)), 0.0);
    double window = 1.0;
    if (range > 0.0) { double x2 = d2/(range*range); window = fmin(fmax(1.0 - x2*x2, 0.0), 1.0); window *= window; }
    // Colours are sRGB-authored: decoded to linear light, lit, encoded back for the RGBA8 target
    double e = srgbDecode(lightColor)*intensity*ndotl*window/fmax(d2, 1e-4);
    return srgbEncode(srgbDecode(albedo)*(srgbDecode(ambient) + e))*255.0;
}

static void test_lit_flat_normal_map_matches_analytic_lambert_within_2_of_255(void)
{
    Camera3D cam = frontCamera();
    const Color albedo = { 230, 180, 120, 255 };
    Color flat = normalTexel(0.0f, 0.0f, 1.0f);      // (128,128,255): decodes to a 0.3 degree tilt
    double decoded[3] = { flat.r/255.0*2.0 - 1.0, flat.g/255.0*2.0 - 1.0, flat.b/255.0*2.0 - 1.0 };
    double vertexOnly[3] = { 0.0, 0.0, 1.0 };
    for (int nm = 0; nm < 2; nm++)
    {
        Scene s = sceneLoad(albedo, flat, nm);
        RblLight l = pointLight((Vector3){ 0.7f, 0.4f, 1.5f }, 1.6f);
        l.color = (Color){ 255, 220, 160, 255 };
        l.range = 6.0f;
        Color ambient = { 30, 30, 30, 255 };
        RT_CHECK(renderSetLights(&l, 1, ambient), "lights rejected");
        Image img = renderOne(&s, cam, centredQuad());
        double worst = 0.0;
        const int probes[5][2] = { { 32, 32 }, { 31, 31 }, { 20, 40 }, { 44, 24 }, { 28, 36 } };
        for (int i = 0; i < 5; i++)
        {
            int px = probes[i][0], py = probes[i][1];
            Color c = rtPixel(img, px, py);
            const unsigned char got[3] = { c.r, c.g, c.b };
            const double lc[3] = { l.color.r/255.0, l.color.g/255.0, l.color.b/255.0 };
            const double al[3] = { albedo.r/255.0, albedo.g/255.0, albedo.b/255.0 };
            for (int ch = 0; ch < 3; ch++)
            {
                double ref = refLambertChannel(px, py, l.position, lc[ch], l.intensity, l.range, ambient.r/255.0, al[ch], nm? decoded : vertexOnly);
                double err = fabs(got[ch] - fmin(ref, 255.0));
                if (err > worst) worst = err;
                RT_CHECK(ref > 20.0 && ref < 235.0, "reference %f outside the informative range", ref);
            }
        }
        RT_CHECK(worst <= 2.0, "normalMap=%d: worst error %.2f/255 against the analytic Lambert", nm, worst);
        if (rtFailuresInCurrentTest() > 0) rtSaveImage(img, nm? "flatmap" : "vertexnormal");
        UnloadImage(img);
        sceneUnload(s);
    }
}

// Under every flip and rotated frame a map tilted toward +U lights the world side the tangent names
static void test_lit_flips_and_rotated_frames_light_the_plus_u_side(void)
{
    Camera3D cam = frontCamera();
    Scene s = sceneLoad(WHITE, normalTexel(0.6f, 0.0f, 0.8f), true);
    RblCameraFrame view = RblGetCameraFrame(cam);
    for (int mask = 0; mask < 16; mask++)
    {
        RblBillboard b = centredQuad();
        if (mask & 1) b.size.x = -2.0f;
        if (mask & 2) b.size.y = -2.0f;
        if (mask & 4) b.source = (Rectangle){ 0, 0, -4, 4 };
        if (mask & 8) b.flags = RBL_FRAME_ROTATED;
        RblVertex q[4];
        RblBillboardVertices(&view, 4, 4, &b, q);
        Vector3 T = { q[0].tangent[0], q[0].tangent[1], q[0].tangent[2] };
        int lum[2];
        for (int side = 0; side < 2; side++)
        {
            float k = side? -3.0f : 3.0f;
            RblLight l = pointLight((Vector3){ T.x*k, T.y*k, 1.0f }, 6.0f);
            RT_CHECK(renderSetLights(&l, 1, BLACK), "scene rejected");
            Image img = renderOne(&s, cam, b);
            lum[side] = luminance(rtPixel(img, TARGET/2, TARGET/2));
            UnloadImage(img);
        }
        RT_CHECK(lum[0] > lum[1] + 30, "mask %d (T = %.0f,%.0f,%.0f): +U side %d should beat -U side %d", mask, T.x, T.y, T.z, lum[0], lum[1]);
    }
    sceneUnload(s);
}

static void test_lit_bad_lights_are_rejected_and_change_nothing(void)
{
    Scene s = sceneLoad(WHITE, normalTexel(0, 0, 1), false);        // 2 light slots
    RblLight good = pointLight((Vector3){ 0, 0, 2 }, 2.0f);
    RT_CHECK(renderSetLights(&good, 1, BLACK), "good light rejected");
    Image before = renderOne(&s, frontCamera(), centredQuad());
    RblLight bad[5] = { good, good, good, good, good };
    bad[0].position.x = NAN; bad[1].intensity = -1.0f; bad[2].range = INFINITY; bad[3].intensity = NAN; bad[4].range = -2.0f;
    for (int i = 0; i < 5; i++)
    {
        warnings = 0;
        RT_CHECK(!renderSetLights(&bad[i], 1, WHITE), "bad light %d accepted", i);
        RT_CHECK(warnings == 1, "bad light %d: %d warnings", i, warnings);
    }
    // A bad light past the program's slots still rejects the scene (the G-buffer lights every one)
    RblLight tail[3] = { good, good, bad[0] };
    warnings = 0;
    RT_CHECK(!renderSetLights(tail, 3, WHITE), "bad light after the slots accepted");
    RT_CHECK(warnings == 1, "bad light after the slots: %d warnings", warnings);
    warnings = 0;
    RT_CHECK(!renderSetLights(&good, -1, WHITE), "negative light count accepted");
    RT_CHECK(!renderSetLights(NULL, 1, WHITE), "NULL lights accepted");
    RT_CHECK(warnings == 2, "%d warnings", warnings);
    Image after = renderOne(&s, frontCamera(), centredQuad());
    Color a = rtPixel(before, 32, 32), b = rtPixel(after, 32, 32);
    RT_CHECK(a.r == b.r && a.g == b.g && a.b == b.b, "rejected lights changed the image (%d vs %d)", a.r, b.r);
    // More lights than slots is no error: the program lights the first maxLights (here the good light
    // and a dark one, so the image is unchanged), the rest are ignored with one (info) log line naming it
    RblLight three[3] = { good, good, pointLight((Vector3){ 0.5f, 0.5f, 0.5f }, 50.0f) };
    three[1].intensity = 0.0f;
    char programName[32];
    snprintf(programName, sizeof(programName), "program %u ", s.lit.id);
    warnings = 0;
    lastWarning[0] = '\0';
    SetTraceLogLevel(LOG_INFO);
    RT_CHECK(renderSetLights(three, 3, BLACK), "more lights than slots rejected");
    SetTraceLogLevel(LOG_WARNING);
    RT_CHECK(warnings == 1 && strstr(lastWarning, programName) != NULL, "lights beyond the slots: %d log lines, want 1 naming %s(%s)", warnings, programName, lastWarning);
    Image capped = renderOne(&s, frontCamera(), centredQuad());
    Color c = rtPixel(capped, 32, 32);
    RT_CHECK(a.r == c.r && a.g == c.g && a.b == c.b, "a light beyond the slots changed the image (%d vs %d)", a.r, c.r);
    // Zero lights: ambient only; a light a hair in front of the surface hits the distance clamp and saturates
    RT_CHECK(renderSetLights(NULL, 0, (Color){ 64, 64, 64, 255 }), "zero lights rejected");
    Image amb = renderOne(&s, frontCamera(), centredQuad());
    RT_CHECK(abs(rtPixel(amb, 32, 32).r - 64) <= 1, "ambient only: %d", rtPixel(amb, 32, 32).r);
    RblLight onSurface = pointLight((Vector3){ 0.0f, 0.0f, 1e-3f }, 1.0f);
    RT_CHECK(renderSetLights(&onSurface, 1, BLACK), "light on the surface rejected");
    Image hot = renderOne(&s, frontCamera(), centredQuad());
    RT_CHECK(rtPixel(hot, 32, 32).r == 255, "light on the surface should saturate, got %d", rtPixel(hot, 32, 32).r);
    UnloadImage(before); UnloadImage(after); UnloadImage(capped); UnloadImage(amb); UnloadImage(hot);
    sceneUnload(s);
}

// ---- batch --------------------------------------------------------------------------------------
static void test_batch_grows_with_a_log_line_skips_bad_input_once_and_matches_immediate(void)
{
    Camera3D cam = frontCamera();
    Scene s = sceneLoad((Color){ 200, 150, 100, 255 }, normalTexel(0, 0, 1), false);
    RblLight l = pointLight((Vector3){ 1, 1, 3 }, 8.0f);
    RT_CHECK(renderSetLights(&l, 1, (Color){ 20, 20, 20, 255 }), "scene rejected");
    RblBatch batch = RblLoadBatch(2);
    RT_CHECK(RblIsBatchValid(batch), "batch not created");
    RenderTexture2D rt = LoadRenderTexture(TARGET, TARGET);
    unsigned int seed = 5u;
    RblBillboard set[9];
    for (int i = 0; i < 9; i++)
    {
        set[i] = centredQuad();
        set[i].size = (Vector2){ 0.6f, 0.6f }; set[i].origin = (Vector2){ 0.3f, 0.3f };
        set[i].position = (Vector3){ rtRandomRange(&seed, -1.5f, 1.5f), rtRandomRange(&seed, -1.5f, 1.5f), -0.1f*i };
        set[i].facing = i%4;
    }
    set[4].position.y = NAN;        // skipped
    set[6].rotation = INFINITY;     // skipped, not logged again
    SetTraceLogLevel(LOG_INFO);
    for (int frame = 0; frame < 2; frame++)
    {
        warnings = 0;
        BeginTextureMode(rt);
        ClearBackground(BLACK);
        BeginMode3D(cam);
        RblBeginBatch(&batch, cam);
        int added = 0;
        for (int i = 0; i < 9; i++) added += RblBatchAdd(&batch, s.material, &set[i]);
        RT_CHECK(added == 7 && batch.count == 7 && batch.skipped == 2, "frame %d: added %d count %d skipped %d", frame, added, batch.count, batch.skipped);
        RblEndBatch(&batch);
        EndMode3D();
        EndTextureMode();
        // frame 0: one "grown" info line per doubling (2 -> 4 -> 8) plus one skip warning; frame 1: the skip warning only
        RT_CHECK(warnings == ((frame == 0)? 3 : 1), "frame %d: %d RBL log lines (%s)", frame, warnings, lastWarning);
        RT_CHECK(batch.capacity == 8, "capacity %d", batch.capacity);
    }
    SetTraceLogLevel(LOG_WARNING);
    Image batched = rtReadTarget(rt);
    // The same billboards drawn one by one through the immediate path give the same pixels
    BeginTextureMode(rt);
    ClearBackground(BLACK);
    BeginMode3D(cam);
    for (int i = 0; i < 9; i++) RblDrawBillboard(cam, s.material, set[i]);
    EndMode3D();
    EndTextureMode();
    Image immediate = rtReadTarget(rt);
    int differing = 0, lit = 0;
    for (int y = 0; y < TARGET; y++)
    for (int x = 0; x < TARGET; x++)
    {
        Color a = rtPixel(batched, x, y), b = rtPixel(immediate, x, y);
        if (a.r != b.r || a.g != b.g || a.b != b.b) differing++;
        if (a.r > 0) lit++;
    }
    RT_CHECK(lit > 200, "batched image nearly empty (%d lit pixels)", lit);
    RT_CHECK(differing == 0, "%d pixels differ between batched and immediate", differing);
    if (rtFailuresInCurrentTest() > 0) { rtSaveImage(batched, "batched"); rtSaveImage(immediate, "immediate"); }
    UnloadImage(batched); UnloadImage(immediate);
    UnloadRenderTexture(rt);
    RblUnloadBatch(&batch);
    RT_CHECK(!RblIsBatchValid(batch) && batch.state == NULL, "unload left state behind");
    sceneUnload(s);
}

// ---- parity with raylib ---------------------------------------------------------------------------
// raylib's own DrawBillboardPro output, captured from an rlgl batch before it is drawn
static void test_parity_camera_plane_positions_and_uvs_equal_raylib_draw_billboard_pro(void)
{
    rlRenderBatch capture = rlLoadRenderBatch(1, 4096);
    RenderTexture2D scratch = LoadRenderTexture(8, 8);
    Texture2D tex = { rlGetTextureIdDefault(), 256, 128, 1, PIXELFORMAT_UNCOMPRESSED_R8G8B8A8 };
    unsigned int seed = 2024u;
    double worstPos = 0.0, worstUv = 0.0;
    int compared = 0;
    for (int camIndex = 0; camIndex < 8; camIndex++)
    {
        Camera3D cam = frontCamera();
        cam.position = (Vector3){ rtRandomRange(&seed, -10, 10), rtRandomRange(&seed, -5, 8), rtRandomRange(&seed, 5, 15) };
        cam.target = (Vector3){ rtRandomRange(&seed, -2, 2), rtRandomRange(&seed, -2, 2), rtRandomRange(&seed, -2, 2) };
        RblCameraFrame view = RblGetCameraFrame(cam);
        BeginTextureMode(scratch);
        rlSetRenderBatchActive(&capture);
        RblBillboard set[64];
        for (int i = 0; i < 64; i++)
        {
            RblBillboard b;
            memset(&b, 0, sizeof(b));
            b.position = (Vector3){ rtRandomRange(&seed, -5, 5), rtRandomRange(&seed, -5, 5), rtRandomRange(&seed, -5, 5) };
            b.size = (Vector2){ rtRandomRange(&seed, 0.1f, 3), rtRandomRange(&seed, 0.1f, 3) };
            b.origin = (Vector2){ rtRandomRange(&seed, 0, 1.5f), rtRandomRange(&seed, 0, 1.5f) };
            b.rotation = (i%2)? rtRandomRange(&seed, -180, 180) : 0.0f;
            b.source = (Rectangle){ floorf(rtRandomRange(&seed, 0, 200)), floorf(rtRandomRange(&seed, 0, 100)), floorf(rtRandomRange(&seed, 1, 56)), floorf(rtRandomRange(&seed, 1, 28)) };
            b.up = (i%3 == 0)? (Vector3){ 0, 1, 0 } : (Vector3){ rtRandomRange(&seed, -0.3f, 0.3f), 1.0f, rtRandomRange(&seed, -0.3f, 0.3f) };
            set[i] = b;
            DrawBillboardPro(cam, tex, b.source, b.position, b.up, b.size, b.origin, b.rotation, WHITE);
        }
        const float *rv = capture.vertexBuffer[capture.currentBuffer].vertices;
        const float *rt = capture.vertexBuffer[capture.currentBuffer].texcoords;
        for (int i = 0; i < 64; i++)
        {
            RblVertex q[4];
            RT_CHECK(RblBillboardVertices(&view, tex.width, tex.height, &set[i], q), "skipped");
            double scale = 1.0 + dLen(d3f(set[i].position)) + set[i].size.x + set[i].size.y;
            for (int k = 0; k < 4; k++)
            {
                const float *p = rv + (i*4 + k)*3, *uv = rt + (i*4 + k)*2;
                double e = v3dist(q[k].position, d3(p[0], p[1], p[2]))/scale;
                double eu = fmax(fabs(q[k].texcoord[0] - uv[0]), fabs(q[k].texcoord[1] - uv[1]));
                if (e > worstPos) worstPos = e;
                if (eu > worstUv) worstUv = eu;
            }
            compared++;
        }
        rlSetRenderBatchActive(NULL);      // draws the captured quads (into the scratch target) and resets
        EndTextureMode();
    }
    RT_CHECK(compared == 512, "compared %d billboards", compared);
    RT_CHECK(worstPos < 1e-6, "worst relative position difference from DrawBillboardPro %.3g", worstPos);
    RT_CHECK(worstUv == 0.0, "worst uv difference from DrawBillboardPro %.3g", worstUv);
    printf("    parity: worst relative corner difference %.2e, worst uv difference %.2e over %d billboards\n", worstPos, worstUv, compared);
    rlUnloadRenderBatch(capture);
    UnloadRenderTexture(scratch);
}

// The tests of this file, in order (gpu_tests.h lists every file's)
#define RBL_RENDER_TESTS \
    RT_TEST(test_shaders_every_lit_variant_compiles_and_links), \
    RT_TEST(test_shaders_compile_failure_is_reported_not_replaced_by_the_default), \
    RT_TEST(test_lit_normal_map_tilted_toward_plus_u_is_brighter_lit_from_plus_u), \
    RT_TEST(test_lit_flat_normal_map_matches_analytic_lambert_within_2_of_255), \
    RT_TEST(test_lit_flips_and_rotated_frames_light_the_plus_u_side), \
    RT_TEST(test_lit_bad_lights_are_rejected_and_change_nothing), \
    RT_TEST(test_batch_grows_with_a_log_line_skips_bad_input_once_and_matches_immediate), \
    RT_TEST(test_parity_camera_plane_positions_and_uvs_equal_raylib_draw_billboard_pro)
