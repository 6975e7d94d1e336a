// Browser GPU suite: the GPU tests of tests/test_gpu_main.c that WebGL2 can run, compiled with
// emscripten and run in headless Chromium (tests/web/run.py serves this over 127.0.0.1 and collects
// the output). The context is WebGL2 on the page's canvas (see rtInitContext in tests/harness.c).
// The subset and why the rest is left out: README "In a browser" and webLeftOut below.
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "rlgl.h"
#include "raymath.h"
#include "harness.h"
#include <GLES3/gl3.h>

#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gpu_tests.h"

// ---- the browser harness itself, checked against values written with raylib's default shader ----
// A rectangle over the top half of a target must read back top row first, in raylib's colour.
static void test_web_default_shader_rectangle_reads_back_top_row_first(void)
{
    RenderTexture2D rt = LoadRenderTexture(TARGET, TARGET);
    BeginTextureMode(rt);
        ClearBackground((Color){ 10, 20, 30, 255 });
        DrawRectangle(0, 0, TARGET, TARGET/2, (Color){ 200, 100, 50, 255 });
    EndTextureMode();
    Image img = rtReadTarget(rt);
    Color top = rtPixel(img, TARGET/2, TARGET/4), bottom = rtPixel(img, TARGET/2, 3*TARGET/4);
    RT_CHECK((top.r == 200) && (top.g == 100) && (top.b == 50) && (top.a == 255), "top %d %d %d %d", top.r, top.g, top.b, top.a);
    RT_CHECK((bottom.r == 10) && (bottom.g == 20) && (bottom.b == 30), "bottom %d %d %d", bottom.r, bottom.g, bottom.b);
    if (rtFailuresInCurrentTest() > 0) rtSaveImage(img, "actual");
    UnloadImage(img);
    UnloadRenderTexture(rt);
}

// Float and half targets read through rtReadFloatPixels (FBO + glReadPixels(GL_RGBA, GL_FLOAT), the
// float readback WebGL2 offers with EXT_color_buffer_float) give the written value c/255, GL rows bottom first.
static void test_web_float_and_half_targets_read_back_the_written_values(void)
{
    static const int formats[] = { PIXELFORMAT_UNCOMPRESSED_R32G32B32A32, PIXELFORMAT_UNCOMPRESSED_R16G16B16A16 };
    for (int f = 0; f < 2; f++)
    {
        unsigned int fbo = rlLoadFramebuffer();
        RenderTexture2D rt = { 0 };
        rt.id = fbo;
        rt.texture.id = rlLoadTexture(NULL, TARGET, TARGET, formats[f], 1);
        rt.texture.width = rt.texture.height = TARGET; rt.texture.mipmaps = 1; rt.texture.format = formats[f];
        rlFramebufferAttach(fbo, rt.texture.id, RL_ATTACHMENT_COLOR_CHANNEL0, RL_ATTACHMENT_TEXTURE2D, 0);
        RT_CHECK(rlFramebufferComplete(fbo), "format %d: float target incomplete (EXT_color_buffer_float?)", formats[f]);
        BeginTextureMode(rt);
            ClearBackground((Color){ 0, 0, 0, 255 });
            DrawRectangle(0, 0, TARGET, TARGET/2, (Color){ 51, 102, 204, 255 });     // 0.2, 0.4, 0.8
        EndTextureMode();
        float *px = rtReadFloatPixels(rt.texture.id, TARGET, TARGET);
        RT_CHECK(px != NULL, "no readback");
        for (int row = 0; (px != NULL) && (row < 2); row++)
        {
            int y = (row == 0)? TARGET - 1 : 0;     // GL row TARGET-1 is the top (the rectangle)
            const float *v = px + ((size_t)y*TARGET + TARGET/2)*4;
            double want[4] = { 0.2, 0.4, 0.8, 1.0 };
            if (row == 1) want[0] = want[1] = want[2] = 0.0;
            // float: the 8-bit vertex colour c/255 (float rounding); half: 11-bit significand, 2^-11 relative
            double tol = (f == 0)? 1e-6 : 0.8/2048.0;
            for (int c = 0; c < 4; c++) RT_CHECK(rtNear(v[c], want[c], tol), "format %d row %d channel %d: %.6f want %.6f", formats[f], row, c, v[c], want[c]);
        }
        free(px);
        rlUnloadFramebuffer(fbo);     // deletes the attached texture too
    }
}

