// Benchmark suite "lighting": cost and accuracy of the forward lit shader (GPU, headless GL).
//   frame cost   ms per frame at 1280x720 of one quad covering every pixel of a RenderTexture, lit by
//                1, 4, 16 and 64 point lights (windowed falloff, range covering the whole screen, so
//                every light is evaluated at every pixel) for each BRDF (Lambert, Blinn-Phong, GGX;
//                albedo-only material, shader defaults otherwise). The same run measures raylib's
//                own path as the baseline: the same quad drawn by DrawBillboardPro with raylib's
//                default (unlit) shader. One timed run draws every case once, each lit frame right
//                after a baseline frame (a slow phase of a noisy machine hits all cases alike); the
//                run's baseline is the median of its baseline frames and every lit case is also
//                reported as its ratio to it (median of the per-run ratios); each case's scene (its
//                lights, RblSetScene) is set before its frame, outside the timed window. One extra case draws
//                the quad through RblDrawBillboard with raylib's default shader (the header's draw
//                path without lighting). Each frame: glFinish, draw, glFinish (GPU work included);
//                medians over the timed runs. Every case is checked once to write every pixel.
//   accuracy     error of the rendered RGBA8 image against the double-precision GGX reference
//                (tests/lighting_reference.h) for dielectric GGX materials of perceptual roughness
//                0.25, 0.5 and 0.8 (material values: RblLitShaderDesc holds compiled features only),
//                rendered with the GGX variant and with the Blinn-Phong variant
//                using the conventional mapping (see BlinnPhongShininess): how much accuracy the
//                cheaper BRDF gives up. Also Blinn-Phong against its own reference (implementation
//                error, not model error). 256x256, a tilted view of the plane z = 0 lit by 3 point
//                lights with visible highlights; interior pixels only (2-pixel border of the quad
//                skipped); per channel |pixel - round(ref*255)|, mean, 99th percentile and max.
// Rows (suite "lighting"):
//   raylib_default_shader: ms_per_frame_1280x720, spread_pct (max - min per-run baseline), runs
//   rbl_draw_unlit: ms_per_frame_1280x720, ratio_to_raylib
//   <brdf>_<n>lights: ms_per_frame_1280x720, ratio_to_raylib, ns_per_pixel_light (over the baseline)
//   accuracy_r<roughness>_<ggx|blinn_phong|blinn_phong_self>: mean_err, p99_err, max_err (1/255), pixels
//   accuracy_r<roughness>_blinn_phong: shininess
// Output: rows appended to $BENCH_CSV (see bench.h) and a summary table on stdout.
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "harness.h"
#include "bench.h"
#include "lighting_reference.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

//----------------------------------------------------------------------------------
// Defines and Macros
//----------------------------------------------------------------------------------
#define SUITE               "lighting"
#define FRAME_W             1280
#define FRAME_H             720
#define ACC_SIZE            256
#define ACC_PLANE           30.0f       // accuracy plane: z = 0, 30x30 centred at the origin
#define ACC_BORDER          2           // pixels of the quad's edge left out of the comparison
#define LIGHT_COUNTS        4
#define ROUGHNESS_COUNT     3

//----------------------------------------------------------------------------------
// Types and Structures Definition
//----------------------------------------------------------------------------------
typedef enum { DRAW_RAYLIB = 0, DRAW_RBL } DrawPath;

typedef struct Frame {
    RenderTexture2D target;
    Camera3D camera;
    DrawPath path;
    Material material;              // DRAW_RBL: lit (or default) shader + albedo texture
    Texture2D texture;              // DRAW_RAYLIB: albedo texture
    RblBillboard quad;              // the quad (fixed facing, normal +Z, filling the view)
} Frame;

#define LIT_CASES (3*LIGHT_COUNTS)         // brdf-major: [brdf*LIGHT_COUNTS + light count index]
typedef struct Round {
    Frame frame;                    // target, camera, quad; path and material set per frame
    Material unlit;                 // raylib's default shader + albedo (RblDrawBillboard)
    Material lit[LIT_CASES];        // lit variants + albedo
    Shader shader[LIT_CASES];
    RblScene scene[LIT_CASES];      // each case's lights (GridLights of its count) and ambient
    bool ok[LIT_CASES];
    double baseMin, baseMax;        // spread of the per-run baselines (timed runs and warm-up)
} Round;

