#include "retarget.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace {

enum class Side { none, left, right };

struct ParsedName {
  Side side = Side::none;
  std::string core;  // lowercase tokens without side, prefixes and digits: "upperarm", "forearm", "spine"
  std::string core_digits;
};

// "mixamorig:LeftForeArm", "B_UpperArm_Left", "upper_arm.L", "thigh.R", "Bip01 L Thigh", "LeftUpLeg".
ParsedName parse(const std::string& raw) {
  std::string name = raw;
  const size_t cut = name.find_last_of(":|");
  if (cut != std::string::npos) name = name.substr(cut + 1);
  std::vector<std::string> tokens;
  std::string cur;
  auto flush = [&] {
    if (!cur.empty()) tokens.push_back(cur);
    cur.clear();
  };
  for (size_t i = 0; i < name.size(); ++i) {
    const char ch = name[i];
    if (!std::isalnum(static_cast<unsigned char>(ch))) {
      flush();
      continue;
    }
    // camelCase boundary: a capital after a lowercase letter or digit starts a token.
    if (std::isupper(static_cast<unsigned char>(ch)) && i > 0 && (std::islower(static_cast<unsigned char>(name[i - 1])) ||
                                                                  std::isdigit(static_cast<unsigned char>(name[i - 1]))))
      flush();
    cur.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(ch))));
  }
  flush();
  static const char* kNoise[] = {"b", "j", "bn", "def", "org", "mch", "bip01", "bip001", "bip", "mixamorig", "jnt", "bone"};
  ParsedName p;
  for (const std::string& t : tokens) {
    if (t == "l" || t == "left") p.side = Side::left;
    else if (t == "r" || t == "right") p.side = Side::right;
    else if (std::find(std::begin(kNoise), std::end(kNoise), t) != std::end(kNoise)) continue;
    else p.core_digits += t;
  }
  for (char ch : p.core_digits)
    if (!std::isdigit(static_cast<unsigned char>(ch))) p.core.push_back(ch);
  return p;
}

struct Wanted {
  Side side;
  std::vector<const char*> synonyms;  // in order of preference
};

Wanted wanted(int bone) {
  switch (bone) {
    case OCTOCAP_BONE_ROOT: return {Side::none, {"hips", "hip", "pelvis", "lowerpelvis", "root"}};
    case OCTOCAP_BONE_TORSO: return {Side::none, {"spine", "lowerspine", "abdomen", "torso", "chest"}};
    case OCTOCAP_BONE_HEAD: return {Side::none, {"neck", "head"}};
    case OCTOCAP_BONE_R_SHOULDER: return {Side::right, {"shoulder", "clavicle", "collar", "collarbone"}};
    case OCTOCAP_BONE_L_SHOULDER: return {Side::left, {"shoulder", "clavicle", "collar", "collarbone"}};
    case OCTOCAP_BONE_R_UPPER_ARM: return {Side::right, {"arm", "upperarm", "uparm", "humerus"}};
    case OCTOCAP_BONE_L_UPPER_ARM: return {Side::left, {"arm", "upperarm", "uparm", "humerus"}};
    case OCTOCAP_BONE_R_LOWER_ARM: return {Side::right, {"forearm", "lowerarm", "loarm", "elbow"}};
    case OCTOCAP_BONE_L_LOWER_ARM: return {Side::left, {"forearm", "lowerarm", "loarm", "elbow"}};
    case OCTOCAP_BONE_R_UPPER_LEG: return {Side::right, {"upleg", "upperleg", "thigh", "hip", "femur"}};
    case OCTOCAP_BONE_L_UPPER_LEG: return {Side::left, {"upleg", "upperleg", "thigh", "hip", "femur"}};
    case OCTOCAP_BONE_R_LOWER_LEG: return {Side::right, {"leg", "lowerleg", "loleg", "shin", "calf", "knee", "tibia"}};
    case OCTOCAP_BONE_L_LOWER_LEG: return {Side::left, {"leg", "lowerleg", "loleg", "shin", "calf", "knee", "tibia"}};
    case OCTOCAP_BONE_R_FOOT: return {Side::right, {"foot", "ankle", "tarsal"}};
    case OCTOCAP_BONE_L_FOOT: return {Side::left, {"foot", "ankle", "tarsal"}};
    case OCTOCAP_BONE_R_HAND: return {Side::right, {"hand", "wrist", "palm"}};
    case OCTOCAP_BONE_L_HAND: return {Side::left, {"hand", "wrist", "palm"}};
  }
  return {Side::none, {}};
}

octocap_bone_info_t bone_info(int b) {
  octocap_bone_info_t info;
  octocap_bone_info(static_cast<uint32_t>(b), &info);
  return info;
}

std::string bone_name(int b) { return bone_info(b).name; }