// What the browser's GPU computes for the transcendentals every lighting term uses, measured against
// double precision on arguments exact in float (k/2^n), in units of the float's ulp at the true value;
// the GLSL ES 3.00 highp bounds (spec 4.5.1) are asserted, and the measured worst is printed: it is
// the reason the lighting tests whose 2/255 bound was set on llvmpipe are left out here.
static double webUlps(double got, double want)
{
    int e; frexp(want, &e);
    return fabs(got - want)/ldexp(1.0, e - 24);
}

static void test_web_transcendentals_are_within_the_glsl_es_3_bounds(void)
{
    static const char *fs =
        "#version 300 es\n"
        "precision highp float;\n"
        "out vec4 finalColor;\n"
        "void main()\n"
        "{\n"
        "    float k = floor(gl_FragCoord.y)*64.0 + floor(gl_FragCoord.x);\n"   // 0..4095, exact
        "    finalColor = vec4(exp2((k - 2048.0)/256.0), log2((k + 1.0)/512.0), pow((k + 1.0)/1024.0, 2.5), inversesqrt((k + 1.0)/64.0));\n"
        "}\n";
    Shader sh = LoadShaderFromMemory(NULL, fs);
    RT_CHECK(IsShaderValid(sh) && (sh.id != rlGetShaderIdDefault()), "measuring shader did not build");
    unsigned int fbo = rlLoadFramebuffer();
    RenderTexture2D rt = { 0 };
    rt.id = fbo;
    rt.texture.id = rlLoadTexture(NULL, 64, 64, PIXELFORMAT_UNCOMPRESSED_R32G32B32A32, 1);
    rt.texture.width = rt.texture.height = 64; rt.texture.mipmaps = 1; rt.texture.format = PIXELFORMAT_UNCOMPRESSED_R32G32B32A32;
    rlFramebufferAttach(fbo, rt.texture.id, RL_ATTACHMENT_COLOR_CHANNEL0, RL_ATTACHMENT_TEXTURE2D, 0);
    BeginTextureMode(rt);
        ClearBackground(BLANK);
        rlDrawRenderBatchActive();
        rlDisableColorBlend();          // the values are written as they are, not blended by their alpha
        BeginShaderMode(sh);
            DrawRectangle(0, 0, 64, 64, WHITE);
        EndShaderMode();
        rlEnableColorBlend();
    EndTextureMode();
    float *px = rtReadFloatPixels(rt.texture.id, 64, 64);
    RT_CHECK(px != NULL, "no readback");
    double worst[4] = { 0 }, worstLogAbs = 0.0;
    int over = 0;
    for (int k = 0; (px != NULL) && (k < 4096); k++)
    {
        // gl_FragCoord.y counts GL rows from the bottom, as rtReadFloatPixels returns them
        const float *v = px + (size_t)k*4;
        double x = (k - 2048)/256.0, l = (k + 1)/512.0, b = (k + 1)/1024.0, r = (k + 1)/64.0;
        double u0 = webUlps(v[0], exp2(x)), u2 = webUlps(v[2], pow(b, 2.5)), u3 = webUlps(v[3], 1.0/sqrt(r));
        if (u0 > worst[0]) worst[0] = u0;
        if (u2 > worst[2]) worst[2] = u2;
        if (u3 > worst[3]) worst[3] = u3;
        if (u0 > 3.0 + 2.0*fabs(x)) over++;                              // exp2: (3 + 2|x|) ulp
        if (u3 > 2.0) over++;                                            // inversesqrt: 2 ulp
        if ((l >= 0.5) && (l <= 2.0))
        {
            double a = fabs(v[1] - log2(l));                             // log2 in [0.5, 2]: absolute 2^-21
            if (a > worstLogAbs) worstLogAbs = a;
            if (a > ldexp(1.0, -21)) over++;
        }
        else
        {
            double u1 = webUlps(v[1], log2(l));                          // elsewhere: 3 ulp
            if (u1 > worst[1]) worst[1] = u1;
            if (u1 > 3.0) over++;
        }
    }
    printf("    exp2 %.2f ulp, log2 %.2f ulp (|x-1| large) / %.2e absolute in [0.5, 2], pow(x, 2.5) %.2f ulp, inversesqrt %.2f ulp\n",
           worst[0], worst[1], worstLogAbs, worst[2], worst[3]);
    RT_CHECK(over == 0, "%d results outside the GLSL ES 3.00 highp bounds", over);
    free(px);
    rlUnloadFramebuffer(fbo);
    UnloadShader(sh);
}