typedef struct ErrorStats { double mean, p99, max; int pixels; } ErrorStats;

//----------------------------------------------------------------------------------
// Frame cost
//----------------------------------------------------------------------------------
static void DrawFrame(Frame *f)
{
    BeginTextureMode(f->target);
    ClearBackground(BLANK);             // alpha 0: coverage check below
    BeginMode3D(f->camera);
    if (f->path == DRAW_RAYLIB)
    {
        Rectangle source = { 0.0f, 0.0f, (float)f->texture.width, (float)f->texture.height };
        DrawBillboardPro(f->camera, f->texture, source, f->quad.position, f->quad.up, f->quad.size, f->quad.origin, 0.0f, WHITE);
    }
    else RblDrawBillboard(f->camera, f->material, f->quad);
    EndMode3D();
    EndTextureMode();
}

// One frame: glFinish, draw, glFinish (GPU work included); milliseconds
static double TimeFrame(Frame *f)
{
    rtFinish();
    double t0 = BenchNowNs();
    DrawFrame(f);
    rtFinish();
    return (BenchNowNs() - t0)*1e-6;
}

// One run of the frame-cost benchmark times every case once, each lit frame right after a baseline
// frame, so slow phases of a noisy machine hit all cases alike; the run's baseline is the median of
// its baseline frames and each lit case also reports its ratio to it (ratios are medians of
// per-run ratios). out: [0, LIT_CASES) ms, [LIT_CASES, 2*LIT_CASES) ratios, then baseline, unlit.
static void RoundRun(void *ctx, double *out)
{
    Round *r = (Round *)ctx;
    double base[LIT_CASES];
    int nb = 0;
    r->frame.path = DRAW_RBL;
    r->frame.material = r->unlit;
    out[2*LIT_CASES + 1] = TimeFrame(&r->frame);
    for (int i = 0; i < LIT_CASES; i++)
    {
        out[i] = 0.0;
        if (!r->ok[i]) continue;
        r->frame.path = DRAW_RAYLIB;
        base[nb++] = TimeFrame(&r->frame);
        r->frame.path = DRAW_RBL;
        r->frame.material = r->lit[i];
        RblSetScene(&r->scene[i]);              // before the frame: TimeFrame's first glFinish absorbs the upload
        out[i] = TimeFrame(&r->frame);
    }
    double roundBase = (nb > 0)? BenchMedian(base, nb) : 0.0;
    if (nb == 0) { r->frame.path = DRAW_RAYLIB; roundBase = TimeFrame(&r->frame); }
    for (int i = 0; i < LIT_CASES; i++) out[LIT_CASES + i] = (roundBase > 0.0)? out[i]/roundBase : 0.0;
    out[2*LIT_CASES] = roundBase;
    if ((r->baseMin == 0.0) || (roundBase < r->baseMin)) r->baseMin = roundBase;
    if (roundBase > r->baseMax) r->baseMax = roundBase;
}

// Pixels the frame left unwritten (alpha 0); the quad must cover the whole target
static int UncoveredPixels(Frame *f)
{
    DrawFrame(f);
    Image img = rtReadTarget(f->target);
    const unsigned char *p = (const unsigned char *)img.data;
    int missing = 0;
    for (int i = 0; i < img.width*img.height; i++) missing += (p[i*4 + 3] == 0);
    UnloadImage(img);
    return missing;
}

// n point lights on a grid 1.5 above the plane, spread over the visible area; range 25 reaches
// every pixel (farthest pixel ~9 units away) so no light is skipped by its window
static void GridLights(RblLight *lights, int n)
{
    int side = (int)lround(sqrt((double)n));
    for (int i = 0; i < n; i++)
    {
        RblLight l;
        memset(&l, 0, sizeof(l));
        l.position = (Vector3){ -3.5f + 7.0f*((float)(i%side) + 0.5f)/(float)side, -2.0f + 4.0f*((float)(i/side) + 0.5f)/(float)side, 1.5f };
        l.color = (Color){ (unsigned char)(200 + (i*37)%56), (unsigned char)(200 + (i*53)%56), (unsigned char)(200 + (i*71)%56), 255 };
        l.intensity = 3.0f/(float)n;
        l.range = 25.0f;
        lights[i] = l;
    }
}

