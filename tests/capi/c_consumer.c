/* The public header compiled as strict C99, used from C exactly as a C user would (called by a test). */
#include "octocap/octocap.h"

int octocap_c_consumer_check(const char* calibration_path) {
  octocap_calibration_t* calib = NULL;
  octocap_session_config_t cfg;
  octocap_session_t* session = NULL;
  uint32_t cameras = 0;
  int ok = 1;
  if (octocap_abi_version() != OCTOCAP_ABI_VERSION) return 0;
  if (octocap_calibration_load(calibration_path, &calib) != OCTOCAP_OK) return 0;
  ok = ok && octocap_calibration_camera_count(calib, &cameras) == OCTOCAP_OK && cameras > 1;
  octocap_session_config_init(&cfg);
  cfg.layout = OCTOCAP_LAYOUT_BODY_25;
  ok = ok && octocap_session_create(&cfg, calib, &session) == OCTOCAP_OK;
  octocap_session_destroy(session);
  octocap_calibration_destroy(calib);
  return ok;
}
