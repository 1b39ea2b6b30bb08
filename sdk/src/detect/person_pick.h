// Which of the people a model found in one view go on to the 3D solve. Kept apart from the detector so that
// multi-person tracking can replace it later.
#pragma once
#include <vector>

#include "detect/decoders.h"

namespace octocap::internal {

enum class PersonPick : int {
  all = 0,             // every person (best score first): the session's cross-view selection decides
  largest = 1,         // the biggest box
  most_confident = 2,  // the highest person score
  nearest_previous = 3 // closest to a hint (last frame's reprojected joints), else most confident
};

// Orders `people` by the strategy and keeps at most max_people (1 for every strategy but `all`).
// `hint` may be empty (no previous frame); its keypoints are in the same pixels as the people's.
void pick_people(std::vector<DetectedPerson>& people, PersonPick pick, const Person2D& hint, size_t max_people,
                 double min_confidence);

}  // namespace octocap::internal
