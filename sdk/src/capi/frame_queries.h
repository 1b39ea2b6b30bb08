// Per-frame queries shared by sessions and subscribers: both hold a FrameResult.
#pragma once
#include <string>

#include "capi/boundary.h"
#include "octocap/octocap.h"
#include "pipeline/frame_result.h"

namespace octocap::capi {

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


void query_frame_info(const FrameResult& f, octocap_frame_info_t* out);
void query_keypoints(const FrameResult& f, octocap_joint_t* out, uint32_t capacity, uint32_t* count);
void query_joints(const FrameResult& f, octocap_joint_t* out, uint32_t capacity, uint32_t* count);
void query_bones(const FrameResult& f, octocap_coord_frame_t frame, octocap_bone_pose_t* out, uint32_t capacity,
                 uint32_t* count);
void to_c_joint(const PointResult& r, octocap_joint_t& out);

}  // namespace octocap::capi
