// FrameResult <-> the IDL's Pose sample, and the skeleton definition sample.
#pragma once
#include <string>
#include <vector>

#include "octocap_stream.h"
#include "core/frame.h"

namespace octocap::internal {

// Owns the buffers a wire Pose points into, so a sample can be written without allocations per frame
// once warmed up.
struct PoseBuffers {
  std::vector<octocap_wire_PointSample> keypoints, joints;
  std::vector<octocap_wire_BoneSample> bones;
  octocap_wire_Pose sample{};
};

void fill_pose(const FrameResult& frame, uint32_t source_id, uint32_t definition_counter, PoseBuffers& out);

constexpr size_t kWirePeople = 16;  // the IDL's bound on PeopleFrame.people (= OCTOCAP_MAX_PEOPLE)

// The same for every person of the frame (the PeopleFrame topic of several-people sessions).
struct PeopleBuffers {
  std::vector<PoseBuffers> people;  // one person's sequences each (their `sample` unused)
  std::vector<octocap_wire_PersonPose> samples;
  octocap_wire_PeopleFrame sample{};
};
void fill_people(const FrameResult& frame, uint32_t source_id, uint32_t definition_counter, PeopleBuffers& out);

// Checks a received Pose or PeopleFrame sample (version, sizes, finite numbers, person ids) and turns it into a
// FrameResult. On failure returns false with the reason in `why`.
bool read_pose(const octocap_wire_Pose& in, LayoutId layout, FrameResult& out, std::string& why);
bool read_people(const octocap_wire_PeopleFrame& in, LayoutId layout, FrameResult& out, std::string& why);

struct Name32 {
  char s[32];
};
struct DefinitionBuffers {
  std::vector<Name32> keypoint_names, joint_names;
  std::vector<octocap_wire_BoneDef> bones;
  octocap_wire_SkeletonDefinition sample{};
};
void fill_definition(LayoutId layout, uint32_t source_id, uint32_t change_counter, DefinitionBuffers& out);

}  // namespace octocap::internal
