// Layout tables and the skeleton definition.
#include <cstring>

#include "capi/boundary.h"
#include "core/layout.h"
#include "core/skeleton.h"

using namespace octocap::internal;

namespace {
const KeypointLayout* find_layout(octocap_layout_t id) {
  for (LayoutId l : all_layouts())
    if (static_cast<int>(l) == static_cast<int>(id)) return &layout(l);
  return nullptr;
}
}  // namespace

extern "C" {

uint32_t octocap_layout_keypoint_count(octocap_layout_t id) {
  const KeypointLayout* l = find_layout(id);
  return l ? static_cast<uint32_t>(l->keypoints.size()) : 0;
}

const char* octocap_layout_name(octocap_layout_t id) {
  const KeypointLayout* l = find_layout(id);
  return l ? l->name : nullptr;
}

octocap_result_t octocap_layout_from_name(const char* name, octocap_layout_t* out) {
  return capi::guard([&] {
    capi::require(name, "name");
    capi::require(out, "out");
    LayoutId id;
    if (!layout_from_name(name, &id))
      throw Error(Errc::invalid_argument,
                  std::string("unknown keypoint layout '") + name + "' (known: BODY_25, BODY_25B, COCO_17, HALPE_26, BLAZEPOSE_33)");
    *out = static_cast<octocap_layout_t>(id);
  });
}

const char* octocap_layout_keypoint_name(octocap_layout_t id, uint32_t index) {
  const KeypointLayout* l = find_layout(id);
  return l && index < l->keypoints.size() ? l->keypoints[index] : nullptr;
}

const char* octocap_joint_name(uint32_t joint) {
  return joint < static_cast<uint32_t>(kJointCount) ? joint_names()[joint] : nullptr;
}

octocap_result_t octocap_bone_info(uint32_t bone, octocap_bone_info_t* out) {
  return capi::guard([&] {
    capi::require(out, "out");
    if (bone >= static_cast<uint32_t>(kBoneCount))
      throw Error(Errc::invalid_argument, "bone index " + std::to_string(bone) + " out of range");
    const BoneDef& d = bone_table()[bone];
    capi::copy_name(out->name, sizeof out->name, d.name);
    out->parent_bone = d.parent;
    out->head_joint = d.head;
    out->tail_joint = d.tail;
    for (int k = 0; k < 3; ++k) out->rest_direction[k] = static_cast<float>(tpose_directions()[bone][k]);
  });
}

}  // extern "C"
