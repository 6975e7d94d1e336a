// Clustered forward lights (RblLitShaderDesc.clustered, the scene's light grid; GPU, headless): the
// grid's image equals the light slots' (same scene, every light in a slot) within 1/255 and the
// double-precision reference (tests/lighting_reference.h) of the sum of every light; 256 and 1024
// lights on opaque and blended sprites, the immediate and instanced paths; edge cases (a light on a
// cell corner, lights behind the camera, a cell over its cap, no lights, huge ranges, only unbounded
// lights); shadow receivers shadow the same light; a scene no clustered program reads builds no grid;
// ES 2 / GL 2.1 keep the slots.
// Included by test_gpu_main.c (after test_lighting.c, whose LitScene helpers it reuses).

#define CL_MAX 1024

static bool clHasGrid(void) { int v = rlGetVersion(); return (v == RL_OPENGL_33) || (v == RL_OPENGL_43) || (v == RL_OPENGL_ES_30); }

// Deterministic scatter (LCG), [0, 1)
static float clRand(unsigned int *seed)
{
    *seed = *seed*1664525u + 1013904223u;
    return (float)((*seed >> 8) & 0xFFFFFF)/16777216.0f;
}

// n small point lights (windowed falloff) scattered over the visible part of litPlane (head-on camera),
// 0.1..0.6 above it, range 0.3..0.8; intensity scaled so the sum stays below display white
static void clScatter(RblLight *lights, int n, unsigned int seed, float intensity)
{
    for (int i = 0; i < n; i++)
    {
        Vector3 p = { -1.9f + 3.8f*clRand(&seed), -1.9f + 3.8f*clRand(&seed), 0.1f + 0.5f*clRand(&seed) };
        lights[i] = litPoint(p, intensity*(0.4f + 0.6f*clRand(&seed)), 0.3f + 0.5f*clRand(&seed));
        lights[i].color = (Color){ (unsigned char)(120 + 135*clRand(&seed)), (unsigned char)(120 + 135*clRand(&seed)), (unsigned char)(120 + 135*clRand(&seed)), 255 };
    }
}

typedef struct ClRender { Image image; bool ok; } ClRender;

// The scene's plane (LitScene sc: camera, albedo, values, path) lit by lights[0..n) through a program of
// desc (maxLights, lightFeatures and clustered from the caller); alpha < 255: a blended sprite over BLANK
static ClRender clRender(const LitScene *sc, RblLitShaderDesc desc, const RblLight *lights, int n, unsigned char alpha)
{
    ClRender out;
    memset(&out, 0, sizeof(out));
    if (sc->path == LIT_PATH_INSTANCED) desc.instanced = true;
    Shader lit = RblLoadLitShader(desc);
    RT_CHECK(RblIsLitShaderValid(lit), "clustered: program failed to load");
    if (!RblIsLitShaderValid(lit)) return out;
    RblScene scene = litSceneOf(sc);
    scene.lights = lights;
    scene.lightCount = n;
    RT_CHECK(RblSetScene(&scene), "clustered: scene of %d lights rejected", n);
    Color albedo = sc->albedo;
    albedo.a = alpha;
    Texture2D tex = solidTexture(albedo);
    Material m = LoadMaterialDefault();
    m.shader = lit;
    RtMaterialValues values = sc->values;
    if (alpha < 255) values.alphaCutoff = -1.0f;            // never discard: blended
    rtSetMaterialValues(&m, values);
    m.maps[MATERIAL_MAP_ALBEDO].texture = tex;
    RenderTexture2D rt = LoadRenderTexture(LIT_TARGET, LIT_TARGET);
    BeginTextureMode(rt);
    ClearBackground(BLANK);
    BeginMode3D(sc->camera);
    if (alpha < 255) BeginBlendMode(BLEND_ALPHA);
    litDrawPlane(sc, m);
    if (alpha < 255) EndBlendMode();
    EndMode3D();
    EndTextureMode();
    out.image = rtReadTarget(rt);
    out.ok = true;
    UnloadRenderTexture(rt);
    UnloadTexture(tex);
    MemFree(m.maps);
    RblUnloadLitShader(&lit);
    return out;
}