// Left out in the browser, each with its reason (printed at the start of the run, not counted);
// `make test-web WEB_FILTER=--left-out` runs just these, to measure them again (a name filter may follow)
static const struct { const char *name; RtTestFn fn; const char *why; } webLeftOut[] = {
    { "test_shadows_omni_cube_faces_hold_the_double_precision_distances", test_shadows_omni_cube_faces_hold_the_double_precision_distances,
      "SwiftShader precision: the omni distance codes of 19200 of 31488 floor texels off the double ray by up to 332 of 65535 code steps (native: 0); the two-lamp lookup test passes here" },
    { "test_thin_relief_matches_the_double_march_on_a_step_a_dome_and_a_ridge", test_thin_relief_matches_the_double_march_on_a_step_a_dome_and_a_ridge,
      "SwiftShader precision: 1 of 401868 judged pixels (ridge, light 4, 16 steps) decides unlike the double march (native: 0)" },
    { "test_atlas_frames_drawn_batched_and_instanced_equal_their_rebuilt_canvases", test_atlas_frames_drawn_batched_and_instanced_equal_their_rebuilt_canvases,
      "loads its atlas fixtures from files: the page has no file system (they are not preloaded)" },
    { "test_lighting_matrix_matches_the_double_reference_within_2_of_255", test_lighting_matrix_matches_the_double_reference_within_2_of_255,
      "SwiftShader precision: measured max 10/255 (GGX spot grazing), mean 0.27/255 vs the 2/255 bound" },
    { "test_lighting_optional_stages_match_the_reference", test_lighting_optional_stages_match_the_reference,
      "SwiftShader precision: constant emission max 6/255; the inner=outer spot edge flips pixels on the step (151/255 on 0.08% of pixels)" },
    { "test_deferred_matches_forward_within_2_of_255_for_billboards_and_models", test_deferred_matches_forward_within_2_of_255_for_billboards_and_models,
      "SwiftShader precision: 2 pixels at 3/255 vs the 2/255 bound" },
    { "test_deferred_ambient_and_occlusion_from_the_geometry_pass_match_forward", test_deferred_ambient_and_occlusion_from_the_geometry_pass_match_forward,
      "SwiftShader: single pixels where two surfaces meet (the sphere resting on the floor) take the other surface: with 5 lights max 5-7/255, ambient only 2/255 (GGX) vs the 1/255 bound; the occlusion view exact" },
    { "test_deferred_matches_forward_for_every_brdf_roughness_and_shininess_flat_and_curved", test_deferred_matches_forward_for_every_brdf_roughness_and_shininess_flat_and_curved,
      "SwiftShader precision: GGX roughness 0.02-0.1 max 27/255, Blinn-Phong n=1024 max 15/255 (sharp highlights, plane)" },
    { "test_view_orthographic_plane_on_every_path_matches_the_double_reference", test_view_orthographic_plane_on_every_path_matches_the_double_reference,
      "SwiftShader precision: perspective max 7/255 vs the 2/255 bound" },
    { "test_raster_interpolated_position_and_window_depth_match_the_true_plane", test_raster_interpolated_position_and_window_depth_match_the_true_plane,
      "SwiftShader interpolation: varyings off by 2.5e-4 of the distance at every depth (llvmpipe <= 2.8e-6), gl_FragCoord.z by 28 24-bit steps at eye 0.5: the cause of the precision rows here" },
    { "test_deferred_distance_view_matches_the_true_plane_within_24_bit_depth_steps", test_deferred_distance_view_matches_the_true_plane_within_24_bit_depth_steps,
      "SwiftShader depth chain: the distance view is off by ~5e-4 of the distance at every depth (931/160/25/7 24-bit steps at eye 0.5/3/20/400; llvmpipe 4/6/4/13)" },
    { "test_deferred_sharp_highlights_on_a_sphere_under_9_light_rigs_within_2_of_255", test_deferred_sharp_highlights_on_a_sphere_under_9_light_rigs_within_2_of_255,
      "SwiftShader depth chain (above): GGX roughness 0.02 and 0.05 metal 3/255 in 1 rig of 9 (means <= 0.02/255; llvmpipe 1/255 in every rig)" },
    { "test_deferred_sharp_highlights_on_tilted_planes_within_2_of_255", test_deferred_sharp_highlights_on_tilted_planes_within_2_of_255,
      "SwiftShader depth chain (above): a 5e-4 rad view-vector error moves a roughness <= 0.1 highlight; max 255/255 on a few pixels (mean <= 0.1/255), 2/255 from roughness 0.3" },
    { "test_deferred_every_brdf_matches_the_double_reference_on_8_bit_and_float_targets", test_deferred_every_brdf_matches_the_double_reference_on_8_bit_and_float_targets,
      "SwiftShader precision: sharp highlights GGX max 22/255 (73.9 linear), Blinn-Phong 12/255 (35.8 linear); every mean within 0.25/255 but linear Lambert 2.7 max (llvmpipe: 1, 1.92 linear)" },
    { "test_deferred_orthographic_float_depth_rebuilds_the_view_distance_within_1_5_steps", test_deferred_orthographic_float_depth_rebuilds_the_view_distance_within_1_5_steps,
      "SwiftShader depth chain: the orthographic view distance off by 1.7 / 18.8 / 193 24-bit steps at 3 / 32 / 320 units (~1.4e-4 of the distance; llvmpipe <= 1.0), the highlight 4/255" },
    { "test_deferred_position_from_depth_error_at_near_middle_far", test_deferred_position_from_depth_error_at_near_middle_far,
      "reads the depth buffer: WebGL2 has no depth readback" },
    { "test_deferred_geometry_variant_of_another_brdf_is_refused_at_draw_and_writes_nothing", test_deferred_geometry_variant_of_another_brdf_is_refused_at_draw_and_writes_nothing,
      "reads the depth buffer: WebGL2 has no depth readback" },
    { "test_shadows_bad_input_is_refused_with_a_log_line_and_changes_nothing", test_shadows_bad_input_is_refused_with_a_log_line_and_changes_nothing,
      "reads the shadow map depth: WebGL2 has no depth readback" },
};

