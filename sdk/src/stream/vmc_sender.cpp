#include "stream/vmc_sender.h"

#include <lo/lo.h>

#include <algorithm>

#include "core/error.h"
#include "core/log.h"
#include "rig/engine_frames.h"

namespace octocap::internal {
namespace {

const char* const kUnityNames[kBoneCount] = {
    "Hips", "Spine", "Neck", "RightShoulder", "RightUpperArm", "RightLowerArm", "LeftShoulder",
    "LeftUpperArm", "LeftLowerArm", "RightUpperLeg", "RightLowerLeg", "LeftUpperLeg", "LeftLowerLeg",
    "RightFoot", "LeftFoot", "RightHand", "LeftHand"};

// Where a bone starts in its parent's frame at rest (rig frame): where its head joint sits against the parent's head
// joint in the T-pose. Mostly the parent's tail; the torso starts where the root does (the root's tail is the left
// hip), the legs at the hips on either side of it, shoulders and head at the neck (the torso's tail).
Eigen::Vector3d rest_offset(int bone, const SkeletonPose& pose) {
  const auto& dirs = tpose_directions();
  const BoneDef& d = bone_table()[bone];
  if (d.parent < 0 || d.head == bone_table()[d.parent].head) return Eigen::Vector3d::Zero();
  if (bone == kBoneRUpperLeg) return -dirs[kBoneRoot] * pose[kBoneRoot].length;
  return dirs[d.parent] * pose[d.parent].length;
}

void add_transform(lo_message m, const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
  const Eigen::Vector3d pu = convert_position(p, CoordFrame::unity);
  const Eigen::Quaterniond qu = convert_rotation(q, CoordFrame::unity);
  for (int k = 0; k < 3; ++k) lo_message_add_float(m, static_cast<float>(pu[k]));
  lo_message_add_float(m, static_cast<float>(qu.x()));
  lo_message_add_float(m, static_cast<float>(qu.y()));
  lo_message_add_float(m, static_cast<float>(qu.z()));
  lo_message_add_float(m, static_cast<float>(qu.w()));
}

}  // namespace

const char* unity_bone_name(int bone) { return bone >= 0 && bone < kBoneCount ? kUnityNames[bone] : nullptr; }

namespace {

lo_bundle new_bundle() {
  // LO_TT_IMMEDIATE's value, without its C99 compound literal (not C++).
  lo_timetag immediate;
  immediate.sec = 0;
  immediate.frac = 1;
  return lo_bundle_new(immediate);
}

// One avatar's bundle: /VMC/Ext/OK, /VMC/Ext/T, and the root and bones when the person has a pose.
void add_person(lo_bundle bundle, const SkeletonPose* pose, int64_t timestamp_us) {
  const bool ok = pose && (*pose)[kBoneRoot].valid;
  lo_message status = lo_message_new();
  lo_message_add_int32(status, ok ? 1 : 0);
  lo_bundle_add_message(bundle, "/VMC/Ext/OK", status);
  lo_message time = lo_message_new();
  lo_message_add_float(time, static_cast<float>(timestamp_us * 1e-6));
  lo_bundle_add_message(bundle, "/VMC/Ext/T", time);
  if (!ok) return;
  lo_message root = lo_message_new();
  lo_message_add_string(root, "root");
  add_transform(root, (*pose)[kBoneRoot].head, (*pose)[kBoneRoot].global);
  lo_bundle_add_message(bundle, "/VMC/Ext/Root/Pos", root);
  auto add_bone = [&](const char* name, const Eigen::Vector3d& offset, const Eigen::Quaterniond& local) {
    lo_message m = lo_message_new();
    lo_message_add_string(m, name);
    add_transform(m, offset, local);
    lo_bundle_add_message(bundle, "/VMC/Ext/Bone/Pos", m);
  };
  const Eigen::Quaterniond identity = Eigen::Quaterniond::Identity();
  const SkeletonPose& p = *pose;
  for (int b = 0; b < kBoneCount; ++b) {
    if (!p[b].valid) continue;
    if (b == kBoneRoot) {
      add_bone(kUnityNames[b], Eigen::Vector3d::Zero(), identity);  // Hips: the root transform carries them
    } else if (b == kBoneTorso) {
      // Humanoid avatars bend the back in three: Spine, Chest, UpperChest each take a third of the torso's rotation
      // and a third of its length (a receiver that has no UpperChest folds it into Chest), so the neck ends where
      // octocap's torso ends.
      const Eigen::Quaterniond third = identity.slerp(1.0 / 3, p[b].local);
      const Eigen::Vector3d step = tpose_directions()[b] * (p[b].length / 3);
      add_bone("Spine", rest_offset(b, p), third);
      add_bone("Chest", step, third);
      add_bone("UpperChest", step, third);
    } else if (b == kBoneHead) {
      // Neck and Head share the neck-to-head bone: half its rotation each, the Head half way along it.
      const Eigen::Quaterniond half = identity.slerp(0.5, p[b].local);
      add_bone("Neck", tpose_directions()[kBoneTorso] * (p[kBoneTorso].length / 3), half);
      add_bone("Head", tpose_directions()[b] * (p[b].length / 2), half);
    } else {
      // Off the torso's tail: a third of the torso above UpperChest.
      const bool on_chest = bone_table()[b].parent == kBoneTorso;
      add_bone(kUnityNames[b], on_chest ? Eigen::Vector3d(tpose_directions()[kBoneTorso] * (p[kBoneTorso].length / 3))
                                        : rest_offset(b, p),
               p[b].local);
    }
  }
}

}  // namespace

struct VmcSender::Impl {
  std::vector<lo_address> addresses;  // one per slot
  ~Impl() {
    for (lo_address a : addresses) lo_address_free(a);
  }
};

VmcSender::VmcSender(const std::string& host, uint16_t port, uint32_t slots)
    : impl_(std::make_unique<Impl>()), slot_ids_(std::max<uint32_t>(slots, 1), 0) {
  if (port + slot_ids_.size() - 1 > 65535)
    throw Error(Errc::invalid_argument, "VMC: ports " + std::to_string(port) + ".." +
                                            std::to_string(port + slot_ids_.size() - 1) + " run past 65535");
  for (size_t n = 0; n < slot_ids_.size(); ++n) {
    const std::string p = std::to_string(port + n);
    lo_address a = lo_address_new(host.c_str(), p.c_str());
    if (!a) throw Error(Errc::invalid_argument, "VMC: cannot send to " + host + ":" + p);
    impl_->addresses.push_back(a);
  }
}

VmcSender::~VmcSender() = default;

void VmcSender::assign_slots(const FrameResult& frame) {
  auto present = [&](uint32_t id) {
    for (const PersonResult& p : frame.people)
      if (p.id == id) return true;
    return false;
  };
  for (uint32_t& id : slot_ids_)
    if (id != 0 && !present(id)) id = 0;
  for (const PersonResult& p : frame.people) {  // in id order: the earlier arrival gets the lower slot
    if (std::find(slot_ids_.begin(), slot_ids_.end(), p.id) != slot_ids_.end()) continue;
    auto free_slot = std::find(slot_ids_.begin(), slot_ids_.end(), 0u);
    if (free_slot == slot_ids_.end()) break;
    *free_slot = p.id;
  }
}

void VmcSender::send(const FrameResult& frame) {
  std::vector<uint32_t> before = slot_ids_;
  assign_slots(frame);
  for (size_t n = 0; n < slot_ids_.size(); ++n) {
    const PersonResult* person = nullptr;
    for (const PersonResult& p : frame.people)
      if (p.id == slot_ids_[n]) person = &p;
    // An empty slot says so once (and the single slot every frame, as VMC senders do when tracking is lost).
    if (!person && before[n] == 0 && slot_ids_.size() > 1) continue;
    lo_bundle bundle = new_bundle();
    add_person(bundle, person ? &person->bones : nullptr, frame.info.timestamp_us);
    if (lo_send_bundle(impl_->addresses[n], bundle) < 0)
      log(LogLevel::warning, std::string("VMC: send failed: ") + lo_address_errstr(impl_->addresses[n]));
    lo_bundle_free_recursive(bundle);
  }
}

}  // namespace octocap::internal
