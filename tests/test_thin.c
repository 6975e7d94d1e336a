// Thin sprites (issue #26 items 4 and 5), GPU, headless:
// - transmission (RblLitShaderDesc.transmission, Material.params[RBL_PARAM_TRANSMISSION], thickness
//   from a material channel): a card lit from behind against refTransmitted in lighting_reference.h
//   (every light type, both BRDFs, the wrap zone, thickness), value 0 renders as the plain program;
// - relief self-shadow (RblLitShaderDesc.relief): a step, a dome and a ridge marched toward
//   directional lights, against a double-precision march of the same definition (every pixel whose
//   decision is not within 1/500 texel of a texel edge or of the ray must agree) and against the
//   continuous ray (the bounded march's error, stated).
// Included by gpu_tests.h after test_lighting.c (its LitScene helpers).

// ---- transmission ---------------------------------------------------------------------------
static void test_thin_transmission_matches_the_double_reference(void)
{
    struct { const char *name; int brdf; int light; float transmission; int thickness; int view; } cases[] = {
        { "directional behind", RBL_BRDF_LAMBERT, 0, 0.6f, 0, 0 },
        { "point behind", RBL_BRDF_LAMBERT, 1, 0.8f, 0, 0 },
        { "spot behind", RBL_BRDF_GGX, 2, 1.0f, 0, 0 },
        { "front grazing (wrap)", RBL_BRDF_BLINN_PHONG, 3, 0.7f, 0, 0 },
        { "front and behind", RBL_BRDF_GGX, 4, 0.5f, 0, 1 },
        { "thickness in A", RBL_BRDF_LAMBERT, 1, 0.9f, RBL_CHANNEL_A, 0 },
        { "thickness in B", RBL_BRDF_LAMBERT, 0, 1.0f, RBL_CHANNEL_B, 1 },
        { "value above 1 clamps", RBL_BRDF_LAMBERT, 0, 7.0f, 0, 0 },
    };
    for (int i = 0; i < (int)(sizeof(cases)/sizeof(cases[0])); i++)
    {
        LitScene sc = litScene(cases[i].brdf);
        sc.desc.transmission = true;
        sc.values.transmission = cases[i].transmission;
        sc.values.roughness = 0.5f;
        switch (cases[i].light)
        {
            case 0: sc.lights[0] = litDirectional((Vector3){ 0.3f, -0.2f, 1.0f }, 2.0f); sc.count = 1; break;
            case 1: sc.lights[0] = litPoint((Vector3){ 0.4f, 0.3f, -1.2f }, 3.0f, 6.0f); sc.count = 1; break;
            case 2: sc.lights[0] = litSpot((Vector3){ 0.2f, 0.0f, -2.0f }, (Vector3){ -0.1f, 0.0f, 1.0f }, 15.0f, 35.0f, 9.0f); sc.count = 1; break;
            case 3: sc.lights[0] = litDirectional((Vector3){ -1.0f, 0.0f, -0.12f }, 3.0f); sc.count = 1; break;      // N.L = 0.12: reflected and wrapped
            default:
                sc.lights[0] = litPoint((Vector3){ 0.5f, 0.5f, 1.5f }, 2.0f, 8.0f);
                sc.lights[1] = litDirectional((Vector3){ -0.2f, 0.1f, 1.0f }, 1.5f);
                sc.count = 2; break;
        }
        if (cases[i].thickness != RBL_CHANNEL_NONE)
        {
            sc.materialMap = true;
            sc.thickness = cases[i].thickness;
            sc.normal = (cases[i].thickness == RBL_CHANNEL_A)? (Color){ 0, 0, 0, 102 } : (Color){ 0, 0, 153, 255 };
        }
        if (cases[i].view) sc.camera = grazingCamera();
        char name[64];
        snprintf(name, sizeof(name), "transmission-%d", i);
        LitError e = litCheckAgainstReference(&sc, name, 2.0, 0.25);
        printf("    %-24s max %.0f mean %.4f /255 over %d pixels, reference %.1f..%.1f\n", cases[i].name, e.max, e.mean, e.pixels, e.refMin, e.refMax);
        // Behind-lit cases: the term is what lights the card (ambient alone is 20..30/255)
        if (cases[i].light <= 2) RT_CHECK(e.refMax > 60.0, "%s: the reference hardly transmits (%.1f): the case tests nothing", cases[i].name, e.refMax);
    }
}