// Display pixels against the reference sum of lights[0..n) (times alpha/255 for a blended sprite over
// BLANK), interior of the plane; every `step`-th pixel per axis
static LitError clCompare(const LitScene *sc, Image img, const RblLight *lights, int n, unsigned char alpha, int step)
{
    LitError e;
    memset(&e, 0, sizeof(e));
    double sum = 0.0;
    RefParams d = litShading(sc);
    LitFrame f = litFrame(sc);
    for (int py = 1; py < LIT_TARGET - 1; py += step)
        for (int px = 1; px < LIT_TARGET - 1; px += step)
        {
            D3 p;
            if (!refPixelOnPlane(sc->camera, LIT_TARGET, LIT_TARGET, px, py, f.origin, f.N, &p)) continue;
            RefSurface s = litSurface(sc, p);
            RefRgb ref = refFinishAt(&d, refShadeView(&d, lights, n, &sc->env, &s, refViewVector(sc->camera, p)), refViewDistance(sc->camera, p));
            Color c = rtPixel(img, px, py);
            const double a = alpha/255.0;
            const double got[3] = { c.r, c.g, c.b }, want[3] = { ref.r*255.0*a, ref.g*255.0*a, ref.b*255.0*a };
            for (int ch = 0; ch < 3; ch++)
            {
                double q = fabs(got[ch] - floor(want[ch] + 0.5));
                if (q > e.max) e.max = q;
                e.refMin = fmin(e.refMin, want[ch]); e.refMax = fmax(e.refMax, want[ch]);
                sum += q;
            }
            e.pixels++;
        }
    e.mean = (e.pixels > 0)? sum/(3.0*e.pixels) : 0.0;
    return e;
}

// Largest channel difference between two display images (and the pixels that differ)
static int clDiff(Image a, Image b, int *differing)
{
    int worst = 0;
    *differing = 0;
    for (int y = 0; y < LIT_TARGET; y++)
        for (int x = 0; x < LIT_TARGET; x++)
        {
            Color p = rtPixel(a, x, y), q = rtPixel(b, x, y);
            int e = abs(p.r - q.r);
            if (abs(p.g - q.g) > e) e = abs(p.g - q.g);
            if (abs(p.b - q.b) > e) e = abs(p.b - q.b);
            if (abs(p.a - q.a) > e) e = abs(p.a - q.a);
            if (e > worst) worst = e;
            *differing += (e > 0);
        }
    return worst;
}

static LitScene clScene(void)
{
    LitScene sc = litScene(RBL_BRDF_BLINN_PHONG);
    sc.values.specular = 0.5f;
    sc.values.shininess = 24.0f;
    sc.env.ambient = (Color){ 12, 12, 16, 255 };
    return sc;
}

// 60 lights every slot program can hold: 54 small points, a classic-falloff point, a spot, a
// directional light, a light behind the camera, one of huge range, one on a corner of the grid's cells.
// The spot (range 3), the light behind the eye (6) and the huge one reach over a quarter of the light
// set: with the directional light, lit everywhere (4 unbounded)
static int clMixedLights(RblLight *l)
{
    clScatter(l, 54, 7u, 0.05f);
    l[54] = litPoint((Vector3){ 0.6f, -0.4f, 0.5f }, 0.15f, 0.7f);
    l[54].falloff = RBL_FALLOFF_CLASSIC; l[54].constant = 1.0f; l[54].linear = 0.5f; l[54].quadratic = 2.0f;
    l[55] = litSpot((Vector3){ -0.5f, 0.5f, 1.2f }, (Vector3){ 0.2f, -0.3f, -1.0f }, 10.0f, 25.0f, 0.6f);
    l[55].range = 3.0f;
    l[56] = litDirectional((Vector3){ 0.3f, -0.2f, -1.0f }, 0.05f);
    l[57] = litPoint((Vector3){ 0.2f, 0.1f, 5.0f }, 2.0f, 6.0f);          // behind the eye (z 4), reaching the plane
    l[58] = litPoint((Vector3){ -0.3f, 0.2f, 3.0f }, 0.3f, 1e6f);         // huge range: lit everywhere
    l[59] = litPoint((Vector3){ 0.0f, 0.0f, 0.3f }, 0.1f, 0.6f);          // moved onto a cell corner below
    return 60;
}

