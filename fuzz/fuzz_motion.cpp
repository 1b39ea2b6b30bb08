// Motion files (TRC, CSV, BVH: the first byte picks which), opened through the C ABI and read as frames.
#include "fuzz_support.h"
#include "octocap/octocap.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  static const char* const kExtensions[] = {".trc", ".csv", ".bvh"};
  const std::string path = fuzz::write_input(data + 1, size - 1, kExtensions[data[0] % 3]);
  octocap_motion_t* motion = nullptr;
  if (octocap_motion_open(path.c_str(), &motion) != OCTOCAP_OK) return 0;
  uint32_t frames = 0;
  double rate = 0;
  octocap_motion_info(motion, &frames, &rate);
  if (!(rate > 0)) __builtin_trap();  // an accepted file has a usable rate
  for (uint32_t f = 0; f < frames && f < 8; ++f) {
    octocap_frame_t* frame = nullptr;
    if (octocap_motion_get_frame(motion, f, &frame) != OCTOCAP_OK) __builtin_trap();
    octocap_joint_t joints[OCTOCAP_JOINT_COUNT];
    octocap_bone_pose_t bones[OCTOCAP_BONE_COUNT];
    uint32_t n = 0;
    if (octocap_frame_get_joints(frame, 0, joints, OCTOCAP_JOINT_COUNT, &n) == OCTOCAP_OK)
      for (const auto& j : joints)
        if (j.valid && !(j.position[0] == j.position[0])) __builtin_trap();  // never a valid NaN
    if (octocap_frame_get_bones(frame, 0, OCTOCAP_FRAME_UNITY, bones, OCTOCAP_BONE_COUNT, &n) == OCTOCAP_OK)
      for (const auto& b : bones)
        if (b.valid && !(b.local_rotation.w == b.local_rotation.w)) __builtin_trap();
    octocap_frame_release(frame);
  }
  octocap_motion_destroy(motion);
  return 0;
}