//----------------------------------------------------------------------------------
// Accuracy
//----------------------------------------------------------------------------------
// Conventional Blinn-Phong exponent for a GGX perceptual roughness r: alpha = r^2 (Disney/Filament
// remapping), and the Beckmann/Blinn-Phong equivalence alpha^2 = 2/(n + 2) (Walter et al. 2007;
// Karis's "Specular BRDF reference") gives n = 2/alpha^2 - 2. Kept >= 1: roughness 1 would give
// n = 0, which the material's shininess (MATERIAL_MAP_NORMAL.value) reads as "default" (32), not as the broadest lobe.
static float BlinnPhongShininess(float roughness)
{
    double alpha = (double)roughness*roughness;
    return (float)fmax(2.0/(alpha*alpha) - 2.0, 1.0);
}

static int CompareDouble(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x < y)? -1 : (x > y)? 1 : 0;
}

// Accuracy scene: the camera looks down at 45 degrees onto the plane z = 0; the three lights'
// mirror highlights all fall inside the view
static Camera3D AccuracyCamera(void)
{
    Camera3D c;
    memset(&c, 0, sizeof(c));
    c.position = (Vector3){ 0.0f, -3.0f, 3.5f };
    c.target = (Vector3){ 0.0f, 0.5f, 0.0f };
    c.up = (Vector3){ 0.0f, 0.0f, 1.0f };
    c.fovy = 45.0f;
    c.projection = CAMERA_PERSPECTIVE;
    return c;
}

static int AccuracyLights(RblLight lights[3])
{
    const Vector3 pos[3] = { { -1.0f, 1.0f, 1.5f }, { 1.5f, 2.0f, 1.0f }, { 0.3f, 3.5f, 2.0f } };
    const Color col[3] = { { 255, 240, 220, 255 }, { 255, 200, 150, 255 }, { 190, 215, 255, 255 } };
    const float intensity[3] = { 1.2f, 0.8f, 1.6f };
    for (int i = 0; i < 3; i++)
    {
        memset(&lights[i], 0, sizeof(lights[i]));
        lights[i].position = pos[i]; lights[i].color = col[i]; lights[i].intensity = intensity[i]; lights[i].range = 10.0f;
    }
    return 3;
}

static bool InsidePlane(D3 p) { return (fabs(p.x) < ACC_PLANE*0.5) && (fabs(p.y) < ACC_PLANE*0.5); }

// What the reference reads for a BRDF and its material values (the values 0.3's desc held)
static RefParams ShadingOf(int brdf, RtMaterialValues values)
{
    RefParams d;
    memset(&d, 0, sizeof(d));
    d.brdf = brdf;
    d.specular = values.specular;
    d.shininess = values.shininess;
    d.specularColor = values.specularColor;
    d.roughness = values.roughness;
    d.metalness = values.metalness;
    d.emissiveColor = values.emissiveColor;
    d.emissiveIntensity = values.emissiveIntensity;
    return d;
}

