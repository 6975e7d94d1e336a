// Bench suite `platforms`: one binary per raylib graphics API (GL 3.3, ES 3, ES 2, GL 2.1), run on
// the matching strict context (tests/bench/run.sh). Rows, per context:
//   compile_link_ms   shader compile + link of each program family, median of 5 cold compilations (run.sh
//                     turns Mesa's shader cache off)
//                     (the registry deletes a program with its last holder, so each load compiles)
//   ms_per_frame      the showcase (examples' lit billboards scene, forward) at 800x450, median of
//                     frames; run.sh adds the ratio ES 3 / GL 3.3 (same machine, same run)
// Families needing GLSL 3 (instanced, deferred geometry) are measured where the context has it.
#define RBL_SHOWCASE_NO_MAIN
#include "../../examples/shaders_lit_billboards.c"
#include "harness.h"
#include "bench.h"

#include <stdio.h>
#include <string.h>

#define PF_WIDTH  800
#define PF_HEIGHT 450

typedef struct PfFamily { const char *name; RblLitShaderDesc desc; bool glsl3; bool caster; } PfFamily;

static double pfCompileMs(const PfFamily *f)
{
    double t[5];
    for (int i = 0; i < 5; i++)
    {
        double start = BenchNowNs();
        if (f->caster)
        {
            RblShadowDesc sd;
            memset(&sd, 0, sizeof(sd));
            sd.size = 16;
            RblShadowMap map = RblLoadShadowMap(sd);        // acquires (compiles) the caster programs
            rtFinish();
            t[i] = (BenchNowNs() - start)/1e6;
            if (!RblIsShadowMapValid(map)) return -1.0;
            RblUnloadShadowMap(&map);
        }
        else
        {
            Shader s = RblLoadLitShader(f->desc);
            rtFinish();
            t[i] = (BenchNowNs() - start)/1e6;
            if (!RblIsLitShaderValid(s)) return -1.0;
            RblUnloadLitShader(&s);
        }
    }
    return BenchMedian(t, 5);
}

static void pfFrame(RenderTexture2D target, int frame)
{
    ShowcaseUpdate((float)frame/60.0f);
    ShowcaseDrawShadows();
    BeginTextureMode(target);
        ClearBackground(showcaseBackground);
        BeginMode3D(showcaseCamera);
            ShowcaseDraw();
        EndMode3D();
    EndTextureMode();
}

int main(void)
{
    const char *ctx = rtInitContext(PF_WIDTH, PF_HEIGHT);
    if (ctx == NULL) { printf("bench_platforms: no context\n"); return 1; }
    PfFamily families[5];
    memset(families, 0, sizeof(families));
    families[0].name = "forward_lambert";
    families[1].name = "forward_ggx_full";
    RblLitShaderDesc *full = &families[1].desc;
    full->maxLights = 8; full->shading.lightFeatures = 15; full->shading.brdf = RBL_BRDF_GGX; full->shading.fog = RBL_FOG_EXP2; full->shading.tonemap = RBL_TONEMAP_ACES;
    full->material.normalEncoding = RBL_NORMAL_HEMIOCT; full->material.specular = true; full->material.occlusion = true;
    full->material.emissive = RBL_EMISSIVE_RGB; full->shading.shadowMaps = 4;
    families[2].name = "shadow_casters"; families[2].caster = true;
    families[3].name = "instanced_ggx_full"; families[3].desc = *full; families[3].desc.instanced = true; families[3].glsl3 = true;
    families[4].name = "deferred_geometry"; families[4].desc = *full; families[4].desc.deferred = true; families[4].glsl3 = true;
    for (int i = 0; i < 5; i++)
    {
        if (families[i].glsl3 && !rtGlsl3()) continue;
        double ms = pfCompileMs(&families[i]);
        char name[64];
        snprintf(name, sizeof(name), "%s_%s", ctx, families[i].name);
        printf("  %-34s compile+link %8.2f ms\n", name, ms);
        BenchCsvRow("platforms", name, "compile_link_ms", ms, "ms");
    }

    ShowcaseInit();
    RenderTexture2D target = LoadRenderTexture(PF_WIDTH, PF_HEIGHT);
    pfFrame(target, 0);
    rtFinish();
    double t[15];
    for (int i = 0; i < 15; i++)
    {
        double start = BenchNowNs();
        pfFrame(target, i + 1);
        rtFinish();
        t[i] = (BenchNowNs() - start)/1e6;
    }
    double ms = BenchMedian(t, 15);
    char name[64];
    snprintf(name, sizeof(name), "%s_showcase", ctx);
    printf("  %-34s %8.2f ms/frame (800x450, median of 15)\n", name, ms);
    BenchCsvRow("platforms", name, "ms_per_frame", ms, "ms");
    UnloadRenderTexture(target);
    ShowcaseUnload();
    RblClose();
    rtCloseContext();
    return 0;
}
