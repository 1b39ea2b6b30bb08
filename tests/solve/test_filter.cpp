// The One Euro filter: less jitter when still, little lag when fast.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "pipeline/session.h"
#include "solve/one_euro.h"
#include "synth.h"
#include "take_score.h"

using namespace octocap::internal;

TEST_CASE("One Euro removes jitter from a still point", "[filter]") {
  OneEuroFilter3 f(1.5, 5.0);
  std::mt19937 rng(1);
  std::normal_distribution<double> g(0, 0.005);  // 5 mm jitter
  double raw = 0, filtered = 0;
  for (int i = 0; i < 600; ++i) {
    const Eigen::Vector3d x(g(rng), 1 + g(rng), g(rng));
    const Eigen::Vector3d y = f.filter(x, 1.0 / 60);
    if (i < 60) continue;
    raw += (x - Eigen::Vector3d(0, 1, 0)).squaredNorm();
    filtered += (y - Eigen::Vector3d(0, 1, 0)).squaredNorm();
  }
  REQUIRE(std::sqrt(filtered / raw) < 0.4);  // jitter at least 2.5x smaller
}

TEST_CASE("One Euro follows fast motion with little lag", "[filter]") {
  OneEuroFilter3 f(1.5, 5.0);
  double worst = 0;
  for (int i = 0; i < 120; ++i) {
    const double t = i / 60.0;
    const Eigen::Vector3d x(3.0 * t, 1, 0);  // 3 m/s, a fast hand
    const Eigen::Vector3d y = f.filter(x, 1.0 / 60);
    if (i > 20) worst = std::max(worst, (y - x).norm());
  }
  // A plain low-pass at the 1.5 Hz min cutoff would trail by about 0.3 m here.
  REQUIRE(worst < 0.04);
}

TEST_CASE("One Euro restarts cleanly after a reset", "[filter]") {
  OneEuroFilter3 f(1.5, 5.0);
  f.filter({0, 0, 0}, 0.01);
  f.filter({0, 0, 0}, 0.01);
  f.reset();
  REQUIRE((f.filter({5, 5, 5}, 0.01) - Eigen::Vector3d(5, 5, 5)).norm() == 0);
}

// The session's default filter follows the measured noise: on CMU motion seen by 4 cameras, with 1 px of detection
// noise it is as good as no filter (the fixed filter doubles the error by lagging), with 6 px as good as the fixed one.
TEST_CASE("the default filter smooths a clean signal less and a noisy one as much as the fixed filter", "[filter]") {
  const Calibration cams = testing::filter_cameras();
  const synth::Motion motion = synth::load_cmu_motion(synth::default_bvh_path(), 0, 300, 4);
  auto run = [&](double sigma, bool filter, bool adaptive) {
    SessionConfig cfg;
    cfg.up = UpAxis::y;
    cfg.filter = filter;
    cfg.filter_adaptive = adaptive;
    const testing::TakeScore s = testing::score_take(cams, motion, cfg, sigma);
    REQUIRE(s.points > 0.9 * 25 * motion.frames.size());
    return s;
  };
  for (double sigma : {1.0, 6.0}) {
    const testing::TakeScore none = run(sigma, false, false), fixed = run(sigma, true, false), adaptive = run(sigma, true, true);
    INFO(sigma << " px: none " << none.mpjpe_mm << " / " << none.jitter_mm << " mm, fixed " << fixed.mpjpe_mm << " / "
               << fixed.jitter_mm << ", adaptive " << adaptive.mpjpe_mm << " / " << adaptive.jitter_mm);
    if (sigma < 2) {  // measured: none 3.2 / 7.7, fixed 6.4 / 5.1, adaptive 3.3 / 7.3
      CHECK(adaptive.mpjpe_mm < 1.1 * none.mpjpe_mm);
      CHECK(adaptive.mpjpe_mm < 0.7 * fixed.mpjpe_mm);
      CHECK(adaptive.jitter_mm <= none.jitter_mm);
    } else {  // measured: none 19.8 / 48.8, fixed and adaptive 16.0 / 28.3
      CHECK(adaptive.mpjpe_mm < 1.02 * fixed.mpjpe_mm);
      CHECK(adaptive.jitter_mm < 1.02 * fixed.jitter_mm);
      CHECK(adaptive.jitter_mm < 0.7 * none.jitter_mm);
    }
  }
}
