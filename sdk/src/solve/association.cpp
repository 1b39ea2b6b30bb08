#include "solve/association.h"

#include <algorithm>
#include <cmath>

#include "core/stats.h"
#include "solve/view_agreement.h"

namespace octocap::internal {
namespace {

// The body's place: the median of its known keypoints per axis (robust to a stray keypoint).
bool body_centre(const std::vector<Eigen::Vector3d>& pose, Eigen::Vector3d& out) {
  std::vector<double> axis[3];
  for (const Eigen::Vector3d& p : pose)
    if (p.allFinite())
      for (int a = 0; a < 3; ++a) axis[a].push_back(p[a]);
  if (axis[0].size() < 3) return false;
  for (int a = 0; a < 3; ++a) out[a] = median_in_place(axis[a], 0);
  return true;
}

double confidence(const Person2D& p) {
  double sum = 0;
  for (const Keypoint2D& k : p) sum += k.confidence;
  return sum;
}

class Associator {
 public:
  Associator(const Calibration& calib, const std::vector<std::vector<Person2D>>& people, const AssociationParams& p)
      : calib_(calib), people_(people), params_(p), used_(people.size()) {
    for (size_t v = 0; v < people.size(); ++v) used_[v].assign(people[v].size(), false);
  }

  // Gives each prior its nearest people (nearest pairs first over all priors and views), then keeps what agrees.
  void continue_priors(const std::vector<std::vector<Eigen::Vector3d>>& priors) {
    struct Pair {
      double d;
      size_t prior, view;
      int person;
    };
    std::vector<Pair> pairs;
    for (size_t t = 0; t < priors.size(); ++t)
      for (size_t v = 0; v < people_.size(); ++v)
        for (size_t p = 0; p < people_[v].size(); ++p) {
          // Between two frames a person moves: more room than the association threshold.
          const double d = distance_to_pose(calib_[v], people_[v][p], priors[t], params_.min_confidence);
          if (d <= 3 * params_.threshold_px) pairs.push_back({d, t, v, static_cast<int>(p)});
        }
    std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.d < b.d; });
    std::vector<std::vector<int>> choice(priors.size(), std::vector<int>(people_.size(), -1));
    std::vector<std::vector<bool>> taken = used_;
    for (const Pair& p : pairs) {
      if (choice[p.prior][p.view] >= 0 || taken[p.view][p.person]) continue;
      choice[p.prior][p.view] = p.person;
      taken[p.view][p.person] = true;
    }
    for (size_t t = 0; t < priors.size(); ++t) accept(choice[t], static_cast<int>(t), params_.min_views);
  }

  // Groups the people no prior took: pairs of views that agree seed a person, grown by the other views.
  void find_new_people() {
    const size_t V = people_.size();
    struct Seed {
      double cost;
      std::vector<int> choice;
    };
    // Bounded work whatever the input (64 views of 64 people would be 8 million pairs): at most kMaxSeedTrials
    // two-view triangulations a frame, from each view's most confident unused people. People left out now are found
    // in a later frame, once the ones taken here are tracked.
    constexpr double kMaxSeedTrials = 4000;
    const double pairs = std::max(1.0, static_cast<double>(V * (V - 1) / 2));
    const size_t keep = std::max<size_t>(2, static_cast<size_t>(std::sqrt(kMaxSeedTrials / pairs)));
    std::vector<std::vector<int>> cands = unused();
    for (size_t v = 0; v < V; ++v) {
      std::stable_sort(cands[v].begin(), cands[v].end(),
                       [&](int x, int y) { return confidence(people_[v][x]) > confidence(people_[v][y]); });
      if (cands[v].size() > keep) cands[v].resize(keep);
    }
    std::vector<Seed> seeds;
    for (size_t a = 0; a < V; ++a)
      for (size_t b = a + 1; b < V; ++b)
        for (int pa : cands[a])
          for (int pb : cands[b]) {
            std::vector<int> trial(V, -1);
            trial[a] = pa;
            trial[b] = pb;
            const auto errs = combination_errors(calib_, people_, trial, params_.min_confidence);
            const double cost = std::max(errs[a], errs[b]);
            if (cost <= params_.threshold_px) seeds.push_back({cost, std::move(trial)});
          }
    std::sort(seeds.begin(), seeds.end(), [](const Seed& x, const Seed& y) { return x.cost < y.cost; });
    for (const Seed& seed : seeds) {
      bool free = true;
      for (size_t v = 0; v < V; ++v)
        if (seed.choice[v] >= 0 && used_[v][seed.choice[v]]) free = false;
      if (!free) continue;
      std::vector<int> choice = seed.choice;
      grow_by_nearest(calib_, people_, unused(), params_.min_confidence, 2 * params_.threshold_px, choice);
      // The same body as a person already found: its views join that person where it has none.
      if (PersonCluster* same = same_body(choice)) {
        std::vector<int> merged = same->choice;
        for (size_t v = 0; v < V; ++v)
          if (merged[v] < 0) merged[v] = choice[v];
        if (merged != same->choice) regrow(*same, merged);
        continue;
      }
      accept(choice, -1, std::max(params_.min_views, params_.birth_views));
    }
  }

