// CPU test suite (no GL): geometry, material maps and shader sources. Built plain and with ASan+UBSan.
#define RBILLBOARD_LIT_IMPLEMENTATION
#include "rbillboard_lit.h"
#include "harness.h"

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_geometry.c"
#include "test_materials.c"
#include "test_shaders_source.c"
#include "test_atlas.c"

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
        RT_TEST(test_hard_near_degenerate_frames_are_orthonormal),
        RT_TEST(test_hard_near_degenerate_frames_follow_the_documented_blend),
        RT_TEST(test_hard_exact_degenerate_frames_are_the_documented_fallbacks),
        RT_TEST(test_hard_zero_negative_and_huge_sizes),
        RT_TEST(test_hard_far_from_origin_keeps_relative_precision),
        RT_TEST(test_hard_degenerate_source_and_texture_size),
        RT_TEST(test_hard_nan_or_inf_in_any_input_is_skipped),
        RT_TEST(test_hard_billboard_checks_and_culling_four_lanes_equal_one_at_a_time),
        RT_TEST(test_geometry_batch_frame_reuse_is_bit_identical_to_single_billboards),
        RT_TEST(test_geometry_rotation_sin_cos_is_exact_at_quadrants_and_within_1_5e_7),
        RT_TEST(test_materials_encodings_round_trip_a_uniform_hemisphere_near_the_reference_errors),
        RT_TEST(test_materials_alpha_coverage_is_kept_on_every_mip_level),
        RT_TEST(test_materials_default_hemioct_meets_max_0_6_and_mean_0_25_degrees),
        RT_TEST(test_materials_xy_error_is_small_near_the_pole_and_over_3_degrees_at_grazing_angles),
        RT_TEST(test_materials_precise_hemioct_is_never_worse_than_rounding_and_better_on_average),
        RT_TEST(test_materials_every_code_decodes_to_a_finite_unit_normal),
        RT_TEST(test_materials_encoder_refuses_nan_inf_zero_and_maps_below_hemisphere_input_to_defined_codes),
        RT_TEST(test_materials_measure_reports_mean_nearest_rank_p99_max_and_counts_only_valid_normals),
        RT_TEST(test_materials_height_plane_tilted_by_a_known_angle_gives_that_normal),
        RT_TEST(test_materials_strength_is_height_units_per_texel_so_one_per_texel_at_strength_1_is_45_degrees),
        RT_TEST(test_materials_height_rising_toward_the_image_top_tilts_normals_to_minus_y),
        RT_TEST(test_materials_hemisphere_bump_gives_the_analytic_sphere_normals),
        RT_TEST(test_materials_wrap_edges_continue_across_the_border_and_clamp_edges_repeat_the_edge_texel),
        RT_TEST(test_materials_height_from_luminance_is_rec709_of_the_linearised_colour),
        RT_TEST(test_materials_occlusion_is_open_on_flat_ground_and_on_tops_and_darker_in_pits),
        RT_TEST(test_materials_pack_layout_flags_follow_the_present_maps_and_absent_channels_take_defaults),
        RT_TEST(test_materials_pack_directx_flag_flips_the_decoded_y),
        RT_TEST(test_materials_pack_zero_vector_normal_texels_become_flat_never_nan),
        RT_TEST(test_materials_pack_rejects_invalid_input_with_a_warning_and_leaves_packed_untouched),
        RT_TEST(test_materials_pack_converts_grayscale_rgb565_and_float_inputs_instead_of_rejecting),
        RT_TEST(test_materials_pack_grey_emissive_becomes_a_mask_and_coloured_emissive_stays_rgb),
        RT_TEST(test_materials_dilation_fills_gutters_with_the_nearest_frame_edge_and_mips_never_mix_frames),
        RT_TEST(test_materials_mip_normals_are_renormalised_and_opposite_tilts_average_to_flat),
        RT_TEST(test_materials_albedo_mips_average_in_linear_light_weighted_by_alpha),
        RT_TEST(test_materials_mip_chain_uses_raylib_sizes_and_layout_and_odd_sizes_keep_constants),
        RT_TEST(test_materials_unload_frees_and_zeroes_the_packed_material),
        RT_TEST(test_shaders_embedded_copies_equal_the_glsl_files),
        RT_TEST(test_shaders_each_stage_lists_its_include_closure_dependencies_first),
        RT_TEST(test_atlas_texturepacker_hash_and_array_give_the_hand_derived_frames),
        RT_TEST(test_atlas_texturepacker_multipack_follows_related_packs_once),
        RT_TEST(test_atlas_aseprite_durations_tags_and_slice_pivots),
        RT_TEST(test_atlas_libgdx_old_and_new_forms_rotate_counter_clockwise_offsets_from_the_bottom),
        RT_TEST(test_atlas_blocks_pack_a_same_layout_normal_sheet_per_frame),
        RT_TEST(test_atlas_player_follows_durations_directions_and_repeats),
        RT_TEST(test_atlas_bulk_instance_update_equals_the_per_sprite_calls),
        RT_TEST(test_atlas_view_sector_boundaries_for_4_8_16_directions),
        RT_TEST(test_atlas_malformed_input_fails_with_one_line),
        RT_TEST(test_atlas_phaser3_textures_are_one_page_each_with_its_normal_sheet_and_scale),
        RT_TEST(test_atlas_sheet_paths_resolve_as_written_then_beside_then_by_the_atlas_name),
        RT_TEST(test_atlas_meta_scale_as_string_or_number_draws_every_export_at_one_world_size),
        RT_TEST(test_atlas_zero_negative_fractional_or_non_finite_page_sizes_are_refused),
        RT_TEST(test_atlas_polygon_frames_keep_their_vertices_uvs_and_triangles_validated),
        RT_TEST(test_atlas_polygon_quads_match_a_double_reference_of_the_quads_fields),
        RT_TEST(test_atlas_libgdx_any_quarter_turn_colon_names_pma_split_and_pad),
        RT_TEST(test_atlas_aseprite_slices_are_sub_frames_with_their_own_pivots),
        RT_TEST(test_atlas_frames_without_a_pivot_stand_on_their_position),
        RT_TEST(test_atlas_premultiplied_pages_pack_mips_as_the_alpha_weighted_mean_kept_premultiplied),
        RT_TEST(test_atlas_real_exporter_files_import_and_rebuild_from_their_sheets),
        RT_TEST(test_sprite_update_checks_and_chunk_bounds_equal_the_one_at_a_time_ones),
    };
    SetTraceLogLevel(LOG_WARNING);
    return rtRun("cpu", tests, (int)(sizeof(tests)/sizeof(tests[0])), argc, argv);
}
