// The 0.x `_init` functions, exported for programs built against a 0.x header (1.0 made them inline over the sized
// `_defaults` functions). Such a program may have any 0.x size of the struct, which this call cannot know, so it
// writes the smallest released size only: never past the caller's struct. Fields a 0.x program set beyond that
// size are then ignored (session creation logs it); rebuilding against the 1.0 header removes the limitation.
// This file must not include octocap.h: the header defines these names as inline functions.
#include <cstdint>

extern "C" {
int32_t octocap_session_config_defaults(void* cfg, uint32_t struct_size);
int32_t octocap_detector_config_defaults(void* cfg, uint32_t struct_size);
int32_t octocap_subscriber_config_defaults(void* cfg, uint32_t struct_size);
int32_t octocap_extrinsics_options_defaults(void* opt, uint32_t struct_size);

#define OCTOCAP_LEGACY __attribute__((visibility("default")))
OCTOCAP_LEGACY void octocap_session_config_init(void* cfg) { (void)octocap_session_config_defaults(cfg, 84); }
OCTOCAP_LEGACY void octocap_detector_config_init(void* cfg) { (void)octocap_detector_config_defaults(cfg, 540); }
OCTOCAP_LEGACY void octocap_subscriber_config_init(void* cfg) { (void)octocap_subscriber_config_defaults(cfg, 52); }
OCTOCAP_LEGACY void octocap_extrinsics_options_init(void* opt) { (void)octocap_extrinsics_options_defaults(opt, 32); }
}