static void test_clustered_equals_the_slots_and_the_double_reference(void)
{
    static RblLight lights[64];
    int n = clMixedLights(lights);
    LitScene sc = clScene();
    // The corner light: a cell corner inside the grid (the grid's box and cell size come from the
    // other lights, which the move leaves as they are)
    RblScene probe = litSceneOf(&sc);
    probe.lights = lights; probe.lightCount = n;
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.shading.brdf = sc.desc.shading.brdf;
    desc.shading.lightFeatures = RblGetLightFeatures(lights, n);
    desc.clustered = true;
    Shader holder = RblLoadLitShader(desc);         // a clustered program: RblSetScene builds the grid
    RT_CHECK(RblSetScene(&probe), "scene rejected");
    RblLightGridStats g = RblGetLightGridStats();
    Vector3 corner = { g.origin.x + g.cellSize*(float)(g.cells[0]/2), g.origin.y + g.cellSize*(float)(g.cells[1]/2), g.origin.z + g.cellSize*(float)(g.cells[2]/2) };
    lights[59].position = corner;
    RT_CHECK(RblSetScene(&probe), "scene rejected");
    RblLightGridStats g2 = RblGetLightGridStats();
    printf("    grid %dx%dx%d cells of %.3f, %d unbounded, %d entries, fullest cell %d; corner light at (%.3f, %.3f, %.3f)\n",
           g2.cells[0], g2.cells[1], g2.cells[2], g2.cellSize, g2.unbounded, g2.entries, g2.fullestCell, corner.x, corner.y, corner.z);
    RT_CHECK((g2.cellSize == g.cellSize) && (g2.origin.x == g.origin.x) && (g2.origin.y == g.origin.y) && (g2.origin.z == g.origin.z), "moving the corner light changed the grid");
    RT_CHECK(g2.cells[0] > 2 && g2.cells[1] > 2 && g2.cells[2] >= 1, "the grid has too few cells to test (%dx%dx%d)", g2.cells[0], g2.cells[1], g2.cells[2]);
    RT_CHECK(g2.unbounded == 4, "the directional light and the 3 wide ones are lit everywhere (got %d unbounded)", g2.unbounded);
    RT_CHECK(g2.cellSize < 0.6f, "cells (%.3f) narrower than every listed light's diameter (>= 0.6): each straddles cell boundaries", g2.cellSize);
    RblUnloadLitShader(&holder);

    for (int path = LIT_PATH_IMMEDIATE; path <= LIT_PATH_INSTANCED; path += LIT_PATH_INSTANCED - LIT_PATH_IMMEDIATE)
    {
        sc.path = path;
        RblLitShaderDesc slots = desc;
        slots.clustered = false; slots.maxLights = n;
        ClRender a = clRender(&sc, desc, lights, n, 255), b = clRender(&sc, slots, lights, n, 255);
        if (!a.ok || !b.ok) { if (a.ok) UnloadImage(a.image); if (b.ok) UnloadImage(b.image); continue; }
        int differing = 0, worst = clDiff(a.image, b.image, &differing);
        LitError ea = clCompare(&sc, a.image, lights, n, 255, 1), eb = clCompare(&sc, b.image, lights, n, 255, 1);
        const char *name = (path == LIT_PATH_IMMEDIATE)? "immediate" : "instanced";
        printf("    %s: grid vs slots worst %d/255 (%d pixels differ); vs reference grid max %.0f mean %.3f, slots max %.0f mean %.3f (%d px, ref %.0f..%.0f)\n",
               name, worst, differing, ea.max, ea.mean, eb.max, eb.mean, ea.pixels, ea.refMin, ea.refMax);
        RT_CHECK(worst <= 1, "%s: grid and slots differ by %d/255", name, worst);
        RT_CHECK(ea.pixels > LIT_TARGET*LIT_TARGET/2, "%s: only %d pixels compared", name, ea.pixels);
        RT_CHECK(ea.max <= 2.0 && ea.mean <= 0.25, "%s: grid vs reference max %.0f mean %.3f /255", name, ea.max, ea.mean);
        RT_CHECK(ea.refMax > 100.0, "%s: the scene is too dark to test (reference up to %.0f)", name, ea.refMax);
        if (rtFailuresInCurrentTest() > 0) { rtSaveImage(a.image, "clustered"); rtSaveImage(b.image, "slots"); }
        UnloadImage(a.image); UnloadImage(b.image);
    }
}

