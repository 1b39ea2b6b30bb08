#include "stream/vmc_sender.h"

#include <lo/lo.h>

#include "core/error.h"
#include "core/log.h"
#include "rig/engine_frames.h"

namespace octocap {
namespace {

const char* const kUnityNames[kBoneCount] = {
    "Hips", "Spine", "Neck", "RightShoulder", "RightUpperArm", "RightLowerArm", "LeftShoulder",
    "LeftUpperArm", "LeftLowerArm", "RightUpperLeg", "RightLowerLeg", "LeftUpperLeg", "LeftLowerLeg"};

// Where a bone starts in its parent's frame at rest (rig frame): the parent's tail, except for bones that
// branch off the middle of their parent (shoulders and head at the neck = the torso's tail; legs at the hips).
Eigen::Vector3d rest_offset(int bone, const SkeletonPose& pose) {
  const auto& dirs = tpose_directions();
  const BoneDef& d = bone_table()[bone];
  if (d.parent < 0) return Eigen::Vector3d::Zero();
  if (bone == kBoneRUpperLeg) return -dirs[kBoneRoot] * pose[kBoneRoot].length;
  if (bone == kBoneLUpperLeg) return dirs[kBoneRoot] * pose[kBoneRoot].length;
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

struct VmcSender::Impl {
  lo_address address = nullptr;
};

VmcSender::VmcSender(const std::string& host, uint16_t port) : impl_(std::make_unique<Impl>()) {
  impl_->address = lo_address_new(host.c_str(), std::to_string(port).c_str());
  if (!impl_->address) throw Error(Errc::invalid_argument, "VMC: cannot send to " + host + ":" + std::to_string(port));
}

VmcSender::~VmcSender() { lo_address_free(impl_->address); }

void VmcSender::send(const FrameResult& frame) {
  // LO_TT_IMMEDIATE's value, without its C99 compound literal (not C++).
  lo_timetag immediate;
  immediate.sec = 0;
  immediate.frac = 1;
  lo_bundle bundle = lo_bundle_new(immediate);
  const SkeletonPose& pose = frame.person_or_blank(0).bones;  // VMC drives one avatar: the first person
  const bool ok = pose[kBoneRoot].valid;
  lo_message status = lo_message_new();
  lo_message_add_int32(status, ok ? 1 : 0);
  lo_bundle_add_message(bundle, "/VMC/Ext/OK", status);
  lo_message time = lo_message_new();
  lo_message_add_float(time, static_cast<float>(frame.info.timestamp_us * 1e-6));
  lo_bundle_add_message(bundle, "/VMC/Ext/T", time);
  if (ok) {
    lo_message root = lo_message_new();
    lo_message_add_string(root, "root");
    add_transform(root, pose[kBoneRoot].head, pose[kBoneRoot].global);
    lo_bundle_add_message(bundle, "/VMC/Ext/Root/Pos", root);
    for (int b = 0; b < kBoneCount; ++b) {
      if (!pose[b].valid) continue;
      lo_message m = lo_message_new();
      lo_message_add_string(m, kUnityNames[b]);
      // Hips carry the root transform already: their local pose is identity.
      if (b == kBoneRoot)
        add_transform(m, Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity());
      else
        add_transform(m, rest_offset(b, pose), pose[b].local);
      lo_bundle_add_message(bundle, "/VMC/Ext/Bone/Pos", m);
    }
  }
  if (lo_send_bundle(impl_->address, bundle) < 0)
    log(LogLevel::warning, std::string("VMC: send failed: ") + lo_address_errstr(impl_->address));
  lo_bundle_free_recursive(bundle);
}

}  // namespace octocap
