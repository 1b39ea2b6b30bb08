// A synthetic take solved by a session and scored against its truth: what the temporal-filter test and benchmark share.
#pragma once
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "pipeline/session.h"
#include "synth.h"

namespace testing {

struct TakeScore {
  double mpjpe_mm = 0;   // mean distance to the truth, keypoints solved in three frames in a row
  double jitter_mm = 0;  // mean length of the 3D acceleration error per frame: what a viewer sees shake
  double median_reprojection_px = 0;
  size_t points = 0;     // keypoint observations scored
};

// The rig the filter was tuned on and is judged on: 4 cameras, 1920x1080, focal 1400 px.
inline octocap::internal::Calibration filter_cameras() {
  octocap::internal::synth::RigOptions rig;
  rig.cameras = 4;
  rig.width = 1920, rig.height = 1080, rig.focal = 1400;
  return octocap::internal::synth::make_camera_ring(rig);
}

// Every frame of `motion` seen by `cams` with Gaussian pixel noise of `sigma` (nothing missing, wrong or swapped),
// solved by one session with `cfg`.
inline TakeScore score_take(const octocap::internal::Calibration& cams, const octocap::internal::synth::Motion& motion,
                            const octocap::internal::SessionConfig& cfg, double sigma, unsigned seed = 3) {
  using namespace octocap::internal;
  Session session(cfg, cams);
  synth::NoiseOptions noise;
  noise.pixel_sigma = sigma;
  noise.missing = noise.outlier = noise.swap = 0;
  std::mt19937 rng(seed);
  std::vector<std::vector<Eigen::Vector3d>> got;
  std::vector<double> reprojection;
  for (size_t n = 0; n < motion.frames.size(); ++n) {
    session.solve(synth::observe(cams, motion.frames[n], LayoutId::body25, noise, rng),
                  static_cast<int64_t>(static_cast<double>(n) * 1e6 / motion.rate_hz));
    std::vector<Eigen::Vector3d> p;
    for (const PointResult& k : session.keypoints()) {
      p.push_back(k.valid ? k.position : Eigen::Vector3d::Constant(NAN));
      if (k.valid) reprojection.push_back(k.reprojection_error_px);
    }
    got.push_back(p);
  }
  TakeScore s;
  for (size_t n = 1; n + 1 < got.size(); ++n)
    for (size_t k = 0; k < got[n].size(); ++k) {
      if (!got[n][k].allFinite() || !got[n - 1][k].allFinite() || !got[n + 1][k].allFinite()) continue;
      s.mpjpe_mm += 1000 * (got[n][k] - motion.frames[n][k]).norm();
      const Eigen::Vector3d a = got[n + 1][k] - 2 * got[n][k] + got[n - 1][k];
      const Eigen::Vector3d t = motion.frames[n + 1][k] - 2 * motion.frames[n][k] + motion.frames[n - 1][k];
      s.jitter_mm += 1000 * (a - t).norm();
      ++s.points;
    }
  if (s.points) s.mpjpe_mm /= static_cast<double>(s.points), s.jitter_mm /= static_cast<double>(s.points);
  if (!reprojection.empty()) {
    std::nth_element(reprojection.begin(), reprojection.begin() + reprojection.size() / 2, reprojection.end());
    s.median_reprojection_px = reprojection[reprojection.size() / 2];
  }
  return s;
}

}  // namespace testing