// A model without clavicles, feet or hands still takes a pose: those bones then stay at rest relative to their parent.
bool optional_bone(int b) {
  return b == OCTOCAP_BONE_L_SHOULDER || b == OCTOCAP_BONE_R_SHOULDER || b == OCTOCAP_BONE_L_FOOT ||
         b == OCTOCAP_BONE_R_FOOT || b == OCTOCAP_BONE_L_HAND || b == OCTOCAP_BONE_R_HAND;
}

// Nodes from `node` up to the root of its tree, node first.
std::vector<int> ancestry(const Character& c, int node) {
  std::vector<int> out;
  for (int n = node; n >= 0; n = c.nodes[n].parent) out.push_back(n);
  return out;
}

// The deepest node that is `a` or an ancestor of it and also `b` or an ancestor of b; -1 in separate trees.
int common_ancestor(const Character& c, int a, int b) {
  const std::vector<int> up_b = ancestry(c, b);
  for (int n : ancestry(c, a))
    if (std::find(up_b.begin(), up_b.end(), n) != up_b.end()) return n;
  return -1;
}

bool is_ancestor(const Character& c, int ancestor, int node) {
  const std::vector<int> up = ancestry(c, node);
  return std::find(up.begin(), up.end(), ancestor) != up.end();
}

}  // namespace

BoneMap find_bone_map(const Character& c) {
  BoneMap map;
  map.fill(-1);
  std::vector<ParsedName> parsed;
  for (const auto& n : c.nodes) parsed.push_back(parse(n.name));
  for (int b = 0; b < OCTOCAP_BONE_COUNT; ++b) {
    const Wanted w = wanted(b);
    for (const char* syn : w.synonyms) {
      for (size_t i = 0; i < c.nodes.size() && map[b] < 0; ++i)
        if (parsed[i].side == w.side && parsed[i].core == syn) map[b] = static_cast<int>(i);
      if (map[b] >= 0) break;
    }
  }
  return map;
}

void apply_bone_map_file(const Character& c, const std::string& path, BoneMap& map) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open bone map " + path);
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path + ": not JSON: " + e.what());
  }
  if (!doc.is_object()) throw std::runtime_error(path + ": expected an object {\"octocap bone\": \"model node\"}");
  for (const auto& [key, value] : doc.items()) {
    int bone = -1;
    for (int b = 0; b < OCTOCAP_BONE_COUNT; ++b)
      if (bone_name(b) == key) bone = b;
    if (bone < 0) throw std::runtime_error(path + ": \"" + key + "\" is not an octocap bone (root, torso, head, l_upper_arm, ...)");
    if (!value.is_string()) throw std::runtime_error(path + ": \"" + key + "\" must name a model node");
    const int node = c.find(value.get<std::string>());
    if (node < 0) throw std::runtime_error(path + ": the model has no node \"" + value.get<std::string>() + "\"");
    map[bone] = node;
  }
}

std::string missing_bones(const BoneMap& map) {
  std::string out;
  for (int b = 0; b < OCTOCAP_BONE_COUNT; ++b)
    if (map[b] < 0 && !optional_bone(b))
      out += (out.empty() ? "" : ", ") + bone_name(b);
  return out;
}

