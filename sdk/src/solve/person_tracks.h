// Identities over time: each 3D person of a frame gets the id of the track it continues, or of a recently lost
// track it resembles (place and build), or a new id. Ids are never reused within a session.
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/layout.h"

namespace octocap::internal {

struct TrackParams {
  double prior_hold_s = 0.5;   // a track missing longer than this stops guiding the association
  double forget_s = 4.0;       // a lost track can take a returning person back for this long
  double reach_m = 1.0;        // how far from where it was lost a returning person may reappear, plus...
  double speed_m_s = 1.5;      // ...this speed times the time away
  double build_tolerance = 0.12;  // relative difference of bone lengths that still is the same person
};

class PersonTracks {
 public:
  PersonTracks(const KeypointLayout& layout, const TrackParams& params = {});
  // The 3D keypoints of the tracks seen within prior_hold_s before `now_us`, for the association; prior_ids()[i]
  // is the id of priors(now)[i].
  const std::vector<std::vector<Eigen::Vector3d>>& priors(int64_t now_us);
  const std::vector<uint32_t>& prior_ids() const { return prior_ids_; }
  // The people of this frame: their poses (layout keypoints, NaN unknown) and the prior each continues (an index into
  // the last priors(), -1 none). Returns an id per person.
  std::vector<uint32_t> update(const std::vector<std::vector<Eigen::Vector3d>>& poses, const std::vector<int>& prior_of,
                               int64_t now_us);
  // Ids forgotten by the last update() (their per-person state can go).
  const std::vector<uint32_t>& forgotten() const { return forgotten_; }
  void reset();

 private:
  struct Track {
    uint32_t id;
    std::vector<Eigen::Vector3d> pose;
    Eigen::Vector3d centre;
    std::vector<double> build;  // running median-ish estimate of bone lengths (NaN unknown)
    int64_t last_seen_us;
  };
  uint32_t reidentify(const Eigen::Vector3d& centre, const std::vector<double>& build, int64_t now_us,
                      const std::vector<bool>& claimed) const;
  std::vector<double> measure_build(const std::vector<Eigen::Vector3d>& pose) const;

  TrackParams params_;
  std::vector<std::pair<int, int>> segments_;  // keypoint pairs whose lengths tell people apart
  std::vector<Track> tracks_;
  std::vector<std::vector<Eigen::Vector3d>> priors_;
  std::vector<uint32_t> prior_ids_;
  std::vector<uint32_t> forgotten_;
  uint32_t next_id_ = 1;
};

}  // namespace octocap::internal
