// Causal One Euro filter (Casiez et al. 2012): heavy smoothing at low speed, little lag at high speed.
#pragma once
#include <Eigen/Core>

namespace octocap::internal {

class OneEuroFilter3 {
 public:
  OneEuroFilter3(double min_cutoff_hz, double beta, double derivative_cutoff_hz = 1.0)
      : min_cutoff_(min_cutoff_hz), beta_(beta), d_cutoff_(derivative_cutoff_hz) {}
  // dt in seconds; the first sample (or the first after reset) passes through. `cutoff_scale` multiplies the minimum
  // cutoff for this sample (an adaptive filter's measured-noise factor).
  Eigen::Vector3d filter(const Eigen::Vector3d& x, double dt, double cutoff_scale = 1.0);
  void reset() { initialised_ = false; }

 private:
  double min_cutoff_, beta_, d_cutoff_;
  bool initialised_ = false;
  Eigen::Vector3d x_prev_ = Eigen::Vector3d::Zero(), dx_prev_ = Eigen::Vector3d::Zero();
};

}  // namespace octocap::internal