Retargeter::Retargeter(const Character& c, const BoneMap& map) : c_(c), map_(map) {
  const std::string missing = missing_bones(map);
  if (!missing.empty()) throw std::runtime_error(c.source + ": no model bone found for " + missing + " (give a --bone-map)");
  rest_locals_ = c.rest_locals();
  rest_globals_ = c.globals(rest_locals_);

  // The root's node: the joint both thighs and the spine hang from. A model whose root bone sits on a sibling branch
  // (the default character's B_LowerPelvis, beside B_Root_Pelvis_T that carries the spine) would otherwise leave
  // every joint between the root and the spine at rest while the body turns: the waist tears.
  root_node_ = common_ancestor(c, common_ancestor(c, map[OCTOCAP_BONE_L_UPPER_LEG], map[OCTOCAP_BONE_R_UPPER_LEG]),
                               map[OCTOCAP_BONE_TORSO]);
  if (root_node_ < 0 || root_node_ == map[OCTOCAP_BONE_TORSO])
    throw std::runtime_error(c.source + ": the thighs (" + c.nodes[map[OCTOCAP_BONE_L_UPPER_LEG]].name + ", " +
                             c.nodes[map[OCTOCAP_BONE_R_UPPER_LEG]].name + ") and the spine (" +
                             c.nodes[map[OCTOCAP_BONE_TORSO]].name +
                             ") have no common parent joint to carry the root's rotation (give a --bone-map)");
  // The spine: from below the root's node up to the chest, where the arms branch off (below the neck's node).
  int chest = common_ancestor(c, common_ancestor(c, map[OCTOCAP_BONE_L_UPPER_ARM], map[OCTOCAP_BONE_R_UPPER_ARM]),
                              map[OCTOCAP_BONE_HEAD]);
  if (chest == map[OCTOCAP_BONE_HEAD]) chest = c.nodes[chest].parent;
  if (chest >= 0 && chest != root_node_ && is_ancestor(c, root_node_, chest) && is_ancestor(c, map[OCTOCAP_BONE_TORSO], chest)) {
    for (int n = chest; n != root_node_; n = c.nodes[n].parent) spine_.push_back(n);
    std::reverse(spine_.begin(), spine_.end());
  } else {
    spine_ = {map[OCTOCAP_BONE_TORSO]};  // arms off the chain: the torso's node takes the whole rotation
  }
  auto pos = [&](int node) { return Eigen::Vector3f(rest_globals_[node].translation()); };

  // The model's own axes from its rest pose: left from the right to the left thigh, up from the hips to the neck.
  const Eigen::Vector3f left = pos(map[OCTOCAP_BONE_L_UPPER_LEG]) - pos(map[OCTOCAP_BONE_R_UPPER_LEG]);
  const Eigen::Vector3f up = pos(map[OCTOCAP_BONE_HEAD]) - pos(map[OCTOCAP_BONE_ROOT]);
  Eigen::Matrix3f axes;  // columns: rig X (left), Y (up), Z (forward) in model coordinates
  axes.col(0) = left.normalized();
  axes.col(1) = (up - axes.col(0) * axes.col(0).dot(up)).normalized();
  axes.col(2) = axes.col(0).cross(axes.col(1));
  to_rig_ = axes.transpose();
  auto template_dir = [&](int b) {
    const octocap_bone_info_t info = bone_info(b);
    return Eigen::Vector3f(axes * Eigen::Vector3f(info.rest_direction[0], info.rest_direction[1], info.rest_direction[2]));
  };

  // Tails: the node of the bone that starts where this one ends, else the child best aligned with the template
  // direction (a head node's children are face bones and, in the default model, a ponytail pointing back).
  for (int b = 0; b < OCTOCAP_BONE_COUNT; ++b) {
    tail_node_[b] = -1;
    if (map[b] < 0) continue;
    const int tail_joint = bone_info(b).tail_joint;
    for (int o = 0; o < OCTOCAP_BONE_COUNT && tail_node_[b] < 0; ++o)
      if (o != b && map[o] >= 0 && bone_info(o).head_joint == tail_joint && map[o] != map[b]) tail_node_[b] = map[o];
    if (tail_node_[b] >= 0) continue;
    float best = -2;
    for (size_t i = 0; i < c.nodes.size(); ++i) {
      const Eigen::Vector3f d = pos(static_cast<int>(i)) - pos(map[b]);
      if (c.nodes[i].parent != map[b] || d.norm() < 1e-6f) continue;
      const float cosine = d.normalized().dot(template_dir(b));
      if (cosine > best) best = cosine, tail_node_[b] = static_cast<int>(i);
    }
  }
  const int knee = map[OCTOCAP_BONE_L_LOWER_LEG];
  leg_length_ = (pos(knee) - pos(map[OCTOCAP_BONE_L_UPPER_LEG])).norm() +
                (tail_node_[OCTOCAP_BONE_L_LOWER_LEG] >= 0 ? (pos(tail_node_[OCTOCAP_BONE_L_LOWER_LEG]) - pos(knee)).norm() : 0.f);

  for (int b = 0; b < OCTOCAP_BONE_COUNT; ++b) {
    correction_[b] = Eigen::Quaternionf::Identity();
    // A model's head rests upright whatever its head node's children point at: no correction for it.
    if (map[b] < 0 || tail_node_[b] < 0 || b == OCTOCAP_BONE_HEAD) continue;
    // octocap's root bone runs from between the hips to the left hip, i.e. along the hip line; a model's hips node
    // usually sits above the thighs, so its line to the left thigh would tilt the pelvis. Use the hip line.
    const Eigen::Vector3f rest = b == OCTOCAP_BONE_ROOT
                                     ? Eigen::Vector3f(pos(map[OCTOCAP_BONE_L_UPPER_LEG]) - pos(map[OCTOCAP_BONE_R_UPPER_LEG]))
                                     : Eigen::Vector3f(pos(tail_node_[b]) - pos(map[b]));
    if (rest.norm() < 1e-6f) continue;
    correction_[b] = Eigen::Quaternionf::FromTwoVectors(rest.normalized(), template_dir(b));
  }
}

std::vector<int> Retargeter::driven_nodes() const {
  std::vector<int> out = {root_node_};
  out.insert(out.end(), spine_.begin(), spine_.end());
  for (int b = 0; b < OCTOCAP_BONE_COUNT; ++b)
    if (map_[b] >= 0 && b != OCTOCAP_BONE_ROOT && b != OCTOCAP_BONE_TORSO &&
        std::find(out.begin(), out.end(), map_[b]) == out.end())
      out.push_back(map_[b]);
  return out;
}

