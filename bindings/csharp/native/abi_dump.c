/* The C side of the C# binding checks, using the public header only:
 *   octocap-abi-dump layout            prints "STRUCT FIELD OFFSET" and "STRUCT sizeof SIZE" lines
 *   octocap-abi-dump solve CALIB DIR OUT  solves a recording frame by frame and writes the raw bytes of every
 *                                      frame's 3D keypoints and bone poses (rig frame) to OUT. */
#include <octocap/octocap.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FIELD(S, F) printf("%s %s %u\n", #S, #F, (unsigned)offsetof(S, F))
#define SIZE(S) printf("%s sizeof %u\n", #S, (unsigned)sizeof(S))

static void layout(void) {
  SIZE(octocap_keypoint2d_t);
  FIELD(octocap_keypoint2d_t, x); FIELD(octocap_keypoint2d_t, y); FIELD(octocap_keypoint2d_t, confidence);
  SIZE(octocap_joint_t);
  FIELD(octocap_joint_t, position); FIELD(octocap_joint_t, confidence); FIELD(octocap_joint_t, reprojection_error_px);
  FIELD(octocap_joint_t, views_used); FIELD(octocap_joint_t, valid);
  SIZE(octocap_quat_t);
  FIELD(octocap_quat_t, x); FIELD(octocap_quat_t, y); FIELD(octocap_quat_t, z); FIELD(octocap_quat_t, w);
  SIZE(octocap_bone_pose_t);
  FIELD(octocap_bone_pose_t, local_rotation); FIELD(octocap_bone_pose_t, global_rotation);
  FIELD(octocap_bone_pose_t, head_position); FIELD(octocap_bone_pose_t, length_m); FIELD(octocap_bone_pose_t, valid);
  SIZE(octocap_frame_info_t);
  FIELD(octocap_frame_info_t, frame_index); FIELD(octocap_frame_info_t, timestamp_us);
  FIELD(octocap_frame_info_t, keypoints_solved); FIELD(octocap_frame_info_t, keypoints_total);
  FIELD(octocap_frame_info_t, mean_reprojection_error_px); FIELD(octocap_frame_info_t, views_with_person);
  FIELD(octocap_frame_info_t, solve_ms);
  SIZE(octocap_bone_info_t);
  FIELD(octocap_bone_info_t, name); FIELD(octocap_bone_info_t, parent_bone); FIELD(octocap_bone_info_t, head_joint);
  FIELD(octocap_bone_info_t, tail_joint); FIELD(octocap_bone_info_t, rest_direction);
  SIZE(octocap_camera_t);
  FIELD(octocap_camera_t, name); FIELD(octocap_camera_t, width); FIELD(octocap_camera_t, height);
  FIELD(octocap_camera_t, matrix); FIELD(octocap_camera_t, distortion); FIELD(octocap_camera_t, fisheye);
  FIELD(octocap_camera_t, rotation); FIELD(octocap_camera_t, translation);
  SIZE(octocap_session_config_t);
  FIELD(octocap_session_config_t, struct_size); FIELD(octocap_session_config_t, layout);
  FIELD(octocap_session_config_t, method); FIELD(octocap_session_config_t, filter);
  FIELD(octocap_session_config_t, up_axis); FIELD(octocap_session_config_t, sigma);
  FIELD(octocap_session_config_t, min_views); FIELD(octocap_session_config_t, delta_m);
  FIELD(octocap_session_config_t, pixel_tolerance); FIELD(octocap_session_config_t, max_candidates);
  FIELD(octocap_session_config_t, min_confidence); FIELD(octocap_session_config_t, outlier_threshold_px);
  FIELD(octocap_session_config_t, volume_min); FIELD(octocap_session_config_t, volume_max);
  FIELD(octocap_session_config_t, filter_min_cutoff_hz); FIELD(octocap_session_config_t, filter_beta);
  FIELD(octocap_session_config_t, worker_threads); FIELD(octocap_session_config_t, first_frame_index);
  FIELD(octocap_session_config_t, stream_enable); FIELD(octocap_session_config_t, stream_domain_id);
  FIELD(octocap_session_config_t, stream_qos); FIELD(octocap_session_config_t, stream_history_depth);
  FIELD(octocap_session_config_t, stream_source_id); FIELD(octocap_session_config_t, stream_topic);
  FIELD(octocap_session_config_t, vmc_port); FIELD(octocap_session_config_t, vmc_host);
  FIELD(octocap_session_config_t, max_people); FIELD(octocap_session_config_t, reserved_1_10);
  FIELD(octocap_session_config_t, stream_security);
  FIELD(octocap_session_config_t, foot_lock); FIELD(octocap_session_config_t, reserved_1_11);
  SIZE(octocap_detector_config_t);
  FIELD(octocap_detector_config_t, struct_size); FIELD(octocap_detector_config_t, model);
  FIELD(octocap_detector_config_t, mode); FIELD(octocap_detector_config_t, person_pick);
  FIELD(octocap_detector_config_t, threads); FIELD(octocap_detector_config_t, mosaic_tile_px);
  FIELD(octocap_detector_config_t, max_people); FIELD(octocap_detector_config_t, min_confidence);
  FIELD(octocap_detector_config_t, parallel_views); FIELD(octocap_detector_config_t, views_per_frame);
  FIELD(octocap_detector_config_t, device); FIELD(octocap_detector_config_t, runtime);
  FIELD(octocap_detector_config_t, precision);
  SIZE(octocap_image_t);
  FIELD(octocap_image_t, pixels); FIELD(octocap_image_t, width); FIELD(octocap_image_t, height);
  FIELD(octocap_image_t, stride_bytes); FIELD(octocap_image_t, format);
  SIZE(octocap_detect_info_t);
  FIELD(octocap_detect_info_t, struct_size); FIELD(octocap_detect_info_t, total_ms);
  FIELD(octocap_detect_info_t, preprocess_ms); FIELD(octocap_detect_info_t, inference_ms);
  FIELD(octocap_detect_info_t, inferences); FIELD(octocap_detect_info_t, layout);
  FIELD(octocap_detect_info_t, keypoint_count); FIELD(octocap_detect_info_t, model);
  FIELD(octocap_detect_info_t, mode); FIELD(octocap_detect_info_t, views_tracked);
  FIELD(octocap_detect_info_t, track_ms); FIELD(octocap_detect_info_t, device);
  FIELD(octocap_detect_info_t, runtime); FIELD(octocap_detect_info_t, precision);
  SIZE(octocap_subscriber_config_t);
  FIELD(octocap_subscriber_config_t, struct_size); FIELD(octocap_subscriber_config_t, domain_id);
  FIELD(octocap_subscriber_config_t, qos); FIELD(octocap_subscriber_config_t, history_depth);
  FIELD(octocap_subscriber_config_t, source_id); FIELD(octocap_subscriber_config_t, topic);
  FIELD(octocap_subscriber_config_t, security);
  SIZE(octocap_stream_info_t);
  FIELD(octocap_stream_info_t, frames_received); FIELD(octocap_stream_info_t, frames_lost);
  FIELD(octocap_stream_info_t, last_gap); FIELD(octocap_stream_info_t, restarts);
  FIELD(octocap_stream_info_t, rejected); FIELD(octocap_stream_info_t, source_id);
  FIELD(octocap_stream_info_t, definition_counter); FIELD(octocap_stream_info_t, layout);
  FIELD(octocap_stream_info_t, has_definition);
  SIZE(octocap_frame_summary_t);
  FIELD(octocap_frame_summary_t, struct_size); FIELD(octocap_frame_summary_t, person_count);
  FIELD(octocap_frame_summary_t, frame_index); FIELD(octocap_frame_summary_t, timestamp_us);
  FIELD(octocap_frame_summary_t, layout); FIELD(octocap_frame_summary_t, keypoint_count);
  FIELD(octocap_frame_summary_t, definition_counter); FIELD(octocap_frame_summary_t, source_id);
  FIELD(octocap_frame_summary_t, view_count); FIELD(octocap_frame_summary_t, joints_in_rig_frame);
  FIELD(octocap_frame_summary_t, solve_ms);
  SIZE(octocap_person_t);
  FIELD(octocap_person_t, struct_size); FIELD(octocap_person_t, id); FIELD(octocap_person_t, keypoints_solved);
  FIELD(octocap_person_t, keypoints_total); FIELD(octocap_person_t, joints_solved);
  FIELD(octocap_person_t, views_with_person); FIELD(octocap_person_t, mean_reprojection_error_px);
  FIELD(octocap_person_t, confidence); FIELD(octocap_person_t, foot_contacts);
  SIZE(octocap_live_config_t);
  FIELD(octocap_live_config_t, struct_size); FIELD(octocap_live_config_t, sync_tolerance_us);
  FIELD(octocap_live_config_t, max_wait_us); FIELD(octocap_live_config_t, open_timeout_ms);
  FIELD(octocap_live_config_t, read_timeout_ms); FIELD(octocap_live_config_t, reconnect_max_ms);
  FIELD(octocap_live_config_t, picture_rate_hz); FIELD(octocap_live_config_t, remote_domain_id);
  FIELD(octocap_live_config_t, remote_topic); FIELD(octocap_live_config_t, quality);
  FIELD(octocap_live_config_t, target_fps); FIELD(octocap_live_config_t, latency_budget_ms);
  FIELD(octocap_live_config_t, remote_security);
  SIZE(octocap_live_stats_t);
  FIELD(octocap_live_stats_t, struct_size); FIELD(octocap_live_stats_t, running); FIELD(octocap_live_stats_t, finished);
  FIELD(octocap_live_stats_t, camera_count); FIELD(octocap_live_stats_t, frame_sets);
  FIELD(octocap_live_stats_t, frames_with_person); FIELD(octocap_live_stats_t, sets_incomplete);
  FIELD(octocap_live_stats_t, frames_not_taken); FIELD(octocap_live_stats_t, fps); FIELD(octocap_live_stats_t, capture_ms);
  FIELD(octocap_live_stats_t, detect_ms); FIELD(octocap_live_stats_t, solve_ms); FIELD(octocap_live_stats_t, publish_ms);
  FIELD(octocap_live_stats_t, latency_p50_ms); FIELD(octocap_live_stats_t, latency_p99_ms);
  FIELD(octocap_live_stats_t, sets_recorded); FIELD(octocap_live_stats_t, recording_pictures_dropped);
  FIELD(octocap_live_stats_t, failed); FIELD(octocap_live_stats_t, last_error);
  FIELD(octocap_live_stats_t, quality_rung); FIELD(octocap_live_stats_t, quality_rungs);
  FIELD(octocap_live_stats_t, views_detected); FIELD(octocap_live_stats_t, target_fps);
  FIELD(octocap_live_stats_t, budget_used); FIELD(octocap_live_stats_t, rung_changes); FIELD(octocap_live_stats_t, model); FIELD(octocap_live_stats_t, views_in_set);
  SIZE(octocap_camera_status_t);
  FIELD(octocap_camera_status_t, struct_size); FIELD(octocap_camera_status_t, state);
  FIELD(octocap_camera_status_t, grabbed); FIELD(octocap_camera_status_t, used); FIELD(octocap_camera_status_t, dropped);
  FIELD(octocap_camera_status_t, reconnects); FIELD(octocap_camera_status_t, fps);
  FIELD(octocap_camera_status_t, nominal_fps); FIELD(octocap_camera_status_t, name);
  FIELD(octocap_camera_status_t, clock_offset_ms);
  FIELD(octocap_camera_status_t, stream_clock);
  FIELD(octocap_camera_status_t, last_error);
  FIELD(octocap_camera_status_t, bad_pictures);
}

