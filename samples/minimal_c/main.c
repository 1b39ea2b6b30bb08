/* Minimal octocap user in C: load a calibration, solve a recording's first frame, print its first person's bones. */
#include <octocap/octocap.h>
#include <stdio.h>
#include <stdlib.h>

static int fail(const char* what) {
  fprintf(stderr, "%s: %s\n", what, octocap_last_error());
  return 1;
}

int main(int argc, char** argv) {
  octocap_calibration_t* calib = NULL;
  octocap_recording_t* rec = NULL;
  octocap_session_t* session = NULL;
  octocap_frame_t* frame = NULL;
  octocap_result_t result;
  octocap_session_config_t cfg;
  octocap_layout_t layout;
  uint32_t views = 0, needed = 0, count = 0, b;
  uint32_t people[64];
  octocap_keypoint2d_t* kps;
  octocap_bone_pose_t bones[OCTOCAP_BONE_COUNT];
  if (octocap_version_number() < OCTOCAP_VERSION_NUMBER || octocap_version_number() / 10000 != OCTOCAP_VERSION_MAJOR) {
    fprintf(stderr, "liboctocap %s is older than this program's header (%d)\n", octocap_version(), OCTOCAP_VERSION_NUMBER);
    return 1;
  }
  if (argc < 3) {
    fprintf(stderr, "usage: %s CALIBRATION.toml KEYPOINTS_DIR\n", argv[0]);
    return 2;
  }
  if (octocap_calibration_load(argv[1], &calib) != OCTOCAP_OK) return fail("calibration");
  if (octocap_recording_open(argv[2], OCTOCAP_LAYOUT_AUTO, &rec) != OCTOCAP_OK) return fail("recording");
  octocap_recording_view_count(rec, &views);
  octocap_recording_layout(rec, &layout);
  if (views > 64) return 1;
  octocap_session_config_init(&cfg);
  cfg.layout = layout;
  if (octocap_session_create(&cfg, calib, &session) != OCTOCAP_OK) return fail("session");
  octocap_recording_read_frame(rec, 0, NULL, 0, &needed, people, views);
  kps = malloc(sizeof *kps * (needed ? needed : 1));
  if (octocap_recording_read_frame(rec, 0, kps, needed, &needed, people, views) != OCTOCAP_OK) return fail("read");
  result = octocap_session_solve_keypoints(session, kps, people, views, 0);
  if (OCTOCAP_FAILED(result)) return fail("solve");
  if (result == OCTOCAP_STATUS_NO_PERSON) {
    printf("nobody in the first frame\n");
    return 0;
  }
  if (octocap_session_get_frame(session, &frame) != OCTOCAP_OK) return fail("frame");
  if (octocap_frame_get_bones(frame, 0, OCTOCAP_FRAME_RIG, bones, OCTOCAP_BONE_COUNT, &count) != OCTOCAP_OK)
    return fail("bones");
  for (b = 0; b < count; ++b) {
    octocap_bone_info_t info;
    octocap_bone_info(b, &info);
    printf("%-12s valid %u  q = (%.3f %.3f %.3f %.3f)\n", info.name, bones[b].valid, bones[b].local_rotation.x,
           bones[b].local_rotation.y, bones[b].local_rotation.z, bones[b].local_rotation.w);
  }
  free(kps);
  octocap_frame_release(frame);
  octocap_session_destroy(session);
  octocap_recording_destroy(rec);
  octocap_calibration_destroy(calib);
  return 0;
}