static void test_thin_transmission_zero_renders_as_the_program_without_it(void)
{
    LitScene sc = litScene(RBL_BRDF_GGX);
    sc.lights[0] = litPoint((Vector3){ 0.4f, 0.3f, 1.0f }, 2.0f, 6.0f);
    sc.lights[1] = litDirectional((Vector3){ 0.3f, -0.2f, 1.0f }, 2.0f);       // behind: lets nothing through at 0
    sc.count = 2;
    LitRender plain = litRender(&sc, 0);
    sc.desc.transmission = true;
    LitRender zero = litRender(&sc, 0);
    int differ = litDifferingPixels(plain.image, zero.image);
    RT_CHECK(differ == 0, "%d pixels differ between transmission 0 and no transmission compiled", differ);
    sc.values.transmission = 0.5f;
    LitRender some = litRender(&sc, 0);
    RT_CHECK(litDifferingPixels(plain.image, some.image) > LIT_TARGET*LIT_TARGET/2, "transmission 0.5 changed too few pixels");
    // Rejection: a thickness channel another map uses (deferred variants: test_deferred_thin.c)
    int before = warnings;
    RblLitShaderDesc bad;
    memset(&bad, 0, sizeof(bad));
    bad.transmission = true; bad.material.occlusion = true; bad.material.thickness = RBL_CHANNEL_A;
    Shader s = RblLoadLitShader(bad);
    RT_CHECK(!RblIsLitShaderValid(s) && (warnings == before + 1), "thickness in occlusion's channel was not refused with one log line");
    litRenderUnload(&plain); litRenderUnload(&zero); litRenderUnload(&some);
}

// A transmitting card lit from behind, with an opaque card between it and the light: the light
// reaching the back is shadow-mapped too (its own caster lets it through). Inside the occluder's
// footprint ambient only; elsewhere ambient + refTransmitted; pixels within 2 texels of the
// footprint's edge not judged
static void test_thin_transmission_behind_an_occluder_is_shadowed(void)
{
    RblLight light = litDirectional((Vector3){ 0.5f, 0.3f, 1.0f }, 1.0f);        // travels +Z: behind the card
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = 1; desc.shading.lightFeatures = RBL_LIGHT_FEATURE_DIRECTIONAL; desc.shading.shadowMaps = 1; desc.transmission = true;
    Shader lit = RblLoadLitShader(desc);
    RblShadowDesc sd;
    memset(&sd, 0, sizeof(sd));
    sd.size = SH_MAP;
    RblShadowMap map = RblLoadShadowMap(sd);
    RT_CHECK(RblIsLitShaderValid(lit) && RblIsShadowMapValid(map), "receiver or shadow map failed to load");
    Texture2D white = solidTexture(WHITE);
    Material m = LoadMaterialDefault();
    m.shader = lit;
    m.maps[MATERIAL_MAP_ALBEDO].texture = white;
    m.params[RBL_PARAM_TRANSMISSION] = 0.8f;
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = &light; scene.lightCount = 1; scene.ambient = (Color){ 40, 40, 40, 255 };
    RT_CHECK(RblBeginShadowMap(&map, &scene, 0, (Vector3){ 0.0f, 0.0f, 0.0f }, SH_FOCUS), "shadow pass refused");
    ShCard occluder = { { 0.0f, 0.0f, -1.0f }, 2.0f, 0 };
    shCardCasters(m, shTopDown(), &occluder);
    RblDrawBillboard(shTopDown(), m, litPlane());                                   // the card casts too: never on itself
    RblEndShadowMap(&map);
    scene.shadowMaps = &map; scene.shadowMapCount = 1;
    RT_CHECK(RblSetScene(&scene), "scene rejected");
    RenderTexture2D rt = LoadRenderTexture(SH_TARGET, SH_TARGET);
    BeginTextureMode(rt);
    ClearBackground(BLANK);
    BeginMode3D(shTopDown());
    RblDrawBillboard(shTopDown(), m, litPlane());
    EndMode3D();
    EndTextureMode();
    Image img = rtReadTarget(rt);
    shClearScene();
    D3 l = dNorm(d3(-0.5, -0.3, -1.0));
    double ambient = srgbDecode(40/255.0), back = refClamp((0.25 - l.z)/1.25, 0.0, 1.0)*0.8;
    int litWant = (int)floor(srgbEncode(ambient + back)*255.0 + 0.5), darkWant = (int)floor(srgbEncode(ambient)*255.0 + 0.5);
    float texel = 2.0f*SH_FOCUS/(SH_MAP - 1);
    int inside = 0, outside = 0, worst = 0;
    for (int y = 0; y < SH_TARGET; y++)
        for (int x = 0; x < SH_TARGET; x++)
        {
            float d = shSquareDistance(shFloorAt(x, y), (Vector2){ -0.5f, -0.7f }, (Vector2){ 1.5f, 1.3f });
            if (fabsf(d) < 2.0f*texel) continue;
            int off = abs(rtPixel(img, x, y).g - ((d < 0.0f)? darkWant : litWant));
            if (off > worst) worst = off;
            if (d < 0.0f) inside++; else outside++;
        }
    printf("    transmitted %d/255, shadowed %d/255: %d pixels in the occluder's footprint, %d outside, worst %d/255\n", litWant, darkWant, inside, outside, worst);
    RT_CHECK((inside > 500) && (outside > 500), "footprint too small or too large to judge (%d in, %d out)", inside, outside);
    RT_CHECK(worst <= 2, "worst %d/255 from the shadowed transmission reference", worst);
    if (rtFailuresInCurrentTest() > 0) rtSaveImage(img, "occluded-transmission");
    UnloadImage(img);
    UnloadRenderTexture(rt);
    MemFree(m.maps);
    UnloadTexture(white);
    RblUnloadShadowMap(&map);
    RblUnloadLitShader(&lit);
}