static void test_clustered_lights_256_and_1024_lights_on_opaque_and_blended_sprites(void)
{
    static RblLight lights[CL_MAX];
    const int counts[2] = { 256, 1024 };
    LitScene sc = clScene();
    for (int c = 0; c < 2; c++)
    {
        const int n = counts[c];
        clScatter(lights, n, 99u + (unsigned int)n, 24.0f/(float)n*((n > 256)? 0.3f : 1.0f));     // 1024: fainter, so the image stays below white
        RblLitShaderDesc desc;
        memset(&desc, 0, sizeof(desc));
        desc.shading.brdf = sc.desc.shading.brdf;
        desc.clustered = true;
        for (int path = LIT_PATH_IMMEDIATE; path <= LIT_PATH_INSTANCED; path += LIT_PATH_INSTANCED - LIT_PATH_IMMEDIATE)
            for (int blended = 0; blended < 2; blended++)
            {
                sc.path = path;
                unsigned char alpha = blended? 128 : 255;
                ClRender r = clRender(&sc, desc, lights, n, alpha);
                if (!r.ok) continue;
                RblLightGridStats g = RblGetLightGridStats();
                LitError e = clCompare(&sc, r.image, lights, n, alpha, 1);
                // What the first 64 lights alone give: the grid must light by all of them
                LitError first = clCompare(&sc, r.image, lights, RBL_MAX_LIGHTS, alpha, 1);
                char name[64];
                snprintf(name, sizeof(name), "%d lights %s %s", n, (path == LIT_PATH_IMMEDIATE)? "immediate" : "instanced", blended? "blended" : "opaque");
                printf("    %s: max %.0f mean %.3f /255 over %d px (ref %.0f..%.0f; the first %d lights alone: max %.0f); grid %dx%dx%d, %d entries, fullest cell %d\n",
                       name, e.max, e.mean, e.pixels, e.refMin, e.refMax, RBL_MAX_LIGHTS, first.max, g.cells[0], g.cells[1], g.cells[2], g.entries, g.fullestCell);
                RT_CHECK(e.pixels > LIT_TARGET*LIT_TARGET/2, "%s: only %d pixels compared", name, e.pixels);
                RT_CHECK(e.max <= 2.0 && e.mean <= 0.25, "%s: vs reference max %.0f mean %.3f /255", name, e.max, e.mean);
                RT_CHECK(first.max > 20.0, "%s: the lights past the first %d change too little to tell (%.0f)", name, RBL_MAX_LIGHTS, first.max);
                RT_CHECK(g.cappedCells == 0, "%s: %d cells capped", name, g.cappedCells);
                if ((rtFailuresInCurrentTest() > 0) || getenv("CL_SAVE")) rtSaveImage(r.image, name);
                UnloadImage(r.image);
            }
    }
}

