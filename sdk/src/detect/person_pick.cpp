#include "detect/person_pick.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace octocap::internal {
namespace {

// Mean distance over keypoints both have with confidence; infinity when they share none.
double distance_to(const DetectedPerson& p, const Person2D& hint, double min_confidence) {
  double sum = 0;
  int n = 0;
  for (size_t k = 0; k < p.keypoints.size() && k < hint.size(); ++k) {
    if (p.keypoints[k].confidence < min_confidence || hint[k].confidence <= 0) continue;
    sum += std::hypot(p.keypoints[k].x - hint[k].x, p.keypoints[k].y - hint[k].y);
    ++n;
  }
  return n ? sum / n : std::numeric_limits<double>::infinity();
}

}  // namespace

void pick_people(std::vector<DetectedPerson>& people, PersonPick pick, const Person2D& hint, size_t max_people,
                 double min_confidence) {
  auto by_score = [](const DetectedPerson& a, const DetectedPerson& b) { return a.score > b.score; };
  switch (pick) {
    case PersonPick::all:
    case PersonPick::most_confident: std::stable_sort(people.begin(), people.end(), by_score); break;
    case PersonPick::largest:
      std::stable_sort(people.begin(), people.end(), [](const DetectedPerson& a, const DetectedPerson& b) {
        return a.box.width * a.box.height > b.box.width * b.box.height;
      });
      break;
    case PersonPick::nearest_previous: {
      std::stable_sort(people.begin(), people.end(), by_score);
      if (hint.empty()) break;
      std::vector<double> d;
      for (const auto& p : people) d.push_back(distance_to(p, hint, min_confidence));
      std::vector<size_t> order(people.size());
      for (size_t i = 0; i < order.size(); ++i) order[i] = i;
      std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return d[a] < d[b]; });
      std::vector<DetectedPerson> sorted;
      for (size_t i : order) sorted.push_back(std::move(people[i]));
      people = std::move(sorted);
      break;
    }
  }
  const size_t keep = pick == PersonPick::all ? max_people : std::min<size_t>(1, max_people);
  if (people.size() > keep) people.resize(keep);
}

}  // namespace octocap::internal
