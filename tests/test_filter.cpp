// The One Euro filter: less jitter when still, little lag when fast.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <random>

#include "solve/one_euro.h"

using namespace octocap;

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
