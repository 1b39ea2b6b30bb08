// The C structs of one frame, from a FrameResult: the single conversion every frame query (and every deprecated
// per-source query) goes through.
#pragma once
#include <cstring>
#include <string>

#include "capi/boundary.h"
#include "core/frame.h"
#include "octocap/octocap.h"

namespace octocap::internal::capi {

// Two-call pattern: out == NULL asks for the count; a short buffer is an error that still reports it.
template <class Fill>
void fill_array(uint32_t needed, const void* out, uint32_t capacity, uint32_t* count, Fill&& fill) {
  require(count, "count");
  *count = needed;
  if (!out) return;
  if (capacity < needed)
    throw Error(Errc::buffer_too_small, "capacity " + std::to_string(capacity) + " < " + std::to_string(needed));
  fill();
}

// Throws Error(invalid_argument) unless `person` < the frame's person count. `allow_empty` lets the deprecated
// queries read person 0 of an empty frame (all missing), as 0.x did.
void check_person(const FrameResult& f, uint32_t person, bool allow_empty = false);
void query_summary(const FrameResult& f, octocap_frame_summary_t* out);
void query_person(const FrameResult& f, uint32_t person, octocap_person_t* out);
void query_frame_info(const FrameResult& f, octocap_frame_info_t* out);  // deprecated 0.x struct
void query_keypoints(const PersonResult& f, octocap_joint_t* out, uint32_t capacity, uint32_t* count);
void query_joints(const PersonResult& f, octocap_joint_t* out, uint32_t capacity, uint32_t* count);
void query_bones(const PersonResult& f, octocap_coord_frame_t frame, octocap_bone_pose_t* out, uint32_t capacity,
                 uint32_t* count);
void query_person_views(const PersonResult& f, int32_t* out, uint32_t capacity, uint32_t* count);
void to_c_joint(const PointResult& r, octocap_joint_t& out);

// Output structs with a caller-set struct_size: fills a full local copy, then copies what the caller's size holds.
// Sizes below `min_size` (the first released one) are refused.
template <class T, class Fill>
void fill_sized(T* out, size_t min_size, const char* name, Fill&& fill) {
  require(out, "out");
  const uint32_t size = out->struct_size;
  if (size < min_size)
    throw Error(Errc::struct_size, std::string(name) + ".struct_size is " + std::to_string(size) + ", at least " +
                                       std::to_string(min_size) + " (set it to sizeof)");
  T full{};
  fill(full);
  full.struct_size = size < sizeof(T) ? size : static_cast<uint32_t>(sizeof(T));
  std::memcpy(out, &full, full.struct_size);
}

}  // namespace octocap::internal::capi