// ---- relief self-shadow ---------------------------------------------------------------------
#include "relief_reference.h"
#define THIN_TARGET 128
static Camera3D thinCamera(void)
{
    Camera3D c;
    memset(&c, 0, sizeof(c));
    c.position = (Vector3){ 0.0f, 0.0f, 4.0f };
    c.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    c.fovy = THIN_CARD*1.04f;
    c.projection = CAMERA_ORTHOGRAPHIC;
    return c;
}

// Renders the card (height field f in the material texture's A, albedo grey) lit by one directional
// light travelling along dir; steps 0 = a program without relief
static Image thinRenderRelief(int f, Vector3 dir, float depth, int steps)
{
    Texture2D material = thinHeightTexture(f);
    Texture2D albedo = solidTexture((Color){ 200, 200, 200, 255 });
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = 1;
    desc.shading.lightFeatures = RBL_LIGHT_FEATURE_DIRECTIONAL;
    desc.material.height = RBL_CHANNEL_A;
    desc.relief = steps > 0;
    desc.reliefSteps = steps;
    Shader lit = RblLoadLitShader(desc);
    RT_CHECK(RblIsLitShaderValid(lit), "relief variant (%d steps) failed to load", steps);
    RblLight light;
    memset(&light, 0, sizeof(light));
    light.type = RBL_LIGHT_DIRECTIONAL; light.direction = dir; light.color = WHITE; light.intensity = 1.0f;
    RT_CHECK(renderSetLights(&light, 1, (Color){ 40, 40, 40, 255 }), "scene rejected");
    Material m = LoadMaterialDefault();
    m.shader = lit;
    m.maps[MATERIAL_MAP_ALBEDO].texture = albedo;
    m.maps[MATERIAL_MAP_NORMAL].texture = material;
    m.maps[MATERIAL_MAP_HEIGHT].value = depth;
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    b.size = (Vector2){ THIN_CARD, THIN_CARD };
    b.origin = (Vector2){ THIN_CARD*0.5f, THIN_CARD*0.5f };
    b.facing = RBL_FACING_FIXED;
    b.axis = (Vector3){ 0.0f, 0.0f, 1.0f };
    b.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    RenderTexture2D rt = LoadRenderTexture(THIN_TARGET, THIN_TARGET);
    BeginTextureMode(rt);
    ClearBackground(BLANK);
    BeginMode3D(thinCamera());
    RblDrawBillboard(thinCamera(), m, b);
    EndMode3D();
    EndTextureMode();
    Image out = rtReadTarget(rt);
    UnloadRenderTexture(rt);
    UnloadTexture(material); UnloadTexture(albedo);
    MemFree(m.maps);
    RblUnloadLitShader(&lit);
    return out;
}

typedef struct ThinReliefStats { int compared, fragile, mirrorMismatch, valueOff, continuousMismatch, shadowed; } ThinReliefStats;