static void test_clustered_edge_cases_zero_lights_unbounded_only_and_a_capped_cell(void)
{
    static RblLight lights[CL_MAX];
    LitScene sc = clScene();
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.shading.brdf = sc.desc.shading.brdf;
    desc.clustered = true;
    desc.shading.lightFeatures = RBL_LIGHT_FEATURE_POINT | RBL_LIGHT_FEATURE_DIRECTIONAL;
    // No lights: the ambient alone
    ClRender r = clRender(&sc, desc, lights, 0, 255);
    if (r.ok)
    {
        LitError e = clCompare(&sc, r.image, lights, 0, 255, 1);
        RblLightGridStats g = RblGetLightGridStats();
        printf("    0 lights: max %.0f /255; grid %dx%dx%d, %d unbounded\n", e.max, g.cells[0], g.cells[1], g.cells[2], g.unbounded);
        RT_CHECK(e.max <= 1.0 && e.pixels > 0, "0 lights: max %.0f", e.max);
        RT_CHECK(g.cells[0] == 0 && g.unbounded == 0, "0 lights: a grid of %d cells, %d unbounded", g.cells[0], g.unbounded);
        UnloadImage(r.image);
    }
    // Only unbounded lights (directional, range 0, huge range): no cells, every light everywhere
    lights[0] = litDirectional((Vector3){ 0.2f, 0.1f, -1.0f }, 0.3f);
    lights[1] = litPoint((Vector3){ 0.5f, 0.5f, 1.0f }, 0.3f, 0.0f);
    lights[2] = litPoint((Vector3){ -0.5f, -0.5f, 2.0f }, 0.5f, 1e9f);
    r = clRender(&sc, desc, lights, 3, 255);
    if (r.ok)
    {
        LitError e = clCompare(&sc, r.image, lights, 3, 255, 1);
        RblLightGridStats g = RblGetLightGridStats();
        printf("    unbounded only: max %.0f mean %.3f /255 (ref %.0f..%.0f); %d unbounded, %d cells\n", e.max, e.mean, e.refMin, e.refMax, g.unbounded, g.cells[0]*g.cells[1]*g.cells[2]);
        RT_CHECK(g.unbounded == 3, "3 unbounded lights, grid lists %d", g.unbounded);
        RT_CHECK(e.max <= 2.0 && e.mean <= 0.25, "unbounded only: max %.0f mean %.3f", e.max, e.mean);
        UnloadImage(r.image);
    }
    // A capped cell: 200 equal lights at one spot (plus a spread-out set so the grid has cells); every
    // cell they touch lists the scene's first RBL_LIGHT_GRID_CELL_LIGHTS of them, said once
    // (the spread set on the left half, x <= -0.6 + 0.8, the clump's cells right of x = 0.8 - a cell)
    const int clump = 200, spread = 64, n = clump + spread;
    clScatter(lights, spread, 5u, 0.1f);
    for (int i = 0; i < spread; i++) lights[i].position.x = -1.9f + (lights[i].position.x + 1.9f)*(1.3f/3.8f);
    for (int i = spread; i < n; i++) lights[i] = litPoint((Vector3){ 1.3f, 0.3f, 0.3f }, 0.002f, 0.5f);
    warnings = 0;
    r = clRender(&sc, desc, lights, n, 255);
    int logged = warnings;
    if (r.ok)
    {
        RblLightGridStats g = RblGetLightGridStats();
        LitError kept = clCompare(&sc, r.image, lights, spread + RBL_LIGHT_GRID_CELL_LIGHTS, 255, 1);
        LitError all = clCompare(&sc, r.image, lights, n, 255, 1);
        printf("    capped: %d cells over the cap (fullest %d), %d warning(s) \"%s\"; vs the first %d lights max %.0f mean %.3f, vs all %d max %.0f\n",
               g.cappedCells, g.fullestCell, logged, lastWarning, spread + RBL_LIGHT_GRID_CELL_LIGHTS, kept.max, kept.mean, n, all.max);
        RT_CHECK(g.cappedCells > 0 && g.fullestCell >= clump, "the clump caps no cell (fullest %d)", g.fullestCell);
        RT_CHECK(logged == 1 && strstr(lastWarning, "RBL_LIGHT_GRID_CELL_LIGHTS") != NULL, "capped cells logged %d times", logged);
        RT_CHECK(kept.max <= 2.0 && kept.mean <= 0.25, "capped: the image is not the first lights' (max %.0f mean %.3f)", kept.max, kept.mean);
        RT_CHECK(all.max > 4.0, "capped: the lights past the cap should be missing (max %.0f vs all)", all.max);
        UnloadImage(r.image);
    }
    // The same capped scene again: not logged again; a scene without one re-arms the note
    warnings = 0;
    RblScene scene = litSceneOf(&sc);
    scene.lights = lights; scene.lightCount = n;
    Shader holder = RblLoadLitShader(desc);
    RT_CHECK(RblSetScene(&scene) && (warnings == 0), "a second capped scene logged %d line(s)", warnings);
    scene.lightCount = spread;
    RT_CHECK(RblSetScene(&scene) && (warnings == 0), "an uncapped scene logged");
    scene.lightCount = n;
    RT_CHECK(RblSetScene(&scene) && (warnings == 1), "a capped scene after an uncapped one logged %d line(s)", warnings);
    RblUnloadLitShader(&holder);
}