int main(int argc, char **argv)
{
    // The browser's own checks, then the shared GPU list less the tests left out (webLeftOut)
    static const RtTest own[] = {
        RT_TEST(test_web_default_shader_rectangle_reads_back_top_row_first),
        RT_TEST(test_web_float_and_half_targets_read_back_the_written_values),
        RT_TEST(test_web_transcendentals_are_within_the_glsl_es_3_bounds),
    };
    enum { OWN = (int)(sizeof(own)/sizeof(own[0])) };
    static RtTest tests[OWN + RBL_GPU_TEST_COUNT];
    int count = 0;
    for (int i = 0; i < OWN; i++) tests[count++] = own[i];
    for (int i = 0; i < RBL_GPU_TEST_COUNT; i++)
    {
        bool left = false;
        for (int k = 0; k < (int)(sizeof(webLeftOut)/sizeof(webLeftOut[0])); k++) left = left || (strcmp(webLeftOut[k].name, rblGpuTests[i].name) == 0);
        if (!left) tests[count++] = rblGpuTests[i];
    }
    const char *backend = rtInitContext(256, 256);
    if (backend == NULL) { printf("web: 0 passed, 1 failed\n"); return 1; }
    printf("  context: %s (%s, %s)\n", backend, (const char *)glGetString(GL_RENDERER), (const char *)glGetString(GL_VERSION));
    SetTraceLogCallback(countingLog);
    enum { LEFT_OUT = (int)(sizeof(webLeftOut)/sizeof(webLeftOut[0])) };
    int rc;
    if ((argc > 1) && (strcmp(argv[1], "--left-out") == 0))
    {
        RtTest leftOut[LEFT_OUT];
        for (int i = 0; i < LEFT_OUT; i++) { leftOut[i].name = webLeftOut[i].name; leftOut[i].fn = webLeftOut[i].fn; leftOut[i].glsl3 = false; }
        rc = rtRun("web", leftOut, LEFT_OUT, argc - 1, argv + 1);     // --left-out [name filter]
    }
    else
    {
        for (int i = 0; i < LEFT_OUT; i++) printf("  n/a   %s (%s)\n", webLeftOut[i].name, webLeftOut[i].why);
        rc = rtRun("web", tests, count, argc, argv);
    }
    RblClose();
    rtCloseContext();
    return rc;
}