// Compares a render against the double march: pixel (px, py) -> texel point, expected lit/shadowed
// colour (Lambert, flat card facing +Z, ambient 40 grey, albedo 200 grey)
static ThinReliefStats thinCompareRelief(Image img, int f, Vector3 dir, double depth, int steps)
{
    ThinReliefStats st;
    memset(&st, 0, sizeof(st));
    D3 l = dNorm(dScale(d3f(dir), -1.0));
    D3 d = d3(l.x, -l.y, l.z);                   // +U = +X, +V = -Y (down the image), out = +Z
    double albedo = srgbDecode(200/255.0), ambient = srgbDecode(40/255.0);
    double litValue = srgbEncode(albedo*(ambient + fmax(l.z, 0.0)))*255.0, darkValue = srgbEncode(albedo*ambient)*255.0;
    Camera3D cam = thinCamera();
    for (int py = 0; py < THIN_TARGET; py++)
        for (int px = 0; px < THIN_TARGET; px++)
        {
            D3 p;
            if (!refPixelOnPlane(cam, THIN_TARGET, THIN_TARGET, px, py, d3(0, 0, 0), d3(0, 0, 1), &p)) continue;
            double u = (p.x + THIN_CARD*0.5)/THIN_CARD, v = (THIN_CARD*0.5 - p.y)/THIN_CARD;
            if ((u < 0.005) || (u > 0.995) || (v < 0.005) || (v > 0.995)) continue;
            ThinMarch want = thinMarch(f, u*THIN_TEXELS, v*THIN_TEXELS, d, depth, steps);
            ThinMarch exact = thinMarch(f, u*THIN_TEXELS, v*THIN_TEXELS, d, depth, 0);
            Color c = rtPixel(img, px, py);
            bool gotLit = fabs(c.g - litValue) < fabs(c.g - darkValue);
            double off = fabs(c.g - floor((gotLit? litValue : darkValue) + 0.5));
            st.compared++;
            if (!gotLit) st.shadowed++;
            if (off > 2.0) st.valueOff++;
            if (gotLit != exact.lit) st.continuousMismatch++;
            if (want.fragile) { st.fragile++; continue; }
            if (gotLit != want.lit) st.mirrorMismatch++;
        }
    return st;
}

static void test_thin_relief_matches_the_double_march_on_a_step_a_dome_and_a_ridge(void)
{
    const Vector3 dirs[5] = { { -1.0f, 0.0f, -1.0f }, { 0.0f, 1.0f, -0.6f }, { 0.7f, -0.5f, -0.9f }, { -0.3f, -1.0f, -0.5f }, { 0.9f, 0.4f, -2.5f } };
    const int stepsOf[3] = { 16, 5, 48 };
    const double depth = 6.0;
    int worstContinuous = 0, compared = 0, fragile = 0, shadowed = 0;
    printf("    %-6s %-5s %-22s %8s %8s %9s %9s %10s\n", "field", "steps", "light direction", "pixels", "shadowed", "fragile", "mismatch", "vs exact");
    for (int f = 0; f < THIN_FIELDS; f++)
        for (int di = 0; di < 5; di++)
            for (int si = 0; si < 3; si++)
            {
                if ((si > 0) && (di > 1)) continue;        // other step counts on two lights
                Image img = thinRenderRelief(f, dirs[di], (float)depth, stepsOf[si]);
                ThinReliefStats st = thinCompareRelief(img, f, dirs[di], depth, stepsOf[si]);
                printf("    %-6s %5d (%5.2f,%5.2f,%5.2f)     %8d %8d %9d %9d %10d\n", thinFieldNames[f], stepsOf[si], dirs[di].x, dirs[di].y, dirs[di].z,
                       st.compared, st.shadowed, st.fragile, st.mirrorMismatch, st.continuousMismatch);
                RT_CHECK(st.compared > THIN_TARGET*THIN_TARGET/2, "%s: only %d pixels compared", thinFieldNames[f], st.compared);
                RT_CHECK(st.mirrorMismatch == 0, "%s dir %d, %d steps: %d pixels decide unlike the double march", thinFieldNames[f], di, stepsOf[si], st.mirrorMismatch);
                RT_CHECK(st.valueOff == 0, "%s dir %d: %d pixels more than 2/255 from the lit or shadowed value", thinFieldNames[f], di, st.valueOff);
                // The bounded march against the continuous ray (it steps over thin features): at 16 steps
                // at most 2 % of the card's pixels decide otherwise, at 48 at most 0.5 %
                if (stepsOf[si] >= 16) RT_CHECK(st.continuousMismatch*((stepsOf[si] >= 48)? 200 : 50) <= st.compared, "%s dir %d, %d steps: %d of %d pixels differ from the continuous ray",
                                                thinFieldNames[f], di, stepsOf[si], st.continuousMismatch, st.compared);
                if (rtFailuresInCurrentTest() > 0) { char tag[48]; snprintf(tag, sizeof(tag), "relief-%s-%d-%d", thinFieldNames[f], di, stepsOf[si]); rtSaveImage(img, tag); }
                if ((stepsOf[si] >= 16) && (st.continuousMismatch > worstContinuous)) worstContinuous = st.continuousMismatch;
                compared += st.compared; fragile += st.fragile; shadowed += st.shadowed;
                UnloadImage(img);
            }
    printf("    %d pixels compared, %d shadowed by relief, %d fragile (within 1/500 texel: not judged); worst vs the continuous ray at >= 16 steps: %d pixels\n",
           compared, shadowed, fragile, worstContinuous);
    RT_CHECK(shadowed > compared/20, "relief shadowed only %d of %d pixels: the fields test nothing", shadowed, compared);
}

