#include "core/layout.h"

#include <algorithm>
#include <cctype>

#include "core/error.h"

namespace octocap::internal {
namespace {

using Alt = std::vector<std::vector<int>>;

// COCO-17 order, shared by COCO_17, BODY_25B and HALPE_26 for their first 17 keypoints.
const std::vector<const char*> kCocoNames = {
    "Nose", "LEye", "REye", "LEar", "REar", "LShoulder", "RShoulder", "LElbow", "RElbow",
    "LWrist", "RWrist", "LHip", "RHip", "LKnee", "RKnee", "LAnkle", "RAnkle"};
const std::vector<std::pair<int, int>> kCocoMirror = {{1, 2}, {3, 4}, {5, 6}, {7, 8}, {9, 10},
                                                      {11, 12}, {13, 14}, {15, 16}};

// The limbs are the same in every COCO-ordered layout; head, neck and root differ.
// Feet, for layouts that have them: the toe joint between big and small toe (else the big toe alone), the heel.
struct FeetKeypoints {
  int r_big = -1, r_small = -1, r_heel = -1, l_big = -1, l_small = -1, l_heel = -1;
};

void add_feet(KeypointLayout& l, const FeetKeypoints& f) {
  if (f.r_big < 0) return;
  // A layout with one toe keypoint (BlazePose's foot index) has no pair to average.
  l.joint_sources[kRToe] = f.r_small < 0 ? Alt{{f.r_big}} : Alt{{f.r_big, f.r_small}, {f.r_big}};
  l.joint_sources[kLToe] = f.l_small < 0 ? Alt{{f.l_big}} : Alt{{f.l_big, f.l_small}, {f.l_big}};
  l.joint_sources[kRHeel] = {{f.r_heel}};
  l.joint_sources[kLHeel] = {{f.l_heel}};
}

KeypointLayout coco_ordered(LayoutId id, const char* name, std::vector<const char*> names, Alt head, Alt neck,
                            Alt root, std::vector<std::pair<int, int>> mirror, FeetKeypoints feet = {}) {
  KeypointLayout l{id, name, std::move(names), {}, std::move(mirror)};
  l.joint_sources[kHead] = std::move(head);
  l.joint_sources[kNeck] = std::move(neck);
  l.joint_sources[kRShoulder] = {{6}};
  l.joint_sources[kRElbow] = {{8}};
  l.joint_sources[kRHand] = {{10}};
  l.joint_sources[kLShoulder] = {{5}};
  l.joint_sources[kLElbow] = {{7}};
  l.joint_sources[kLHand] = {{9}};
  l.joint_sources[kRHip] = {{12}};
  l.joint_sources[kRKnee] = {{14}};
  l.joint_sources[kRFoot] = {{16}};
  l.joint_sources[kLHip] = {{11}};
  l.joint_sources[kLKnee] = {{13}};
  l.joint_sources[kLFoot] = {{15}};
  l.joint_sources[kRoot] = std::move(root);
  add_feet(l, feet);
  return l;
}

std::vector<const char*> concat(std::vector<const char*> a, const std::vector<const char*>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::vector<std::pair<int, int>> concat(std::vector<std::pair<int, int>> a, const std::vector<std::pair<int, int>>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

KeypointLayout make_body25() {
  KeypointLayout l{LayoutId::body25, "BODY_25",
                   {"Nose", "Neck", "RShoulder", "RElbow", "RWrist", "LShoulder", "LElbow", "LWrist", "MidHip",
                    "RHip", "RKnee", "RAnkle", "LHip", "LKnee", "LAnkle", "REye", "LEye", "REar", "LEar",
                    "LBigToe", "LSmallToe", "LHeel", "RBigToe", "RSmallToe", "RHeel"},
                   {},
                   {{2, 5}, {3, 6}, {4, 7}, {9, 12}, {10, 13}, {11, 14}, {15, 16}, {17, 18}, {19, 22}, {20, 23},
                    {21, 24}}};
  l.joint_sources[kHead] = {{17, 18}, {0}};
  l.joint_sources[kNeck] = {{1}, {2, 5}};
  l.joint_sources[kRShoulder] = {{2}};
  l.joint_sources[kRElbow] = {{3}};
  l.joint_sources[kRHand] = {{4}};
  l.joint_sources[kLShoulder] = {{5}};
  l.joint_sources[kLElbow] = {{6}};
  l.joint_sources[kLHand] = {{7}};
  l.joint_sources[kRHip] = {{9}};
  l.joint_sources[kRKnee] = {{10}};
  l.joint_sources[kRFoot] = {{11}};
  l.joint_sources[kLHip] = {{12}};
  l.joint_sources[kLKnee] = {{13}};
  l.joint_sources[kLFoot] = {{14}};
  l.joint_sources[kRoot] = {{9, 12}, {8}};
  add_feet(l, {22, 23, 24, 19, 20, 21});
  return l;
}

// MediaPipe BlazePose GHUM's 33 landmarks: a face (eyes with their corners, ears, mouth), the COCO limbs in another
// order, three points of each hand, heels and foot tips (the "foot index", between the first toes' tips).
KeypointLayout make_blazepose33() {
  KeypointLayout l{LayoutId::blazepose33, "BLAZEPOSE_33",
                   {"Nose", "LEyeInner", "LEye", "LEyeOuter", "REyeInner", "REye", "REyeOuter", "LEar", "REar",
                    "LMouth", "RMouth", "LShoulder", "RShoulder", "LElbow", "RElbow", "LWrist", "RWrist",
                    "LPinky", "RPinky", "LIndex", "RIndex", "LThumb", "RThumb", "LHip", "RHip", "LKnee", "RKnee",
                    "LAnkle", "RAnkle", "LHeel", "RHeel", "LFootIndex", "RFootIndex"},
                   {},
                   {{1, 4}, {2, 5}, {3, 6}, {7, 8}, {9, 10}, {11, 12}, {13, 14}, {15, 16}, {17, 18}, {19, 20},
                    {21, 22}, {23, 24}, {25, 26}, {27, 28}, {29, 30}, {31, 32}}};
  l.joint_sources[kHead] = {{7, 8}, {0}};
  l.joint_sources[kNeck] = {{11, 12}};
  l.joint_sources[kRShoulder] = {{12}};
  l.joint_sources[kRElbow] = {{14}};
  l.joint_sources[kRHand] = {{16}};
  l.joint_sources[kLShoulder] = {{11}};
  l.joint_sources[kLElbow] = {{13}};
  l.joint_sources[kLHand] = {{15}};
  l.joint_sources[kRHip] = {{24}};
  l.joint_sources[kRKnee] = {{26}};
  l.joint_sources[kRFoot] = {{28}};
  l.joint_sources[kLHip] = {{23}};
  l.joint_sources[kLKnee] = {{25}};
  l.joint_sources[kLFoot] = {{27}};
  l.joint_sources[kRoot] = {{23, 24}};
  add_feet(l, {32, -1, 30, 31, -1, 29});
  l.joint_sources[kRKnuckles] = {{20, 18}};  // index and little finger
  l.joint_sources[kLKnuckles] = {{19, 17}};
  return l;
}

const std::vector<KeypointLayout>& table() {
  static const std::vector<KeypointLayout> layouts = {
      make_body25(),
      coco_ordered(LayoutId::body25b, "BODY_25B",
                   concat(kCocoNames, {"Neck", "Head", "LBigToe", "LSmallToe", "LHeel", "RBigToe", "RSmallToe",
                                       "RHeel"}),
                   {{18}, {3, 4}, {0}}, {{17}, {5, 6}}, {{11, 12}},
                   concat(kCocoMirror, {{19, 22}, {20, 23}, {21, 24}}), {22, 23, 24, 19, 20, 21}),
      coco_ordered(LayoutId::coco17, "COCO_17", kCocoNames, {{3, 4}, {0}}, {{5, 6}}, {{11, 12}}, kCocoMirror),
      coco_ordered(LayoutId::halpe26, "HALPE_26",
                   concat(kCocoNames, {"Head", "Neck", "Hip", "LBigToe", "RBigToe", "LSmallToe", "RSmallToe",
                                       "LHeel", "RHeel"}),
                   {{17}, {3, 4}, {0}}, {{18}, {5, 6}}, {{11, 12}, {19}},
                   concat(kCocoMirror, {{20, 21}, {22, 23}, {24, 25}}), {21, 23, 25, 20, 22, 24}),
      make_blazepose33(),
  };
  return layouts;
}

std::string normalized_name(const std::string& s) {
  std::string out;
  for (char c : s)
    if (c != '_' && c != '-' && c != ' ') out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

const KeypointLayout& layout(LayoutId id) {
  for (const auto& l : table())
    if (l.id == id) return l;
  throw Error(Errc::invalid_argument, "unknown keypoint layout id " + std::to_string(static_cast<int>(id)));
}

const std::vector<LayoutId>& all_layouts() {
  static const std::vector<LayoutId> ids = {LayoutId::body25, LayoutId::body25b, LayoutId::coco17,
                                            LayoutId::halpe26, LayoutId::blazepose33};
  return ids;
}

LayoutId layout_for_count(size_t keypoint_count) {
  switch (keypoint_count) {
    case 25: return LayoutId::body25;
    case 17: return LayoutId::coco17;
    case 26: return LayoutId::halpe26;
    case 33: return LayoutId::blazepose33;
    default:
      throw Error(Errc::invalid_argument, "no known keypoint layout has " + std::to_string(keypoint_count) +
                                              " keypoints (known: BODY_25 and BODY_25B 25, COCO_17 17, HALPE_26 26, "
                                              "BLAZEPOSE_33 33)");
  }
}

bool layout_from_name(const std::string& name, LayoutId* out) {
  const std::string n = normalized_name(name);
  if (n == "COCO") {
    *out = LayoutId::coco17;
    return true;
  }
  for (const auto& l : table()) {
    if (normalized_name(l.name) == n) {
      *out = l.id;
      return true;
    }
  }
  return false;
}

}  // namespace octocap::internal
