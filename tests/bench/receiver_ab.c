// Shadow receiver cost across header versions (tests/bench/receiver_ab.sh builds this file against
// several commits' rbillboard_lit.h and runs the binaries alternately). Uses only the API every
// version since the first shadow maps has: RblLoadLitShader, RblLoadShadowMap, RblBeginShadowMap,
// RblSetScene, RblDrawBillboard; -DAB_OMNI adds the point-light (omni) and cascaded rows.
// The scene is bench_shadows' receiver: a floor filling a 1280x720 top-down orthographic view,
// one directional light, one 512 map cast by a 3 x 3 card (drawn only into the map), Lambert.
// One run: for each shadowed variant an unshadowed frame then the variant's frame (RblSetScene
// before each, as bench_shadows); ratio = shadowed/unshadowed of that pair; the run's ratio per
// variant is the median of PAIRS pairs. Prints one line per run and the median over runs.
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "rlgl.h"
#include "harness.h"
#include "bench.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

// The 1.0 API moved the lighting fields into desc.shading (receiver_ab.sh defines AB_SHADING there)
#if defined(AB_SHADING)
    #define AB_SH(d) (d).shading
    #define AB_FEATURES RblGetLightFeatures
#else
    #define AB_SH(d) (d)
    #define AB_FEATURES RblLightFeatures
#endif

#define W 1280
#define H 720
#define PAIRS 5
#define RUNS 7

enum { V_PCF1 = 0, V_PCF2, V_MIXED, V_OMNI, V_CASCADES, V_COUNT };
static const char *vName[V_COUNT] = { "single_pcf1", "single_pcf2", "single_pcf2_2maps_program", "omni_pcf2", "cascades4_pcf2" };

typedef struct Ab {
    RenderTexture2D target;
    Camera3D camera;
    RblBillboard floor;
    Texture2D white;
    Material base[V_COUNT], shadowed[V_COUNT];
    RblScene baseScene[V_COUNT], scene[V_COUNT];
    bool ok[V_COUNT];
} Ab;

static Material Mat(Shader s, Texture2D white)
{
    Material m = LoadMaterialDefault();
    m.shader = s;
    m.maps[MATERIAL_MAP_ALBEDO].texture = white;
    return m;
}

static double Frame(Ab *ab, const RblScene *scene, Material m)
{
    RblSetScene(scene);
    rtFinish();
    double t0 = BenchNowNs();
    BeginTextureMode(ab->target);
    ClearBackground(BLANK);
    BeginMode3D(ab->camera);
    RblDrawBillboard(ab->camera, m, ab->floor);
    EndMode3D();
    EndTextureMode();
    rtFinish();
    return (BenchNowNs() - t0)*1e-6;
}

static RblBillboard Card(void)
{
    RblBillboard b;
    memset(&b, 0, sizeof(b));
    double a = 17.0*PI/180.0;
    b.position = (Vector3){ 0.0f, 0.0f, 1.5f };
    b.size = (Vector2){ 3.0f, 3.0f };
    b.origin = (Vector2){ 1.5f, 1.5f };
    b.facing = RBL_FACING_FIXED;
    b.axis = (Vector3){ 0.0f, 0.0f, 1.0f };
    b.up = (Vector3){ (float)-sin(a), (float)cos(a), 0.0f };
    return b;
}