static void test_thin_relief_off_and_flat_relief_shadow_nothing(void)
{
    // The same field without the flag, and with relief height 0 (negative clamps): every pixel lit
    const Vector3 dir = { -1.0f, 0.0f, -1.0f };
    Image off = thinRenderRelief(THIN_STEP, dir, 6.0f, 0);
    Image flat = thinRenderRelief(THIN_STEP, dir, -3.0f, 16);
    ThinReliefStats a = thinCompareRelief(off, THIN_STEP, dir, 0.0, 16), b = thinCompareRelief(flat, THIN_STEP, dir, 0.0, 16);
    RT_CHECK((a.shadowed == 0) && (b.shadowed == 0), "relief off / height <= 0 shadowed %d / %d pixels", a.shadowed, b.shadowed);
    UnloadImage(off); UnloadImage(flat);
    int before = warnings;
    RblLitShaderDesc bad;
    memset(&bad, 0, sizeof(bad));
    bad.relief = true;                                  // no height channel
    Shader s = RblLoadLitShader(bad);
    RT_CHECK(!RblIsLitShaderValid(s) && (warnings == before + 1), "relief without a height channel was not refused with one log line");
    bad.material.height = RBL_CHANNEL_B; bad.reliefSteps = RBL_MAX_RELIEF_STEPS + 1;
    s = RblLoadLitShader(bad);
    RT_CHECK(!RblIsLitShaderValid(s) && (warnings == before + 2), "reliefSteps above the maximum was not refused with one log line");
}

