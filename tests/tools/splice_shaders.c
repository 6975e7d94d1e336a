// Writes every stage of every program family as the loader splices it, in each GLSL dialect, to
// <dir>/<dialect>/<family>-<case>.<vert|frag>, for a static check with glslangValidator (tests/run.sh).
// Families needing GLSL 3 (instanced, deferred G-buffer and passes) are written for 330 and 300 es only.
// Usage: splice_shaders <dir>
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

static int written = 0;

static void writeStage(const char *dir, int glsl, const char *name, bool vertex, const char *defines, const char *const *const *parts)
{
    char prologue[1400], path[512];
    rbl__stagePrologue(glsl, vertex, defines, prologue, sizeof(prologue));
    char *text = rbl__joinStage(prologue, parts);
    snprintf(path, sizeof(path), "%s/%i/%s.%s", dir, glsl, name, vertex? "vert" : "frag");
    FILE *f = fopen(path, "w");
    if ((f == NULL) || (text == NULL)) { printf("splice_shaders: cannot write %s\n", path); RBL_FREE(text); if (f) fclose(f); return; }
    fputs(text, f);
    fclose(f);
    RBL_FREE(text);
    written++;
}

int main(int argc, char **argv)
{
    if (argc < 2) { printf("usage: splice_shaders <dir>\n"); return 1; }
    const char *dir = argv[1];
    mkdir(dir, 0755);
    const int dialects[4] = { 330, 300, 120, 100 };
    // Descs that switch every feature on and off between them (normalised as the loader does)
    RblLitShaderDesc cases[6];
    memset(cases, 0, sizeof(cases));
    cases[1].maxLights = 8; cases[1].shading.lightFeatures = 15; cases[1].shading.brdf = RBL_BRDF_BLINN_PHONG; cases[1].shading.fog = RBL_FOG_LINEAR;
    cases[1].shading.tonemap = RBL_TONEMAP_REINHARD; cases[1].material.normalEncoding = RBL_NORMAL_HEMIOCT; cases[1].material.specular = true;
    cases[1].material.occlusion = true; cases[1].material.emissive = RBL_EMISSIVE_MASK; cases[1].shading.shadowMaps = 4; cases[1].shading.shadowFilter = 3;
    cases[2] = cases[1]; cases[2].shading.brdf = RBL_BRDF_GGX; cases[2].shading.fog = RBL_FOG_EXP2; cases[2].shading.tonemap = RBL_TONEMAP_ACES;
    cases[2].material.normalEncoding = RBL_NORMAL_XY; cases[2].material.emissive = RBL_EMISSIVE_RGB; cases[2].shading.gamma = 2.2f; cases[2].shading.shadowMaps = 1;
    cases[3] = cases[2]; cases[3].material.normalEncoding = RBL_NORMAL_RGB; cases[3].material.specular = false; cases[3].shading.linearOutput = true; cases[3].debugOutput = RBL_DEBUG_OUTPUT_WORLD_NORMAL;
    cases[2].crossFade = true;      // with cases 3 and 5 (deferred) after it; 4 instanced
    cases[4] = cases[1]; cases[4].instanced = true; cases[4].crossFade = true;
    cases[5] = cases[2]; cases[5].deferred = true;
    for (int di = 0; di < 4; di++)
    {
        int glsl = dialects[di];
        char sub[512];
        snprintf(sub, sizeof(sub), "%s/%i", dir, glsl);
        mkdir(sub, 0755);
        for (int c = 0; c < 6; c++)
        {
            RblLitShaderDesc d;
            if (rbl__normaliseLitDesc(cases[c], &d) != NULL) { printf("splice_shaders: case %d rejected\n", c); return 1; }
            if ((d.instanced || d.deferred) && (glsl < 300)) continue;
            char defines[1536], name[64];
            rbl__litDefines(&d, defines, sizeof(defines));
            size_t at = strlen(defines);
            rbl__shadowDefines(d.shading.shadowMaps, rbl__shadowKindsOf(NULL, 0, d.shading.shadowMaps), defines + at, sizeof(defines) - at);
            // The receivers' other map kinds: map 0 omni (perspective, casters target: code 7), then
            // cascaded (orthographic, casters target: code 10)
            for (int kind = 1; (kind <= 2) && (d.shading.shadowMaps > 0) && !d.deferred; kind++)
            {
                char other[1536];
                rbl__litDefines(&d, other, sizeof(other));
                size_t o = strlen(other);
                int kinds = (rbl__shadowKindsOf(NULL, 0, d.shading.shadowMaps) & ~15) | ((kind == 1)? 7 : 10);
                rbl__shadowDefines(d.shading.shadowMaps, kinds, other + o, sizeof(other) - o);
                snprintf(name, sizeof(name), "lit-%d-%s", c, (kind == 1)? "omni" : "cascades");
                writeStage(dir, glsl, name, false, other, rbl__pass_lit_fs);
            }
            snprintf(name, sizeof(name), "lit-%d", c);
            writeStage(dir, glsl, name, true, defines, d.instanced? rbl__pass_lit_instanced_vs : rbl__pass_lit_vs);
            writeStage(dir, glsl, name, false, defines, d.deferred? rbl__pass_gbuffer_fs : rbl__pass_lit_fs);
            snprintf(name, sizeof(name), "caster-%d", c);
            writeStage(dir, glsl, name, false, defines, rbl__pass_shadow_caster_fs);
            if (glsl < 300) continue;
            // The batch-record vertex stage (GLSL 3; programs without cross-fades, as rbl__recordable)
            if (!d.instanced && !d.crossFade)
            {
                char record[1600];
                snprintf(record, sizeof(record), "%s#define RBL_BATCH_RECORD\n", defines);
                snprintf(name, sizeof(name), "record-%d", c);
                writeStage(dir, glsl, name, true, record, rbl__pass_lit_instanced_vs);
            }
            // Deferred light passes: the lighting desc of this case, with and without the light counter
            RblLitShaderDesc lighting = d;
            lighting.deferred = false; lighting.instanced = false;
            if (cases[c].shading.shadowMaps == 0) continue;
            rbl__litDefines(&lighting, defines, sizeof(defines));
            at = strlen(defines);
            rbl__shadowDefines(lighting.shading.shadowMaps, rbl__shadowKindsOf(NULL, 0, lighting.shading.shadowMaps), defines + at, sizeof(defines) - at);
            for (int counting = 0; counting < 2; counting++)
            {
                char passDefines[1600];
                snprintf(passDefines, sizeof(passDefines), "%s%s", defines, counting? "#define RBL_COUNT_LIGHTS\n" : "");
                snprintf(name, sizeof(name), "fullscreen-%d-%d", c, counting); writeStage(dir, glsl, name, true, passDefines, rbl__pass_fullscreen_vs);
                snprintf(name, sizeof(name), "volume-%d-%d", c, counting); writeStage(dir, glsl, name, true, passDefines, rbl__pass_volume_vs);
                snprintf(name, sizeof(name), "fullscreen-%d-%d", c, counting); writeStage(dir, glsl, name, false, passDefines, rbl__pass_deferred_fullscreen_fs);
                snprintf(name, sizeof(name), "lights-%d-%d", c, counting); writeStage(dir, glsl, name, false, passDefines, rbl__pass_deferred_volume_fs);
                snprintf(name, sizeof(name), "resolve-%d-%d", c, counting); writeStage(dir, glsl, name, false, passDefines, rbl__pass_deferred_resolve_fs);
            }
        }
    }
    printf("splice_shaders: %d stages written under %s\n", written, dir);
    return 0;
}
