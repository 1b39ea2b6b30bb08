// The keypoint layout tables are data; check they are self-consistent.
#include <catch2/catch_test_macros.hpp>
#include <set>
#include <string>

#include "core/error.h"
#include "core/layout.h"
#include "octocap/octocap.h"

using namespace octocap::internal;

TEST_CASE("every layout maps every skeleton joint onto valid keypoints", "[layout]") {
  for (LayoutId id : all_layouts()) {
    const KeypointLayout& l = layout(id);
    INFO(l.name);
    std::set<std::string> names(l.keypoints.begin(), l.keypoints.end());
    REQUIRE(names.size() == l.keypoints.size());  // no duplicate names
    // Every layout has the paper's joints; feet (toes and heels) all or none: COCO_17 has none; knuckles only where
    // there are hand points (BLAZEPOSE_33).
    const bool feet = id != LayoutId::coco17, hands = id == LayoutId::blazepose33;
    for (int j = 0; j < kJointCount; ++j) {
      INFO(joint_names()[j]);
      const bool has = j <= kRoot || (j <= kLHeel ? feet : hands);
      REQUIRE(l.joint_sources[j].empty() == !has);
      for (const auto& alt : l.joint_sources[j]) {
        REQUIRE_FALSE(alt.empty());
        for (int k : alt) REQUIRE((k >= 0 && k < static_cast<int>(l.keypoints.size())));
      }
    }
    // Mirror pairs join an L keypoint to its R twin.
    for (auto [a, b] : l.mirror_pairs) {
      std::string la = l.keypoints[a], lb = l.keypoints[b];
      if (la[0] == 'R') std::swap(la, lb);
      REQUIRE(la[0] == 'L');
      REQUIRE(lb[0] == 'R');
      REQUIRE(la.substr(1) == lb.substr(1));
    }
  }
}

TEST_CASE("layouts have the published keypoint orders", "[layout]") {
  REQUIRE(std::string(octocap_layout_keypoint_name(OCTOCAP_LAYOUT_BODY_25, 1)) == "Neck");
  REQUIRE(std::string(octocap_layout_keypoint_name(OCTOCAP_LAYOUT_BODY_25, 8)) == "MidHip");
  REQUIRE(std::string(octocap_layout_keypoint_name(OCTOCAP_LAYOUT_BODY_25, 24)) == "RHeel");
  REQUIRE(std::string(octocap_layout_keypoint_name(OCTOCAP_LAYOUT_BODY_25B, 17)) == "Neck");
  REQUIRE(std::string(octocap_layout_keypoint_name(OCTOCAP_LAYOUT_BODY_25B, 18)) == "Head");
  REQUIRE(std::string(octocap_layout_keypoint_name(OCTOCAP_LAYOUT_COCO_17, 5)) == "LShoulder");
  REQUIRE(std::string(octocap_layout_keypoint_name(OCTOCAP_LAYOUT_HALPE_26, 19)) == "Hip");
  REQUIRE(octocap_layout_keypoint_count(OCTOCAP_LAYOUT_COCO_17) == 17);
  // MediaPipe's landmark order (pose_landmark: 0 nose ... 29/30 heels, 31/32 foot index).
  REQUIRE(octocap_layout_keypoint_count(OCTOCAP_LAYOUT_BLAZEPOSE_33) == 33);
  REQUIRE(std::string(octocap_layout_keypoint_name(OCTOCAP_LAYOUT_BLAZEPOSE_33, 11)) == "LShoulder");
  REQUIRE(std::string(octocap_layout_keypoint_name(OCTOCAP_LAYOUT_BLAZEPOSE_33, 22)) == "RThumb");
  REQUIRE(std::string(octocap_layout_keypoint_name(OCTOCAP_LAYOUT_BLAZEPOSE_33, 29)) == "LHeel");
  REQUIRE(std::string(octocap_layout_keypoint_name(OCTOCAP_LAYOUT_BLAZEPOSE_33, 32)) == "RFootIndex");
  REQUIRE(octocap_layout_keypoint_count(OCTOCAP_LAYOUT_AUTO) == 0);
  REQUIRE(octocap_layout_keypoint_name(OCTOCAP_LAYOUT_COCO_17, 17) == nullptr);
}

TEST_CASE("layout names parse loosely and unknown names are refused", "[layout]") {
  octocap_layout_t l = OCTOCAP_LAYOUT_AUTO;
  REQUIRE(octocap_layout_from_name("body25b", &l) == OCTOCAP_OK);
  REQUIRE(l == OCTOCAP_LAYOUT_BODY_25B);
  REQUIRE(octocap_layout_from_name("COCO", &l) == OCTOCAP_OK);
  REQUIRE(l == OCTOCAP_LAYOUT_COCO_17);
  REQUIRE(octocap_layout_from_name("MPII", &l) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  REQUIRE(std::string(octocap_last_error()).find("MPII") != std::string::npos);
  REQUIRE(layout_for_count(25) == LayoutId::body25);
  REQUIRE(layout_for_count(33) == LayoutId::blazepose33);
  REQUIRE_THROWS_AS(layout_for_count(18), Error);
}
