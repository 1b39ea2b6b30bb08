// The DDS topics octocap's participants create, by what they carry; one list that the publishers, readers and the
// keystore's permissions (which roles may write or read which) are all written from.
#pragma once
#include <string>

namespace octocap::internal {

// Every topic is "<base><suffix>" for the base a user names (--topic, default "octocap").
inline constexpr const char* kDefinitionTopicSuffix = "_definition";  // the skeleton definition
inline constexpr const char* kPoseTopicSuffix = "_pose";              // one person a frame
inline constexpr const char* kPeopleTopicSuffix = "_people";          // everyone of a frame
inline constexpr const char* kKeypointsTopicSuffix = "_keypoints2d";  // a capture node's 2D keypoints, per camera

inline std::string topic_name(const std::string& base, const char* suffix) { return base + suffix; }

}  // namespace octocap::internal