int main(int argc, char **argv)
{
    const char *label = (argc > 1)? argv[1] : "?";
    SetTraceLogLevel(LOG_WARNING);
    if (rtInitContext(W, H) == NULL) { printf("receiver_ab: no context\n"); return 1; }
    static Ab abs;
    Ab *ab = &abs;
    ab->target = LoadRenderTexture(W, H);
    memset(&ab->camera, 0, sizeof(ab->camera));
    ab->camera.position = (Vector3){ 0.0f, 0.0f, 10.0f };
    ab->camera.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    ab->camera.fovy = 8.0f;
    ab->camera.projection = CAMERA_ORTHOGRAPHIC;
    ab->floor.size = (Vector2){ 20.0f, 20.0f };
    ab->floor.origin = (Vector2){ 10.0f, 10.0f };
    ab->floor.facing = RBL_FACING_FIXED;
    ab->floor.axis = (Vector3){ 0.0f, 0.0f, 1.0f };
    ab->floor.up = (Vector3){ 0.0f, 1.0f, 0.0f };
    Image img = GenImageColor(4, 4, WHITE);
    ab->white = LoadTextureFromImage(img);
    UnloadImage(img);

    static RblLight sun, point, sunAndPoint[2];
    sun.type = RBL_LIGHT_DIRECTIONAL; sun.direction = (Vector3){ 0.5f, 0.3f, -1.0f }; sun.color = WHITE; sun.intensity = 1.0f;
    point.type = RBL_LIGHT_POINT; point.position = (Vector3){ 0.5f, -0.3f, 4.0f }; point.color = WHITE; point.intensity = 12.0f; point.range = 30.0f;
    sunAndPoint[0] = sun; sunAndPoint[1] = point;
    RblScene sunScene; memset(&sunScene, 0, sizeof(sunScene));
    sunScene.lights = &sun; sunScene.lightCount = 1; sunScene.ambient = (Color){ 40, 40, 40, 255 };
    RblLitShaderDesc d;
    memset(&d, 0, sizeof(d));
    d.maxLights = 1; AB_SH(d).lightFeatures = AB_FEATURES(&sun, 1); AB_SH(d).brdf = RBL_BRDF_LAMBERT;
    Shader unshadowed = RblLoadLitShader(d);
    AB_SH(d).shadowMaps = 1; AB_SH(d).shadowFilter = 1;
    Shader pcf1 = RblLoadLitShader(d);
    AB_SH(d).shadowFilter = 2;
    Shader pcf2 = RblLoadLitShader(d);
    AB_SH(d).shadowMaps = 2;
    Shader pcf2two = RblLoadLitShader(d);

    RblShadowDesc sd;
    memset(&sd, 0, sizeof(sd));
    sd.size = 512;
    RblShadowMap map = RblLoadShadowMap(sd);
    RblBillboard card = Card();
    Material plain = Mat(unshadowed, ab->white);
    if (RblBeginShadowMap(&map, &sunScene, 0, (Vector3){ 0.0f, 0.0f, 0.0f }, 8.0f)) { RblDrawBillboard(ab->camera, plain, card); RblEndShadowMap(&map); }
    else { printf("receiver_ab: map failed\n"); return 1; }
    RblScene mapScene = sunScene;
    mapScene.shadowMaps = &map; mapScene.shadowMapCount = 1;
    for (int v = 0; v < V_COUNT; v++) { ab->base[v] = plain; ab->baseScene[v] = sunScene; ab->scene[v] = mapScene; }
    ab->shadowed[V_PCF1] = Mat(pcf1, ab->white); ab->ok[V_PCF1] = RblIsLitShaderValid(pcf1);
    ab->shadowed[V_PCF2] = Mat(pcf2, ab->white); ab->ok[V_PCF2] = RblIsLitShaderValid(pcf2);
    ab->shadowed[V_MIXED] = Mat(pcf2two, ab->white); ab->ok[V_MIXED] = RblIsLitShaderValid(pcf2two);
#if defined(AB_OMNI)
    {
        // The point light with an omni map, and the sun with 4 cascades over an oblique camera; the
        // baseline is the unshadowed variant of the same light features
        RblLitShaderDesc od;
        memset(&od, 0, sizeof(od));
        od.maxLights = 1; AB_SH(od).lightFeatures = AB_FEATURES(sunAndPoint, 2); AB_SH(od).brdf = RBL_BRDF_LAMBERT;
        Material plain2 = Mat(RblLoadLitShader(od), ab->white);
        AB_SH(od).shadowMaps = 1; AB_SH(od).shadowFilter = 2;
        Shader s2 = RblLoadLitShader(od);
        RblShadowDesc rod = sd; rod.omni = true;
        static RblShadowMap omni, cascades;
        omni = RblLoadShadowMap(rod);
        RblShadowDesc rcd = sd; rcd.cascades = 4;
        cascades = RblLoadShadowMap(rcd);
        static RblScene pointOnly;
        memset(&pointOnly, 0, sizeof(pointOnly)); pointOnly.lights = &point; pointOnly.lightCount = 1; pointOnly.ambient = sunScene.ambient;
        bool ok = RblIsLitShaderValid(s2) && RblIsShadowMapValid(omni) && RblIsShadowMapValid(cascades);
        for (int f = 0; ok && (f < RblShadowMapPasses(omni)); f++)
            if (RblBeginShadowMapPass(&omni, &pointOnly, 0, f, (Vector3){ 0 }, 0.0f)) { RblDrawBillboard(ab->camera, plain, card); RblEndShadowMap(&omni); }
            else ok = false;
        Camera3D oblique;
        memset(&oblique, 0, sizeof(oblique));
        oblique.position = (Vector3){ 0.0f, -12.0f, 6.0f }; oblique.target = (Vector3){ 0.0f, 2.0f, 0.0f }; oblique.up = (Vector3){ 0.0f, 0.0f, 1.0f };
        oblique.fovy = 60.0f; oblique.projection = CAMERA_PERSPECTIVE;
        ok = ok && RblFitShadowCascades(&cascades, oblique, 16.0f/9.0f, 0.5f, 40.0f);
        for (int c = 0; ok && (c < RblShadowMapPasses(cascades)); c++)
            if (RblBeginShadowMapPass(&cascades, &sunScene, 0, c, (Vector3){ 0 }, 0.0f)) { RblDrawBillboard(ab->camera, plain, card); RblEndShadowMap(&cascades); }
            else ok = false;
        ab->base[V_OMNI] = ab->base[V_CASCADES] = plain2;
        ab->baseScene[V_OMNI] = pointOnly; ab->baseScene[V_CASCADES] = sunScene;
        ab->scene[V_OMNI] = pointOnly; ab->scene[V_OMNI].shadowMaps = &omni; ab->scene[V_OMNI].shadowMapCount = 1;
        ab->scene[V_CASCADES] = sunScene; ab->scene[V_CASCADES].shadowMaps = &cascades; ab->scene[V_CASCADES].shadowMapCount = 1;
        ab->shadowed[V_OMNI] = ab->shadowed[V_CASCADES] = Mat(s2, ab->white);
        ab->ok[V_OMNI] = ab->ok[V_CASCADES] = ok;
    }
#endif
    // Warm-up: every variant drawn once (compiles anything compiled on first use)
    for (int v = 0; v < V_COUNT; v++) if (ab->ok[v]) { Frame(ab, &ab->baseScene[v], ab->base[v]); Frame(ab, &ab->scene[v], ab->shadowed[v]); }
    double runMed[V_COUNT][RUNS];
    for (int run = 0; run < RUNS; run++)
    {
        printf("%s run %d:", label, run);
        for (int v = 0; v < V_COUNT; v++)
        {
            if (!ab->ok[v]) continue;
            double r[PAIRS];
            for (int i = 0; i < PAIRS; i++)
            {
                double b = Frame(ab, &ab->baseScene[v], ab->base[v]);
                double s = Frame(ab, &ab->scene[v], ab->shadowed[v]);
                r[i] = s/b;
            }
            runMed[v][run] = BenchMedian(r, PAIRS);
            printf(" %s %.3f", vName[v], runMed[v][run]);
        }
        printf("\n");
    }
    printf("%s median:", label);
    for (int v = 0; v < V_COUNT; v++) if (ab->ok[v]) printf(" %s %.3f", vName[v], BenchMedian(runMed[v], RUNS));
    printf("\n");
    rtCloseContext();
    return 0;
}