// ---- blended casters: partial, coloured shadows ----------------------------------------------
// A white floor seen from above (test_shadows.c's set-up); a directional light; an opaque card and
// a red glass card (alpha 128) at height 1. The glass is drawn between RblBeginShadowBlend and
// RblEndShadowBlend on each billboard path; the floor's receiver reads the transmittance target.
// Expected in double precision: lit = Lambert(ambient + E cos), under the glass the light x T with
// T = mix(1, glass colour (linear), alpha) coloured or 1 - alpha grey, under the opaque card ambient
// only; every pixel more than 2 texels from a footprint's analytic edge within 2/255
static Image thinBlendRender(int path, int mode, bool receiverReads)
{
    // mode: 0 coloured, 1 grey (coverage only), 2 the glass drawn as an opaque caster would be (no blend pass)
    RblLight light = litDirectional((Vector3){ 0.5f, 0.3f, -1.0f }, 1.0f);
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = 1; desc.shading.lightFeatures = RBL_LIGHT_FEATURE_DIRECTIONAL; desc.shading.shadowMaps = 1;
    desc.shadowTransmittance = receiverReads;
    Shader lit = RblLoadLitShader(desc);
    RblShadowDesc sd;
    memset(&sd, 0, sizeof(sd));
    sd.size = SH_MAP; sd.transmittance = true;
    RblShadowMap map = RblLoadShadowMap(sd);
    RT_CHECK(RblIsLitShaderValid(lit) && RblIsShadowMapValid(map) && (map.transmittance.id != 0), "receiver or transmittance shadow map failed to load");
    Texture2D white = solidTexture(WHITE), glass = solidTexture((Color){ 255, 40, 40, 128 });
    Material opaqueMat = LoadMaterialDefault(), glassMat = LoadMaterialDefault();
    opaqueMat.shader = glassMat.shader = lit;
    opaqueMat.maps[MATERIAL_MAP_ALBEDO].texture = white;
    glassMat.maps[MATERIAL_MAP_ALBEDO].texture = glass;
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = &light; scene.lightCount = 1; scene.ambient = (Color){ 40, 40, 40, 255 };
    Camera3D viewer = shTopDown();
    RT_CHECK(RblBeginShadowMap(&map, &scene, 0, (Vector3){ 0.0f, 0.0f, 0.0f }, SH_FOCUS), "shadow pass refused");
    ShCard opaqueCard = { { 1.8f, 0.0f, 1.0f }, 1.4f, 0 }, glassCard = { { -1.5f, 0.0f, 1.0f }, 1.6f, path };
    shCardCasters(opaqueMat, viewer, &opaqueCard);
    if (mode < 2)
    {
        RT_CHECK(RblBeginShadowBlend(mode == 0), "blend pass refused");
        shCardCasters(glassMat, viewer, &glassCard);
        RblEndShadowBlend();
    }
    RblEndShadowMap(&map);
    scene.shadowMaps = &map; scene.shadowMapCount = 1;
    RT_CHECK(RblSetScene(&scene), "scene rejected");
    Material floor = LoadMaterialDefault();
    floor.shader = lit;
    floor.maps[MATERIAL_MAP_ALBEDO].texture = white;
    RenderTexture2D rt = LoadRenderTexture(SH_TARGET, SH_TARGET);
    BeginTextureMode(rt);
    ClearBackground(BLANK);
    BeginMode3D(shTopDown());
    RblDrawBillboard(shTopDown(), floor, litPlane());
    EndMode3D();
    EndTextureMode();
    Image img = rtReadTarget(rt);
    shClearScene();
    UnloadRenderTexture(rt);
    MemFree(floor.maps); MemFree(opaqueMat.maps); MemFree(glassMat.maps);
    UnloadTexture(white); UnloadTexture(glass);
    RblUnloadShadowMap(&map);
    RblUnloadLitShader(&lit);
    return img;
}

typedef struct ThinTint { int judged, glass, opaque, worst; } ThinTint;

static ThinTint thinCompareTint(Image img, int mode, bool receiverReads)
{
    ThinTint t = { 0, 0, 0, 0 };
    D3 l = dNorm(d3(-0.5, -0.3, 1.0));
    double ambient = srgbDecode(40/255.0), cosL = l.z, a = 128/255.0;
    double glassLin[3] = { srgbDecode(1.0), srgbDecode(40/255.0), srgbDecode(40/255.0) };
    float texel = 2.0f*SH_FOCUS/(SH_MAP - 1);
    Vector2 shift = { 0.5f, 0.3f };                     // height 1 x (D.x, D.y)/-D.z
    for (int y = 0; y < SH_TARGET; y++)
        for (int x = 0; x < SH_TARGET; x++)
        {
            Vector2 p = shFloorAt(x, y);
            float dg = shSquareDistance(p, (Vector2){ -1.5f - 0.8f + shift.x, -0.8f + shift.y }, (Vector2){ -1.5f + 0.8f + shift.x, 0.8f + shift.y });
            float dopq = shSquareDistance(p, (Vector2){ 1.8f - 0.7f + shift.x, -0.7f + shift.y }, (Vector2){ 1.8f + 0.7f + shift.x, 0.7f + shift.y });
            if ((fabsf(dg) < 2.0f*texel) || (fabsf(dopq) < 2.0f*texel)) continue;
            double T[3] = { 1.0, 1.0, 1.0 };
            if ((dg < 0.0f) && receiverReads && (mode < 2))
                for (int c = 0; c < 3; c++) T[c] = (mode == 0)? (1.0 - a + a*glassLin[c]) : (1.0 - a);
            if (dopq < 0.0f) T[0] = T[1] = T[2] = 0.0;
            Color got = rtPixel(img, x, y);
            const int g[3] = { got.r, got.g, got.b };
            for (int c = 0; c < 3; c++)
            {
                int want = (int)floor(srgbEncode(ambient + cosL*T[c])*255.0 + 0.5);
                int off = abs(g[c] - want);
                if (off > t.worst) t.worst = off;
            }
            t.judged++;
            t.glass += (dg < 0.0f);
            t.opaque += (dopq < 0.0f);
        }
    return t;
}

