// Every size a released header gave each config struct, and the two moves that keep old callers working: filling
// only the caller's size with defaults, and reading a caller's struct into the current one (defaults for what its
// version did not have). The sizes are those of the headers in git history (tests/abi/ builds callers against them).
#pragma once
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <string>

#include "capi/boundary.h"
#include "octocap/octocap.h"

namespace octocap::internal::capi {

// octocap_session_config_t: 0.1 (84), 0.2 streaming (152), 0.2 VMC = 1.0 (216), 0.3 with the detector config nested
// at its end (760; see LegacySessionConfig03), 1.3 max_people (224), 1.10 stream_security (736), 1.11 foot_lock (744).
constexpr std::initializer_list<uint32_t> kSessionConfigSizes = {84, 152, 216, 760, 224, 736, 744};
// The size of the 1.0 session config, which the 0.3 layout nests its detector config after.
constexpr uint32_t kSessionConfigSize10 = 216;
// octocap_detector_config_t: 0.3 (540), 0.3 parallel_views = 1.0 (544), 1.5 views_per_frame and device (552), 1.9
// runtime and precision (560).
constexpr std::initializer_list<uint32_t> kDetectorConfigSizes = {540, 544, 552, 560};
// The size of the 1.0 detector config, which the 0.3 session config nests.
constexpr uint32_t kDetectorConfigSize10 = 544;
// octocap_subscriber_config_t: 0.2 (52), 1.10 security (564).
constexpr std::initializer_list<uint32_t> kSubscriberConfigSizes = {52, 564};
// octocap_extrinsics_options_t: without (32) and with `refine` (36).
constexpr std::initializer_list<uint32_t> kExtrinsicsOptionsSizes = {32, 36};

// octocap_live_config_t: 1.0 (28), 1.1 remote cameras (64), 1.8 the rate governor (76), 1.10 remote_security (588).
constexpr std::initializer_list<uint32_t> kLiveConfigSizes = {28, 64, 76, 588};
// octocap_node_config_t: 1.1 (92), 1.10 security (604).
constexpr std::initializer_list<uint32_t> kNodeConfigSizes = {92, 604};

// The 0.3 session config: 1.0's 216 bytes of session fields, then the 1.0 detector config (now set with
// octocap_session_set_detector()). Bytes, not today's struct: the detector config grows, this layout never does.
struct LegacySessionConfig03 {
  unsigned char base[kSessionConfigSize10];
  alignas(4) unsigned char detector[kDetectorConfigSize10];
};
static_assert(sizeof(octocap_session_config_t) == 744 && offsetof(octocap_session_config_t, max_people) == 216 &&
                  offsetof(octocap_session_config_t, stream_security) == 224 &&
                  offsetof(octocap_session_config_t, foot_lock) == 736,
              "1.3's session config is 1.0's and max_people, 1.10 adds stream_security, 1.11 foot_lock: grow it only at "
              "its end");
// octocap_person_t, an output struct filled up to the caller's size: 1.0 (32), 1.11 foot_contacts (36).
constexpr uint32_t kPersonSize10 = 32;
static_assert(sizeof(octocap_person_t) == 36 && offsetof(octocap_person_t, foot_contacts) == kPersonSize10,
              "octocap_person_t grows only at its end");
static_assert(offsetof(LegacySessionConfig03, detector) == 216 && sizeof(LegacySessionConfig03) == 760,
              "the 0.3 layout must stay byte-exact");
static_assert(sizeof(octocap_detector_config_t) == 560 && sizeof(octocap_subscriber_config_t) == 564 &&
                  sizeof(octocap_extrinsics_options_t) == 36 && sizeof(octocap_live_config_t) == 588 &&
                  sizeof(octocap_node_config_t) == 604,
              "a config struct grew: add its new size to the tables above and to tests/abi");

inline bool known_size(uint32_t size, std::initializer_list<uint32_t> sizes) {
  return std::find(sizes.begin(), sizes.end(), size) != sizes.end();
}

inline std::string size_list(std::initializer_list<uint32_t> sizes) {
  std::string s;
  for (uint32_t n : sizes) s += (s.empty() ? "" : ", ") + std::to_string(n);
  return s;
}

inline void check_size(uint32_t size, std::initializer_list<uint32_t> sizes, const char* name) {
  if (!known_size(size, sizes))
    throw Error(Errc::struct_size, std::string(name) + ".struct_size is " + std::to_string(size) +
                                       "; the sizes of released headers are " + size_list(sizes) +
                                       " (fill it with its _init() first)");
}

// Writes the first `size` bytes of `defaults` (whose struct_size is then `size`) into `out`.
template <class T>
void write_defaults(void* out, uint32_t size, T defaults) {
  defaults.struct_size = size;
  std::memcpy(out, &defaults, std::min<size_t>(size, sizeof(T)));
}

// The caller's struct as the current one: its `struct_size` bytes over the defaults.
template <class T>
T widen(const T& given, T defaults) {
  std::memcpy(&defaults, &given, std::min<size_t>(given.struct_size, sizeof(T)));
  defaults.struct_size = sizeof(T);
  return defaults;
}

}  // namespace octocap::internal::capi
