// CPU test suite (no GL): geometry and shader sources. Built plain and with ASan+UBSan.
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "harness.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_geometry.c"
#include "test_shaders_source.c"

int main(int argc, char **argv)
{
    static const RtTest tests[] = {
        RT_TEST(test_geometry_corners_match_double_reference_in_every_mode),
        RT_TEST(test_geometry_camera_modes_face_the_eye),
        RT_TEST(test_geometry_tangent_follows_plus_u_under_every_flip_and_rotated_frame),
        RT_TEST(test_geometry_uvs_match_raylib_layout_and_mirror_inside_the_source),
        RT_TEST(test_geometry_rounded_normals_bend_outward_and_stay_orthonormal),
        RT_TEST(test_hard_camera_looking_straight_up_or_down_gets_a_stable_frame),
        RT_TEST(test_hard_target_equals_position_and_billboard_at_the_eye),
        RT_TEST(test_hard_zero_negative_and_huge_sizes),
        RT_TEST(test_hard_far_from_origin_keeps_relative_precision),
        RT_TEST(test_hard_degenerate_source_and_texture_size),
        RT_TEST(test_hard_nan_or_inf_in_any_input_is_skipped),
        RT_TEST(test_shaders_embedded_copies_equal_the_glsl_files),
    };
    SetTraceLogLevel(LOG_WARNING);
    return rtRun("cpu", tests, (int)(sizeof(tests)/sizeof(tests[0])), argc, argv);
}
