/* A program as it was written against an old header (tests/abi/headers/, taken from git history), compiled against
 * that header and run against today's library. OLD_API says which header: 1 = 0.1, 2 = 0.2 (streaming),
 * 3 = 0.2 with VMC, 4 = 0.3 (detector nested in the session config), 5 = the last 0.3, 6 = 1.1 (live capture,
 * capture nodes), 7 = 1.2 (live recording; the session config before max_people), 8 = 1.3, 9 = 1.4 (the detector
 * config before detection scheduling and the device).
 *
 * It checks what the compatibility promise says: no _init writes past the caller's struct (guard bytes after each
 * struct stay intact), every old struct size is accepted, and the old per-source queries still solve the built-in
 * sample to its ground truth. Usage: old_caller CALIBRATION.toml KEYPOINTS_DIR GROUND_TRUTH.csv */
#include <math.h>
#include <octocap/octocap.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define GUARD 0xA5
#define GUARD_BYTES 1024

static int failures = 0;

static void expect(int ok, const char* what) {
  if (!ok) {
    fprintf(stderr, "old caller (API %d): FAILED: %s (%s)\n", OLD_API, what, octocap_last_error());
    ++failures;
  }
}

/* Every byte past `size` in the guarded box must be untouched. */
static int guard_intact(const unsigned char* box, size_t size) {
  size_t i;
  for (i = size; i < size + GUARD_BYTES; ++i)
    if (box[i] != GUARD) return 0;
  return 1;
}