// Renders the accuracy scene with the brdf's variant and the material values, and compares it with the
// reference computed for refParams; false when the shader failed to load or the scene was rejected
static bool MeasureAccuracy(RenderTexture2D target, Material material, int brdf, RtMaterialValues materialValues, RefParams refParams,
                            Color albedo, Color ambient, ErrorStats *stats)
{
    RblLight lights[3];
    int count = AccuracyLights(lights);
    RblLitShaderDesc desc;
    memset(&desc, 0, sizeof(desc));
    desc.shading.brdf = brdf;
    desc.maxLights = count;
    Shader lit = RblLoadLitShader(desc);
    if (!RblIsLitShaderValid(lit)) return false;
    RblScene scene;
    memset(&scene, 0, sizeof(scene));
    scene.lights = lights; scene.lightCount = count; scene.ambient = ambient;
    if (!RblSetScene(&scene)) { RblUnloadLitShader(&lit); return false; }
    material.shader = lit;
    rtSetMaterialValues(&material, materialValues);

    Camera3D camera = AccuracyCamera();
    RblBillboard quad;
    memset(&quad, 0, sizeof(quad));
    quad.size = (Vector2){ ACC_PLANE, ACC_PLANE };
    quad.origin = (Vector2){ ACC_PLANE*0.5f, ACC_PLANE*0.5f };
    quad.facing = RBL_FACING_FIXED;
    quad.axis = (Vector3){ 0.0f, 0.0f, 1.0f };
    quad.up = (Vector3){ 0.0f, 1.0f, 0.0f };

    BeginTextureMode(target);
    ClearBackground(BLANK);
    BeginMode3D(camera);
    RblDrawBillboard(camera, material, quad);
    EndMode3D();
    EndTextureMode();
    Image img = rtReadTarget(target);
    RblUnloadLitShader(&lit);

    RefEnvironment env;
    memset(&env, 0, sizeof(env));
    env.ambient = ambient;
    env.up = d3(0, 0, 1);
    RefSurface surface;
    memset(&surface, 0, sizeof(surface));
    surface.normal = d3(0, 0, 1);
    surface.albedo = refLinear(albedo);
    surface.specularMap = -1.0;
    surface.occlusion = 1.0;
    D3 eye = d3f(camera.position), p0 = d3(0, 0, 0), n = d3(0, 0, 1);

    double *errors = (double *)malloc((size_t)ACC_SIZE*ACC_SIZE*3*sizeof(double)), sum = 0.0;
    int values = 0;
    const unsigned char *px = (const unsigned char *)img.data;
    for (int y = ACC_BORDER; y < ACC_SIZE - ACC_BORDER; y++)
        for (int x = ACC_BORDER; x < ACC_SIZE - ACC_BORDER; x++)
        {
            // interior: this pixel and those ACC_BORDER away see the quad (not its edge)
            D3 hit, probe;
            bool interior = refPixelOnPlane(camera, ACC_SIZE, ACC_SIZE, x, y, p0, n, &hit) && InsidePlane(hit);
            for (int k = 0; interior && (k < 4); k++)
            {
                int qx = x + ((k == 0)? -ACC_BORDER : (k == 1)? ACC_BORDER : 0), qy = y + ((k == 2)? -ACC_BORDER : (k == 3)? ACC_BORDER : 0);
                interior = refPixelOnPlane(camera, ACC_SIZE, ACC_SIZE, qx, qy, p0, n, &probe) && InsidePlane(probe);
            }
            if (!interior) continue;
            surface.position = hit;
            RefRgb ref = refFinish(&refParams, refShade(&refParams, lights, count, &env, &surface, eye), hit, eye);
            const unsigned char *c = px + ((size_t)y*ACC_SIZE + x)*4;
            double r[3] = { ref.r, ref.g, ref.b };
            for (int ch = 0; ch < 3; ch++)
            {
                double e = fabs((double)c[ch] - floor(r[ch]*255.0 + 0.5));
                if (c[3] != 255) e = 255.0;         // an unwritten or translucent pixel is wrong outright
                errors[values++] = e;
                sum += e;
            }
        }
    UnloadImage(img);
    qsort(errors, (size_t)values, sizeof(double), CompareDouble);
    stats->pixels = values/3;
    stats->mean = (values > 0)? sum/values : 0.0;
    stats->p99 = (values > 0)? errors[(int)ceil(0.99*values) - 1] : 0.0;
    stats->max = (values > 0)? errors[values - 1] : 0.0;
    free(errors);
    return true;
}

