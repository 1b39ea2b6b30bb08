// VMC protocol output (OSC over UDP, as Virtual Motion Capture, VSeeFace and their Unity receivers speak it):
// one bundle per frame with /VMC/Ext/Root/Pos, /VMC/Ext/Bone/Pos per Unity HumanBodyBones bone (local position
// and rotation, Unity's left-handed frame), /VMC/Ext/T and /VMC/Ext/OK.
#pragma once
#include <cstdint>
#include <memory>
#include <string>

#include "core/frame.h"
#include "core/frame_sink.h"

namespace octocap {

constexpr uint16_t kVmcDefaultPort = 39539;

class VmcSender : public FrameSink {
 public:
  VmcSender(const std::string& host, uint16_t port);
  ~VmcSender() override;
  VmcSender(const VmcSender&) = delete;
  VmcSender& operator=(const VmcSender&) = delete;
  // Sends the frame; a bone octocap could not solve is left out, so receivers keep its last pose.
  void send(const FrameResult& frame);
  void publish(const FrameResult& frame) override { send(frame); }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Unity HumanBodyBones name of each octocap bone (the engine bone at the octocap bone's head joint).
const char* unity_bone_name(int bone);

}  // namespace octocap