#define CHECK_INIT(TYPE, INIT)                                                        \
  do {                                                                                \
    static unsigned char box[sizeof(TYPE) + GUARD_BYTES];                             \
    memset(box, GUARD, sizeof box);                                                   \
    INIT((TYPE*)(void*)box);                                                          \
    expect(guard_intact(box, sizeof(TYPE)), #INIT " wrote past " #TYPE);             \
    expect(((TYPE*)(void*)box)->struct_size <= sizeof(TYPE), #INIT " struct_size");   \
  } while (0)

/* Ground truth: `frame,NAME_x,NAME_y,NAME_z,...`, one row per frame, keypoints in layout order. */
static double* read_truth(const char* path, int* rows, int* cols) {
  FILE* f = fopen(path, "r");
  char line[65536];
  double* v = NULL;
  int r = 0, c = 0;
  if (!f) return NULL;
  if (!fgets(line, sizeof line, f)) return NULL;
  while (fgets(line, sizeof line, f)) {
    char* p = strchr(line, ',');
    int k = 0;
    v = realloc(v, sizeof *v * (size_t)(r + 1) * 256);
    while (p && k < 256) {
      char* end;
      ++p;
      v[r * 256 + k] = (*p == ',' || *p == '\n' || *p == '\0') ? NAN : strtod(p, &end);
      ++k;
      p = strchr(p, ',');
    }
    c = k;
    ++r;
  }
  fclose(f);
  *rows = r;
  *cols = c;
  return v;
}

int main(int argc, char** argv) {
  octocap_calibration_t* calib = NULL;
  octocap_recording_t* rec = NULL;
  octocap_session_t* session = NULL;
  static unsigned char cfg_box[sizeof(octocap_session_config_t) + GUARD_BYTES];
  octocap_session_config_t* cfg = (octocap_session_config_t*)(void*)cfg_box;
  octocap_layout_t layout;
  uint32_t views = 0, frames = 0, needed = 0, n = 0, f, k;
  uint32_t people[64];
  octocap_keypoint2d_t* kps = malloc(sizeof *kps * 64 * 64);
  octocap_joint_t joints[64];
  octocap_bone_pose_t bones[OCTOCAP_BONE_COUNT];
  octocap_frame_info_t info;
  double err_sum = 0;
  long err_n = 0, solved = 0, total = 0;
  int truth_rows = 0, truth_cols = 0;
  double* truth;
  if (argc != 4 || !kps) return 2;
  truth = read_truth(argv[3], &truth_rows, &truth_cols);
  expect(truth != NULL && truth_rows > 0, "reading the ground truth");
  expect(octocap_abi_version() == OCTOCAP_ABI_VERSION, "same ABI line");

  /* _init writes only what this program's struct holds. */
  memset(cfg_box, GUARD, sizeof cfg_box);
  octocap_session_config_init(cfg);
  expect(guard_intact(cfg_box, sizeof *cfg), "octocap_session_config_init wrote past the session config");
#if OLD_API >= 2
  CHECK_INIT(octocap_subscriber_config_t, octocap_subscriber_config_init);
#endif
#if OLD_API >= 4
  CHECK_INIT(octocap_extrinsics_options_t, octocap_extrinsics_options_init);
  CHECK_INIT(octocap_detector_config_t, octocap_detector_config_init);
#endif
#if OLD_API >= 6
  CHECK_INIT(octocap_live_config_t, octocap_live_config_init);
  CHECK_INIT(octocap_node_config_t, octocap_node_config_init);
#endif

  expect(octocap_calibration_load(argv[1], &calib) == OCTOCAP_OK, "loading the calibration");
  expect(octocap_recording_open(argv[2], OCTOCAP_LAYOUT_AUTO, &rec) == OCTOCAP_OK, "opening the keypoints");
  if (failures) return 1;
  octocap_recording_view_count(rec, &views);
  octocap_recording_frame_count(rec, &frames);
  octocap_recording_layout(rec, &layout);

#if OLD_API >= 4 && OLD_API < 6
  /* A 0.3 program that fills the fields past 0.1 itself and gives its whole struct's size: the nested detector config
   * is read at its old place. */
  memset((unsigned char*)cfg + cfg->struct_size, 0, sizeof *cfg - cfg->struct_size);
  cfg->struct_size = sizeof *cfg;
  octocap_detector_config_init(&cfg->detector);
  cfg->layout = layout;
  cfg->detector.mode = 99;
  expect(octocap_session_create(cfg, calib, &session) == OCTOCAP_ERROR_INVALID_ARGUMENT,
         "the 0.3 layout's nested detector config is checked");
  expect(strstr(octocap_last_error(), "detector") != NULL, "the error names the detector");
  cfg->detector.mode = OCTOCAP_DETECT_CROP;
  expect(octocap_session_create(cfg, calib, &session) == OCTOCAP_OK, "the whole 0.3 struct is accepted");
  octocap_session_destroy(session);
  session = NULL;
  octocap_session_config_init(cfg);
#endif

  cfg->layout = layout;
  expect(octocap_session_create(cfg, calib, &session) == OCTOCAP_OK, "creating a session from the old struct");
  if (failures) return 1;
  for (f = 0; f < frames; ++f) {
    if (octocap_recording_read_frame(rec, f, kps, 64 * 64, &needed, people, views) != OCTOCAP_OK) {
      expect(0, "reading a frame");
      break;
    }
    if (octocap_session_solve_keypoints(session, kps, people, views, (int64_t)f * 33333) != OCTOCAP_OK) {
      expect(0, "solving a frame");
      break;
    }
    expect(octocap_session_get_frame_info(session, &info) == OCTOCAP_OK && info.frame_index == (int64_t)f,
           "frame info");
    expect(octocap_session_get_keypoints3d(session, joints, 64, &n) == OCTOCAP_OK, "keypoints");
    for (k = 0; k < n; ++k) {
      const double* t = truth && (int)f < truth_rows ? truth + f * 256 + 3 * k : NULL;
      ++total;
      if (!joints[k].valid) continue;
      ++solved;
      if (t && (int)(3 * k + 2) < truth_cols && !isnan(t[0])) {
        const double dx = joints[k].position[0] - t[0], dy = joints[k].position[1] - t[1],
                     dz = joints[k].position[2] - t[2];
        err_sum += sqrt(dx * dx + dy * dy + dz * dz);
        ++err_n;
      }
    }
    expect(octocap_session_get_bones(session, OCTOCAP_FRAME_UNITY, bones, OCTOCAP_BONE_COUNT, &n) == OCTOCAP_OK &&
               n == OCTOCAP_BONE_COUNT && bones[OCTOCAP_BONE_R_UPPER_ARM].valid,
           "bones");
#if OLD_API >= 6
    {
      /* Frames (1.1): a buffer of the old header's joint and bone counts still takes them, whatever was appended. */
      octocap_frame_t* frame = NULL;
      octocap_joint_t skeleton[OCTOCAP_JOINT_COUNT];
      uint32_t got = 0;
      expect(octocap_session_get_frame(session, &frame) == OCTOCAP_OK, "frame");
      expect(octocap_frame_get_joints(frame, 0, skeleton, OCTOCAP_JOINT_COUNT, &got) == OCTOCAP_OK &&
                 got == OCTOCAP_JOINT_COUNT && skeleton[OCTOCAP_JOINT_ROOT].valid,
             "frame joints in an old-sized buffer");
      expect(octocap_frame_get_bones(frame, 0, OCTOCAP_FRAME_RIG, bones, OCTOCAP_BONE_COUNT, &got) == OCTOCAP_OK &&
                 got == OCTOCAP_BONE_COUNT && bones[OCTOCAP_BONE_L_LOWER_LEG].valid,
             "frame bones in an old-sized buffer");
      octocap_frame_release(frame);
    }
#endif
  }
  printf("old caller (API %d): %u frames, %ld / %ld keypoints solved, %.1f mm from the ground truth\n", OLD_API,
         frames, solved, total, err_n ? 1000 * err_sum / err_n : -1.0);
  expect(total > 0 && solved >= 0.95 * total, "95 % of the keypoints solved");
  expect(err_n > 0 && 1000 * err_sum / err_n < 20.0, "within 20 mm of the ground truth");
  octocap_session_destroy(session);
  octocap_recording_destroy(rec);
  octocap_calibration_destroy(calib);
  free(kps);
  free(truth);
  return failures ? 1 : 0;
}