static void test_clustered_grid_is_built_only_for_clustered_programs(void)
{
    static RblLight lights[256];
    clScatter(lights, 256, 3u, 0.05f);
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = 16;
    Shader plain = RblLoadLitShader(desc);
    RT_CHECK(RblIsLitShaderValid(plain), "plain program");
    RT_CHECK(!litHasUniform(plain, "rblGridDims") && litHasUniform(plain, "rblLightPosition"), "the slot program reads the grid");
    int before = RblGetLightGridStats().builds;
    for (int i = 0; i < 3; i++) RT_CHECK(renderSetLights(lights, 256, BLACK), "scene");
    RT_CHECK(RblGetLightGridStats().builds == before, "scenes without a clustered program built %d grids", RblGetLightGridStats().builds - before);
    desc.clustered = true;
    Shader grid = RblLoadLitShader(desc);
    RT_CHECK(RblIsLitShaderValid(grid), "clustered program");
    RT_CHECK(litHasUniform(grid, "rblGridDims") && !litHasUniform(grid, "rblLightPosition"), "the clustered program reads slots");
    RT_CHECK(RblGetLightGridStats().builds == before + 1, "loading a clustered program after the scene builds its grid once (%d)", RblGetLightGridStats().builds - before);
    for (int i = 0; i < 3; i++) RT_CHECK(renderSetLights(lights, 256, BLACK), "scene");
    RT_CHECK(RblGetLightGridStats().builds == before + 4, "one build per scene (%d)", RblGetLightGridStats().builds - before);
    Shader second = RblLoadLitShader(desc);
    RT_CHECK(RblGetLightGridStats().builds == before + 4, "a second clustered program rebuilt the grid");
    RT_CHECK(renderSetLights(lights, 256, BLACK), "scene");
    RT_CHECK(RblGetLightGridStats().builds == before + 5, "two clustered programs built %d grids for one scene", RblGetLightGridStats().builds - before - 4);
    RblUnloadLitShader(&second);
    RblUnloadLitShader(&grid);
    RblUnloadLitShader(&plain);
}

// A shadowed spot light among 20 point lights (the spot is light 7, listed by the grid's cells): a
// clustered receiver's floor equals the slot receiver's (the map shadows the same light), and the card's
// shadow is there (darker than the unshadowed floor)
static Image clShadowRender(const RblLight *lights, int n, int shadowed, bool clustered, bool withMap)
{
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.maxLights = n;
    desc.shading.lightFeatures = RblGetLightFeatures(lights, n);
    desc.shading.shadowMaps = 1;
    desc.clustered = clustered;
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
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = lights; scene.lightCount = n; scene.ambient = (Color){ 30, 30, 30, 255 };
    if (withMap)
    {
        ShCard card = { { 0.3f, -0.2f, 1.0f }, 1.5f, 0 };
        RT_CHECK(RblBeginShadowMap(&map, &scene, shadowed, (Vector3){ 0.0f, 0.0f, 0.0f }, 4.0f), "shadow pass refused");
        shCardCasters(m, shTopDown(), &card);
        RblEndShadowMap(&map);
        scene.shadowMaps = &map; scene.shadowMapCount = 1;
    }
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
    UnloadRenderTexture(rt);
    UnloadTexture(white);
    MemFree(m.maps);
    RblUnloadShadowMap(&map);
    RblUnloadLitShader(&lit);
    return img;
}

static void test_clustered_receivers_shadow_the_same_light_as_the_slots(void)
{
    static RblLight lights[21];
    unsigned int seed = 31u;
    for (int i = 0; i < 21; i++)
    {
        Vector3 p = { -14.0f + 28.0f*clRand(&seed), -14.0f + 28.0f*clRand(&seed), 0.5f + clRand(&seed) };
        lights[i] = litPoint(p, 0.4f, 1.5f + 1.5f*clRand(&seed));
    }
    lights[3].position = (Vector3){ -1.5f, 1.0f, 0.6f };        // two small lights in view
    lights[12].position = (Vector3){ 1.8f, -1.2f, 0.8f };
    const int shadowed = 7;
    lights[shadowed] = litSpot((Vector3){ 0.3f, -0.2f, 4.0f }, (Vector3){ 0.0f, 0.0f, -1.0f }, 50.0f, 60.0f, 16.0f);
    lights[shadowed].range = 6.5f;                              // under a quarter of the lights' extent: in the cells
    Image grid = clShadowRender(lights, 21, shadowed, true, true), slots = clShadowRender(lights, 21, shadowed, false, true);
    Image open = clShadowRender(lights, 21, shadowed, true, false);
    RblLightGridStats g = RblGetLightGridStats();
    int differing = 0, worst = clDiff(grid, slots, &differing), darker = 0;
    for (int y = 0; y < SH_TARGET; y++)
        for (int x = 0; x < SH_TARGET; x++) darker += (rtPixel(grid, x, y).r + 40 < rtPixel(open, x, y).r);
    printf("    shadowed spot (light %d, %d unbounded in the grid): grid vs slots worst %d/255 (%d px differ); %d pixels in the card's shadow\n",
           shadowed, g.unbounded, worst, differing, darker);
    RT_CHECK(g.unbounded == 0, "the spot should be listed by cells (%d unbounded)", g.unbounded);
    RT_CHECK(worst <= 1, "clustered and slot receivers differ by %d/255", worst);
    RT_CHECK(darker > 400, "the card's shadow is missing (%d dark pixels)", darker);
    if (rtFailuresInCurrentTest() > 0) { rtSaveImage(grid, "grid"); rtSaveImage(slots, "slots"); rtSaveImage(open, "unshadowed"); }
    UnloadImage(grid); UnloadImage(slots); UnloadImage(open);
}

