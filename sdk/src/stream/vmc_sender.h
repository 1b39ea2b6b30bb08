// VMC protocol output (OSC over UDP, as Virtual Motion Capture, VSeeFace and their Unity receivers speak it):
// one bundle per frame with /VMC/Ext/Root/Pos, /VMC/Ext/Bone/Pos per Unity HumanBodyBones bone (local position
// and rotation, Unity's left-handed frame), /VMC/Ext/T and /VMC/Ext/OK. A VMC receiver drives one avatar, so several
// people go to as many ports: port + n for the person in slot n. A person keeps their slot while tracked; a newcomer
// takes the lowest free one; a slot whose person went gets /VMC/Ext/OK 0 once, so its receiver knows.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/frame.h"
#include "core/frame_sink.h"

namespace octocap::internal {

constexpr uint16_t kVmcDefaultPort = 39539;

class VmcSender : public FrameSink {
 public:
  // `slots`: how many people are sent (ports port .. port + slots - 1).
  VmcSender(const std::string& host, uint16_t port, uint32_t slots = 1);
  ~VmcSender() override;
  VmcSender(const VmcSender&) = delete;
  VmcSender& operator=(const VmcSender&) = delete;
  // Sends the frame; a bone octocap could not solve is left out, so receivers keep its last pose.
  void send(const FrameResult& frame);
  void publish(const FrameResult& frame) override { send(frame); }

 private:
  void assign_slots(const FrameResult& frame);
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::vector<uint32_t> slot_ids_;
};

// Unity HumanBodyBones name of each octocap bone (the engine bone at the octocap bone's head joint).
const char* unity_bone_name(int bone);

}  // namespace octocap::internal