static int fail(const char* what) {
  fprintf(stderr, "octocap-abi-dump: %s: %s\n", what, octocap_last_error());
  return 1;
}

static int solve(const char* calib_path, const char* dir, const char* out_path) {
  octocap_calibration_t* calib = NULL;
  octocap_recording_t* rec = NULL;
  octocap_session_t* s = NULL;
  octocap_frame_t* frame = NULL;
  octocap_session_config_t cfg;
  octocap_layout_t lay;
  uint32_t views = 0, frames = 0, f, needed = 0, n = 0;
  uint32_t people[64];
  octocap_keypoint2d_t* kps = malloc(sizeof *kps * 64 * 64);
  octocap_joint_t joints[64];
  octocap_bone_pose_t bones[OCTOCAP_BONE_COUNT];
  FILE* out = fopen(out_path, "wb");
  if (!out || !kps) return 1;
  if (octocap_calibration_load(calib_path, &calib) != OCTOCAP_OK) return fail("calibration");
  if (octocap_recording_open(dir, OCTOCAP_LAYOUT_AUTO, &rec) != OCTOCAP_OK) return fail("recording");
  octocap_recording_view_count(rec, &views);
  octocap_recording_frame_count(rec, &frames);
  octocap_recording_layout(rec, &lay);
  octocap_session_config_init(&cfg);
  cfg.layout = lay;
  if (octocap_session_create(&cfg, calib, &s) != OCTOCAP_OK) return fail("session");
  for (f = 0; f < frames; ++f) {
    if (octocap_recording_read_frame(rec, f, kps, 64 * 64, &needed, people, views) != OCTOCAP_OK) return fail("read");
    if (octocap_session_solve_keypoints(s, kps, people, views, (int64_t)f * 33333) != OCTOCAP_OK) return fail("solve");
    if (octocap_session_get_frame(s, &frame) != OCTOCAP_OK) return fail("frame");
    octocap_frame_get_keypoints3d(frame, 0, joints, 64, &n);
    fwrite(joints, sizeof joints[0], n, out);
    octocap_frame_get_bones(frame, 0, OCTOCAP_FRAME_RIG, bones, OCTOCAP_BONE_COUNT, &n);
    fwrite(bones, sizeof bones[0], n, out);
    octocap_frame_release(frame);
  }
  fclose(out);
  free(kps);
  octocap_session_destroy(s);
  octocap_recording_destroy(rec);
  octocap_calibration_destroy(calib);
  return 0;
}

int main(int argc, char** argv) {
  if (argc == 2 && strcmp(argv[1], "layout") == 0) {
    layout();
    return 0;
  }
  if (argc == 5 && strcmp(argv[1], "solve") == 0) return solve(argv[2], argv[3], argv[4]);
  fprintf(stderr, "usage: octocap-abi-dump layout | solve CALIB.toml KEYPOINTS_DIR OUT.bin\n");
  return 2;
}
