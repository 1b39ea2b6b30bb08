#include "solve/person_tracks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/stats.h"

namespace octocap::internal {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Eigen::Vector3d centre_of(const std::vector<Eigen::Vector3d>& pose) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int n = 0;
  for (const Eigen::Vector3d& p : pose)
    if (p.allFinite()) sum += p, ++n;
  return n ? Eigen::Vector3d(sum / n) : Eigen::Vector3d::Constant(kNaN);
}

// Median relative difference of the segments both builds know; NaN when fewer than 3 are shared.
double build_difference(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> d;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i)
    if (std::isfinite(a[i]) && std::isfinite(b[i]) && b[i] > 0) d.push_back(std::abs(a[i] - b[i]) / b[i]);
  return d.size() < 3 ? kNaN : median_in_place(d, kNaN);
}

// In double: the difference of two extreme int64 timestamps overflows int64.
double seconds_between(int64_t from_us, int64_t to_us) {
  return (static_cast<double>(to_us) - static_cast<double>(from_us)) * 1e-6;
}

}  // namespace

PersonTracks::PersonTracks(const KeypointLayout& layout, const TrackParams& params) : params_(params) {
  auto index = [&](const char* name) {
    for (size_t k = 0; k < layout.keypoints.size(); ++k)
      if (std::string(layout.keypoints[k]) == name) return static_cast<int>(k);
    return -1;
  };
  // Limbs and widths: together they tell two adults apart better than height alone, and each is measured well.
  const char* pairs[][2] = {{"LShoulder", "LElbow"}, {"LElbow", "LWrist"}, {"RShoulder", "RElbow"},
                            {"RElbow", "RWrist"},    {"LHip", "LKnee"},     {"LKnee", "LAnkle"},
                            {"RHip", "RKnee"},       {"RKnee", "RAnkle"},   {"LShoulder", "RShoulder"},
                            {"LHip", "RHip"}};
  for (auto& p : pairs) {
    const int a = index(p[0]), b = index(p[1]);
    if (a >= 0 && b >= 0) segments_.emplace_back(a, b);
  }
}

void PersonTracks::reset() {
  tracks_.clear();
  priors_.clear();
  prior_ids_.clear();
  forgotten_.clear();
  // next_id_ goes on: ids are never reused within a session.
}

std::vector<double> PersonTracks::measure_build(const std::vector<Eigen::Vector3d>& pose) const {
  std::vector<double> out;
  for (const auto& [a, b] : segments_) {
    const bool known = a < static_cast<int>(pose.size()) && b < static_cast<int>(pose.size()) && pose[a].allFinite() &&
                       pose[b].allFinite();
    out.push_back(known ? (pose[a] - pose[b]).norm() : kNaN);
  }
  return out;
}

const std::vector<std::vector<Eigen::Vector3d>>& PersonTracks::priors(int64_t now_us) {
  priors_.clear();
  prior_ids_.clear();
  for (const Track& t : tracks_)
    if (seconds_between(t.last_seen_us, now_us) <= params_.prior_hold_s) {
      priors_.push_back(t.pose);
      prior_ids_.push_back(t.id);
    }
  return priors_;
}

uint32_t PersonTracks::reidentify(const Eigen::Vector3d& centre, const std::vector<double>& build, int64_t now_us,
                                  const std::vector<bool>& claimed) const {
  uint32_t best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < tracks_.size(); ++i) {
    const Track& t = tracks_[i];
    if (claimed[i]) continue;
    const double away_s = seconds_between(t.last_seen_us, now_us);
    const double d = (centre - t.centre).norm();
    if (!(d <= params_.reach_m + params_.speed_m_s * std::max(0.0, away_s))) continue;
    // Someone else's build is someone else: a returning person must also look like the one who left.
    const double diff = build_difference(build, t.build);
    if (std::isfinite(diff) && diff > params_.build_tolerance) continue;
    if (d < best_distance) best_distance = d, best = t.id;
  }
  return best;
}

std::vector<uint32_t> PersonTracks::update(const std::vector<std::vector<Eigen::Vector3d>>& poses,
                                           const std::vector<int>& prior_of, int64_t now_us) {
  std::vector<uint32_t> ids(poses.size(), 0);
  std::vector<bool> claimed(tracks_.size(), false);
  auto track_index = [&](uint32_t id) {
    for (size_t i = 0; i < tracks_.size(); ++i)
      if (tracks_[i].id == id) return static_cast<int>(i);
    return -1;
  };
  for (size_t p = 0; p < poses.size(); ++p)
    if (prior_of[p] >= 0 && prior_of[p] < static_cast<int>(prior_ids_.size())) {
      ids[p] = prior_ids_[prior_of[p]];
      claimed[track_index(ids[p])] = true;
    }
  for (size_t p = 0; p < poses.size(); ++p) {
    if (ids[p] != 0) continue;
    const uint32_t again = reidentify(centre_of(poses[p]), measure_build(poses[p]), now_us, claimed);
    if (again != 0) {
      ids[p] = again;
      claimed[track_index(again)] = true;
      continue;
    }
    ids[p] = next_id_++;
    tracks_.push_back({ids[p], {}, Eigen::Vector3d::Constant(kNaN), std::vector<double>(segments_.size(), kNaN), now_us});
    claimed.push_back(true);
  }
  for (size_t p = 0; p < poses.size(); ++p) {
    Track& t = tracks_[track_index(ids[p])];
    t.pose = poses[p];
    t.centre = centre_of(poses[p]);
    t.last_seen_us = now_us;
    // Bone lengths settle slowly (an exponential average): one bad frame does not change who a person is.
    const std::vector<double> b = measure_build(poses[p]);
    for (size_t i = 0; i < b.size(); ++i) {
      if (!std::isfinite(b[i])) continue;
      t.build[i] = std::isfinite(t.build[i]) ? 0.9 * t.build[i] + 0.1 * b[i] : b[i];
    }
  }
  forgotten_.clear();
  for (auto it = tracks_.begin(); it != tracks_.end();) {
    if (seconds_between(it->last_seen_us, now_us) > params_.forget_s) {
      forgotten_.push_back(it->id);
      it = tracks_.erase(it);
    } else {
      ++it;
    }
  }
  return ids;
}

}  // namespace octocap::internal