//----------------------------------------------------------------------------------
// Main
//----------------------------------------------------------------------------------
int main(void)
{
    double benchStart = BenchNowNs();
    SetTraceLogLevel(LOG_WARNING);
    const char *backend = rtInitContext(FRAME_W, FRAME_H);
    if (backend == NULL) { printf("bench_lighting: no headless GL context, skipped\n"); return 0; }

    // ---- frame cost ------------------------------------------------------------------------------
    const int lightCounts[LIGHT_COUNTS] = { 1, 4, 16, 64 };
    const int brdfs[3] = { RBL_BRDF_LAMBERT, RBL_BRDF_BLINN_PHONG, RBL_BRDF_GGX };
    const char *brdfName[3] = { "lambert", "blinn_phong", "ggx" };
    Image albedoImg = GenImageColor(4, 4, (Color){ 200, 160, 120, 255 });
    Texture2D albedo = LoadTextureFromImage(albedoImg);

    Round rd;
    memset(&rd, 0, sizeof(rd));
    Frame *f = &rd.frame;
    f->target = LoadRenderTexture(FRAME_W, FRAME_H);
    f->camera.position = (Vector3){ 0.0f, 0.0f, 5.0f };
    f->camera.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    f->camera.fovy = 45.0f;
    f->camera.projection = CAMERA_PERSPECTIVE;
    float h = (float)(2.0*5.0*tan(22.5*PI/180.0));
    f->quad.size = (Vector2){ h*FRAME_W/FRAME_H*1.05f, h*1.05f };     // a little beyond every edge
    f->quad.origin = (Vector2){ f->quad.size.x*0.5f, f->quad.size.y*0.5f };
    f->quad.facing = RBL_FACING_FIXED;
    f->quad.axis = (Vector3){ 0.0f, 0.0f, 1.0f };
    f->quad.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    f->texture = albedo;
    rd.unlit = LoadMaterialDefault();
    rd.unlit.maps[MATERIAL_MAP_ALBEDO].texture = albedo;
    int problems = 0;

    // every variant loaded and checked once (the coverage check also compiles it on the GPU)
    f->path = DRAW_RAYLIB;
    int missing = UncoveredPixels(f);
    if (missing > 0) { printf("bench_lighting: raylib baseline leaves %d pixels unwritten\n", missing); problems++; }
    f->path = DRAW_RBL;
    f->material = rd.unlit;
    missing = UncoveredPixels(f);
    if (missing > 0) { printf("bench_lighting: RblDrawBillboard (unlit) leaves %d pixels unwritten\n", missing); problems++; }
    // each light count's lights (the scenes point here), checked once by RblSetScene; every lit program
    // receives each case's scene, and those with fewer slots light its first lights (a LOG_INFO line)
    static RblLight grid[LIGHT_COUNTS][RBL_MAX_LIGHTS];
    bool gridOk[LIGHT_COUNTS];
    for (int c = 0; c < LIGHT_COUNTS; c++)
    {
        GridLights(grid[c], lightCounts[c]);
        RblScene check;
        memset(&check, 0, sizeof(check));
        check.lights = grid[c]; check.lightCount = lightCounts[c]; check.ambient = (Color){ 20, 20, 24, 255 };
        gridOk[c] = RblSetScene(&check);
    }
    for (int b = 0; b < 3; b++)
        for (int c = 0; c < LIGHT_COUNTS; c++)
        {
            int i = b*LIGHT_COUNTS + c;
            RblLitShaderDesc desc;
            memset(&desc, 0, sizeof(desc));
            desc.maxLights = lightCounts[c];
            desc.shading.brdf = brdfs[b];
            rd.shader[i] = RblLoadLitShader(desc);
            memset(&rd.scene[i], 0, sizeof(rd.scene[i]));
            rd.scene[i].lights = grid[c];
            rd.scene[i].lightCount = lightCounts[c];
            rd.scene[i].ambient = (Color){ 20, 20, 24, 255 };
            rd.ok[i] = RblIsLitShaderValid(rd.shader[i]) && gridOk[c];
            if (!rd.ok[i]) { printf("bench_lighting: %s with %d lights: shader or lights rejected\n", brdfName[b], lightCounts[c]); problems++; continue; }
            rd.lit[i] = rd.unlit;
            rd.lit[i].shader = rd.shader[i];
            f->material = rd.lit[i];
            RblSetScene(&rd.scene[i]);
            missing = UncoveredPixels(f);
            if (missing > 0) { printf("bench_lighting: %s_%dlights leaves %d pixels unwritten\n", brdfName[b], lightCounts[c], missing); problems++; }
        }

    // llvmpipe: a run (every case once) takes about 1-3 s
    const BenchTiming timing = { 1, 3, 7, 6e9 };
    double med[2*LIT_CASES + 2];
    int runs = BenchMedianOfRuns(RoundRun, &rd, 2*LIT_CASES + 2, timing, med);
    double base = med[2*LIT_CASES], unlitMs = med[2*LIT_CASES + 1];
    double spread = (base > 0.0)? 100.0*(rd.baseMax - rd.baseMin)/base : 0.0;
    double litMs[3][LIGHT_COUNTS], litRatio[3][LIGHT_COUNTS];
    for (int i = 0; i < LIT_CASES; i++)
    {
        litMs[i/LIGHT_COUNTS][i%LIGHT_COUNTS] = rd.ok[i]? med[i] : -1.0;
        litRatio[i/LIGHT_COUNTS][i%LIGHT_COUNTS] = med[LIT_CASES + i];
        if (rd.ok[i]) RblUnloadLitShader(&rd.shader[i]);
    }
    MemFree(rd.unlit.maps);
    UnloadRenderTexture(f->target);

    BenchCsvRow(SUITE, "raylib_default_shader", "ms_per_frame_1280x720", base, "ms");
    BenchCsvRow(SUITE, "raylib_default_shader", "spread_pct", spread, "%");
    BenchCsvRow(SUITE, "raylib_default_shader", "runs", runs, "runs");
    BenchCsvRow(SUITE, "rbl_draw_unlit", "ms_per_frame_1280x720", unlitMs, "ms");
    BenchCsvRow(SUITE, "rbl_draw_unlit", "ratio_to_raylib", unlitMs/base, "x");
    for (int b = 0; b < 3; b++)
        for (int c = 0; c < LIGHT_COUNTS; c++)
        {
            if (litMs[b][c] < 0.0) continue;
            char name[64];
            snprintf(name, sizeof(name), "%s_%dlights", brdfName[b], lightCounts[c]);
            BenchCsvRow(SUITE, name, "ms_per_frame_1280x720", litMs[b][c], "ms");
            BenchCsvRow(SUITE, name, "ratio_to_raylib", litRatio[b][c], "x");
            BenchCsvRow(SUITE, name, "ns_per_pixel_light", (litMs[b][c] - base)*1e6/((double)FRAME_W*FRAME_H*lightCounts[c]), "ns");
        }

    // ---- accuracy ------------------------------------------------------------------------------------
    // Blinn-Phong specular intensity: the header's normalised Blinn-Phong is
    // specular*(n + 8)/8*NdotH^n (pi folded in), which approximates the microfacet specular D*V*F
    // at F = F0 (Blinn-Phong D = (n + 2)/(2 pi)*NdotH^n with the implicit visibility 1/4); a
    // dielectric GGX material has F0 = 0.04, so the material's specular = 0.04 (no Fresnel rise at grazing
    // angles: part of the model error measured here). Diffuse is the same Lambert term in both.
    const float roughness[ROUGHNESS_COUNT] = { 0.25f, 0.5f, 0.8f };
    const Color accAlbedo = { 180, 130, 100, 255 }, accAmbient = { 20, 20, 24, 255 };
    Image accImg = GenImageColor(4, 4, accAlbedo);
    Texture2D accTex = LoadTextureFromImage(accImg);
    RenderTexture2D accTarget = LoadRenderTexture(ACC_SIZE, ACC_SIZE);
    Material accMat = LoadMaterialDefault();
    accMat.maps[MATERIAL_MAP_ALBEDO].texture = accTex;
    ErrorStats err[ROUGHNESS_COUNT][3];         // ggx, blinn_phong vs GGX ref, blinn_phong vs its own ref
    float shininess[ROUGHNESS_COUNT];
    bool accOk[ROUGHNESS_COUNT][3];
    const char *accName[3] = { "ggx", "blinn_phong", "blinn_phong_self" };
    for (int r = 0; r < ROUGHNESS_COUNT; r++)
    {
        RtMaterialValues ggx;
        memset(&ggx, 0, sizeof(ggx));
        ggx.roughness = roughness[r];
        ggx.metalness = 0.0f;
        RtMaterialValues bp;
        memset(&bp, 0, sizeof(bp));
        bp.shininess = shininess[r] = BlinnPhongShininess(roughness[r]);
        bp.specular = 0.04f;
        RefParams ggxRef = ShadingOf(RBL_BRDF_GGX, ggx), bpRef = ShadingOf(RBL_BRDF_BLINN_PHONG, bp);
        accOk[r][0] = MeasureAccuracy(accTarget, accMat, RBL_BRDF_GGX, ggx, ggxRef, accAlbedo, accAmbient, &err[r][0]);
        accOk[r][1] = MeasureAccuracy(accTarget, accMat, RBL_BRDF_BLINN_PHONG, bp, ggxRef, accAlbedo, accAmbient, &err[r][1]);
        accOk[r][2] = MeasureAccuracy(accTarget, accMat, RBL_BRDF_BLINN_PHONG, bp, bpRef, accAlbedo, accAmbient, &err[r][2]);
        for (int k = 0; k < 3; k++)
        {
            char name[64];
            snprintf(name, sizeof(name), "accuracy_r%03d_%s", (int)lround(roughness[r]*100.0f), accName[k]);
            if (!accOk[r][k]) { printf("bench_lighting: %s: shader or lights rejected\n", name); problems++; continue; }
            BenchCsvRow(SUITE, name, "mean_err", err[r][k].mean, "1/255");
            BenchCsvRow(SUITE, name, "p99_err", err[r][k].p99, "1/255");
            BenchCsvRow(SUITE, name, "max_err", err[r][k].max, "1/255");
            BenchCsvRow(SUITE, name, "pixels", err[r][k].pixels, "pixels");
            if (k == 1) BenchCsvRow(SUITE, name, "shininess", shininess[r], "exponent");
        }
    }
    MemFree(accMat.maps);
    UnloadRenderTexture(accTarget);
    UnloadTexture(accTex);
    UnloadImage(accImg);
    UnloadTexture(albedo);
    UnloadImage(albedoImg);
    RblClose();
    rtCloseContext();

    // ---- summary -------------------------------------------------------------------------------------
    printf("lighting: ms per frame, %dx%d, one full-screen quad, point lights (windowed, every light reaches every pixel); %s context\n",
           FRAME_W, FRAME_H, backend);
    printf("  raylib default shader (DrawBillboardPro) %8.2f ms  (baseline 1.00x; per-run baselines spread %.0f%%)\n", base, spread);
    printf("  RblDrawBillboard, raylib default shader  %8.2f ms  (%.2fx)\n", unlitMs, unlitMs/base);
    printf("  median of %d runs, each timing every case once, each lit frame right after a baseline frame\n", runs);
    printf("  %-12s", "lights");
    for (int c = 0; c < LIGHT_COUNTS; c++) printf(" %8d ms %7s", lightCounts[c], "ratio");
    printf("\n");
    for (int b = 0; b < 3; b++)
    {
        printf("  %-12s", brdfName[b]);
        for (int c = 0; c < LIGHT_COUNTS; c++)
        {
            if (litMs[b][c] < 0.0) printf(" %11s %7s", "-", "-");
            else printf(" %11.2f %6.1fx", litMs[b][c], litRatio[b][c]);
        }
        printf("\n");
    }
    printf("  marginal cost per light per pixel at 64 lights: ");
    for (int b = 0; b < 3; b++)
        if (litMs[b][LIGHT_COUNTS - 1] >= 0.0)
            printf("%s %.2f ns%s", brdfName[b], (litMs[b][LIGHT_COUNTS - 1] - base)*1e6/((double)FRAME_W*FRAME_H*64), (b < 2)? ", " : "\n");

    printf("\nlighting: error against the double-precision GGX reference, 1/255 per channel (%dx%d, 3 point lights, dielectric,\n", ACC_SIZE, ACC_SIZE);
    printf("  albedo (%d,%d,%d); Blinn-Phong: shininess = 2/alpha^2 - 2, alpha = roughness^2, specular 0.04 = F0)\n", accAlbedo.r, accAlbedo.g, accAlbedo.b);
    printf("  %-9s %9s | %-20s | %-20s | %-20s\n", "roughness", "shininess", "GGX mean/p99/max", "Blinn-Phong mean/p99/max", "BP vs BP ref mean/max");
    for (int r = 0; r < ROUGHNESS_COUNT; r++)
    {
        printf("  %-9.2f %9.1f |", roughness[r], shininess[r]);
        for (int k = 0; k < 3; k++)
        {
            if (!accOk[r][k]) { printf(" %-20s |", "-"); continue; }
            if (k < 2) printf(" %6.3f %5.0f %6.0f   |", err[r][k].mean, err[r][k].p99, err[r][k].max);
            else printf(" %6.3f %6.0f\n", err[r][k].mean, err[r][k].max);
        }
        if (!accOk[r][2]) printf("\n");
    }
    printf("  (%d interior pixels per image)\n", accOk[0][0]? err[0][0].pixels : 0);
    for (int r = 0; r < ROUGHNESS_COUNT; r++)
        if (accOk[r][0] && (err[r][0].max > 2.0))
            printf("  note: GGX at roughness %.2f differs from its reference by up to %.0f/255 (more than 2/255)\n", roughness[r], err[r][0].max);
    printf("bench_lighting: done in %.1f s, rows in %s%s\n", (BenchNowNs() - benchStart)*1e-9, BenchCsvPath(), problems? " (with problems, see above)" : "");
    return 0;
}