static void test_clustered_falls_back_to_the_slots_without_glsl3(void)
{
    static RblLight lights[8];
    clScatter(lights, 8, 11u, 0.3f);
    LitScene sc = clScene();
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.shading.brdf = sc.desc.shading.brdf;
    desc.maxLights = 8;
    desc.clustered = true;
    SetTraceLogLevel(LOG_INFO);             // the fallback is an info line
    lastWarning[0] = '\0';
    Shader lit = RblLoadLitShader(desc);
    SetTraceLogLevel(LOG_WARNING);
    bool said = (strstr(lastWarning, "clustered lights need GLSL 3") != NULL);
    RT_CHECK(said == !clHasGrid(), "the fallback to the slots %s logged (last line \"%s\")", said? "was" : "was not", lastWarning);
    RT_CHECK(RblIsLitShaderValid(lit), "clustered desc refused");
    bool grid = litHasUniform(lit, "rblGridDims"), slots = litHasUniform(lit, "rblLightPosition");
    printf("    %s: grid %s, slots %s\n", clHasGrid()? "GLSL 3" : "GLSL 1", grid? "yes" : "no", slots? "yes" : "no");
    RT_CHECK(grid == clHasGrid() && slots == !clHasGrid(), "GLSL 3 reads the grid, GLSL 1 the slots (grid %d slots %d)", grid, slots);
    RblUnloadLitShader(&lit);
    // Either way, the image is the slot program's and the reference's (8 lights fit the slots)
    RblLitShaderDesc plain = desc;
    plain.clustered = false;
    ClRender a = clRender(&sc, desc, lights, 8, 255), b = clRender(&sc, plain, lights, 8, 255);
    if (a.ok && b.ok)
    {
        int differing = 0, worst = clDiff(a.image, b.image, &differing);
        LitError e = clCompare(&sc, a.image, lights, 8, 255, 1);
        printf("    clustered desc vs slots worst %d/255; vs reference max %.0f mean %.3f\n", worst, e.max, e.mean);
        RT_CHECK(worst <= 1, "clustered desc vs slots %d/255", worst);
        RT_CHECK(e.max <= 2.0 && e.mean <= 0.25, "clustered desc vs reference max %.0f mean %.3f", e.max, e.mean);
    }
    if (a.ok) UnloadImage(a.image);
    if (b.ok) UnloadImage(b.image);
}

// The tests of this file, in order (gpu_tests.h lists every file's)
#define RBL_CLUSTERED_TESTS \
    RT_TEST_GLSL3(test_clustered_equals_the_slots_and_the_double_reference), \
    RT_TEST_GLSL3(test_clustered_lights_256_and_1024_lights_on_opaque_and_blended_sprites), \
    RT_TEST_GLSL3(test_clustered_edge_cases_zero_lights_unbounded_only_and_a_capped_cell), \
    RT_TEST_GLSL3(test_clustered_grid_is_built_only_for_clustered_programs), \
    RT_TEST_GLSL3(test_clustered_receivers_shadow_the_same_light_as_the_slots), \
    RT_TEST(test_clustered_falls_back_to_the_slots_without_glsl3)