std::vector<Eigen::Affine3f> Retargeter::pose(const octocap_bone_pose_t* bones) const {
  const Eigen::Matrix3f axes = to_rig_.transpose();
  // The measured rotation of bone b from the template, in model axes, with the turn of the model's rest bone onto
  // the template's: a node's posed global is this times its rest global.
  auto measured = [&](int b) {
    const octocap_quat_t& q = bones[b].global_rotation;
    const Eigen::Matrix3f rig = Eigen::Quaternionf(q.w, q.x, q.y, q.z).toRotationMatrix();
    return Eigen::Quaternionf(axes * rig * to_rig_ * correction_[b].toRotationMatrix()).normalized();
  };
  std::vector<int> bone_of(c_.nodes.size(), -1);
  for (int b = 0; b < OCTOCAP_BONE_COUNT; ++b)
    if (map_[b] >= 0 && b != OCTOCAP_BONE_ROOT && b != OCTOCAP_BONE_TORSO) bone_of[map_[b]] = b;
  // Node -> its rotation from rest, for the nodes the root and the torso drive.
  std::vector<int> share_of(c_.nodes.size(), -1);  // spine index, -2 for the root's node
  if (bones[OCTOCAP_BONE_ROOT].valid) share_of[root_node_] = -2;
  const bool spread = bones[OCTOCAP_BONE_TORSO].valid;
  const Eigen::Quaternionf hips = bones[OCTOCAP_BONE_ROOT].valid ? measured(OCTOCAP_BONE_ROOT) : Eigen::Quaternionf::Identity();
  const Eigen::Quaternionf torso = spread ? measured(OCTOCAP_BONE_TORSO) : Eigen::Quaternionf::Identity();
  const Eigen::Quaternionf against_hips = hips.conjugate() * torso;
  if (spread)
    for (size_t k = 0; k < spine_.size(); ++k) share_of[spine_[k]] = static_cast<int>(k);

  std::vector<Eigen::Affine3f> g(c_.nodes.size());
  for (size_t i = 0; i < c_.nodes.size(); ++i) {
    const int parent = c_.nodes[i].parent;
    g[i] = parent < 0 ? rest_locals_[i] : g[parent] * rest_locals_[i];
    Eigen::Quaternionf from_rest;
    if (share_of[i] == -2) {
      from_rest = hips;
    } else if (share_of[i] >= 0) {
      // Node k of n takes (k + 1) / n of the torso's turn against the hips; without a measured root, the hips stay.
      const float share = static_cast<float>(share_of[i] + 1) / static_cast<float>(spine_.size());
      from_rest = hips * Eigen::Quaternionf::Identity().slerp(share, against_hips);
    } else if (bone_of[i] >= 0 && bones[bone_of[i]].valid) {
      from_rest = measured(bone_of[i]);
    } else {
      continue;  // unmapped or unmeasured: at rest relative to its parent
    }
    g[i].linear() = from_rest.toRotationMatrix() * rest_globals_[i].linear();
  }
  return g;
}

Eigen::Affine3f Retargeter::placement(const octocap_bone_pose_t* bones, const std::vector<Eigen::Affine3f>& globals,
                                      float scale) const {
  const octocap_bone_pose_t& upper = bones[OCTOCAP_BONE_L_UPPER_LEG];
  const octocap_bone_pose_t& lower = bones[OCTOCAP_BONE_L_LOWER_LEG];
  if (scale <= 0)
    scale = upper.valid && lower.valid && leg_length_ > 0 ? (upper.length_m + lower.length_m) / leg_length_ : 1.0f;
  const Eigen::Vector3f root(bones[OCTOCAP_BONE_ROOT].head_position[0], bones[OCTOCAP_BONE_ROOT].head_position[1],
                             bones[OCTOCAP_BONE_ROOT].head_position[2]);
  const Eigen::Vector3f hip_centre =
      (globals[map_[OCTOCAP_BONE_L_UPPER_LEG]].translation() + globals[map_[OCTOCAP_BONE_R_UPPER_LEG]].translation()) / 2;
  Eigen::Affine3f t = Eigen::Affine3f::Identity();
  t.translate(root);
  t.linear() = scale * to_rig_;
  t.translate(-hip_centre);
  return t;
}

Eigen::Vector3f Retargeter::bone_head(const std::vector<Eigen::Affine3f>& globals, int b) const {
  return globals[map_[b]].translation();
}

Eigen::Vector3f Retargeter::bone_tail(const std::vector<Eigen::Affine3f>& globals, int b) const {
  return tail_node_[b] >= 0 ? Eigen::Vector3f(globals[tail_node_[b]].translation()) : bone_head(globals, b);
}