  std::vector<PersonCluster> take() {
    // Most views first (then priors first): the people best seen survive the cap.
    std::stable_sort(clusters_.begin(), clusters_.end(), [](const PersonCluster& a, const PersonCluster& b) {
      const auto seen = [](const PersonCluster& c) { return std::count_if(c.choice.begin(), c.choice.end(), [](int p) { return p >= 0; }); };
      return seen(a) > seen(b);
    });
    if (clusters_.size() > params_.max_people) clusters_.resize(params_.max_people);
    return std::move(clusters_);
  }

 private:
  // Keeps the views of `choice` that agree with the rest; a person of at least `min_views` views inside the volume
  // becomes a cluster and its 2D people are used up. (Dropping the worst view can change the others' errors, so it
  // is done one view at a time.)
  void accept(std::vector<int> choice, int prior, int min_views) {
    std::vector<Eigen::Vector3d> pose;
    if (!agreeing(choice, pose, min_views)) return;
    Eigen::Vector3d centre;
    if (!body_centre(pose, centre)) return;
    if (!params_.volume.isEmpty() && !params_.volume.contains(centre)) return;  // a bystander outside the volume
    for (size_t v = 0; v < choice.size(); ++v)
      if (choice[v] >= 0) used_[v][choice[v]] = true;
    clusters_.push_back({std::move(choice), prior, std::move(pose)});
  }

  // A cluster grown by more views: kept when they agree with it (the views it had are never lost).
  void regrow(PersonCluster& cluster, std::vector<int> choice) {
    std::vector<Eigen::Vector3d> pose;
    if (!agreeing(choice, pose, params_.min_views)) return;
    for (size_t v = 0; v < choice.size(); ++v)
      if (cluster.choice[v] >= 0 && choice[v] != cluster.choice[v]) return;
    for (size_t v = 0; v < choice.size(); ++v)
      if (choice[v] >= 0) used_[v][choice[v]] = true;
    cluster.choice = std::move(choice);
    cluster.pose = std::move(pose);
  }

  // The cluster whose body this choice's triangulation lies on: most keypoints within 15 cm (two people's bodies are
  // never that close everywhere, even in an embrace).
  PersonCluster* same_body(const std::vector<int>& choice) {
    std::vector<Eigen::Vector3d> pose;
    combination_errors(calib_, people_, choice, params_.min_confidence, &pose);
    for (PersonCluster& c : clusters_) {
      int near = 0, shared = 0;
      for (size_t k = 0; k < pose.size() && k < c.pose.size(); ++k) {
        if (!pose[k].allFinite() || !c.pose[k].allFinite()) continue;
        ++shared;
        near += (pose[k] - c.pose[k]).norm() < 0.15;
      }
      if (shared >= 3 && near * 2 > shared) return &c;
    }
    return nullptr;
  }

  // Drops the views of `choice` that disagree with the rest, worst first; true when `min_views` remain.
  bool agreeing(std::vector<int>& choice, std::vector<Eigen::Vector3d>& pose, int min_views) const {
    for (;;) {
      const auto errs = combination_errors(calib_, people_, choice, params_.min_confidence, &pose);
      int worst = -1, seen = 0;
      for (size_t v = 0; v < choice.size(); ++v) {
        if (choice[v] < 0) continue;
        ++seen;
        if (errs[v] > params_.threshold_px && (worst < 0 || errs[v] > errs[worst])) worst = static_cast<int>(v);
      }
      if (seen < min_views) return false;
      if (worst < 0) return true;
      choice[worst] = -1;
    }
  }

  // Each view's 2D people not yet part of a person.
  std::vector<std::vector<int>> unused() const {
    std::vector<std::vector<int>> out(people_.size());
    for (size_t v = 0; v < people_.size(); ++v)
      for (size_t p = 0; p < people_[v].size(); ++p)
        if (!used_[v][p]) out[v].push_back(static_cast<int>(p));
    return out;
  }

  const Calibration& calib_;
  const std::vector<std::vector<Person2D>>& people_;
  const AssociationParams& params_;
  std::vector<std::vector<bool>> used_;
  std::vector<PersonCluster> clusters_;
};

}  // namespace

std::vector<PersonCluster> associate_people(const Calibration& calib, const std::vector<std::vector<Person2D>>& people,
                                            const std::vector<std::vector<Eigen::Vector3d>>& priors,
                                            const AssociationParams& params) {
  Associator a(calib, people, params);
  a.continue_priors(priors);
  a.find_new_people();
  return a.take();
}

}  // namespace octocap::internal