static void test_thin_blended_casters_cast_partial_coloured_shadows(void)
{
    const char *paths[3] = { "immediate", "batched", "instanced" };
    const char *modes[3] = { "coloured", "grey", "no blend pass" };
    for (int mode = 0; mode < 3; mode++)
        for (int path = 0; path < 3; path++)
        {
            if ((mode > 0) && (path > 0)) continue;
            Image img = thinBlendRender(path, mode, true);
            ThinTint t = thinCompareTint(img, mode, true);
            printf("    %-14s %-10s %6d pixels judged (%d under the glass, %d under the opaque card): worst %d/255\n", modes[mode], paths[path], t.judged, t.glass, t.opaque, t.worst);
            RT_CHECK((t.glass > 300) && (t.opaque > 300), "%s %s: footprints too small to judge", modes[mode], paths[path]);
            RT_CHECK(t.worst <= 2, "%s %s: worst %d/255 from the double reference", modes[mode], paths[path], t.worst);
            if (rtFailuresInCurrentTest() > 0) { char tag[48]; snprintf(tag, sizeof(tag), "tint-%d-%d", mode, path); rtSaveImage(img, tag); }
            if ((mode == 0) && (path == 0))
            {
                // Under the glass: red kept, green and blue dimmed to about half
                Vector2 c = { -1.0f, 0.3f };
                int px = (int)((c.x + SH_VIEW*0.5f)/SH_VIEW*SH_TARGET), py = (int)((SH_VIEW*0.5f - c.y)/SH_VIEW*SH_TARGET);
                Color under = rtPixel(img, px, py);
                printf("    floor under the red glass: (%d, %d, %d)\n", under.r, under.g, under.b);
                RT_CHECK((under.r > under.g + 40) && (under.g == under.b), "the glass's shadow is not red: (%d, %d, %d)", under.r, under.g, under.b);
            }
            UnloadImage(img);
        }
    // A receiver that does not read the target is untinted (the glass casts nothing opaque)
    Image img = thinBlendRender(0, 0, false);
    ThinTint t = thinCompareTint(img, 0, false);
    RT_CHECK(t.worst <= 2, "receiver without shadowTransmittance: worst %d/255 from the untinted reference", t.worst);
    UnloadImage(img);
    // Refusals: outside a pass, a map without the target; the ES 2 refusal is in the desc check
    int before = warnings;
    RT_CHECK(!RblBeginShadowBlend(true) && (warnings == before + 1), "RblBeginShadowBlend outside a shadow pass was not refused with one log line");
    RblShadowDesc sd;
    memset(&sd, 0, sizeof(sd));
    sd.size = 64;
    RblShadowMap plain = RblLoadShadowMap(sd);
    RblLight light = litDirectional((Vector3){ 0.0f, 0.0f, -1.0f }, 1.0f);
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = &light; scene.lightCount = 1;
    if (RblBeginShadowMap(&plain, &scene, 0, (Vector3){ 0.0f, 0.0f, 0.0f }, 1.0f))
    {
        before = warnings;
        RT_CHECK(!RblBeginShadowBlend(false) && (warnings == before + 1), "RblBeginShadowBlend on a map without a transmittance target was not refused");
        RblEndShadowMap(&plain);
    }
    RblUnloadShadowMap(&plain);
    RblLitShaderDesc bad;
    memset(&bad, 0, sizeof(bad));
    bad.shadowTransmittance = true;
    before = warnings;
    Shader s = RblLoadLitShader(bad);
    RT_CHECK(!RblIsLitShaderValid(s) && (warnings == before + 1), "shadowTransmittance without shadow maps was not refused with one log line");
}

#define RBL_THIN_TESTS \
    RT_TEST(test_thin_transmission_matches_the_double_reference), \
    RT_TEST(test_thin_transmission_zero_renders_as_the_program_without_it), \
    RT_TEST(test_thin_transmission_behind_an_occluder_is_shadowed), \
    RT_TEST(test_thin_relief_matches_the_double_march_on_a_step_a_dome_and_a_ridge), \
    RT_TEST(test_thin_relief_off_and_flat_relief_shadow_nothing), \
    RT_TEST_GLSL3(test_thin_blended_casters_cast_partial_coloured_shadows)
