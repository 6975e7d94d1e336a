// GPU-skinned Models (RblLitShaderDesc.skinning; raylib built with SUPPORT_GPU_SKINNING): the lit
// variant and the shadow caster skin raylib's bone attributes by the Model's boneMatrices. References:
// tests/skin_rig.h skins the same bind mesh in double precision from the keyframe Transforms, drawn
// with the unskinned lit variant (a CPU-skinned rendering of the same pose).
#include "skin_rig.h"

#define SK_TARGET 128

static Camera3D skCamera(void)
{
    Camera3D c;
    memset(&c, 0, sizeof(c));
    c.position = (Vector3){ 3.5f, -5.5f, 2.2f };
    c.target = (Vector3){ 0.3f, 0.0f, 1.2f };
    c.up = (Vector3){ 0.0f, 0.0f, 1.0f };
    c.fovy = 40.0f;
    c.projection = CAMERA_PERSPECTIVE;
    return c;
}

static RblLitShaderDesc skDesc(bool skinning)
{
    RblLitShaderDesc d;
    memset(&d, 0, sizeof(d));
    d.maxLights = 1;
    d.shading.lightFeatures = RBL_LIGHT_FEATURE_DIRECTIONAL;
    d.shading.brdf = RBL_BRDF_BLINN_PHONG;
    d.skinning = skinning;
    return d;
}

// raylib built without SUPPORT_GPU_SKINNING (a pkg-config raylib): desc.skinning must be refused at
// load with one log line (Mesh.vboId has no bone buffers to draw from); the tests below then stop here
static bool skUnsupported(void)
{
#if RBL_GPU_SKINNING
    return false;
#else
    warnings = 0;
    Shader s = RblLoadLitShader(skDesc(true));
    RT_CHECK(s.id == 0 && warnings == 1, "skinning without RBL_GPU_SKINNING: id %u, %d log lines", s.id, warnings);
    printf("    raylib built without SUPPORT_GPU_SKINNING: desc.skinning refused (checked), nothing to render\n");
    return true;
#endif
}

