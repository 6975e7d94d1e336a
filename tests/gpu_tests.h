// The GPU suite's tests, one list for every runner: tests/test_gpu_main.c (EGL, OSMesa, ES 3, ES 2,
// GL 2.1) and tests/web/test_web_main.c (WebGL2, less the tests it states it leaves out). Needs the
// implementation, harness.h, gpu_common.h and the C headers included first.
#ifndef RBL_TESTS_GPU_TESTS_H
#define RBL_TESTS_GPU_TESTS_H

#include "reference.h"
#include "test_render.c"
#include "test_api.c"
#include "test_instanced.c"
#include "test_material_render.c"
#include "test_lighting.c"
#include "test_deferred.c"
#include "test_view.c"
#include "test_shadows.c"
#include "test_self_shadow.c"
#include "test_skinning.c"
#include "test_sprites.c"
#include "test_atlas_render.c"
#include "test_fade.c"
#include "test_held.c"
#include "test_cull.c"

static const RtTest rblGpuTests[] = {
        RBL_API_TESTS,
        RBL_HELD_TESTS,
        RT_TEST(test_shaders_every_lit_variant_compiles_and_links),
        RT_TEST(test_shaders_compile_failure_is_reported_not_replaced_by_the_default),
        RT_TEST(test_lit_normal_map_tilted_toward_plus_u_is_brighter_lit_from_plus_u),
        RT_TEST(test_lit_flat_normal_map_matches_analytic_lambert_within_2_of_255),
        RT_TEST(test_lit_flips_and_rotated_frames_light_the_plus_u_side),
        RT_TEST(test_lit_bad_lights_are_rejected_and_change_nothing),
        RT_TEST(test_atlas_frames_drawn_batched_and_instanced_equal_their_rebuilt_canvases),
        RT_TEST(test_atlas_rotated_frames_light_like_the_upright_frame),
        RT_TEST(test_atlas_page_and_its_normal_sheet_load_in_one_call_and_light_as_the_reference),
        RT_TEST(test_atlas_premultiplied_pages_light_and_blend_as_their_straight_colour),
        RT_TEST(test_batch_grows_with_a_log_line_skips_bad_input_once_and_matches_immediate),
        RT_TEST(test_cull_batches_skip_what_the_camera_cannot_see_and_draw_the_same_picture),
        RT_TEST(test_cull_shadow_pass_batches_skip_casters_outside_the_light_and_cast_the_same_shadows),
        RT_TEST(test_parity_camera_plane_positions_and_uvs_equal_raylib_draw_billboard_pro),
        RT_TEST_GLSL3(test_paths_instanced_vertices_equal_the_cpu_path_in_every_mode),
        RT_TEST_GLSL3(test_paths_instanced_hard_cases_stay_finite),
        RT_TEST_GLSL3(test_paths_instanced_near_degenerate_frames_agree_with_the_cpu_path),
        RT_TEST_GLSL3(test_paths_instanced_tiny_up_and_axis_read_alike_on_cpu_and_gpu),
        RT_TEST_GLSL3(test_paths_instanced_rotation_agrees_with_the_cpu_at_any_angle),
        RT_TEST_GLSL3(test_paths_instanced_draw_matches_batched_pixels_and_skips_bad_instances),
        RT_TEST_GLSL3(test_paths_instanced_validation_bound_is_2_to_the_120_in_every_float_field),
        RT_TEST_GLSL3(test_paths_instanced_location_cache_survives_program_id_reuse),
        RT_TEST(test_materials_mid_grey_srgb_albedo_lights_as_linear_0_214),
        RT_TEST(test_materials_shader_decodes_every_encoding_like_the_cpu),
        RT_TEST(test_materials_absent_maps_are_not_declared_or_sampled),
        RT_TEST(test_materials_occlusion_dims_ambient_only),
        RT_TEST(test_materials_emission_adds_after_lighting),
        RT_TEST(test_materials_packed_atlas_renders_like_its_separate_maps),
        RT_TEST(test_lighting_every_variant_compiles_and_each_handle_owns_its_program),
        RT_TEST(test_lighting_bad_descs_and_lights_are_rejected_with_a_log_line),
        RT_TEST(test_lighting_matrix_matches_the_double_reference_within_2_of_255),
        RT_TEST(test_lighting_optional_stages_match_the_reference),
        RT_TEST(test_lighting_hard_roughness_zero),
        RT_TEST(test_lighting_hard_metal_with_black_albedo),
        RT_TEST(test_lighting_hard_grazing_normal_ndotv_zero),
        RT_TEST(test_lighting_hard_light_behind_the_surface),
        RT_TEST(test_lighting_hard_light_on_the_shaded_point),
        RT_TEST(test_lighting_hard_range_zero_and_intensity_zero_and_zero_lights),
        RT_TEST(test_lighting_hard_maximum_light_count),
        RT_TEST(test_lighting_hard_half_float_overflow_before_tonemap),
        RT_TEST(test_lighting_hard_zero_length_map_normal_is_the_flat_normal),
        RT_TEST(test_lighting_billboard_and_model_quad_render_identical_pixels),
        RT_TEST_GLSL3(test_deferred_gbuffer_is_10_bytes_per_pixel_and_resize_and_unload_leak_nothing),
        RT_TEST_GLSL3(test_deferred_matches_forward_within_2_of_255_for_billboards_and_models),
        RT_TEST_GLSL3(test_deferred_ambient_and_occlusion_from_the_geometry_pass_match_forward),
        RT_TEST_GLSL3(test_deferred_matches_forward_with_an_orthographic_camera),
        RT_TEST_GLSL3(test_deferred_eye_inside_a_light_volume_is_lit_like_forward),
        RT_TEST_GLSL3(test_deferred_1024_lights_match_the_double_reference),
        RT_TEST_GLSL3(test_deferred_matches_forward_for_every_brdf_roughness_and_shininess_flat_and_curved),
        RT_TEST_GLSL3(test_deferred_sharp_highlights_on_a_sphere_under_9_light_rigs_within_2_of_255),
        RT_TEST_GLSL3(test_deferred_sharp_highlights_on_tilted_planes_within_2_of_255),
        RT_TEST_GLSL3(test_deferred_every_brdf_matches_the_double_reference_on_8_bit_and_float_targets),
        RT_TEST_GLSL3(test_deferred_normal_encoding_error_table_against_published_figures),
        RT_TEST_GLSL3(test_deferred_position_from_depth_error_at_near_middle_far),
        RT_TEST_GLSL3(test_deferred_distance_view_matches_the_true_plane_within_24_bit_depth_steps),
        RT_TEST_GLSL3(test_deferred_orthographic_float_depth_rebuilds_the_view_distance_within_1_5_steps),
        RT_TEST_GLSL3(test_raster_interpolated_position_and_window_depth_match_the_true_plane),
        RT_TEST_GLSL3(test_deferred_forced_failure_logs_and_the_forward_fallback_renders),
        RT_TEST_GLSL3(test_deferred_transparent_billboards_drawn_forward_sort_against_deferred_depth),
        RT_TEST_GLSL3(test_deferred_debug_views_show_what_they_name),
        RT_TEST_GLSL3(test_deferred_geometry_variant_of_another_brdf_is_refused_at_draw_and_writes_nothing),
        RT_TEST(test_view_orthographic_plane_on_every_path_matches_the_double_reference),
        RT_TEST(test_view_orthographic_fog_runs_along_the_view_axis),
        RT_TEST(test_view_orthographic_sphere_model_matches_the_double_reference),
        RT_TEST(test_view_card_seen_from_behind_is_lit_on_the_side_the_viewer_sees),
        RT_TEST(test_view_card_from_behind_far_light_adds_nothing_and_tilt_keeps_its_side),
        RT_TEST(test_view_culling_is_off_only_for_draws_that_show_a_back_and_restored),
        RT_TEST(test_view_card_seen_from_behind_receives_shadows_on_its_lit_side),
        RT_TEST(test_view_open_model_seen_from_below_is_lit_on_the_side_seen),
        RT_TEST(test_shadows_opaque_card_darkens_its_analytic_footprint_within_a_texel),
        RT_TEST(test_shadows_transparent_hole_in_a_sprite_lets_light_through_on_every_path),
        RT_TEST(test_shadows_raylib_model_casts_its_footprint),
        RT_TEST(test_shadows_no_acne_on_a_floor_lit_at_up_to_80_degrees),
        RT_TEST(test_shadows_standing_card_casts_from_its_base_without_peter_panning),
        RT_TEST(test_shadows_axis_locked_billboard_casts_under_a_light_straight_above),
        RT_TEST_GLSL3(test_shadows_axis_tilt_is_the_same_on_cpu_and_gpu),
        RT_TEST_GLSL3(test_shadows_forward_and_deferred_agree_within_2_of_255),
        RT_TEST(test_shadows_bad_input_is_refused_with_a_log_line_and_changes_nothing),
        RT_TEST(test_shadows_hard_cases_stay_finite),
        RT_TEST(test_shadows_pass_restores_the_callers_target_and_matrices),
        RT_TEST(test_shadows_sprites_never_shadow_themselves_in_a_sweep_of_every_light_direction),
        RT_TEST(test_shadows_sprite_receives_a_crates_shadow_and_never_its_own_in_the_users_scene),
        RT_TEST(test_shadows_light_over_an_axis_sprite_moves_its_shadow_continuously),
        RT_TEST(test_shadows_caster_identity_is_the_same_on_every_path_and_in_any_order),
        RT_TEST(test_shadows_self_shadow_option_drops_the_identities),
        RT_TEST_GLSL3(test_shadows_deferred_sprites_never_shadow_themselves_and_match_forward),
        RT_TEST(test_sprites_sorted_translucent_cards_draw_alike_in_any_submission_order),
        RT_TEST(test_sprites_hybrid_smoke_behind_a_tree_shows_through_its_holes),
        RT_TEST(test_sprites_bad_sort_settings_are_refused_and_draw_nothing),
        RT_TEST_GLSL3(test_sprites_instanced_sort_draws_alike_in_any_array_order),
        RT_TEST(test_sprites_soft_particles_fade_by_depth_distance_to_the_scene),
        RT_TEST(test_sprites_soft_particles_in_a_plain_frame_with_two_added_lines),
        RT_TEST(test_sprites_npot_packed_atlas_uploads_what_the_context_can_sample),
        RT_TEST_GLSL3(test_sprites_soft_particles_read_a_gbuffer_depth),
        RT_TEST(test_skinning_lit_model_animates_and_matches_the_cpu_skinned_rendering),
        RT_TEST(test_skinning_shadow_animates_and_matches_the_cpu_skinned_caster),
        RT_TEST(test_skinning_bad_input_is_refused_and_draws_nothing),
        RBL_FADE_TESTS,
    };
#define RBL_GPU_TEST_COUNT ((int)(sizeof(rblGpuTests)/sizeof(rblGpuTests[0])))

#endif
