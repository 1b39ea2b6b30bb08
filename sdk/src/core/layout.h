// Keypoint layouts as data tables: names, order, and how each maps onto the skeleton (core/skeleton.h).
#pragma once
#include <array>
#include <string>
#include <vector>

#include "core/skeleton.h"

namespace octocap::internal {

enum class LayoutId : int { automatic = 0, body25 = 1, body25b = 2, coco17 = 3, halpe26 = 4, blazepose33 = 5 };

struct KeypointLayout {
  LayoutId id;
  const char* name;
  std::vector<const char*> keypoints;
  // For each skeleton joint: alternatives tried in order; an alternative is a set of keypoints whose mean is
  // the joint, used only when all of them are present (e.g. head = mean of the ears, else the nose).
  std::array<std::vector<std::vector<int>>, kJointCount> joint_sources;
  // Left/right keypoint pairs, for detecting and repairing swapped detections.
  std::vector<std::pair<int, int>> mirror_pairs;
};

// The one rule deriving a skeleton joint from keypoints (the solver, the motion readers, calibration and the crops all
// use it): the first of `alternatives` whose keypoints are all `present(k)`; the joint is their mean. Null if none is.
template <class Present>
const std::vector<int>* first_present_alternative(const std::vector<std::vector<int>>& alternatives, Present present) {
  for (const std::vector<int>& alternative : alternatives) {
    bool all = !alternative.empty();
    for (int k : alternative) all = all && present(k);
    if (all) return &alternative;
  }
  return nullptr;
}

const KeypointLayout& layout(LayoutId id);  // throws Error for automatic/unknown ids
const std::vector<LayoutId>& all_layouts();
// AUTO resolution from a keypoint count: 25 -> BODY_25, 17 -> COCO_17, 26 -> HALPE_26, 33 -> BLAZEPOSE_33.
LayoutId layout_for_count(size_t keypoint_count);
// Case-insensitive; accepts "COCO" for COCO_17, "BODY25B" without underscore, etc.
bool layout_from_name(const std::string& name, LayoutId* out);

}  // namespace octocap::internal