// One lit frame of model (materials[0] drawn as given) under a directional light from the camera's side
static Image skRender(Model model)
{
    RblLight sun = litDirectional((Vector3){ -0.4f, 1.0f, -0.6f }, 1.0f);
    RT_CHECK(renderSetLights(&sun, 1, (Color){ 30, 30, 30, 255 }), "scene rejected");
    RenderTexture2D rt = LoadRenderTexture(SK_TARGET, SK_TARGET);
    BeginTextureMode(rt);
    ClearBackground(BLANK);
    BeginMode3D(skCamera());
    RblDrawModel(model, (Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f, WHITE);
    EndMode3D();
    EndTextureMode();
    Image img = rtReadTarget(rt);
    UnloadRenderTexture(rt);
    return img;
}

typedef struct SkDiff {
    int covered;        // pixels drawn in either image
    int coverage;       // pixels drawn in one image only
    int interior;       // pixels compared away from edges
    int maxInterior;    // largest channel difference there
    int changed;        // pixels differing by more than 8/255 anywhere (or in coverage)
} SkDiff;

static SkDiff skCompare(Image a, Image b)
{
    SkDiff d;
    memset(&d, 0, sizeof(d));
    for (int y = 0; y < a.height; y++)
        for (int x = 0; x < a.width; x++)
        {
            Color p = rtPixel(a, x, y), q = rtPixel(b, x, y);
            if ((p.a == 0) && (q.a == 0)) continue;
            d.covered++;
            int diff = abs(p.r - q.r);
            if (abs(p.g - q.g) > diff) diff = abs(p.g - q.g);
            if (abs(p.b - q.b) > diff) diff = abs(p.b - q.b);
            if (p.a != q.a) { d.coverage++; d.changed++; continue; }
            if (diff > 8) d.changed++;
            if (skEdge(a, x, y) || skEdge(b, x, y)) continue;
            d.interior++;
            if (diff > d.maxInterior) d.maxInterior = diff;
        }
    return d;
}

// Lit skinned Model: pixels change between keyframes and match the CPU-skinned rendering of each
// pose; at the bind pose (identity bone matrices) it matches the unskinned bind mesh
static void test_skinning_lit_model_animates_and_matches_the_cpu_skinned_rendering(void)
{
    if (skUnsupported()) return;
    Texture2D white = solidTexture(WHITE);
    SkinRig rig = skinRigLoad();
    Shader skinned = RblLoadLitShader(skDesc(true)), plain = RblLoadLitShader(skDesc(false));
    RT_CHECK(RblIsLitShaderValid(skinned) && RblIsLitShaderValid(plain), "skinned or plain lit program failed to load");
    RT_CHECK(skinned.locs[SHADER_LOC_MATRIX_BONETRANSFORMS] != -1 && skinned.locs[SHADER_LOC_VERTEX_BONEIDS] != -1 &&
             skinned.locs[SHADER_LOC_VERTEX_BONEWEIGHTS] != -1, "skinned program lacks boneMatrices or the bone attributes");
    RT_CHECK(plain.locs[SHADER_LOC_MATRIX_BONETRANSFORMS] == -1 && plain.locs[SHADER_LOC_VERTEX_BONEIDS] == -1, "unskinned program declares skinning");
    rig.model.materials[0].shader = skinned;
    rig.model.materials[0].maps[MATERIAL_MAP_ALBEDO].texture = white;
    rig.model.materials[0].maps[MATERIAL_MAP_ALBEDO].color = (Color){ 210, 190, 170, 255 };
    Image gpu[2];
    for (int f = 0; f < 2; f++)
    {
        UpdateModelAnimation(rig.model, rig.anim, (float)f);
        warnings = 0;
        gpu[f] = skRender(rig.model);
        RT_CHECK(warnings == 0, "frame %d: %d log lines (%s)", f, warnings, lastWarning);
        Model cpu = skinCpuModel(&rig, f);
        cpu.materials[0].shader = plain;
        cpu.materials[0].maps[MATERIAL_MAP_ALBEDO] = rig.model.materials[0].maps[MATERIAL_MAP_ALBEDO];
        Image ref = skRender(cpu);
        SkDiff d = skCompare(gpu[f], ref);
        // Interior: float rounding of positions and normals only (both paths shade alike): 2/255.
        // Coverage: silhouette pixels whose centre a rounded vertex moves across, < 1% of those covered.
        RT_CHECK(d.covered > 1000 && d.interior > d.covered/2, "frame %d: %d pixels covered, %d interior (expected a visible column)", f, d.covered, d.interior);
        RT_CHECK(d.maxInterior <= 2, "frame %d: GPU vs CPU skinning differ by %d/255 away from edges (over %d pixels)", f, d.maxInterior, d.interior);
        RT_CHECK(d.coverage*100 <= d.covered, "frame %d: %d of %d pixels covered by one rendering only", f, d.coverage, d.covered);
        printf("    frame %d: GPU vs double CPU skinning: %d px covered, %d interior max %d/255, %d coverage-only, %d differ > 8/255\n",
               f, d.covered, d.interior, d.maxInterior, d.coverage, d.changed);
        if ((d.maxInterior > 2) || (d.coverage*100 > d.covered)) { rtSaveImage(gpu[f], (f == 0)? "gpu0" : "gpu1"); rtSaveImage(ref, (f == 0)? "cpu0" : "cpu1"); }
        UnloadImage(ref);
        cpu.materials[0].shader = (Shader){ 0 };
        cpu.materials[0].maps[MATERIAL_MAP_ALBEDO].texture = (Texture2D){ 0 };
        UnloadModel(cpu);
    }
    // Identity pose: the unskinned program drawing the bind mesh of the same Model
    UpdateModelAnimation(rig.model, rig.anim, 0.0f);
    rig.model.materials[0].shader = plain;
    Image bind = skRender(rig.model);
    SkDiff id = skCompare(gpu[0], bind);
    RT_CHECK(id.maxInterior <= 1 && id.coverage*100 <= id.covered, "identity pose: skinned vs bind mesh %d/255 interior, %d coverage-only of %d", id.maxInterior, id.coverage, id.covered);
    SkDiff anim = skCompare(gpu[0], gpu[1]);
    RT_CHECK(anim.changed > 400, "keyframes 0 and 1 differ in only %d pixels", anim.changed);
    // The zero-weight plate keeps its bind pose: its pixels are the same in both frames
    Vector2 c = GetWorldToScreenEx((Vector3){ 1.1f, 0.0f, 0.4f }, skCamera(), SK_TARGET, SK_TARGET);
    int plateMoved = 0, plateSeen = 0;
    for (int dy = -3; dy <= 3; dy++)
        for (int dx = -3; dx <= 3; dx++)
        {
            Color p = rtPixel(gpu[0], (int)c.x + dx, (int)c.y + dy), q = rtPixel(gpu[1], (int)c.x + dx, (int)c.y + dy);
            if (p.a == 255) plateSeen++;
            if ((p.r != q.r) || (p.g != q.g) || (p.b != q.b) || (p.a != q.a)) plateMoved++;
        }
    RT_CHECK(plateSeen == 49 && plateMoved == 0, "zero-weight plate: %d of 49 pixels drawn, %d changed between frames", plateSeen, plateMoved);
    printf("    identity pose vs bind mesh: interior max %d/255, %d coverage-only; keyframes differ in %d pixels; zero-weight plate unchanged (%d px)\n",
           id.maxInterior, id.coverage, anim.changed, plateSeen);
    if (anim.changed <= 400) { rtSaveImage(gpu[0], "frame0"); rtSaveImage(gpu[1], "frame1"); }
    UnloadImage(bind); UnloadImage(gpu[0]); UnloadImage(gpu[1]);
    rig.model.materials[0].shader = (Shader){ 0 };
    rig.model.materials[0].maps[MATERIAL_MAP_ALBEDO].texture = (Texture2D){ 0 };
    skinRigUnload(&rig);
    RblUnloadLitShader(&skinned);
    RblUnloadLitShader(&plain);
    UnloadTexture(white);
}

// Shadow of a skinned Model: it moves between keyframes and matches the CPU-skinned caster's
static void skModelCaster(Material m, Camera3D viewer, void *ctx)
{
    (void)m; (void)viewer;
    RblDrawModel(*(Model *)ctx, (Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f, WHITE);
}

static void test_skinning_shadow_animates_and_matches_the_cpu_skinned_caster(void)
{
    if (skUnsupported()) return;
    Texture2D white = solidTexture(WHITE);
    SkinRig rig = skinRigLoad();
    Shader skinned = RblLoadLitShader(skDesc(true));
    rig.model.materials[0].shader = skinned;        // the caster swaps in its own program; this is the colour pass's
    ShSetup s = shSetup((Vector3){ 0.6f, 0.35f, -1.0f });
    ShSetup ref = s; ref.noShadow = true;
    Image lit = shRender(&ref, NULL, NULL, white, false);
    Image shadow[2];
    int dark[2];
    for (int f = 0; f < 2; f++)
    {
        UpdateModelAnimation(rig.model, rig.anim, (float)f);
        warnings = 0;
        shadow[f] = shRender(&s, skModelCaster, &rig.model, white, false);
        RT_CHECK(warnings == 0, "frame %d: %d log lines (%s)", f, warnings, lastWarning);
        Model cpu = skinCpuModel(&rig, f);
        Image cref = shRender(&s, skModelCaster, &cpu, white, false);
        UnloadModel(cpu);
        int thr = shThreshold(lit, shadow[f]);
        int mismatch = 0, edge = 0;
        dark[f] = 0;
        for (int y = 0; y < SH_TARGET; y++)
            for (int x = 0; x < SH_TARGET; x++)
            {
                bool a = rtPixel(shadow[f], x, y).r < thr, b = rtPixel(cref, x, y).r < thr;
                if (a) dark[f]++;
                if (a != b) { mismatch++; if (skEdge(shadow[f], x, y) || skEdge(cref, x, y)) edge++; }
            }
        // The two casters differ by float rounding: only penumbra pixels may flip, none inside
        RT_CHECK(dark[f] > 150 && mismatch == edge && mismatch*50 <= dark[f], "frame %d: %d dark pixels, %d differ from the CPU-skinned caster's shadow (%d at edges)", f, dark[f], mismatch, edge);
        printf("    frame %d shadow: %d dark pixels, %d differ from the CPU-skinned caster (all at the penumbra: %s)\n", f, dark[f], mismatch, (mismatch == edge)? "yes" : "no");
        if (mismatch != edge) { rtSaveImage(shadow[f], (f == 0)? "shadow0" : "shadow1"); rtSaveImage(cref, (f == 0)? "cpushadow0" : "cpushadow1"); }
        UnloadImage(cref);
    }
    int thr = shThreshold(lit, shadow[0]), moved = 0;
    for (int y = 0; y < SH_TARGET; y++)
        for (int x = 0; x < SH_TARGET; x++) if ((rtPixel(shadow[0], x, y).r < thr) != (rtPixel(shadow[1], x, y).r < thr)) moved++;
    RT_CHECK(moved > 100, "the shadow changed in only %d pixels between keyframes", moved);
    printf("    shadow moved: %d floor pixels changed between keyframes\n", moved);
    UnloadImage(lit); UnloadImage(shadow[0]); UnloadImage(shadow[1]);
    rig.model.materials[0].shader = (Shader){ 0 };
    skinRigUnload(&rig);
    RblUnloadLitShader(&skinned);
    UnloadTexture(white);
}

// Refusals and the limits: a skinned program draws only GPU-skinned meshes of a Model with bone
// matrices in range; each refusal is one log line and draws nothing
static void test_skinning_bad_input_is_refused_and_draws_nothing(void)
{
    if (skUnsupported()) return;
    SkinRig rig = skinRigLoad();
    Shader skinned = RblLoadLitShader(skDesc(true));
    rig.model.materials[0].shader = skinned;
    UpdateModelAnimation(rig.model, rig.anim, 1.0f);
    Matrix *bones = rig.model.boneMatrices;
    Model cube = LoadModelFromMesh(GenMeshCube(1, 1, 1));
    cube.materials[0].shader = skinned;
    Matrix nanBones[SKIN_BONES];
    memcpy(nanBones, bones, sizeof(nanBones));
    nanBones[1].m13 = NAN;
    struct { const char *what; int kind; } cases[] = {
        { "boneMatrices NULL", 0 }, { "boneCount over RBL_MAX_BONES", 1 }, { "boneCount 0", 2 }, { "NaN bone matrix", 3 },
        { "mesh without bone data", 4 }, { "RblDrawMesh (no bone matrices)", 5 }, { "billboard with a skinned program", 6 },
    };
    for (size_t i = 0; i < sizeof(cases)/sizeof(cases[0]); i++)
    {
        Model m = rig.model;
        if (cases[i].kind == 0) m.boneMatrices = NULL;
        if (cases[i].kind == 1) m.skeleton.boneCount = RBL_MAX_BONES + 1;
        if (cases[i].kind == 2) m.skeleton.boneCount = 0;
        if (cases[i].kind == 3) m.boneMatrices = nanBones;
        RenderTexture2D rt = LoadRenderTexture(SK_TARGET, SK_TARGET);
        BeginTextureMode(rt);
        ClearBackground(BLANK);
        BeginMode3D(skCamera());
        warnings = 0;
        if (cases[i].kind <= 3) RblDrawModel(m, (Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f, WHITE);
        if (cases[i].kind == 4) RblDrawModel(cube, (Vector3){ 0.0f, 0.0f, 1.0f }, 1.0f, WHITE);
        if (cases[i].kind == 5) RblDrawMesh(rig.model.meshes[0], rig.model.materials[0], MatrixIdentity());
        if (cases[i].kind == 6) { RblBillboard b; memset(&b, 0, sizeof(b)); b.size = (Vector2){ 1, 1 }; RblDrawBillboard(skCamera(), rig.model.materials[0], b); }
        int lines = warnings;
        EndMode3D();
        EndTextureMode();
        Image img = rtReadTarget(rt);
        int drawn = 0;
        for (int y = 0; y < SK_TARGET; y++) for (int x = 0; x < SK_TARGET; x++) if (rtPixel(img, x, y).a != 0) drawn++;
        RT_CHECK(lines == 1 && drawn == 0, "%s: %d log lines (expected 1), %d pixels drawn (last: %s)", cases[i].what, lines, drawn, lastWarning);
        UnloadImage(img);
        UnloadRenderTexture(rt);
    }
    // Load-time refusals: skinning on the instanced path
    RblLitShaderDesc d = skDesc(true);
    d.instanced = true;
    warnings = 0;
    Shader s = RblLoadLitShader(d);
    RT_CHECK(s.id == 0 && warnings == 1, "instanced + skinning: id %u, %d log lines", s.id, warnings);
    // An unskinned program draws a skinned Model in its bind pose, quietly (raylib's DrawModel does the same)
    Shader plain = RblLoadLitShader(skDesc(false));
    rig.model.materials[0].shader = plain;
    warnings = 0;
    Image img = skRender(rig.model);
    RT_CHECK(warnings == 0, "unskinned program on a skinned Model: %d log lines (%s)", warnings, lastWarning);
    UnloadImage(img);
    rig.model.materials[0].shader = (Shader){ 0 };
    cube.materials[0].shader = (Shader){ 0 };
    UnloadModel(cube);
    skinRigUnload(&rig);
    RblUnloadLitShader(&skinned);
    RblUnloadLitShader(&plain);
}

// The tests of this file, in order (gpu_tests.h lists every file's)
#define RBL_SKINNING_TESTS \
    RT_TEST(test_skinning_lit_model_animates_and_matches_the_cpu_skinned_rendering), \
    RT_TEST(test_skinning_shadow_animates_and_matches_the_cpu_skinned_caster), \
    RT_TEST(test_skinning_bad_input_is_refused_and_draws_nothing)
